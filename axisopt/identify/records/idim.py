"""Inverse dynamic identification (IDIM) of a feed axis from time records, and the effects beyond
the rigid baseline it names: the estimation run is identified by least squares and instrumental
variables (:mod:`.estimators`, on the rows of :mod:`.timemodel`), each candidate effect
(:func:`.effects.time_effects`: its columns, shape search, when a record can show it and its
physical range) is fitted jointly with the baseline, and effects are selected forward by
:data:`.selection.TIME_RULE`.

Selection: each round the candidates are sorted by dBIC = n ln(RSS1/RSS0) + dp ln n on the
estimation run; a candidate passes when dBIC < -10, the RMSE of the effort predicted on the
validation runs (or, with no validation run, 5 contiguous blocks of the estimation run held out in
turn) falls by at least 5 %, and its values are physical; the best that passes is accepted and every
other candidate keeps the first criterion it failed as its reason; another candidate that passes too
and predicts the held-out data within the rule's resolution is recorded as an equally good
explanation (``equivalent``). When no single effect passes, pairs of the candidates that lower
BIC alone are fitted together and accepted on the same tests when each member is needed
(:func:`best_pair`). The baseline and final fits carry plausibility and identifiability flags
(:func:`baseline_flags`), the final residual is tested for structure (:mod:`.timeresidual`) and,
with a motor encoder, the lost motion measured (:mod:`.lostmotion`). The text and JSON of a
:class:`TimeDiagnosis` are in :mod:`axisopt.report.timediag`. Nothing here imports the CLI or YAML.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

from ...errors import InputError
from ..effects import TimeModel, time_effects
from ..selection import TIME_RULE as RULE
from .controller import heldout_gain as controller_heldout_gain
from .estimators import (
    Controller,
    Estimate,
    fit_controller,
    instrumental_variables,
    least_squares,
    lstsq,
    predict,
    search_shape,
)
from .lostmotion import LostMotion, lost_motion
from .regression import (
    BASE,
    UNITS,
    Rows,
    make_rows,
    matrix,
    processing_for,
    symbol,
    terms_by_name,
    unit_of,
)
from .signature import steady_line
from .unexplained import Unexplained, analyse_residual, noise_floor, periodic_peak, residual_peak

# the design's values the order lines read (effects.orders), passed on as Processing fields
ORDER_KEYS = ("reduction", "ball_order", "belt_teeth")


@dataclass
class TimeCandidate:
    effect: TimeModel
    estimate: Estimate
    dbic: float
    gain: float  # [%] validation (or held-out block) RMSE reduction
    reason: str = ""  # why it was not accepted ('' when accepted or not yet judged)
    together: str = ""  # accepted as a pair with this effect (neither passes alone)


@dataclass
class TimeDiagnosis:
    quantity: str
    estimation: Rows
    validation: list
    controller: Controller | None
    baseline_ls: Estimate
    baseline_iv: Estimate
    final: Estimate  # IV with the accepted effects
    final_ls: Estimate
    accepted: list  # TimeCandidate in order
    rounds: list  # list of lists of TimeCandidate
    skipped: dict  # effect -> reason it was not a candidate
    residual_peak: tuple  # (frequency [Hz], ratio to median) of the baseline residual spectrum
    times: dict  # seconds: ls, iv, diagnose
    # name, lead, efficiency (for the torque -> force note)
    design: dict = field(default_factory=dict)
    # (round, TimeCandidate, reason): outside its physical range
    rejected: list = field(default_factory=list)
    # (round, TimeCandidate, TimeCandidate, Estimate, dBIC, gain, reason)
    pairs: list = field(default_factory=list)
    unexplained: Unexplained | None = None  # structure left in the final residual
    # 'baseline' / 'final' -> [plausibility or identifiability notes]
    flags: dict = field(default_factory=dict)
    # lost motion between motor and table (records with motor_position)
    lost: LostMotion | None = None
    # (round, accepted, alternative, % apart): equally good
    equivalent: list = field(default_factory=list)
    # the record's top table speed [m/s] (the regime effects' plausibility is judged in)
    top_speed: float = 0.0

    @property
    def verdict(self) -> list:
        return [c.effect.name for c in self.accepted] + (
            ["backlash"] if self.lost and self.lost.accepted else []
        )

    @property
    def validation_mode(self) -> str:
        return "validation runs" if self.validation else "5 held-out blocks of the estimation run"


def heldout_rmse(est_rows: Rows, val_rows: list, terms, shape) -> float:
    if val_rows:
        e = least_squares(est_rows, terms, shape)
        r = np.concatenate([v.y - predict(v, e) for v in val_rows])
        return float(np.sqrt(np.mean(r**2)))
    W = matrix(est_rows, terms, shape)
    y = est_rows.y
    blocks = np.array_split(np.arange(len(y)), 5)
    err = []
    for b in blocks:
        m = np.ones(len(y), bool)
        m[b] = False
        th = lstsq(W[m], y[m])
        err.append(y[b] - W[b] @ th)
    r = np.concatenate(err)
    return float(np.sqrt(np.mean(r**2)))


@dataclass
class TimeContext:
    """What an effect's ``skip`` sees of the estimation run: the baseline residual's spectral peak,
    the span of positions covered, the stroke and lead (record coordinate)."""

    rows: Rows
    base: Estimate
    peak: tuple  # (frequency [Hz], ratio to median) of the baseline residual spectrum
    span: float
    stroke_q: float
    lead_q: float
    position_unit: tuple  # (unit, factor from SI) of a position in the record's coordinate

    def periodic_peak(self):
        """(period, share) when the baseline residual is mostly periodic in position, else None."""
        return periodic_peak(self.rows, self.base)

    def steady_line(self):
        """(frequency, share) when the baseline residual's spectral peak is a steady line in time
        (one phase through the run: a periodic disturbance, not a resonance the moves excite), else
        None."""
        return steady_line(self.rows, self.base, self.peak[0])


def implausible(effects, est: Estimate, base: Estimate, proc=None) -> str:
    """Why the effects' fitted values leave their physical range ('' when they do not); every range
    is relative to the baseline's own friction (each effect declares its range,
    :class:`.effects.TimeModel`); with ``proc``, also values the record cannot resolve
    (``resolved``)."""
    fc, fv = abs(base.value("Fc")), abs(base.value("Fv"))
    out = [t for e in effects for t in e.why_implausible(est.value, fc, fv)]
    if proc is not None:
        out += [
            t for e in effects if e.resolved is not None for t in [e.resolved(est.value, proc)] if t
        ]
    return "; ".join(out)


def fit_candidate(est_rows: Rows, terms, effect: TimeModel, shape: dict) -> tuple:
    """LS fit of ``terms`` with the effect's shape parameter found on the estimation run: (estimate,
    shape)."""
    shape = dict(shape)
    sh = effect.shape
    if sh is not None and sh.search is not None:
        own = [t for t in terms if t not in effect.terms]
        r0 = est_rows.y - matrix(est_rows, own, shape) @ least_squares(est_rows, own, shape).theta
        shape.update(
            sh.search(est_rows, r0, lambda v: least_squares(est_rows, terms, {**shape, **v}).rss)
        )
    elif sh is not None and sh.bounds is not None:
        lo, hi = sh.bounds(est_rows.sig, est_rows.proc)
        shape[sh.name] = search_shape(est_rows, terms, shape, lo, hi, sh.name)
    elif sh is not None and sh.choices is not None:
        fits = [
            least_squares(est_rows, terms, {**shape, sh.name: v}) for v in sh.choices(est_rows.proc)
        ]
        best = min(fits, key=lambda e: e.rss)
        return best, dict(best.shape)
    return least_squares(est_rows, terms, shape), shape


def diagnose_time(
    records: list,
    *,
    stroke_q: float,
    candidates=None,
    max_effects: int = 3,
    design: dict | None = None,
    lead_q: float = 0.0,
) -> TimeDiagnosis:
    """Identify the estimation record ``records[0]`` (LS and IV), select effects, validate on the
    rest."""
    import time

    t0 = time.perf_counter()
    est = records[0]
    proc = processing_for(est, stroke_q, lead_q)
    # the design's turning parts, for the lines in motor and screw orders (effects.orders)
    proc = replace(proc, **{k: (design or {})[k] for k in ORDER_KEYS if k in (design or {})})
    est_rows = make_rows(est, proc)
    val_rows = [make_rows(r, proc) for r in records[1:]]
    ctrl = fit_controller(est_rows, (design or {}).get("controller"))
    if ctrl is not None:
        ctrl.heldout_gain = controller_heldout_gain(ctrl, val_rows)
    tl = time.perf_counter()
    base_ls = least_squares(est_rows, BASE)
    t_ls = time.perf_counter() - tl
    ti = time.perf_counter()
    base_iv = instrumental_variables(est_rows, BASE, ctrl=ctrl, start=base_ls)
    t_iv = time.perf_counter() - ti

    effects = time_effects()
    names = list(candidates) if candidates else list(effects)
    pool, skipped = [], {}
    peak = residual_peak(est_rows, base_ls)
    span = float(np.ptp(est_rows.sig["q"][est_rows.keep]))
    ctx = TimeContext(
        est_rows, base_ls, peak, span, stroke_q, lead_q, UNITS[est.quantity]["position"]
    )
    for nm in names:
        e = effects[nm]
        # the record lacks the signal: not a candidate at all
        if any(k not in est_rows.sig for k in e.needs):
            if candidates:
                raise InputError(
                    f"--effects {nm}: the record has no {', '.join(e.needs)} signal ({e.summary})",
                    source=est.source,
                )
            continue
        short = e.too_short(ctx) if e.too_short is not None and candidates else ""
        if short:
            raise InputError(f"--effects {nm}: {short}", source=est.source)
        why = e.skip(ctx) if e.skip is not None else ""
        if why:
            skipped[nm] = why
        else:
            pool.append(e)

    terms, shape = list(BASE), {}
    cur = base_ls
    cur_ho = heldout_rmse(est_rows, val_rows, terms, shape)
    accepted, rounds, rejected, pairs, equivalent = [], [], [], [], []
    while len(accepted) < max_effects:
        scored = []
        for e in pool:
            if e in [c.effect for c in accepted]:
                continue
            tt = terms + list(e.terms)
            fit, sh = fit_candidate(est_rows, tt, e, shape)
            dbic = fit.bic - cur.bic
            ho = heldout_rmse(est_rows, val_rows, tt, sh)
            scored.append(TimeCandidate(e, fit, dbic, RULE.gain(cur_ho, ho)))
        if not scored:
            break
        scored.sort(key=lambda c: c.dbic)
        rounds.append(scored)
        top = None
        # the best candidate by dBIC that is physical and predicts held-out data better
        for c in scored:
            why = implausible([c.effect], c.estimate, base_ls, est_rows.proc)
            if why:
                rejected.append((len(rounds), c, why))
            c.reason = RULE.reason(c.dbic, c.gain, why)
            if not c.reason and top is None:
                top = c
        if top is not None:
            top.reason = ""
            ho_top = cur_ho * (1.0 - top.gain / 100.0)
            # another that passes too and predicts as well: the data do not tell them apart
            for c in scored:
                d = (
                    RULE.equivalent(ho_top, cur_ho * (1.0 - c.gain / 100.0))
                    if c is not top and not c.reason
                    else None
                )
                if d is not None:
                    equivalent.append((len(rounds), top, c, d))
            for c in scored:
                if c is not top and not c.reason:
                    c.reason = f"{top.effect.name} explains more (dBIC {top.dbic:.1f})"
            accepted.append(top)
            terms += list(top.effect.terms)
            shape.update(top.estimate.shape)
            cur = top.estimate
            cur_ho = heldout_rmse(est_rows, val_rows, terms, shape)
            continue
        # pairs only when some candidate found signal (dBIC < -10) that no single effect turns into
        # an accepted explanation: a residual at the noise floor costs no pair fits
        if len(accepted) + 2 > max_effects or not any(c.dbic < RULE.accept_dbic for c in scored):
            break
        pair = best_pair(
            est_rows, val_rows, scored, terms, shape, cur, cur_ho, base_ls, len(rounds), pairs
        )
        if pair is None:
            break
        a_, b_, fit = pair[1], pair[2], pair[3]
        for c, other in ((a_, b_), (b_, a_)):
            c.reason, c.together = (
                f"alone: {c.reason}; accepted together with {other.effect.name}",
                other.effect.name,
            )
        accepted += [a_, b_]
        terms += list(a_.effect.terms) + list(b_.effect.terms)
        shape = dict(fit.shape)
        cur = fit
        cur_ho = heldout_rmse(est_rows, val_rows, terms, shape)
        for c in (a_, b_):
            c.gain = pair[5]
    final_ls = least_squares(est_rows, terms, shape) if accepted else base_ls
    final = (
        instrumental_variables(est_rows, terms, shape, ctrl=ctrl, start=final_ls)
        if accepted
        else base_iv
    )
    un = analyse_residual([est_rows] + val_rows, final)
    flags = {
        "baseline": baseline_flags(base_iv, est.quantity),
        "final": baseline_flags(final, est.quantity),
    }
    flags["final"] += _shape_flags(final, est_rows, effects.values(), est.quantity)
    vmax = float(np.max(np.abs(est_rows.sig["v"][est_rows.keep]))) * (
        1.0 if est.quantity == "force" else lead_q / (2.0 * math.pi) if lead_q else 0.0
    )
    flags["final"] += [
        f"{c.effect.name}: {why}"
        for c in accepted
        if c.effect.regime is not None
        for why in [c.effect.regime(vmax)]
        if why
    ]
    lost = lost_motion(
        est_rows, val_rows, final_ls, noise_floor(est_rows), (design or {}).get("lead", 0.0)
    )
    times = {"ls": t_ls, "iv": t_iv, "diagnose": time.perf_counter() - t0}
    return TimeDiagnosis(
        est.quantity,
        est_rows,
        val_rows,
        ctrl,
        base_ls,
        base_iv,
        final,
        final_ls,
        accepted,
        rounds,
        skipped,
        peak,
        times,
        dict(design or {}),
        rejected,
        pairs,
        un,
        flags,
        lost,
        equivalent,
        vmax,
    )


def _shape_flags(final: Estimate, rows: Rows, effects, quantity: str) -> list:
    """A shape parameter searched over a range and found at its end is not identified by the
    record."""
    out = []
    for e in effects:
        sh = e.shape
        if sh is None or sh.bounds is None or sh.name not in final.shape:
            continue
        lo, hi = sh.bounds(rows.sig, rows.proc)
        if not 1.05 * lo < final.shape[sh.name] < 0.95 * hi:
            u, f = UNITS[quantity][sh.unit]
            out.append(
                f"{sh.name} = {final.shape[sh.name] * f:.3g} {u} is at the end of its search range "
                f"({lo * f:.3g}..{hi * f:.3g} {u}): the "
                + ("Stribeck velocity" if sh.name == "vs" else sh.label.split(" (")[0])
                + " is not identifiable from this record"
            )
    return out


def best_pair(est_rows, val_rows, scored, terms, shape, cur, cur_ho, base_ls, rnd, log):
    """When no single effect passes, effects that only help together: every pair of the round's
    candidates that lower BIC at all alone (at most :data:`.selection.TIME_RULE` ``pair_pool``),
    fitted jointly with the shapes each found alone; a pair is accepted on the rule's tests and when
    it beats each of its members alone by ``min_gain`` (each is needed).  The pair with the largest
    held-out gain wins; every pair tried is logged with its reason."""
    pool = RULE.pair_pool_of(scored)  # each must show some signal alone
    best = None
    for i in range(len(pool)):
        for j in range(i + 1, len(pool)):
            a, b = pool[i], pool[j]
            sh0 = {
                **shape,
                **{k: v for k, v in a.estimate.shape.items() if k not in shape},
                **{k: v for k, v in b.estimate.shape.items() if k not in shape},
            }
            tt = terms + list(a.effect.terms) + list(b.effect.terms)
            fit, sh = least_squares(est_rows, tt, sh0), sh0  # shapes as found for each alone
            dbic = fit.bic - cur.bic
            ho = heldout_rmse(est_rows, val_rows, tt, sh)
            gain = RULE.gain(cur_ho, ho)
            why = implausible([a.effect, b.effect], fit, base_ls, est_rows.proc)
            reason = RULE.pair_reason(dbic, gain, why, max(a.gain, b.gain))
            entry = [rnd, a, b, fit, dbic, gain, reason]
            log.append(entry)
            if not reason and (best is None or gain > best[5]):
                best = entry
    if best is not None:
        for e in log:
            if e is not best and e[0] == rnd and not e[6]:
                e[6] = (
                    f"{best[1].effect.name} + {best[2].effect.name} predicts better ({best[5]:.1f} "
                    "%)"
                )
    return best


def baseline_flags(est: Estimate, quantity: str) -> list:
    """Plausibility and identifiability of a fit's baseline terms: a moving mass or inertia, viscous
    or Coulomb friction that is not positive is never a physical fit; a term whose standard
    deviation is zero or undefined, or larger than its value, is not identifiable from the
    record."""
    out = []
    known = terms_by_name()
    sym = "J" if quantity == "torque" else "M"
    for t in est.terms:
        i = est.terms.index(t)
        v, sd = float(est.theta[i]), float(est.std[i])
        u, f = unit_of(quantity, t)
        name = symbol(quantity, t)
        if t == "M" and v <= 0.0:
            out.append(
                f"{sym} = {v * f:.3g} {u} is not positive: no moving body has zero or negative "
                "inertia -- the record does not excite acceleration enough for its sampling and "
                "noise (too coarse, too slow), or effort and position disagree in sign"
            )
        elif t == "Fc" and v < 0.0:
            out.append(
                f"Fc = {v * f:.3g} {u} is negative: friction that drives the axis -- check the "
                "signs of the effort and position columns, or a force the record does not carry "
                "(external_force)"
            )
        elif t == "Fv" and v < 0.0:
            out.append(
                f"Fv = {v * f:.3g} {u} is negative: damping that feeds energy in -- a missing "
                "low-speed (Stribeck) rise or a force the record does not carry pulls it below zero"
            )
        if t in BASE or t in known:
            if not math.isfinite(sd) or sd == 0.0:
                out.append(
                    f"{name} is not identifiable from this record: its uncertainty is "
                    f"{'undefined' if not math.isfinite(sd) else 'zero'} (a degenerate column)"
                )
            elif t in ("M", "Fv", "Fc") and sd >= abs(v):
                out.append(
                    f"{name} = {v * f:.3g} ± {sd * f:.3g} {u} is not identifiable from this record "
                    "(the uncertainty exceeds the value)"
                )
    return out


def diagnose_time_files(
    paths, *, plant, gain: str | None = None, candidates=None, max_effects: int = 3
) -> TimeDiagnosis:
    """Read the records (the first the estimation run, the others validation runs) and diagnose them
    against ``plant`` (:class:`.plant.Plant`: lead, efficiency and stroke are used)."""
    from .record import check_same_columns, read_time_record
    from .signal import windowed

    if candidates:
        effects = time_effects()
        unknown = [c for c in candidates if c not in effects]
        if unknown:
            raise InputError(
                f"--effects: unknown time-record effect '{unknown[0]}'; known: {', '.join(effects)}"
            )
    if max_effects < 0:
        raise InputError("--max-effects must not be negative")
    recs = [
        read_time_record(p, lead=plant.lead, gain=gain, efficiency=plant.efficiency) for p in paths
    ]
    for r in recs[1:]:
        check_same_columns(recs[0], r)
        if r.quantity != recs[0].quantity:
            raise InputError(
                f"a {r.quantity} record cannot validate the {recs[0].quantity} record "
                f"{recs[0].name}",
                source=r.source,
            )
    to_q = 1.0 if recs[0].quantity == "force" else 2.0 * math.pi / plant.lead
    design = {
        "name": plant.name,
        "lead": plant.lead,
        "efficiency": plant.efficiency,
        "reduction": plant.reduction,
        "ball_order": plant.ball_order,
        "belt_teeth": plant.belt_teeth,
        "controller": plant.controller,
    }
    recs = [windowed(r) for r in recs]
    return diagnose_time(
        recs,
        stroke_q=plant.stroke * to_q,
        candidates=candidates,
        max_effects=max_effects,
        design=design,
        lead_q=plant.lead * to_q,
    )

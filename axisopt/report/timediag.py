"""Time-record diagnosis output (:class:`axisopt.identify.records.idim.TimeDiagnosis`): console
text, at most 100 columns, and a JSON-ready dict.  Nothing here prints.

Parameters are shown in the record's coordinate (:data:`axisopt.identify.records.regression.UNITS`);
lengths of the lost motion and of residual signatures as table travel through the lead.  A residual
signature is put in words with its candidate causes and the measurement that would separate them
(:data:`SIGNATURE_WORDS`).
"""

from __future__ import annotations

import math

from ..identify.effects import time_effects
from ..identify.records.estimators import Estimate, mode_frequency, rel_error
from ..identify.records.idim import TimeDiagnosis
from ..identify.records.regression import UNITS, shape_params, symbol, term, unit_of
from ..identify.records.signal import BUTTER_ORDER
from ..identify.selection import TIME_RULE
from .text import wrap_words
from .timeresidual import (
    as_mm,
    order_lines,
    unexplained_dict,
    unexplained_lines,
)


def _fmt(v, s=None):
    if s is None or not math.isfinite(s):
        return f"{v:.4g}"
    return f"{v:.4g} ± {s:.2g}"


def _param_lines(q, est: Estimate, only=None, indent="    ") -> list:
    out = []
    for t, v, s in zip(est.terms, est.theta, est.std):
        if only is not None and t not in only:
            continue
        u, f = unit_of(q, t)
        label = "moving inertia (motor side)" if (q, t) == ("torque", "M") else term(t).label
        out.append(f"{indent}{symbol(q, t):<7}{_fmt(v * f, s * f):>22} {u:<10} {label}".rstrip())
    if "vs" in est.shape and (only is None or "Fs" in only):
        u, f = UNITS[q]["speed"]
        out.append(
            f"{indent}{'vs':<7}{est.shape['vs'] * f:>22.4g} {u:<10} Stribeck velocity (1-D search)"
        )
    for nm, (label, u, f) in _shapes(q, est, only):
        out.append(f"{indent}{nm:<7}{est.shape[nm] * f:>22.5g} {u:<10} {label}")
    for nm, v, u, label in _derived(q, est, only):
        out.append(f"{indent}{nm:<7}{v:>22.4g} {u:<10} {label}")
    fr = mode_frequency(est)
    if fr is not None and (only is None or "beta" in only):
        out.append(f"{indent}{'f_r':<7}{fr:>22.4g} {'Hz':<10} resonance sqrt(M/beta)/2pi")
    return out


# the Stribeck velocity has its own line; the ripple's period is the lead's
SHAPES_APART = ("vs", "period")


def _shapes(q, est: Estimate, only=None) -> list:
    """(name, (label, unit, factor)) of the searched shape parameters of ``est`` (the effects' own
    terms in ``only`` when given) shown beside its terms."""
    known = shape_params()
    owners = {}
    for eff in time_effects().values():
        if eff.shape is not None:
            for nm in (eff.shape.name, *(a[0] for a in eff.shape.also)):
                owners[nm] = eff.terms
    out = []
    for nm in est.shape:
        if nm in SHAPES_APART or nm not in known:
            continue
        if only is not None and not set(owners.get(nm, ())) & set(only):
            continue
        label, kind = known[nm]
        u, f = UNITS[q][kind]
        out.append((nm, (label, u, f)))
    return out


def _derived(q, est: Estimate, only=None) -> list:
    """(name, value, unit, label) of the quantities the effects of ``est`` derive from their
    terms."""
    out = []
    for eff in time_effects().values():
        if not eff.derived or not all(t in est.terms for t in eff.terms):
            continue
        if only is not None and not set(eff.terms) & set(only):
            continue
        for nm, label, kind, fn in eff.derived:
            u, f = UNITS[q][kind]
            out.append((nm, fn(est.value) * f, u, label))
    return out


def _errors(diag, est) -> str:
    parts = [f"estimation {100 * rel_error(diag.estimation, est):.2f} %"]
    parts += [f"{v.record.name} {100 * rel_error(v, est):.2f} %" for v in diag.validation]
    return ", ".join(parts)


def _compact(q, est: Estimate, terms) -> str:
    out = []
    for t in terms:
        i = est.terms.index(t)
        u, f = unit_of(q, t)
        out.append(f"{symbol(q, t)} {_fmt(est.theta[i] * f, est.std[i] * f)} {u}")
    if "vs" in est.shape and "Fs" in terms:
        u, f = UNITS[q]["speed"]
        out.append(f"vs {est.shape['vs'] * f:.3g} {u}")
    for nm, (_label, u, f) in _shapes(q, est, terms):
        out.append(f"{nm} {est.shape[nm] * f:.5g} {u}")
    for nm, v, u, _label in _derived(q, est, terms):
        out.append(f"{nm} {v:.4g} {u}")
    fr = mode_frequency(est)
    if fr is not None and "beta" in terms:
        out.append(f"f_r {fr:.3g} Hz")
    return ", ".join(out)


def time_diagnosis_text(diag: TimeDiagnosis) -> str:
    """Console text, at most 100 columns (prose wrapped with indented continuation)."""
    q = diag.quantity
    er, p = diag.estimation, diag.estimation.proc
    rec = er.record
    unit_eff = UNITS[q]["effort"][0]
    spd_u, spd_f = UNITS[q]["speed"]
    L = [
        f"time-record identification (IDIM) of {diag.design.get('name', 'the axis')}: {q} data, "
        + ("table coordinate" if q == "force" else "motor angle coordinate")
    ]
    L += wrap_words(
        f"estimation  {rec.name}: {rec.n} samples at {p.fs:.6g} Hz, {er.n} regression rows"
        + (f"; {rec.gain_note}" if rec.gain_note else "")
        + (f"; {rec.run_note()}" if rec.run_note() else ""),
        cont="              ",
    )
    for v in diag.validation:
        note = v.record.run_note()
        L += wrap_words(
            f"validation  {v.record.name}: {v.record.n} samples, {v.n} regression rows"
            + (f"; {note}" if note else ""),
            cont="              ",
        )
    L += wrap_words(
        f"filter      zero-phase Butterworth, order {BUTTER_ORDER} (|H|^2 by FFT, as "
        f"forward-backward), cut-off {p.fc:.1f} Hz: {p.rule}; motion bandwidth {p.f_motion:.1f} Hz",
        cont="              ",
    )
    L += wrap_words(
        f"decimation  parallel: every column and the {q} low-passed at {p.fdec:.1f} Hz, every "
        f"{p.nd}th row kept; rows below {p.vmin * spd_f:.3g} {spd_u} or at reversals left out",
        cont="              ",
    )
    L += controller_lines(diag.controller)
    L.append("")
    L.append(
        "baseline  f = M a + Fv v + Fc sgn(v) + offset"
        if q == "force"
        else "baseline  T = J a + Fv w + Fc sgn(w) + offset (motor side)"
    )
    for est in (diag.baseline_ls, diag.baseline_iv):
        L += wrap_words(f"{est.method}" + (f"  ({est.note})" if est.note else ""), cont="      ")
        L += _param_lines(q, est)
        L += wrap_words(f"{q} error ||y - y_hat||/||y||: {_errors(diag, est)}", indent="    ")
    for f in diag.flags.get("baseline", []):
        L += wrap_words(f"! {f}", indent="  ", cont="      ")
    if q == "torque" and diag.design.get("lead"):
        lead, eta = diag.design["lead"], diag.design.get("efficiency", 1.0)
        g = 2 * math.pi / lead
        b = diag.baseline_iv.as_dict()
        L += wrap_words(
            f"table side through lead {lead * 1e3:g} mm and efficiency {eta:g} (F = T 2pi eta/p, M "
            f"= J (2pi/p)^2 eta): M {b['M'] * g * g * eta:.4g} kg, Fv {b['Fv'] * g * g * eta:.4g} "
            f"N.s/m, Fc {b['Fc'] * g * eta:.4g} N, offset {b['offset'] * g * eta:.4g} N"
        )
    L.append("")
    rule = TIME_RULE
    L += wrap_words(
        "candidates, each fitted (LS) jointly with the baseline; dBIC on the estimation run, gain "
        f"on the {diag.validation_mode}; accepted if dBIC < {rule.accept_dbic:g} and gain >= "
        f"{rule.min_gain:g} %",
        indent="",
        cont="  ",
    )
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            L += wrap_words(
                f"{k}  {cnd.effect.name:<20} dBIC {cnd.dbic:>8.1f}  gain {cnd.gain:>6.1f} %  "
                + _compact(q, cnd.estimate, cnd.effect.terms),
                cont=" " * 52,
            )
    for nm, why in diag.skipped.items():
        L += wrap_words(f"-  {nm:<20} not tried: {why}", cont=" " * 26)
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            if cnd.reason:
                L += wrap_words(
                    f"{k}  {cnd.effect.name:<20} not accepted: {cnd.reason}", cont=" " * 26
                )
    rest = 0
    for k, a, b, _est, dbic, gain, why in diag.pairs:
        if why and (dbic >= rule.accept_dbic or gain < rule.min_gain):
            rest += 1
            continue
        L += wrap_words(
            f"{k}  pair {a.effect.name} + {b.effect.name}: dBIC {dbic:.1f}, gain {gain:.1f} %: "
            + (f"not accepted: {why}" if why else "accepted (neither passes alone)"),
            cont=" " * 26,
        )
    if rest:
        L += wrap_words(
            f"-  {rest} pair{'s' if rest > 1 else ''} of these candidates tried together: none "
            f"lowers BIC by {-rule.accept_dbic:g} and predicts the held-out data {rule.min_gain:g} "
            "% better",
            cont=" " * 26,
        )
    L.append("")
    if diag.accepted:
        parts = []
        for c in diag.accepted:
            if c.together and parts and parts[-1].startswith(c.together):
                parts[-1] = parts[-1].replace(" (", f" together with {c.effect.name} (", 1)
                continue
            parts.append(
                f"{c.effect.name} ({c.effect.summary}; gain {c.gain:.0f} % on held-out data)"
            )
        L += wrap_words("verdict: " + ", then ".join(parts), indent="", cont="  ")
        L += wrap_words(
            f"final fit ({diag.final.method}"
            + (f"; {diag.final.note}" if diag.final.note else "")
            + ")",
            cont="    ",
        )
        L += _param_lines(q, diag.final)
        L += order_lines(diag)
        L += wrap_words(f"{q} error: {_errors(diag, diag.final)}", indent="    ")
        for f in diag.flags.get("final", []):
            L += wrap_words(f"! {f}", indent="  ", cont="      ")
        L += _equivalent_lines(diag)
    elif not (diag.lost and diag.lost.accepted):
        L += wrap_words(
            "verdict: nothing named beyond the baseline: " + _why_none(diag), indent="", cont="  "
        )
    L += _lost_motion_lines(diag)
    L += unexplained_lines(diag)
    L += wrap_words(
        f"the offset [{unit_eff}] holds any Coulomb asymmetry (Fc+ - Fc-)/2: while the axis moves "
        "the two are the same column"
    )
    return "\n".join(L)


def _equivalent_text(diag: TimeDiagnosis, a, b, apart: float) -> str:
    top = diag.top_speed
    notes = [
        f"{e.name}: {w}"
        for e in (a.effect, b.effect)
        if e.regime is not None
        for w in [e.regime(top)]
        if w
    ]
    return (
        f"{a.effect.name} and {b.effect.name} explain the data equally well: held-out RMSE "
        f"{apart:.2f} % apart, within the rule's {TIME_RULE.resolution:g} % resolution (dBIC "
        f"{a.dbic:.1f} against {b.dbic:.1f}); {a.effect.name} is named for its lower dBIC, not "
        "because the data tell them apart. "
        + (" ".join(n[0].upper() + n[1:] + "." for n in notes) + " " if notes else "")
        + f"To separate them: for {a.effect.name}, "
        f"{a.effect.evidence or 'a test that shows it alone'}; for {b.effect.name}, "
        f"{b.effect.evidence or 'a test that shows it alone'}."
    )


def _equivalent_lines(diag: TimeDiagnosis) -> list:
    out = []
    for _k, a, b, apart in diag.equivalent:
        out += wrap_words("~ " + _equivalent_text(diag, a, b, apart), indent="  ", cont="      ")
    return out


def _lost_motion_lines(diag: TimeDiagnosis) -> list:
    lm = diag.lost
    if lm is None:
        return []
    q = diag.quantity
    b, sb = as_mm(diag, lm.width) * 1e3, as_mm(diag, lm.width_std) * 1e3
    sym = "v1" if q == "force" else "w1"
    what = (
        f"motor_position against position: e = e0 + (b/2) sgn(F) + F/k, F = {q} - m1 a1 - Fc1 "
        f"sgn({sym}) - Fv1 {sym} the force the transmission carries (the motor side's own friction "
        f"taken out: Fc1 {_fmt_unit(q, 'Fc', lm.motor_coulomb)}, Fv1 "
        f"{_fmt_unit(q, 'Fv', lm.motor_viscous)}); b = {b:.3g} ± {sb:.2g} um of table travel"
    )
    if math.isfinite(lm.stiffness) and lm.stiffness > 0:
        per_m = lm.stiffness / (as_mm(diag, 1.0) * 1e-3)  # effort per metre of table travel
        k_txt = (
            f"{per_m / 1e6:.3g} N/um"
            if q == "force"
            else f"{per_m / 1e6:.3g} N.m per um of table travel"
        )
        what += f", windup stiffness k {k_txt}"
    m_u = UNITS[q]["mass"][0]
    what += (
        f", motor-side m1 {lm.motor_mass:.3g} {m_u}; held-out RMS of e "
        f"{as_mm(diag, lm.rms_before) * 1e3:.3g} -> {as_mm(diag, lm.rms_after) * 1e3:.3g} um (gain "
        f"{lm.gain:.0f} %)"
    )
    if lm.accepted:
        head = (
            "verdict: backlash (lost motion between motor and table, measured by the two "
            "encoders): "
        )
        return wrap_words(head + what, indent="", cont="  ")
    return wrap_words(
        f"lost motion between motor and table not named ({lm.reason}): {what}", indent="", cont="  "
    )


def _why_none(diag: TimeDiagnosis) -> str:
    """The true reason no effect was named: the best candidates and what stopped each."""
    if not diag.rounds:
        return "no candidate effect applies to this record"
    best = diag.rounds[0][:3]
    out = [
        f"{c.effect.name}: "
        + (
            f"dBIC {c.dbic:.1f} and gain {c.gain:.1f} %, but {c.reason}"
            if c.reason.startswith("would need")
            else c.reason
        )
        for c in best
    ]
    return "; ".join(out)


def _est_dict(q, est: Estimate) -> dict:
    d = {
        "method": est.method,
        "note": est.note,
        "iterations": est.iterations,
        "converged": est.converged,
        "parameters": [
            {
                "name": symbol(q, t),
                "value": float(v * unit_of(q, t)[1]),
                "std": float(s * unit_of(q, t)[1]),
                "unit": unit_of(q, t)[0],
                "label": term(t).label,
            }
            for t, v, s in zip(est.terms, est.theta, est.std)
        ],
    }
    if "vs" in est.shape:
        u, f = UNITS[q]["speed"]
        d["parameters"].append(
            {
                "name": "vs",
                "value": est.shape["vs"] * f,
                "std": None,
                "unit": u,
                "label": "Stribeck velocity (1-D search)",
            }
        )
    for nm, (label, u, f) in _shapes(q, est):
        d["parameters"].append(
            {"name": nm, "value": est.shape[nm] * f, "std": None, "unit": u, "label": label}
        )
    for nm, v, u, label in _derived(q, est):
        d["parameters"].append({"name": nm, "value": v, "std": None, "unit": u, "label": label})
    fr = mode_frequency(est)
    if fr is not None:
        d["parameters"].append(
            {"name": "f_r", "value": fr, "std": None, "unit": "Hz", "label": "resonance"}
        )
    return d


def time_diagnosis_dict(diag: TimeDiagnosis) -> dict:
    q, p = diag.quantity, diag.estimation.proc
    runs = [diag.estimation] + diag.validation

    def errs(est):
        return {r.record.source: rel_error(r, est) for r in runs}

    return {
        "kind": "time_record",
        "design": diag.design.get("name"),
        "quantity": q,
        "files": [
            {
                "file": r.record.source,
                "role": "estimation" if i == 0 else "validation",
                "samples": r.record.n,
                "rows": r.n,
            }
            for i, r in enumerate(runs)
        ],
        "processing": {
            "fs_Hz": p.fs,
            "cutoff_Hz": p.fc,
            "cutoff_rule": p.rule,
            "motion_bandwidth_Hz": p.f_motion,
            "decimation": p.nd,
            "decimation_cutoff_Hz": p.fdec,
            "filter": f"zero-phase Butterworth order {BUTTER_ORDER} (|H|^2 by FFT)",
        },
        "controller": diag.controller.as_dict() if diag.controller else None,
        "baseline": {
            "LS": {**_est_dict(q, diag.baseline_ls), "relative_error": errs(diag.baseline_ls)},
            "IV": {**_est_dict(q, diag.baseline_iv), "relative_error": errs(diag.baseline_iv)},
        },
        "candidates": [
            [
                {
                    "effect": c.effect.name,
                    "dBIC": c.dbic,
                    "gain_percent": c.gain,
                    **_est_dict(q, c.estimate),
                }
                for c in rnd
            ]
            for rnd in diag.rounds
        ],
        "skipped": diag.skipped,
        "verdict": diag.verdict,
        "rejected": [
            {"round": k, "effect": c.effect.name, "dBIC": c.dbic, "would_need": why}
            for k, c, why in diag.rejected
        ],
        "gain_percent": [c.gain for c in diag.accepted],
        "not_accepted": [
            {
                "round": k,
                "effect": c.effect.name,
                "dBIC": c.dbic,
                "gain_percent": c.gain,
                "reason": c.reason,
            }
            for k, rnd in enumerate(diag.rounds, start=1)
            for c in rnd
            if c.reason
        ],
        "pairs": [
            {
                "round": k,
                "effects": [a.effect.name, b.effect.name],
                "dBIC": dbic,
                "gain_percent": gain,
                "accepted": not why,
                "reason": why,
            }
            for k, a, b, _e, dbic, gain, why in diag.pairs
        ],
        "flags": diag.flags,
        "equivalent": [
            {
                "round": k,
                "named": a.effect.name,
                "alternative": b.effect.name,
                "percent_apart": apart,
                "dBIC": [a.dbic, b.dbic],
                "text": _equivalent_text(diag, a, b, apart),
                "to_separate": {a.effect.name: a.effect.evidence, b.effect.name: b.effect.evidence},
            }
            for k, a, b, apart in diag.equivalent
        ],
        "top_speed_mm_s": diag.top_speed * 1e3,
        "unexplained": unexplained_dict(diag),
        "lost_motion": None
        if diag.lost is None
        else {
            "accepted": diag.lost.accepted,
            "reason": diag.lost.reason,
            "width_um": as_mm(diag, diag.lost.width) * 1e3,
            "width_std_um": as_mm(diag, diag.lost.width_std) * 1e3,
            **_lost_motion_params(diag),
            "gain_percent": diag.lost.gain,
        },
        "final": {**_est_dict(q, diag.final), "relative_error": errs(diag.final)},
        "seconds": diag.times,
    }


def controller_lines(c) -> list:
    """The position loop: its structure (stated by the design or chosen from the record) and
    gains (:mod:`axisopt.identify.records.controller`)."""
    if c is None:
        return []
    ff = f"feed-forward v {c.kv:.3g}, a {c.ka:.3g} (R2 {c.r2:.3f})"
    casc = c.cascade
    if casc is None:
        how = "PD fitted from the reference" if c.source == "fitted" else "PD stated by the design"
        text = f"controller  {how}: Kp {c.kp:.4g}, Kd {c.kd:.4g}, {ff}"
    else:
        how = "chosen from the record" if c.source == "fitted" else "stated by the design"
        kx, kv, ti = casc
        text = (
            f"controller  P-PI cascade (position P, velocity PI), {how}: Kx {kx:.3g} 1/s, Kv "
            f"{kv:.4g}, Ti {ti * 1e3:.3g} ms (Kx and 1/Ti enter alike: the smaller is named Kx); "
            f"as Kp {c.kp:.4g}, Kd {c.kd:.4g}, Ki {c.ki:.4g}, {ff}"
        )
    if casc is not None and casc[0] * casc[2] > 0.5:
        # corners within 2x of each other: the roots of a nearly double quadratic split poorly
        text += (
            "; Kx and 1/Ti lie within 2x: their sum and product are determined, the split poorly"
        )
    if casc is not None and c.heldout_gain is not None:
        text += f"; the integral term's held-out gain {c.heldout_gain:.0f} %"
    out = wrap_words(text, cont="              ")
    if c.note:
        out += wrap_words(f"! {c.note}", indent="  ", cont="      ")
    return out


def _fmt_unit(q: str, term: str, value: float) -> str:
    u, f = unit_of(q, term)
    return f"{value * f:.3g} {u}"


def _lost_motion_params(diag) -> dict:
    """The windup stiffness, the motor side's mass and friction of the lost motion's fit (in the
    record's units: force records N, kg, N s/m; torque records N.m, kg.m^2, N.m.s/rad)."""
    lm, q = diag.lost, diag.quantity
    k = lm.stiffness if math.isfinite(lm.stiffness) else None
    per_um = None if k is None else k / (as_mm(diag, 1.0) * 1e-3) / 1e6
    key = "N" if q == "force" else "N.m"
    return {
        f"stiffness_{key}_per_um": per_um,
        "motor_mass": lm.motor_mass,
        f"motor_coulomb_{key}": lm.motor_coulomb,
        "motor_viscous": lm.motor_viscous,
    }

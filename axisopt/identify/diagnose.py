"""Diagnosis: fit the design's model to measured data, find where it misfits, name the cause.

1. Baseline: the design's own model with the calibration parameters a test engineer fits
   (``measure.baseline_params``), weighted by measurement noise (estimated from the data).
2. Residuals against every recorded factor; a table of where misfit concentrates.
3. Forward selection over the effect library: each applicable candidate is fitted jointly with the
   current parameters and scored by BIC; the best is accepted if ``dBIC < -10`` and the grouped
   cross-validation RMSE (leave one position / load level / cycle block out) improves.
   Every candidate not accepted keeps the first criterion it failed (dBIC, a value outside its physical
   range, held-out gain); when no single effect passes, pairs of the best candidates are fitted jointly and
   accepted when each member is needed (:func:`_best_pair`).
4. Gain on held-out data (pooled and per file), parameters +- 1 sigma with plausibility flags (a parameter
   the data do not fix is "not identifiable", see :func:`.fit._covariance`), runner-up and margin.
5. What remains: the final residual of every file is tested along each recorded factor against the noise
   floor (:func:`table_unexplained`); structure left is the "unexplained" verdict, in words.

Ref.: /work/shared/reference/model-discrepancy.md sec. 2 (method, acceptance rule, gain table).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..display import frame, html_table, one_line
from ..errors import InputError
from .effects import library
from .fit import Block, FitResult, Problem, fit, row_function
from .measure import FEATURES, Y_UNIT, Obs, baseline_params, baseline_terms, observations, output

ACCEPT_DBIC = -10.0  # Kass-Raftery "very strong"
MIN_CV_GAIN = 0.05  # held-out RMSE must fall by at least 5 %
MAX_FOLDS = 8


@dataclass
class Context:
    plant: object
    obs: list
    resid: list = field(default_factory=list)  # per obs: prediction - y (SI) of the current model
    params: dict = field(default_factory=dict)  # effect name -> its Param list


@dataclass
class Candidate:
    effect: object
    fit: FitResult
    dbic: float
    cv_rmse: float | None = None
    cv_gain: float | None = None
    problem: Problem | None = None
    holdout: np.ndarray | None = None
    names: tuple = ()  # the effect's own parameter names
    reason: str = ""  # why it was not accepted ('' when accepted)


@dataclass
class Accepted:
    effect: object
    fit: FitResult
    dbic: float
    cv_before: float
    cv_after: float
    runner_up: Candidate | None
    plausibility: list
    together: str = ""  # accepted as a pair with this effect (neither passes alone)

    @property
    def gain(self) -> float:
        return 100.0 * (1.0 - self.cv_after / self.cv_before)


@dataclass(repr=False)
class Diagnosis:
    plant: object
    obs: list
    baseline: FitResult
    final: FitResult
    effects: list  # accepted Effect objects in order
    accepted: list  # Accepted records
    rounds: list  # list of lists of Candidate (all candidates of each selection round)
    cv_baseline: float
    cv_final: float
    noise: list  # per obs: estimated sigma in measurement units
    holdout_baseline: np.ndarray
    holdout_final: np.ndarray
    param_owner: dict = field(default_factory=dict)  # effect parameter name -> effect name
    rejected: list = field(default_factory=list)  # (round, Candidate, [implausibility texts]) never accepted
    pairs: list = field(default_factory=list)  # dicts: round, a, b, fit, dbic, gain, reason (pairs tried)
    unexplained: list = field(default_factory=list)  # per obs: TableUnexplained of the final residual

    @property
    def y(self) -> np.ndarray:
        return np.concatenate([o.y for o in self.obs])

    @property
    def verdict(self) -> str:
        return ", ".join(e.name for e in self.effects) if self.effects else "none"

    @property
    def gain(self) -> float:
        return 100.0 * (1.0 - self.cv_final / self.cv_baseline) if self.cv_baseline > 0 else 0.0

    def to_frame(self):
        """pandas DataFrame of the final fit's parameters, one row each: ``effect`` (the accepted effect that
        owns it, 'baseline' otherwise), ``parameter``, ``label``, ``value`` and ``sigma`` in ``unit``."""
        rows = [{"effect": self.param_owner.get(p["name"], "baseline"), "parameter": p["name"],
                 "label": p["label"], "value": p["value"], "sigma": p["sigma"], "unit": p["unit"]}
                for p in param_rows(self.final)]
        return frame(rows, ("effect", "parameter", "label", "value", "sigma", "unit"))

    def __repr__(self) -> str:
        files = ", ".join(str(o.dataset.source) for o in self.obs)
        return one_line("Diagnosis", repr(getattr(self.plant, "name", "")), {
            "verdict": self.verdict, "held-out error down": f"{self.gain:.1f} %", "data": files})

    def _repr_html_(self) -> str:
        rows = [{"effect": self.param_owner.get(p["name"], "baseline"), "parameter": p["name"],
                 "value": p["text"]} for p in param_rows(self.final)]
        return html_table(rows, repr(self))


def build_problem(ctx, effects, base) -> Problem:
    obs, plant = ctx.obs, ctx.plant
    params = list(base) + [p for e in effects for p in ctx.params[e.name]]
    names = [p.name for p in params]
    blocks = []
    for o in obs:
        feats = FEATURES[o.kind]

        def predict(th, z, kind=o.kind, feats=feats):
            P = {n: th[i] for i, n in enumerate(names)}
            Z = {f: z[i] for i, f in enumerate(feats)}
            q = baseline_terms(plant, P)
            for e in effects:
                if kind in e.kinds:
                    e.apply(kind, q, P, Z, plant)
            return output(kind, q, Z, plant)

        blocks.append(Block(row_function(predict, len(params), len(feats)), o.Z, o.y, o.w))
    return Problem(params, blocks)


def _split(obs, v):
    out, i = [], 0
    for o in obs:
        out.append(v[i : i + o.n])
        i += o.n
    return out


def split_by_observation(obs, v) -> list:
    """``v`` (the stacked rows of every observation) cut into one array per observation."""
    return _split(obs, v)


def param_text(p, v, s) -> str:
    """A fitted parameter as text in its display unit: value ± sigma, or 'not identifiable'."""
    unit = "" if p.unit in ("", "-") else f" {p.unit}"
    sd = f" ± {p.show(s):.3g}" if math.isfinite(s) else ""
    return f"{p.show(v):.4g}{sd}{unit}" + ("" if math.isfinite(s) else " (not identifiable from these data)")


def param_rows(res, names=None) -> list:
    """The parameters of a fit (only ``names`` when given) as dicts: name, label, value, sigma, unit, text."""
    sig = dict(zip([p.name for p in res.params], res.sigma))
    return [
        {
            "name": p.name,
            "label": p.label,
            "value": p.show(v),
            "sigma": p.show(sig[p.name]) if math.isfinite(sig[p.name]) else None,
            "unit": p.unit,
            "text": param_text(p, v, sig[p.name]),
        }
        for p, v in zip(res.params, res.theta)
        if names is None or p.name in names
    ]


# Factors whose levels alternate between neighbouring rows of a test (load direction, cycle, mode): the noise
# floor never takes differences across them.
_CATEGORICAL_FACTORS = ("direction", "cycle", "mode")
MIN_REPLICATE_DOF = 5


def noise_sigma_rel(o: Obs, resid: np.ndarray) -> tuple[float, str]:
    """Noise floor relative to the weight scale, and how it was estimated.

    1. Replicates: rows with the same value of every recorded factor (a reading repeated at the same
       position, load, direction, cycle, ...) differ by noise alone, whatever the model gets wrong; the pooled
       within-replicate standard deviation is used when it has at least 5 degrees of freedom.
    2. Otherwise second differences of the residual along one continuous factor within rows that share all
       other factors (:func:`_second_difference_sigma`): misfit constant or linear along it cancels, and an
       effect that alternates between neighbouring rows (hysteresis, a direction-dependent friction) is
       never differenced across."""
    r = resid / o.scale
    if o.factors:
        # every model feature too: an FRF's real and imaginary rows share their factors but are no replicates
        keys = np.column_stack([np.asarray(v, dtype=float) for v in o.factors.values()] + list(o.Z))
        _, inv, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
        inv = np.asarray(inv).ravel()
        rep = counts[inv] >= 2
        dof = int(rep.sum() - np.count_nonzero(counts >= 2))
        if dof >= MIN_REPLICATE_DOF:
            means = np.bincount(inv, weights=r, minlength=len(counts)) / counts
            ss = float(np.sum(((r - means[inv]) ** 2)[rep]))
            s = math.sqrt(ss / dof)
            return max(s, 1e-6), f"pooled scatter of {int(np.count_nonzero(counts >= 2))} replicate groups " \
                                 f"({dof} degrees of freedom)"
    s, how = _second_difference_sigma(o, r)
    if s is not None:
        return s, how
    return 0.01, "assumed 1 % (too few rows to estimate)"


def _second_difference_sigma(o: Obs, r: np.ndarray):
    """Noise from second differences of the residual along one continuous factor, within rows that share
    every other factor (and the factor's sign): misfit that is constant or linear along that factor cancels
    (an offset per load direction, a stiffness error growing with the load, a friction term set by the
    normal load).  Tried along each continuous factor with four or more levels; the smallest estimate is kept
    (structure only adds).  Gaussian noise: var(e1 - 2 e2 + e3) = 6 sigma^2; median-absolute-deviation form."""
    names = list(o.factors)
    if not names:
        return None, ""
    cols = {k: np.asarray(o.factors[k], dtype=float) for k in names}
    best = None
    for inner in names:
        v = cols[inner]
        if inner in ("direction", "mode") or len(np.unique(v)) < 4:  # cycles are ordered: a trend cancels
            continue
        keys = [cols[k] for k in names if k != inner] + [np.sign(v)]
        order = np.lexsort((v, *keys))
        same = np.ones(len(order) - 1, dtype=bool)
        for k in keys:
            ks = k[order]
            same &= ks[1:] == ks[:-1]
        rs = r[order]
        d2 = rs[2:] - 2.0 * rs[1:-1] + rs[:-2]
        ok = same[1:] & same[:-1]
        d2 = d2[ok]
        if len(d2) < 5:
            continue
        s = 1.4826 * float(np.median(np.abs(d2 - np.median(d2)))) / math.sqrt(6.0)
        if best is None or s < best[0]:
            best = (max(s, 1e-6), f"second differences along {inner} within rows sharing the other factors")
    return best if best is not None else (None, "")


def _check_positions(ds, plant) -> None:
    """Positions are measured from the stroke start; data off the design's stroke is a wrong design or a
    wrong zero, and would be extrapolated silently."""
    pos = ds.columns.get("position")
    if pos is None:
        return
    tol = 0.02 * plant.stroke + 1e-3
    bad = np.nonzero((pos < -tol) | (pos > plant.stroke + tol))[0]
    if len(bad):
        i = bad[0]
        raise InputError(f"position {pos[i] * 1e3:.1f} mm is outside the design's stroke "
                         f"0..{plant.stroke * 1e3:.0f} mm (positions are measured from the stroke start)",
                         source=str(ds.source),
                         where=f"line {int(ds.lines[i])}, column position")


def folds_for(obs) -> np.ndarray:
    out = []
    for o in obs:
        levels = np.unique(o.groups)
        k = min(MAX_FOLDS, len(levels))
        idx = np.searchsorted(levels, o.groups)
        if k < 2:  # nothing to hold out: a "held-out" error would be the in-sample one
            raise InputError("held-out validation needs at least 2 groups (positions, load levels or cycles); "
                             f"this file has {len(levels)}", source=str(o.dataset.source))
        out.append(idx % k)
    return np.concatenate(out)


def cv_rmse(problem: Problem, theta, folds) -> tuple[float, np.ndarray]:
    """Grouped cross-validation: refit without each fold, predict it; RMSE of weighted residuals."""
    pred = problem.predict(theta).copy()
    for k in np.unique(folds[folds >= 0]):
        test = folds == k
        res = fit(problem, theta, mask=~test, maxit=15, tol=1e-7)
        pred[test] = res.prediction[test]
    r = (pred - problem.y) * problem.w
    return float(np.sqrt(np.mean(r**2))), pred


SUBSAMPLE = 1500  # rows used to choose among multi-start initial values on large data sets


def _fit_effects(ctx, effects, base, theta_prev, prev_names):
    prob = build_problem(ctx, effects, base)
    names = [p.name for p in prob.params]
    new = effects[-1] if effects else None
    starts = [{}] + [s for s in (new.starts(ctx) if new is not None else []) if s]
    inits = [
        np.array(
            [
                theta_prev.get(n, p.init) if n in prev_names else st.get(n, p.init)
                for n, p in zip(names, prob.params)
            ]
        )
        for st in starts
    ]
    n = len(prob.y)
    if len(inits) > 1 and n > 2 * SUBSAMPLE:  # pick the start on a strided subsample, refine on all rows
        k = n // SUBSAMPLE
        sub = Problem(prob.params, [Block(b.function, b.Z[:, ::k], b.y[::k], b.w[::k]) for b in prob.blocks])
        inits = [min((fit(sub, th0) for th0 in inits), key=lambda r: r.rss).theta]
    best = None
    for th0 in inits:
        res = fit(prob, th0)
        if best is None or res.rss < best.rss:
            best = res
    return prob, best


def diagnose(datasets, plant, *, candidates=None, max_effects: int = 3) -> Diagnosis:
    """Diagnose measured ``datasets`` (list of :class:`~.data.Dataset`) against ``plant``."""
    for ds in datasets:
        _check_positions(ds, plant)
    obs = [observations(ds, plant) for ds in datasets]
    kinds = {o.kind for o in obs}
    base = baseline_params(kinds, plant)
    ctx = Context(plant, obs)
    lib = library()
    pool = [lib[n] for n in (candidates or lib)]

    # baseline, then noise weights from its residuals, then refit with those weights
    prob, base_fit = _fit_effects(ctx, [], base, {}, set())
    for o, r in zip(obs, _split(obs, base_fit.prediction - prob.y)):
        o.sigma_rel, o.noise_method = noise_sigma_rel(o, r)
    prob, base_fit = _fit_effects(ctx, [], base, {}, set())
    folds = folds_for(obs)
    cv_base, ho_base = cv_rmse(prob, base_fit.theta, folds)

    accepted, rounds, effects, rejected = [], [], [], []
    cur_fit, cur_cv, cur_ho = base_fit, cv_base, ho_base
    ctx.resid = _split(obs, base_fit.prediction - prob.y)
    active = [e for e in pool if e.applicable(ctx)]
    ctx.params = {e.name: e.params(ctx) for e in active}
    pairs = []
    while len(effects) < max_effects:
        prev = cur_fit.values()
        scored = []
        for e in active:
            if e in effects:
                continue
            p_e, res = _fit_effects(ctx, effects + [e], base, prev, set(prev))
            scored.append(
                Candidate(
                    e,
                    res,
                    res.bic - cur_fit.bic,
                    problem=p_e,
                    names=tuple(p.name for p in ctx.params[e.name]),
                )
            )
        if not scored:
            break
        scored.sort(key=lambda c: c.dbic)
        rounds.append(scored)
        # the best candidate by BIC that is physical and predicts held-out data better; a candidate that explains
        # the data only with a value outside its physical range is reported ("would need ...") and the next one
        # considered; every candidate not accepted keeps the first criterion it failed as its reason
        top = None
        for c in scored:
            if top is not None:
                c.reason = f"{top.effect.name} was accepted first (dBIC {top.dbic:.1f})"
                continue
            bad = plausibility(c.fit, effects + [c.effect], names=c.names)
            if c.dbic >= ACCEPT_DBIC:
                c.reason = f"dBIC {c.dbic:.1f} not below {ACCEPT_DBIC:g}" + (
                    f"; and it would need {'; '.join(bad)}" if bad else "")
                continue
            if bad:
                rejected.append((len(rounds), c, bad))
                c.reason = "would need " + "; ".join(bad)
                continue
            c.cv_rmse, c.holdout = cv_rmse(c.problem, c.fit.theta, folds)
            c.cv_gain = 100.0 * (1.0 - c.cv_rmse / cur_cv)
            if c.cv_gain < 100.0 * MIN_CV_GAIN:
                c.reason = f"held-out gain {c.cv_gain:.1f} % below {100 * MIN_CV_GAIN:g} %"
                continue
            top = c
        if top is None:
            # pairs only when some candidate found signal (dBIC < -10) that no single effect turns into an
            # accepted explanation: a misfit at the noise floor costs no pair fits
            if len(effects) + 2 > max_effects or not any(c.dbic < ACCEPT_DBIC for c in scored):
                break
            pair = _best_pair(ctx, scored, effects, base, cur_fit, cur_cv, folds, len(rounds), pairs)
            if pair is None:
                break
            a_, b_, p_fit, p_cv, p_ho = pair["a"], pair["b"], pair["fit"], pair["cv"], pair["holdout"]
            effects += [a_.effect, b_.effect]
            plaus = plausibility(p_fit, effects)
            for c, other in ((a_, b_), (b_, a_)):
                c.reason = f"alone: {c.reason}; accepted together with {other.effect.name}"
                accepted.append(Accepted(c.effect, p_fit, pair["dbic"], cur_cv, p_cv, None, plaus,
                                         together=other.effect.name))
            cur_fit, cur_cv, cur_ho = p_fit, p_cv, p_ho
            ctx.resid = _split(obs, cur_fit.prediction - prob.y)
            continue
        runner = next((c for c in scored if c is not top), None)
        if runner is not None and runner.cv_gain is None and runner.dbic < ACCEPT_DBIC:
            runner.cv_rmse, runner.holdout = cv_rmse(runner.problem, runner.fit.theta, folds)
            runner.cv_gain = 100.0 * (1.0 - runner.cv_rmse / cur_cv)
        effects.append(top.effect)
        accepted.append(
            Accepted(
                top.effect, top.fit, top.dbic, cur_cv, top.cv_rmse, runner, plausibility(top.fit, effects)
            )
        )
        cur_fit, cur_cv, cur_ho = top.fit, top.cv_rmse, top.holdout
        ctx.resid = _split(obs, cur_fit.prediction - prob.y)
    noise = [o.sigma_rel * float(np.median(o.scale)) for o in obs]
    owner = {p.name: e.name for e in effects for p in ctx.params[e.name]}
    return Diagnosis(
        plant,
        obs,
        base_fit,
        cur_fit,
        effects,
        accepted,
        rounds,
        cv_base,
        cur_cv,
        noise,
        ho_base,
        cur_ho,
        owner,
        rejected,
        pairs,
        table_unexplained(obs, _split(obs, cur_fit.residual), effects),
    )


MAX_PAIR_POOL = 5  # pairs among at most this many single candidates (the best by dBIC): 10 joint fits


def _best_pair(ctx, scored, effects, base, cur_fit, cur_cv, folds, rnd, log):
    """Effects that only help together: when no single candidate passes, every pair of the round's best
    ``MAX_PAIR_POOL`` candidates is fitted jointly and scored like a single one (dBIC < -10, plausible,
    held-out gain >= 5 %); it must also beat each member alone by 5 % of held-out error (each is needed).
    The pair with the largest held-out gain is returned (a dict), every pair tried is logged with its reason."""
    prev = cur_fit.values()
    pool = scored[:MAX_PAIR_POOL]
    best = None
    for i in range(len(pool)):
        for j in range(i + 1, len(pool)):
            a, b = pool[i], pool[j]
            prob_p, res = _fit_effects(ctx, effects + [a.effect, b.effect], base, prev, set(prev))
            entry = {"round": rnd, "a": a, "b": b, "fit": res, "problem": prob_p, "dbic": res.bic - cur_fit.bic,
                     "gain": None, "reason": ""}
            log.append(entry)
            names = a.names + b.names
            bad = plausibility(res, effects + [a.effect, b.effect], names=names)
            if entry["dbic"] >= ACCEPT_DBIC:
                entry["reason"] = f"dBIC {entry['dbic']:.1f} not below {ACCEPT_DBIC:g}"
                continue
            if bad:
                entry["reason"] = "would need " + "; ".join(bad)
                continue
            entry["cv"], entry["holdout"] = cv_rmse(prob_p, res.theta, folds)
            entry["gain"] = gain = 100.0 * (1.0 - entry["cv"] / cur_cv)
            for c in (a, b):
                if c.cv_gain is None:
                    c.cv_rmse, c.holdout = cv_rmse(c.problem, c.fit.theta, folds)
                    c.cv_gain = 100.0 * (1.0 - c.cv_rmse / cur_cv)
            alone = max(a.cv_gain, b.cv_gain)
            if gain < 100.0 * MIN_CV_GAIN:
                entry["reason"] = f"held-out gain {gain:.1f} % below {100 * MIN_CV_GAIN:g} %"
            elif gain - alone < 100.0 * MIN_CV_GAIN:
                entry["reason"] = (f"held-out gain {gain:.1f} % is not {100 * MIN_CV_GAIN:g} % above the better "
                                   f"member alone ({alone:.1f} %)")
            elif best is None or gain > best["gain"]:
                best = entry
    if best is not None:
        for e in log:
            if e is not best and e["round"] == rnd and not e["reason"]:
                e["reason"] = f"{best['a'].effect.name} + {best['b'].effect.name} predicts better"
    return best


@dataclass
class TableUnexplained:
    """Structure left in the final noise-weighted residual of one test (1 = the noise floor)."""

    kind: str
    source: str
    rms: float  # noise-weighted RMS of the final residual [-]
    probes: list  # residual.Probe, one per recorded factor (and the velocity shape of friction data)

    @property
    def remaining(self) -> list:
        """Significant probes, largest share first -- only when the misfit exceeds the noise floor."""
        if self.rms < UNEXPLAINED_RMS:
            return []
        return sorted([p for p in self.probes if p.significant], key=lambda p: -p.share)


UNEXPLAINED_RMS = 1.5  # a noise-weighted residual RMS below this is at the noise floor, whatever its pattern


def table_unexplained(obs, resid_w, effects=()) -> list:
    """Test the final residual of every test for structure along its recorded factors (see
    :mod:`.residual`): the share of the residual variance each factor's levels hold, its significance; for
    friction data the velocity dependence's shape (v|v|, v, low-speed rise, direction)."""
    from . import residual as rs

    out = []
    for o, r in zip(obs, resid_w):
        r = np.asarray(r, dtype=float)
        probes = [rs.factor_probe(name, r, vals, max_bins=8 if name == "velocity" else 6)
                  for name, vals in o.factors.items() if len(np.unique(vals)) > 1]
        if o.kind == "friction":
            v = o.feature("velocity")
            vs = float(np.quantile(np.abs(v), 0.25)) or 1e-3
            shapes = {"v|v|": v * np.abs(v), "v": v, "low_speed": np.sign(v) * np.exp(-np.abs(v) / vs)}
            if np.ptp(np.sign(v)) > 0:
                shapes.update({"|v|": np.abs(v), "sgn": np.sign(v)})
            # the shapes are compared after what the model already fits along velocity: its Coulomb level, and
            # its viscous slope when the viscous effect is in the model
            W = np.column_stack([np.sign(v), v] if "viscous" in [e.name for e in effects] else [np.sign(v)])
            if "viscous" in [e.name for e in effects]:
                shapes.pop("v")
            for pr in probes:
                if pr.kind == "velocity":
                    nm, sh = rs.best_shape(r, shapes, W)
                    # one smooth column can hold more than the level means do (bins average it out)
                    pr.detail.update(shape=nm, shape_share=min(sh / pr.share, 1.0) if pr.share > 0 else 0.0)
                    pr.share = max(pr.share, sh)
        out.append(TableUnexplained(o.kind, str(o.dataset.source), float(np.sqrt(np.mean(r**2))), probes))
    return out


def table_signature(p, disp) -> tuple:
    """(what, causes, measurement) of a table probe; ``disp(name, value)`` formats a factor level."""
    from . import residual as rs

    d = p.detail
    lo, hi = d.get("worst", (0.0, 0.0))
    where = f" (largest at {disp(p.kind, lo)}" + (f"..{disp(p.kind, hi)})" if hi != lo else ")")
    if p.kind == "velocity" and d.get("shape_share", 0.0) >= 0.7:
        what, causes, measure = rs.VELOCITY_WORDS[d["shape"]]
        return f"depends on velocity: {what}", causes, measure
    if p.kind == "velocity":
        return ("depends on velocity in a shape none of the library's terms has" + where,
                "a friction law outside the library", "a friction curve over the whole speed range, both ways")
    what, causes, measure = rs.FACTOR_WORDS.get(p.kind, (f"varies with {p.kind}", "an effect outside the library",
                                                         f"vary {p.kind} on purpose"))
    return what + where, causes, measure


def plausibility(res: FitResult, effects, names=None) -> list:
    """Flags for fitted values outside their physically plausible range (only ``names`` when given)."""
    out = []
    for p, v in zip(res.params, res.theta):
        if p.plausible is None or (names is not None and p.name not in names):
            continue
        lo, hi = p.plausible
        if not lo <= v <= hi:
            note = f" ({p.plausible_note})" if p.plausible_note else ""
            out.append(
                f"{p.name} = {p.show(v):.4g} {p.unit} outside {p.show(lo):.4g}..{p.show(hi):.4g}{note}"
            )
    return out


# ------------------------------------------------------------------------------ residual analysis
def residual_table(o: Obs, resid: np.ndarray, max_bins: int = 6) -> list:
    """Where misfit concentrates: for every recorded factor, the share of residual variance explained by
    its levels (eta^2), the worst level and its RMS.  ``resid`` = prediction - y (SI)."""
    unit, f = Y_UNIT[o.kind]
    r = resid * f
    if o.kind == "stiffness":  # misfit in compliance: a wrong stiffness would otherwise just track |F|
        force = o.feature("force")
        ok = np.abs(force) > 0.05 * np.max(np.abs(force))
        r = np.where(ok, resid / np.where(ok, force, 1.0), 0.0) * 1e6
        unit = "um/N"
    total = float(np.sum((r - r.mean()) ** 2)) or 1e-300
    rows = []
    for name, vals in o.factors.items():
        levels = np.unique(vals)
        if len(levels) < 2:
            continue
        if len(levels) > max_bins:
            edges = np.quantile(vals, np.linspace(0, 1, max_bins + 1)[1:-1])
            idx = np.searchsorted(edges, vals, side="right")
            labels = [
                f"{_disp(name, vals[idx == i].min())}..{_disp(name, vals[idx == i].max())}"
                for i in range(max_bins)
            ]
        else:
            idx = np.searchsorted(levels, vals)
            labels = [_disp(name, v) for v in levels]
        between, worst = 0.0, (None, -1.0)
        for i in np.unique(idx):
            ri = r[idx == i]
            between += len(ri) * (ri.mean() - r.mean()) ** 2
            rms = float(np.sqrt(np.mean(ri**2)))
            if rms > worst[1]:
                worst = (labels[i], rms)
        rows.append(
            {
                "factor": name,
                "eta2": between / total,
                "worst_level": worst[0],
                "worst_rms": worst[1],
                "rms": float(np.sqrt(np.mean(r**2))),
                "unit": unit,
            }
        )
    rows.sort(key=lambda d: -d["eta2"])
    return rows


_DISP = {
    "position": (1e3, "mm"),
    "velocity": (1e3, "mm/s"),
    "frequency": (1.0, "Hz"),
    "force": (1.0, "N"),
    "normal_load": (1.0, "N"),
    "axial_load": (1.0, "N"),
    "time": (1.0, "s"),
    "temperature": (1.0, "K"),
}


def _disp(name, v):
    f, u = _DISP.get(name, (1.0, ""))
    return f"{v * f:.4g}{(' ' + u) if u else ''}"


def display_value(name, v) -> str:
    """A factor's value in its display unit (e.g. a velocity in mm/s), as text."""
    return _disp(name, v)

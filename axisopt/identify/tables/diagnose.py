"""Diagnosis of reduced tables: fit the design's model to measured data, find where it misfits, name
the cause.

1. Baseline: the design's own model with the calibration parameters a test engineer fits
   (``measure.baseline_params``), weighted by measurement noise (estimated from the data,
   :func:`.tableresidual.noise_sigma_rel`).
2. Residuals against every recorded factor; a table of where misfit concentrates
   (:mod:`.tableresidual`).
3. Forward selection over the effect library (:func:`.effects.library`): each applicable candidate
   is fitted jointly with the current parameters and judged by :data:`.selection.TABLE_RULE` -- dBIC
   < -10, its values in their physical range, and the grouped cross-validation RMSE (leave one
   position / load level / cycle block out) at least 5 % lower.  Every candidate not accepted keeps
   the first criterion it failed; when no single effect passes, pairs of the best candidates are
   fitted jointly and accepted when each member is needed (:func:`_best_pair`).
4. Gain on held-out data (pooled and per file), parameters +- 1 sigma with plausibility flags (a
   parameter the data do not fix is "not identifiable", see :func:`.fit.covariance`), runner-up and
   margin.
5. What remains: the final residual of every file is tested along each recorded factor against the
   noise floor (:func:`.tableresidual.table_unexplained`); structure left is the "unexplained"
   verdict, in words.

The information criterion and its threshold: Kass and Raftery, "Bayes factors", J. Am. Stat. Assoc.
90 (1995) 773-795; grouped cross-validation: Roberts et al., Ecography 40 (2017) 913-929.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ...display import frame, html_table, one_line
from ...errors import InputError
from ..effects import library
from ..fit import Block, FitResult, Problem, fit, row_function
from ..selection import TABLE_RULE as RULE
from .measure import FEATURES, baseline_params, baseline_terms, observations, output
from .unexplained import noise_sigma_rel, table_unexplained

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
    # (round, Candidate, [implausibility texts]) never accepted
    rejected: list = field(default_factory=list)
    # dicts: round, a, b, fit, dbic, gain, reason (pairs tried)
    pairs: list = field(default_factory=list)
    # per obs: TableUnexplained of the final residual
    unexplained: list = field(default_factory=list)
    # (round, named, alternative, % apart): equally good
    equivalent: list = field(default_factory=list)
    # texts: an accepted effect outside its plausible regime
    regime: list = field(default_factory=list)

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
        """pandas DataFrame of the final fit's parameters, one row each: ``effect`` (the accepted
        effect that owns it, 'baseline' otherwise), ``parameter``, ``label``, ``value`` and
        ``sigma`` in ``unit``."""
        rows = [
            {
                "effect": self.param_owner.get(p["name"], "baseline"),
                "parameter": p["name"],
                "label": p["label"],
                "value": p["value"],
                "sigma": p["sigma"],
                "unit": p["unit"],
            }
            for p in param_rows(self.final)
        ]
        return frame(rows, ("effect", "parameter", "label", "value", "sigma", "unit"))

    def __repr__(self) -> str:
        files = ", ".join(str(o.dataset.source) for o in self.obs)
        return one_line(
            "Diagnosis",
            repr(getattr(self.plant, "name", "")),
            {"verdict": self.verdict, "held-out error down": f"{self.gain:.1f} %", "data": files},
        )

    def _repr_html_(self) -> str:
        rows = [
            {
                "effect": self.param_owner.get(p["name"], "baseline"),
                "parameter": p["name"],
                "value": p["text"],
            }
            for p in param_rows(self.final)
        ]
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


def split_by_observation(obs, v) -> list:
    """``v`` (the stacked rows of every observation) cut into one array per observation."""
    out, i = [], 0
    for o in obs:
        out.append(v[i : i + o.n])
        i += o.n
    return out


_split = split_by_observation


def param_text(p, v, s) -> str:
    """A fitted parameter as text in its display unit: value ± sigma, or 'not identifiable'."""
    unit = "" if p.unit in ("", "-") else f" {p.unit}"
    sd = f" ± {p.show(s):.3g}" if math.isfinite(s) else ""
    return f"{p.show(v):.4g}{sd}{unit}" + (
        "" if math.isfinite(s) else " (not identifiable from these data)"
    )


def param_rows(res, names=None) -> list:
    """The parameters of a fit (only ``names`` when given) as dicts: name, label, value, sigma,
    unit, text."""
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


def _check_positions(ds, plant) -> None:
    """Positions are measured from the stroke start; data off the design's stroke is a wrong design
    or a wrong zero, and would be extrapolated silently."""
    pos = ds.columns.get("position")
    if pos is None:
        return
    tol = 0.02 * plant.stroke + 1e-3
    bad = np.nonzero((pos < -tol) | (pos > plant.stroke + tol))[0]
    if len(bad):
        i = bad[0]
        raise InputError(
            f"position {pos[i] * 1e3:.1f} mm is outside the design's stroke "
            f"0..{plant.stroke * 1e3:.0f} mm (positions are measured from the stroke start)",
            source=str(ds.source),
            where=f"line {int(ds.lines[i])}, column position",
        )


def folds_for(obs) -> np.ndarray:
    out = []
    for o in obs:
        levels = np.unique(o.groups)
        k = min(MAX_FOLDS, len(levels))
        idx = np.searchsorted(levels, o.groups)
        if k < 2:  # nothing to hold out: a "held-out" error would be the in-sample one
            raise InputError(
                "held-out validation needs at least 2 groups (positions, load levels or cycles); "
                f"this file has {len(levels)}",
                source=str(o.dataset.source),
            )
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
    # pick the start on a strided subsample, refine on all rows
    if len(inits) > 1 and n > 2 * SUBSAMPLE:
        k = n // SUBSAMPLE
        sub = Problem(
            prob.params, [Block(b.function, b.Z[:, ::k], b.y[::k], b.w[::k]) for b in prob.blocks]
        )
        inits = [min((fit(sub, th0) for th0 in inits), key=lambda r: r.rss).theta]
    best = None
    for th0 in inits:
        res = fit(prob, th0)
        if best is None or res.rss < best.rss:
            best = res
    return prob, best


# effects accepted at most by default: one default for the command line (--max-effects), Python and
# both pipelines
MAX_EFFECTS = 3


def diagnose(datasets, plant, *, candidates=None, max_effects: int = MAX_EFFECTS) -> Diagnosis:
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

    accepted, rounds, effects, rejected, equivalent = [], [], [], [], []
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
        # the best candidate by BIC that is physical and predicts held-out data better; a candidate
        # that explains the data only with a value outside its physical range is reported ("would
        # need ...") and the next one considered; every candidate not accepted keeps the first
        # criterion it failed as its reason
        top = None
        for c in scored:
            if top is not None:
                c.reason = f"{top.effect.name} was accepted first (dBIC {top.dbic:.1f})"
                continue
            bad = plausibility(c.fit, effects + [c.effect], names=c.names)
            if c.dbic < RULE.accept_dbic and bad:
                rejected.append((len(rounds), c, bad))

            def held_out(c=c, before=cur_cv):
                c.cv_rmse, c.holdout = cv_rmse(c.problem, c.fit.theta, folds)
                c.cv_gain = RULE.gain(before, c.cv_rmse)
                return c.cv_gain

            c.reason = RULE.reason(c.dbic, held_out, "; ".join(bad))
            if not c.reason:
                top = c
        if top is None:
            # pairs only when some candidate found signal (dBIC < -10) that no single effect turns
            # into an accepted explanation: a misfit at the noise floor costs no pair fits
            if len(effects) + 2 > max_effects or not any(c.dbic < RULE.accept_dbic for c in scored):
                break
            pair = _best_pair(
                ctx, scored, effects, base, cur_fit, cur_cv, folds, len(rounds), pairs
            )
            if pair is None:
                break
            a_, b_, p_fit, p_cv, p_ho = (
                pair["a"],
                pair["b"],
                pair["fit"],
                pair["cv"],
                pair["holdout"],
            )
            # another pair that passes and predicts as well: the data do not tell them apart
            for e in pairs:
                d = (
                    RULE.equivalent(p_cv, e["cv"])
                    if e.get("passed") and e["round"] == len(rounds)
                    else None
                )
                if (
                    d is None
                    and e.get("passed")
                    and e["round"] == len(rounds)
                    and max(p_cv, e["cv"]) <= AT_FLOOR
                ):
                    d, floor = 100.0 * abs(e["cv"] - p_cv) / p_cv, (p_cv, e["cv"])
                else:
                    floor = None
                if d is not None:
                    equivalent.append(
                        (
                            len(rounds),
                            f"{a_.effect.name} + {b_.effect.name}",
                            f"{e['a'].effect.name} + {e['b'].effect.name}",
                            d,
                            (a_.effect, b_.effect, e["a"].effect, e["b"].effect),
                            floor,
                        )
                    )
            effects += [a_.effect, b_.effect]
            plaus = plausibility(p_fit, effects)
            for c, other in ((a_, b_), (b_, a_)):
                c.reason = f"alone: {c.reason}; accepted together with {other.effect.name}"
                accepted.append(
                    Accepted(
                        c.effect,
                        p_fit,
                        pair["dbic"],
                        cur_cv,
                        p_cv,
                        None,
                        plaus,
                        together=other.effect.name,
                    )
                )
            cur_fit, cur_cv, cur_ho = p_fit, p_cv, p_ho
            ctx.resid = _split(obs, cur_fit.prediction - prob.y)
            continue
        # another single that passes and predicts as well: say so, with what separates them
        for c in scored:
            if (
                c is top
                or c.dbic >= RULE.accept_dbic
                or plausibility(c.fit, effects + [c.effect], names=c.names)
            ):
                continue
            if c.cv_gain is None:
                c.cv_rmse, c.holdout = cv_rmse(c.problem, c.fit.theta, folds)
                c.cv_gain = RULE.gain(cur_cv, c.cv_rmse)
            if c.cv_gain < RULE.min_gain:
                continue
            d = RULE.equivalent(top.cv_rmse, c.cv_rmse)
            # both leave only noise in the held-out readings
            floor = max(top.cv_rmse, c.cv_rmse) <= AT_FLOOR
            if d is not None or floor:
                apart = 100.0 * abs(c.cv_rmse - top.cv_rmse) / top.cv_rmse
                equivalent.append(
                    (
                        len(rounds),
                        top.effect.name,
                        c.effect.name,
                        apart,
                        (top.effect, c.effect),
                        (top.cv_rmse, c.cv_rmse) if d is None else None,
                    )
                )
        runner = next((c for c in scored if c is not top), None)
        if runner is not None and runner.cv_gain is None and runner.dbic < RULE.accept_dbic:
            runner.cv_rmse, runner.holdout = cv_rmse(runner.problem, runner.fit.theta, folds)
            runner.cv_gain = RULE.gain(cur_cv, runner.cv_rmse)
        effects.append(top.effect)
        accepted.append(
            Accepted(
                top.effect,
                top.fit,
                top.dbic,
                cur_cv,
                top.cv_rmse,
                runner,
                plausibility(top.fit, effects),
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
        equivalent,
        regime_flags(obs, effects),
    )


# held-out RMSE (weighted: in noise floors) at or below which an explanation leaves only noise; two
# that both do are not told apart by the held-out readings, however far apart their RMSE (a few
# readings' scatter)
AT_FLOOR = 1.1


def top_speed(obs) -> float:
    """The highest table speed [m/s] in the friction tables (0 without one)."""
    return max(
        (float(np.max(np.abs(o.dataset.columns["velocity"]))) for o in obs if o.kind == "friction"),
        default=0.0,
    )


def regime_flags(obs, effects) -> list:
    """An accepted effect named outside the regime it is plausible in (its declaration's ``regime``,
    judged at the tables' top speed, as for time records)."""
    v = top_speed(obs)
    if not v > 0:
        return []
    return [
        f"{e.name}: {w}"
        for e in effects
        if e.time is not None and e.time.regime is not None
        for w in [e.time.regime(v)]
        if w
    ]


def _best_pair(ctx, scored, effects, base, cur_fit, cur_cv, folds, rnd, log):
    """Effects that only help together: when no single candidate passes, every pair of the round's
    best candidates (:data:`.selection.TABLE_RULE`: ``pair_pool``) is fitted jointly and judged like
    a single one; it must also beat each member alone by ``min_gain`` of held-out error (each is
    needed).  The pair with the largest held-out gain is returned (a dict), every pair tried is
    logged with its reason."""
    prev = cur_fit.values()
    pool = RULE.pair_pool_of(scored)
    best = None
    for i in range(len(pool)):
        for j in range(i + 1, len(pool)):
            a, b = pool[i], pool[j]
            prob_p, res = _fit_effects(ctx, effects + [a.effect, b.effect], base, prev, set(prev))
            entry = {
                "round": rnd,
                "a": a,
                "b": b,
                "fit": res,
                "problem": prob_p,
                "dbic": res.bic - cur_fit.bic,
                "gain": None,
                "reason": "",
            }
            log.append(entry)
            bad = plausibility(res, effects + [a.effect, b.effect], names=a.names + b.names)

            def held_out(entry=entry, prob_p=prob_p, res=res, a=a, b=b):
                entry["cv"], entry["holdout"] = cv_rmse(prob_p, res.theta, folds)
                entry["gain"] = RULE.gain(cur_cv, entry["cv"])
                for c in (a, b):
                    if c.cv_gain is None:
                        c.cv_rmse, c.holdout = cv_rmse(c.problem, c.fit.theta, folds)
                        c.cv_gain = RULE.gain(cur_cv, c.cv_rmse)
                return entry["gain"]

            entry["reason"] = RULE.pair_reason(
                entry["dbic"], held_out, "; ".join(bad), lambda a=a, b=b: max(a.cv_gain, b.cv_gain)
            )
            if not entry["reason"] and (best is None or entry["gain"] > best["gain"]):
                best = entry
    if best is not None:
        for e in log:
            if e is not best and e["round"] == rnd and not e["reason"]:
                e["reason"] = f"{best['a'].effect.name} + {best['b'].effect.name} predicts better"
                e["passed"] = True
    return best


def plausibility(res: FitResult, effects, names=None) -> list:
    """Flags for fitted values outside their physically plausible range (only ``names`` when
    given)."""
    out = []
    for p, v in zip(res.params, res.theta):
        if p.plausible is None or (names is not None and p.name not in names):
            continue
        lo, hi = p.plausible
        if not lo <= v <= hi:
            note = f" ({p.plausible_note})" if p.plausible_note else ""
            out.append(
                f"{p.name} = {p.show(v):.4g} {p.unit} outside "
                f"{p.show(lo):.4g}..{p.show(hi):.4g}{note}"
            )
    return out

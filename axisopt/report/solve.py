"""A :class:`~axisopt.search.result.SolveResult` as ``axisopt solve`` shows it: the text it prints
(:func:`format_result`; a Pareto front's table :func:`format_pareto`) and the front's scatter matrix
(:func:`plot_pareto`).  Nothing here prints."""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..catalog.columns import PART_SLOTS
from ..model.goals import OBJECTIVE_TABLE
from ..search.result import OPTIMAL

# The cutting force's components beside the feed force, as a rule of thumb for turning: feed F_f =
# 0.50 F_c and passive (radial) F_p = 0.25 F_c of the tangential F_c (E. Isakov, "Calculated Forces
# When Turning", Cutting Tool Engineering, 2013, who adds that the rule "is not a good practice
# because the results are not as accurate as they could be"): guidance for the designer where the
# cut's own components are unknown, never a model default.
FEED_SHARE, PASSIVE_SHARE = 0.50, 0.25
COMPONENT_KEYS = ("normal_load", "cross_load")


def load_components(axis, assumed) -> dict | None:
    """When the axis gives ``axial_load`` but not the cut's normal or cross component (``assumed``:
    the axis keys left at their defaults), what the guides were sized without and the turning rule
    of thumb from the feed force (:data:`FEED_SHARE`, :data:`PASSIVE_SHARE`); None when both are
    given or there is no axial load."""
    missing = [k for k in COMPONENT_KEYS if k in assumed]
    if not missing or axis.axial_load <= 0.0:
        return None
    fc = axis.axial_load / FEED_SHARE
    text = (
        f"guides sized without the cut's {' and '.join(missing)} (not given: 0 N); give "
        f"{'them' if len(missing) > 1 else 'it'} with tool_height and tool_offset (where the cut "
        "acts).  Turning rule of thumb (Isakov, CTE 2013: F_f = 0.5 F_c, F_p = 0.25 F_c): "
        f"axial_load {_num(axis.axial_load)} N as the feed force puts the tangential force near "
        f"{_num(fc)} N, the passive near {_num(PASSIVE_SHARE * fc)} N"
    )
    return {
        "missing": missing,
        "axial_load_N": axis.axial_load,
        "tangential_estimate_N": fc,
        "passive_estimate_N": PASSIVE_SHARE * fc,
        "rule": "turning rule of thumb F_f = 0.5 F_c, F_p = 0.25 F_c (Isakov, Cutting Tool "
        "Engineering 2013)",
        "text": text,
    }


def cheaper_lines(res) -> list:
    """A stiffness or frequency optimum's cheaper neighbour (``res.cheaper``: a design within the
    problem's tolerance that costs markedly less), wrapped at 100 columns; [] without one."""
    ch = getattr(res, "cheaper", None)
    if not ch:
        return []
    saved = ch["best_cost"] - ch["cost"]
    parts = "  ".join(f"{k} {v}" for k, v in ch["parts"].items() if v)
    text = (
        f"cheaper: {ch['objective']:,.3f} {ch['unit']} (within {100 * ch['tolerance']:g} % of the "
        f"best) costs {ch['cost']:,.0f} EUR, {saved:,.0f} EUR ({100 * saved / ch['best_cost']:.0f} "
        f"%) less than the optimum's {ch['best_cost']:,.0f} EUR: {ch['mounting']}  {parts}; to "
        "choose it: objective {mode: lexicographic, order: "
        f"[{'stiffness' if ch['unit'] == 'N/um' else 'frequency'}, cost], tolerance: "
        f"{ch['tolerance']:g}}}"
    )
    return textwrap.wrap(text, 100, subsequent_indent="  ")


def format_result(res, top: int | None = None, problem=None) -> str:
    """The text ``axisopt solve`` prints: status, the best design's evaluation (or the Pareto front,
    or why the problem is infeasible), the limits at the optimum, the runners-up and the
    certificate.  With the
    ``problem``: a line when the guides were sized without the cut's normal or cross component
    (:func:`load_components`)."""
    from ..model import evaluate
    from .evaluation import evaluation_table

    c = res.certificate
    L = [
        f"problem {res.problem}: {res.objective_label}",
        f"method {res.method}: status {res.status}"
        + (
            " (proven global optimum over the catalog)"
            if res.status == OPTIMAL and c.proven
            else ""
        )
        + f", {res.time:.2f} s"
        + (f"  [{res.solver_status}]" if res.solver_status not in ("", "ipopt") else ""),
    ]
    if res.arrangements and res.pareto is not None:
        L.append(
            f"arrangements: the front of {res.arrangements} arrangements merged (each design names "
            "its own)"
        )
    elif res.arrangements:  # search.counterbalance / search.twin_drive options
        L.append(
            f"arrangement: {res.arrangement} ({'best' if res.best is not None else 'closest'} of "
            f"{res.arrangements} arrangements)"
        )
    # a part the search left out, each on its own line
    notes = [f"  left out: {what}" for what in res.left_out]
    if res.message:
        notes.append(f"  note: {res.message}")
    comp = None if problem is None else load_components(problem.axis, problem.assumed)
    if comp is not None:
        notes.extend(
            textwrap.wrap(
                f"note: {comp['text']}", 100, initial_indent="  ", subsequent_indent="    "
            )
        )
    # the misses that decide and what to change first, the notes after
    if res.infeasibility is not None:
        L.extend(
            textwrap.wrap(
                f"misses: {res.infeasibility.deciding()}",
                100,
                initial_indent="  ",
                subsequent_indent="      ",
            )
        )
        L.extend(relax_lines(res.infeasibility))
    L.extend(notes)
    L.append("")
    if res.pareto is not None:
        L.append(format_pareto(res.pareto, top))
    elif res.best is not None:
        b = res.best
        L.append(f"best: {b.objective:,.3f} {res.objective_unit}")
        L.extend(cheaper_lines(res))
        L.append(
            evaluation_table(evaluate(b.design), None if problem is None else problem.margin_map)
        )
        if res.binding:
            L.append("")
            L.append(
                "limits at the optimum (what relaxing each by 10 % buys, re-solved)"
                + ("; on the governing side" if b.design.axis.twin_drive else "")
            )
            # max_positioning_error: 21 + 1
            w = max([18] + [len(bd.limit) + 1 for bd in res.binding])
            L.append(
                f"  {'limit':<{w}}{'value':>12}{'at optimum':>12}{'relaxed to':>12}  {'unit':<6}"
                f"{'gain ' + res.objective_unit:>14}"
            )
            for bd in res.binding:
                # a gain within the re-solve's tolerance (not binding) is none: "+0", not a rounding
                # residue
                gain = (
                    "-"
                    if bd.objective_gain is None or not math.isfinite(bd.objective_gain)
                    else f"{bd.objective_gain:+.4g}"
                    if bd.binding
                    else "+0"
                )
                L.append(
                    f"  {bd.limit:<{w}}{_v(bd.value):>12}{_v(bd.at_optimum):>12}"
                    f"{_v(bd.relaxed_to):>12}  "
                    f"{bd.unit:<6}{gain:>14}{'  BINDING' if bd.binding else ''}"
                )
            for bd in res.binding:
                if bd.binding:
                    verb = "raising" if bd.limit.startswith("max") else "lowering"
                    L.append(
                        f"  {verb} {bd.limit.replace('_', ' ')} to {_v(bd.relaxed_to)} {bd.unit} "
                        f"buys {bd.objective_gain:+.4g} {res.objective_unit}"
                    )
        if res.runners_up:
            L.append("")
            L.append("best designs")
            L.append(_cand_table([b] + list(res.runners_up), res.objective_unit))
    if res.infeasibility is not None:
        inf = res.infeasibility
        if inf.unmeetable:
            L.append(
                "limits no catalog combination can meet (each checked on its own, best preload):"
            )
            for name, best, lim, unit in inf.unmeetable:
                u = f" {unit}" if unit else ""
                L.append(
                    f"  {name}: limit {_num(lim)}{u}, best any combination reaches {_num(best)}{u}"
                )
        else:
            L.append(
                "every limit is met by some combination, but no combination meets all of them "
                "together"
            )
        L.append("")
        L.append("closest designs (sum of relative misses):")
        for cand in inf.closest:
            miss = ", ".join(f"{k} by {100 * v:.1f} %" for k, v in cand.misses.items())
            L.append(
                f"  #{cand.rank} {cand.mounting} {' / '.join(cand.parts().values())}"
                f" preload {cand.nut_preload:.0f} N: misses {miss or 'nothing'}"
            )
    L.append("")
    L.append("certificate")
    if c.feasible is None:  # Bonmin: one MINLP per mounting, nothing counted or bounded
        L.append(
            f"  combinations {c.combinations:,}; MINLP solves {c.nlps_solved} "
            f"(not SUCCESS {c.nlp_failures}); feasible combinations not counted"
        )
    else:
        blocks = (
            f"; screened {c.screened:,}, the rest pruned by their (nut, bearing) block's bound"
            if res.method == "default" and c.screened is not None
            else ""
        )
        L.append(f"  combinations {c.combinations:,}{blocks}")
        if c.pruned_by_dominance:
            L.append(
                f"  never formed {c.pruned_by_dominance:,} (a coupling another beats on every "
                "count, or one that cannot carry the motor's peak torque)"
            )
        L.append(
            f"  feasible {c.feasible:,}{' (screened)' if res.method == 'default' else ''}; pruned "
            f"by bound {c.pruned_by_bound:,}; exact 1-D solves {c.exact_evaluations:,}; NLPs "
            f"{c.nlps_solved} (failures {c.nlp_failures})"
        )
    gap = (
        "0 (proven)"
        if c.proven and c.gap == 0
        else ("unknown" if not math.isfinite(c.gap) else f"{c.gap:.3%}")
    )
    if not c.screening_time:
        rate = ""
    elif c.screened is None:  # every combination screened
        rate = f"; screening {c.screening_time:.3f} s ({c.screening_rate / 1e6:.1f} M designs/s)"
    # the blocks' bounds, then the combinations of the opened blocks (one by one, or a drive at a
    # time)
    else:
        rate = (
            f"; screening {c.screening_time:.3f} s (block bounds, {c.screened:,} combinations in "
            "opened blocks)"
        )
    if res.best is None and c.proven:  # no design: there is no optimum to have a gap to
        L.append(f"  infeasibility proven (every combination is accounted for){rate}")
    else:
        L.append(f"  optimality gap {gap}{rate}")
    for n in c.notes:
        L.append(f"  {n}")
    L.extend(estimated_lines(c.estimated))
    from .text import fit_lines

    return fit_lines("\n".join(L))


def _change_text(d) -> str:
    """One design change (search.advice): 'lower axis.max_speed from 20 to 15.5 m/min', 'add a
    balance cylinder
    ...', with its note in brackets."""
    note = f" ({d.note})" if d.note else ""
    if d.edit:  # a list of the catalog section (search.widen)
        what = ", ".join(d.values)
        return (
            f"add {what} to {d.key}" if d.edit == "add" else f"remove {what} from {d.key}"
        ) + note
    if d.key == "axis.counterbalance" and d.value == 0:
        return f"add axis.counterbalance {{kind: cylinder, force: {_v(d.to)} {d.unit}}}{note}"
    verb = "lower" if d.to < d.value else "raise"
    return f"{verb} {d.key} from {_v(d.value)} to {_v(d.to)} {d.unit}{note}"


def relax_lines(inf) -> list:
    """The first lines of an infeasible answer: an axis change that the search verified makes it
    feasible (first: a design change before a vendor's rule), then what to relax, by how much, for
    which closest design."""
    L0 = []
    if inf.design_changes:
        texts = [_change_text(d) for d in inf.design_changes]
        what = (
            "the axis"
            if all(d.key.startswith("axis.") for d in inf.design_changes)
            else "the design"
        )
        head = f"  change {what}: " if len(texts) == 1 else f"  change {what}, together: "
        L0 = [head + "; ".join(texts) + ": the catalogs then hold a design (re-solved)"]
    # a check no margin frees (its available value is 0: a catalog value missing): said, never
    # relaxed to 0
    L0 += [f"  no limit frees this: {m}" for m in inf.missing]
    rel = inf.relax
    if not rel:
        return L0

    def amount(r):
        u = f" {r.unit}" if r.unit else ""
        sign = "+" if r.relaxed_to > r.value else "-"
        rule = " (below the vendor's rule)" if r.below_vendor_rule else ""
        return (
            f"{r.key} from {_v(r.value)}{u} to {_v(r.relaxed_to)}{u} ({sign}{_num(100 * r.change)} "
            f"%){rule}"
        )

    d = rel[0].design
    who = f"design #{rel[0].design_rank}" + (
        f" ({d.mounting} {' / '.join(d.parts().values())})" if d else ""
    )
    # search.relax: a vendor margin is never proposed below 0.95 (MARGIN_FLOOR); a design needing
    # one lower breaks a rule no relaxation frees, as a compatibility rule
    rule = "a compatibility rule or a vendor's rule no margin down to 0.95 frees"
    if inf.relax_blocked_by:
        head = (
            f"  no relaxation of the limits is enough: every closest design breaks {rule}; "
            f"{who} breaks {', '.join(inf.relax_blocked_by)} and besides needs "
        )
    else:
        head = "  to make it feasible, relax "
    if len(rel) == 1 and not inf.relax_blocked_by:
        L = [f"{head}{amount(rel[0])}: {who} then meets every limit"]
    elif len(rel) == 1:
        L = [f"{head}{amount(rel[0])}"]
    else:
        L = [
            f"{head}these {len(rel)} limits{' relaxed' if inf.relax_blocked_by else ''} together "
            "(smallest change first)"
            + ("" if inf.relax_blocked_by else f"; {who} then meets every limit")
            + ":"
        ]
        L += [f"    {amount(r)}" for r in rel]
    for rank, rules in inf.not_relaxable:
        L.append(f"  design #{rank} left out: it breaks {', '.join(rules)} ({rule}, not relaxable)")
    if inf.design_changes:
        L[0] = "  or " + L[0].lstrip()
    return L0 + L


def _cand_table(cands, unit, keys=()) -> str:
    """Best designs in 100 columns: the numbers on one line per design, its parts below it (after
    the first design, only the parts in which it differs from the one above).  The goals' columns
    come from ``model.goals.OBJECTIVE_TABLE`` (``Goal.column``): those shown always, the preload,
    then those of the front's ``keys`` (the positioning error)."""
    slots = ("arrangement", "screw", "grade", *PART_SLOTS[1:])
    obj = f"obj {unit}" if unit != "-" else ""
    always = [g for g in OBJECTIVE_TABLE if g.column is not None and g.column.always]
    extra = [
        g for g in OBJECTIVE_TABLE if g.column is not None and not g.column.always and g.key in keys
    ]
    L = [
        f"  {'#':>3} {'mounting':<17}{obj:>12}"
        + "".join(f"{g.column.header:>{g.column.width}}" for g in always)
        + f"{'preload N':>11}"
        + "".join(f"{g.column.header:>{g.column.width}}" for g in extra)
    ]
    prev = None
    for c in cands:
        val = f"{c.objective:,.3f}" if obj else ""
        L.append(
            f"  {c.rank:>3} {c.mounting:<17}{val:>12}"
            + "".join(_goal_cell(c, g) for g in always)
            + f"{c.nut_preload:>11.0f}"
            + "".join(_goal_cell(c, g) for g in extra)
        )
        parts = (
            c.parts()
            | ({"grade": c.screw_grade} if getattr(c, "screw_grade", "") else {})
            | ({"arrangement": c.arrangement} if c.arrangement else {})
        )
        if prev is None:
            shown = [f"{k} {parts[k]}" for k in slots if parts.get(k)]
        else:
            shown = [
                f"{k} {parts[k]}" for k in slots if parts.get(k) and parts.get(k) != prev.get(k)
            ]
            shown += [f"no {k}" for k in slots if prev.get(k) and not parts.get(k)]
            shown = ["same parts as above" if not shown else "as above but " + shown[0]] + shown[1:]
        L.extend(
            textwrap.wrap(
                "  ".join(shown),
                100,
                initial_indent=" " * 8,
                subsequent_indent=" " * 8,
                break_on_hyphens=False,
            )
        )
        prev = parts
    return "\n".join(L)


def _goal_cell(c, g) -> str:
    """The goal ``g``'s value of the design ``c`` in its column (``Goal.column``)."""
    return format(c.goal(g.key), f">{g.column.width}{g.column.spec}")


def estimated_lines(estimated) -> list:
    """Text lines for ``Certificate.estimated`` (what of the optimum rests on estimated part
    values)."""
    if not estimated:
        return []
    from ..model.estimates import estimate_text

    out = ["  rests on estimated values (not in the vendor's table; catalogs/SOURCES.md):"]
    for r in estimated:
        vals = "; ".join(estimate_text(e) for e in r["estimates"])
        out.extend(
            textwrap.wrap(
                f"{r['what']} ({r['output']}): {vals}",
                100,
                initial_indent="    ",
                subsequent_indent="        ",
            )
        )
    return out


def format_pareto(front, top: int | None = None) -> str:
    """The front's designs sorted by the first objective; ``top`` of them (all when None)."""
    shown = front.points if top is None else front.points[:top]
    L = [
        f"Pareto front: {len(front.points)} non-dominated designs of {front.feasible:,} feasible "
        f"({', '.join(f'{s} {k}' for k, s in zip(front.keys, front.senses))})"
    ]
    if len(shown) < len(front.points):
        L.append(
            f"  the first {len(shown)} by {front.keys[0]} shown (--top N for more, --json for all)"
        )
    L.append(_cand_table(shown, "-", front.keys))
    return "\n".join(L)


def _v(v) -> str:
    """A limit or design value: 20,000 / 1,250 / 98.5 / 0.785 ('-' when missing)."""
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    return _num(float(v)) if abs(v) >= 100 else f"{v:.4g}"


def _num(v: float) -> str:
    """1,500 / 0.785 / 12.4: thousands separators for large values, three significant digits
    otherwise."""
    return f"{v:,.0f}" if abs(v) >= 100 else f"{v:.3g}"


def plot_pareto(front, path: str | None = None):
    """Scatter matrix of every objective pair: the non-dominated designs in colour (by the first
    objective), a sample of the feasible designs they dominate in grey, each axis labelled with its
    unit and whether it is maximised or minimised; the diagonal shows each objective's spread over
    the front.  Returns the matplotlib Figure (not registered with pyplot; Jupyter shows it as an
    image); written to ``path`` only when given."""
    from ..figure import Figure

    keys, d = front.keys, len(front.keys)
    F = np.array([[p.goal(k) for k in keys] for p in front.points]).reshape(-1, d)
    C = (
        np.asarray(front.cloud, dtype=float).reshape(-1, d)
        if front.cloud is not None
        else np.zeros((0, d))
    )
    size = 2.6 * d if d > 2 else 5.5
    fig = Figure(figsize=(size + 1.0, size))
    axes = fig.subplots(d, d, squeeze=False)
    label = [
        f"{k.replace('_', ' ')} [{u}] ({'max' if s == 'max' else 'min'})"
        for k, u, s in zip(keys, front.units, front.senses)
    ]
    sc = None
    for i in range(d):
        for j in range(d):
            ax = axes[i][j]
            if i == j:
                ax.hist(F[:, i], bins=min(20, max(len(F), 1)), color="tab:blue", alpha=0.7)
                ax.set_yticks([])
            else:
                if len(C):
                    ax.scatter(
                        C[:, j],
                        C[:, i],
                        s=4,
                        color="0.75",
                        alpha=0.5,
                        linewidths=0,
                        rasterized=True,
                        label="feasible (sample)" if (i, j) == (1, 0) else None,
                    )
                sc = ax.scatter(
                    F[:, j],
                    F[:, i],
                    c=F[:, 0],
                    s=14,
                    cmap="viridis",
                    label="Pareto front" if (i, j) == (1, 0) else None,
                )
            ax.grid(True, alpha=0.3)
            if i == d - 1:
                ax.set_xlabel(label[j], fontsize=8)
            if j == 0:
                ax.set_ylabel(label[i], fontsize=8)
            ax.tick_params(labelsize=7)
    if d > 1:
        axes[1][0].legend(fontsize=7, loc="best")
    if sc is not None:
        fig.colorbar(sc, ax=axes, label=label[0], shrink=0.8)
    fig.suptitle(
        f"Pareto front: {len(front.points)} non-dominated of {front.feasible:,} feasible designs"
    )
    if path is not None:
        from ..fileio import save_figure

        save_figure(fig, path)
    return fig


__all__ = [
    "format_result",
    "format_pareto",
    "load_components",
    "relax_lines",
    "estimated_lines",
    "plot_pareto",
]

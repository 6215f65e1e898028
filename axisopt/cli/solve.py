"""``axisopt solve PROBLEM.yaml``: the sizing search from the command line."""

from __future__ import annotations

import math
import sys
import textwrap

from .common import (
    EXIT_NEGATIVE,
    EXIT_OK,
    EXIT_UNPROVEN,
    add_html_report,
    check_html_report,
    one_line,
    show,
    stdout_taken,
    write_json,
    wrote,
)


def register(sub) -> None:
    s = sub.add_parser("solve", help="choose parts and preload that maximise stiffness/frequency (proven)")
    s.add_argument("problem", help="problem YAML file")
    s.add_argument("--method", choices=("default", "exhaustive", "bonmin", "scip"), default="default",
                   help="default: proven optimum (bounds); exhaustive: every combination; bonmin: MINLP; "
                        "scip: global MINLP (pip install 'axisopt[scip]')")
    s.add_argument("--json", metavar="FILE", help="write the result as JSON ('-' for stdout)")
    s.add_argument("--plot", metavar="FILE.png", help="plot the best designs (or the Pareto front)")
    s.add_argument("--top", type=int, default=5, metavar="N", help="designs to show (best + runners-up)")
    s.add_argument("--time-limit", type=float, default=100.0, metavar="S", help="Bonmin / SCIP time limit [s]")
    s.add_argument("--no-sensitivity", action="store_true",
                   help="skip re-solving with each limit relaxed by 10 %%")
    s.add_argument("--save-design", metavar="FILE.yaml|DIR",
                   help="write the best design as a design YAML (evaluate and compare read it); a directory "
                        "gets the --top designs shown (or every Pareto point) as 1.yaml, 2.yaml, ... (01.yaml from 10)")
    add_html_report(s, "the result")
    s.set_defaults(func=cmd_solve)


def cmd_solve(args) -> int:
    from ..errors import InputError
    from ..problem import load_problem
    from ..search import solve

    if args.top < 1:
        raise InputError(f"--top must be at least 1, got {args.top}")
    if not (math.isfinite(args.time_limit) and args.time_limit > 0):
        raise InputError(f"--time-limit must be positive, got {args.time_limit}")
    check_html_report(args.report)
    problem = load_problem(args.problem)
    if args.save_design and _single_file(args.save_design) and problem.objective.mode == "pareto":
        raise InputError("a Pareto front has several designs: give a directory, not a .yaml file",
                         where="--save-design")
    res = solve(problem, args.method, top=args.top, time_limit=args.time_limit,
                sensitivities=not args.no_sensitivity)
    quiet = stdout_taken(args.json, args.save_design)
    text = format_result(res, top=args.top) if not quiet or args.report else ""
    if not quiet:
        show(text)
    if args.json:
        d = res.to_dict()
        if res.best is not None and res.best.design is not None:
            from ..model import evaluate
            from ..report import evaluation_dict

            d["evaluation"] = evaluation_dict(evaluate(res.best.design))
        write_json(d, args.json)
    if args.plot:
        if res.pareto is not None:
            from ..search.pareto import plot_pareto

            plot_pareto(res.pareto, args.plot)
        elif res.best is not None:
            from ..model import evaluate
            from ..report import plot_profiles
            from ..report.plots import distinct_labels

            cands = [res.best] + list(res.runners_up)
            parts = [{"mounting": c.mounting, **c.parts()} for c in cands]
            labels = distinct_labels(parts, [f"#{c.rank}" for c in cands]) if len(cands) > 1 else \
                [" / ".join(str(v) for v in parts[0].values() if v)]
            plot_profiles([evaluate(c.design) for c in cands], args.plot, labels=labels,
                          limits={k: v for k, v in problem.limits if k in ("min_stiffness", "min_frequency")})
        if not quiet:
            print(f"\nplot written to {args.plot}")
    if args.report:
        from ..report.html import solve_page, write_page

        write_page(solve_page(res, problem, text), args.report, plotly=args.plotly)
        wrote(args.report, quiet)
    if args.save_design:
        written = save_designs(res, args.save_design, args.top, args.problem)
        if not written:
            print(f"axisopt: no design saved: the problem is {res.status}", file=sys.stderr)
        elif not quiet:
            print(f"\n{len(written)} design YAML written: {', '.join(written)}" if len(written) < 4 else
                  f"\n{len(written)} design YAMLs written to {args.save_design}")
    return exit_code(res.status)


def save_designs(res, target: str, top: int, problem_path: str) -> list:
    """Write the best design to ``target`` (a .yaml file) or the shown designs into ``target`` (a directory,
    ranks as 1.yaml, 2.yaml ...; Pareto points in front order).  Returns the paths written."""
    from pathlib import Path

    from ..design import design_to_yaml
    from ..fileio import make_output_dir, write_text_atomic

    cands = list(res.pareto.points) if res.pareto is not None else \
        ([res.best] + list(res.runners_up))[:top] if res.best is not None else []
    cands = [c for c in cands if c is not None and c.design is not None]
    problem_path = one_line(problem_path)  # a comment line: no line break in a file name may inject YAML
    if not cands:
        return []
    single = _single_file(target)
    out = []
    paths = [Path(target)] if single else [Path(target) / f"{i:0{len(str(len(cands)))}d}.yaml"
                                                 for i in range(1, len(cands) + 1)]
    if not single:
        make_output_dir(target)
    for c, path in zip(cands if not single else cands[:1], paths):
        what = "Pareto point" if res.pareto is not None else f"rank {c.rank}"
        head = (f"# written by axisopt solve {problem_path} ({res.method}, {res.status}): {what}, "
                f"{res.objective_label} = {c.objective:.6g} {res.objective_unit}\n") if res.pareto is None else \
            f"# written by axisopt solve {problem_path} ({res.method}, {res.status}): {what}\n"
        write_text_atomic(str(path), head + design_to_yaml(c.design), what="design YAML")
        out.append(str(path))
    return out


def _single_file(target: str) -> bool:
    """--save-design names one file (.yaml/.yml, or '-' for stdout), not a directory."""
    from ..fileio import is_stdout

    return target.lower().endswith((".yaml", ".yml")) or is_stdout(target)


def exit_code(status: str) -> int:
    """0 proven optimum, 1 proven infeasible, 3 anything unproven (Bonmin's point, time limit, failure)."""
    return {"optimal": EXIT_OK, "infeasible": EXIT_NEGATIVE}.get(status, EXIT_UNPROVEN)


def _n(v, nd=1):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    return f"{v:,.{nd}f}"


def format_result(res, top: int | None = None) -> str:
    from ..model import evaluate
    from ..report import evaluation_table

    c = res.certificate
    L = [f"problem {res.problem}: {res.objective_label}",
         f"method {res.method}: status {res.status}"
         + (" (proven global optimum over the catalog)" if res.status == "optimal" and c.proven else "")
         + f", {res.time:.2f} s" + (f"  [{res.solver_status}]" if res.solver_status not in ("", "ipopt") else "")]
    if res.message:
        L.append(f"  note: {res.message}")
    if res.infeasibility is not None:
        L.extend(relax_lines(res.infeasibility))
    L.append("")
    if res.pareto is not None:
        L.append(format_pareto(res.pareto, top))
    elif res.best is not None:
        b = res.best
        L.append(f"best: {b.objective:,.3f} {res.objective_unit}")
        L.append(evaluation_table(evaluate(b.design)))
        if res.binding:
            L.append("")
            L.append("limits at the optimum (what relaxing each by 10 % buys, re-solved)")
            L.append(f"  {'limit':<18}{'value':>12}{'at optimum':>12}{'relaxed to':>12}{'gain':>14}")
            for bd in res.binding:
                gain = "-" if bd.objective_gain is None or not math.isfinite(bd.objective_gain) else \
                    f"{bd.objective_gain:+.4g} {res.objective_unit}"
                L.append(f"  {bd.limit:<18}{_v(bd.value):>12}{_v(bd.at_optimum):>12}"
                         f"{_v(bd.relaxed_to):>12}{gain:>14}  {bd.unit}{'  BINDING' if bd.binding else ''}")
            for bd in res.binding:
                if bd.binding:
                    verb = "raising" if bd.limit.startswith("max") else "lowering"
                    L.append(f"  {verb} {bd.limit.replace('_', ' ')} to {_v(bd.relaxed_to)} {bd.unit} buys "
                             f"{bd.objective_gain:+.4g} {res.objective_unit}")
        if res.runners_up:
            L.append("")
            L.append("best designs")
            L.append(_cand_table([b] + list(res.runners_up), res.objective_unit))
    if res.infeasibility is not None:
        inf = res.infeasibility
        if inf.unmeetable:
            L.append("limits no catalog combination can meet (each checked on its own, best preload):")
            for name, best, lim, unit in inf.unmeetable:
                u = f" {unit}" if unit else ""
                L.append(f"  {name}: limit {_num(lim)}{u}, best any combination reaches {_num(best)}{u}")
        else:
            L.append("every limit is met by some combination, but no combination meets all of them together")
        L.append("")
        L.append("closest designs (sum of relative misses):")
        for cand in inf.closest:
            miss = ", ".join(f"{k} by {100 * v:.1f} %" for k, v in cand.misses.items())
            L.append(f"  #{cand.rank} {cand.mounting} {' / '.join(cand.parts().values())}"
                     f" preload {cand.nut_preload:.0f} N: misses {miss or 'nothing'}")
    L.append("")
    L.append("certificate")
    if c.feasible is None:  # Bonmin: one MINLP per mounting, nothing counted or bounded
        L.append(f"  combinations {c.combinations:,}; MINLP solves {c.nlps_solved} "
                 f"(not SUCCESS {c.nlp_failures}); feasible combinations not counted")
    else:
        blocks = (f"; screened {c.screened:,}, the rest pruned by their (nut, bearing) block's bound"
                  if res.method == "default" and c.screened is not None else "")
        L.append(f"  combinations {c.combinations:,}{blocks}")
        if c.pruned_by_dominance:
            L.append(f"  never formed {c.pruned_by_dominance:,} (a coupling another beats on every count, or one "
                     "that cannot carry the motor's peak torque)")
        L.append(f"  feasible {c.feasible:,}{' (screened)' if res.method == 'default' else ''}; pruned by bound "
                 f"{c.pruned_by_bound:,}; exact 1-D solves {c.exact_evaluations:,}; NLPs {c.nlps_solved} "
                 f"(failures {c.nlp_failures})")
    gap = "0 (proven)" if c.proven and c.gap == 0 else ("unknown" if not math.isfinite(c.gap) else f"{c.gap:.3%}")
    if not c.screening_time:
        rate = ""
    elif c.screened is None:  # every combination screened
        rate = f"; screening {c.screening_time:.3f} s ({c.screening_rate / 1e6:.1f} M designs/s)"
    else:  # the blocks' bounds, then the combinations of the opened blocks one by one
        rate = f"; screening {c.screening_time:.3f} s (block bounds, {c.screened:,} combinations one by one)"
    L.append(f"  optimality gap {gap}{rate}")
    for n in c.notes:
        L.append(f"  {n}")
    L.extend(estimated_lines(c.estimated))
    from ..report.evaluation import fit_lines

    return fit_lines("\n".join(L))


def relax_lines(inf) -> list:
    """The first lines of an infeasible answer: what to relax, by how much, for which closest design."""
    rel = inf.relax
    if not rel:
        return []

    def amount(r):
        u = f" {r.unit}" if r.unit else ""
        sign = "+" if r.relaxed_to > r.value else "-"
        rule = " (below the vendor's rule)" if r.below_vendor_rule else ""
        return f"{r.key} from {_v(r.value)}{u} to {_v(r.relaxed_to)}{u} ({sign}{_num(100 * r.change)} %){rule}"

    d = rel[0].design
    who = f"design #{rel[0].design_rank}" + (f" ({d.mounting} {' / '.join(d.parts().values())})" if d else "")
    if inf.relax_blocked_by:
        head = (f"  no relaxation of the limits is enough: every closest design breaks a compatibility rule; "
                f"{who} breaks {', '.join(inf.relax_blocked_by)} and besides needs ")
    else:
        head = "  to make it feasible, relax "
    if len(rel) == 1 and not inf.relax_blocked_by:
        L = [f"{head}{amount(rel[0])}: {who} then meets every limit"]
    elif len(rel) == 1:
        L = [f"{head}{amount(rel[0])}"]
    else:
        L = [f"{head}these {len(rel)} limits{' relaxed' if inf.relax_blocked_by else ''} together (smallest "
             "change first)"
             + ("" if inf.relax_blocked_by else f"; {who} then meets every limit") + ":"]
        L += [f"    {amount(r)}" for r in rel]
    for rank, rules in inf.not_relaxable:
        L.append(f"  design #{rank} left out: it breaks {', '.join(rules)} (a compatibility rule, not relaxable)")
    return L


def _cand_table(cands, unit) -> str:
    """Best designs in 100 columns: the numbers on one line per design, its parts below it (after the first
    design, only the parts in which it differs from the one above)."""
    slots = ("screw", "nut", "bearing", "guide", "motor", "coupling")
    obj = f"obj {unit}" if unit != "-" else ""
    L = [f"  {'#':>3} {'mounting':<17}{obj:>12}{'k N/um':>9}{'f Hz':>8}{'cost EUR':>10}{'mass kg':>9}"
         f"{'preload N':>11}"]
    prev = None
    for c in cands:
        val = f"{c.objective:,.3f}" if obj else ""
        L.append(f"  {c.rank:>3} {c.mounting:<17}{val:>12}{c.min_stiffness:>9.1f}{c.min_frequency:>8.1f}"
                 f"{c.cost:>10,.0f}{c.total_mass:>9.1f}{c.nut_preload:>11.0f}")
        parts = c.parts()
        if prev is None:
            shown = [f"{k} {parts[k]}" for k in slots if parts.get(k)]
        else:
            shown = [f"{k} {parts[k]}" for k in slots if parts.get(k) and parts.get(k) != prev.get(k)]
            shown = ["same parts as above" if not shown else "as above but " + shown[0]] + shown[1:]
        L.extend(textwrap.wrap("  ".join(shown), 100, initial_indent=" " * 8, subsequent_indent=" " * 8,
                               break_on_hyphens=False))
        prev = parts
    return "\n".join(L)


def estimated_lines(estimated) -> list:
    """Text lines for ``Certificate.estimated`` (what of the optimum rests on estimated part values)."""
    if not estimated:
        return []
    from ..model.estimates import estimate_text

    out = ["  rests on estimated values (not in the vendor's table; catalogs/SOURCES.md):"]
    for r in estimated:
        vals = "; ".join(estimate_text(e) for e in r["estimates"])
        out.extend(textwrap.wrap(f"{r['what']} ({r['output']}): {vals}", 100, initial_indent="    ",
                                 subsequent_indent="        "))
    return out


def format_pareto(front, top: int | None = None) -> str:
    """The front's designs sorted by the first objective; ``top`` of them (all when None)."""
    shown = front.points if top is None else front.points[:top]
    L = [f"Pareto front: {len(front.points)} non-dominated designs of {front.feasible:,} feasible "
         f"({', '.join(f'{s} {k}' for k, s in zip(front.keys, front.senses))})"]
    if len(shown) < len(front.points):
        L.append(f"  the first {len(shown)} by {front.keys[0]} shown (--top N for more, --json for all)")
    L.append(_cand_table(shown, "-"))
    return "\n".join(L)


def _v(v) -> str:
    """A limit or design value: 20,000 / 1,250 / 98.5 / 0.785 ('-' when missing)."""
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "-"
    return _num(float(v)) if abs(v) >= 100 else f"{v:.4g}"


def _num(v: float) -> str:
    """1,500 / 0.785 / 12.4: thousands separators for large values, three significant digits otherwise."""
    return f"{v:,.0f}" if abs(v) >= 100 else f"{v:.3g}"

"""``axisopt solve PROBLEM.yaml``: the sizing search from the command line."""

from __future__ import annotations

import math
import sys
import time

from .common import (
    EXIT_NEGATIVE,
    EXIT_OK,
    EXIT_UNPROVEN,
    add_html_report,
    check_html_report,
    one_line,
    show,
    stdout_taken,
    write_html_report,
    write_json,
    wrote,
)


class _MethodNames:
    """The ``--method`` choices: the names of ``search.front.METHOD_TABLE``, read when the parser
    first asks (the command line's start-up imports no search code)."""

    def __contains__(self, name) -> bool:
        return name in self._names()

    def __iter__(self):
        return iter(self._names())

    @staticmethod
    def _names() -> tuple:
        from ..search import METHODS

        return METHODS


def register(sub) -> None:
    s = sub.add_parser(
        "solve", help="choose parts and preload that maximise stiffness/frequency (proven)"
    )
    s.add_argument("problem", help="problem YAML file")
    # the choices are read when a --method is given or the help printed: a metavar, so that building
    # the parser does not list them (argparse would import the search at every start-up)
    s.add_argument(
        "--method",
        choices=_MethodNames(),
        default="default",
        metavar="METHOD",
        help="%(choices)s; default: proven optimum (bounds); exhaustive: every combination; "
        "bonmin: MINLP; scip: global MINLP (pip install 'axisopt[scip]')",
    )
    s.add_argument("--json", metavar="FILE", help="write the result as JSON ('-' for stdout)")
    s.add_argument("--plot", metavar="FILE.png", help="plot the best designs (or the Pareto front)")
    s.add_argument(
        "--top", type=int, default=5, metavar="N", help="designs to show (best + runners-up)"
    )
    s.add_argument(
        "--time-limit",
        type=float,
        default=100.0,
        metavar="S",
        help="time limit [s] of every method (default 100): the best found so far, its gap, and a "
        "note when it cuts the search",
    )
    s.add_argument(
        "--no-sensitivity",
        action="store_true",
        help="skip re-solving with each limit relaxed by 10 %%",
    )
    s.add_argument(
        "--save-design",
        metavar="FILE.yaml|DIR",
        help="write the best design as a design YAML (evaluate and compare read it); a directory "
        "gets the --top designs shown (or every Pareto point) as 1.yaml, 2.yaml, ... (01.yaml from "
        "10); the nut preload in round figures that keep every limit met",
    )
    add_html_report(s, "the result")
    s.set_defaults(func=cmd_solve)


def cmd_solve(args) -> int:
    from ..errors import InputError
    from ..problem import load_problem
    from ..report.solve import format_result, load_components
    from ..search import solve

    if args.top < 1:
        raise InputError(f"--top must be at least 1, got {args.top}")
    if not (math.isfinite(args.time_limit) and args.time_limit > 0):
        raise InputError(f"--time-limit must be positive, got {args.time_limit}")
    check_html_report(args.report, args.plotly)
    problem = load_problem(args.problem)
    if args.save_design and _single_file(args.save_design) and problem.objective.mode == "pareto":
        raise InputError(
            "a Pareto front has several designs: give a directory, not a .yaml file",
            where="--save-design",
        )
    if problem.drives is not None:
        return _solve_drive_types(args, problem)
    started = time.perf_counter()
    res = solve(
        problem,
        args.method,
        top=args.top,
        time_limit=args.time_limit,
        sensitivities=not args.no_sensitivity,
    )
    if res.pareto is None:  # the drive types the catalogs offer by default (search.drivedefault)
        from ..search.drivedefault import offer

        deadline = started + args.time_limit
        other = offer(problem, res, args.method, top=args.top, deadline=deadline).result
        if other is not None:  # its files (--plot, --save-design, --report) are the drive types'
            return _show_drive_types(args, other)
    quiet = stdout_taken(args.json, args.save_design)
    text = format_result(res, top=args.top, problem=problem) if not quiet or args.report else ""
    if not quiet:
        show(text)
    if args.json:
        d = res.to_dict()
        d["load_components"] = load_components(problem.axis, problem.assumed)
        if res.best is not None and res.best.design is not None:
            from ..model import evaluate
            from ..report import evaluation_dict

            d["evaluation"] = evaluation_dict(evaluate(res.best.design))
        write_json(d, args.json)
    if args.plot:
        if res.pareto is not None:
            from ..report.solve import plot_pareto

            plot_pareto(res.pareto, args.plot)
        elif res.best is not None:
            from ..model import evaluate
            from ..report import plot_profiles
            from ..report.plots import distinct_labels

            cands = [res.best] + list(res.runners_up)
            parts = [{"mounting": c.mounting, **c.parts()} for c in cands]
            labels = (
                distinct_labels(parts, [f"#{c.rank}" for c in cands])
                if len(cands) > 1
                else [" / ".join(str(v) for v in parts[0].values() if v)]
            )
            plot_profiles(
                [evaluate(c.design) for c in cands],
                args.plot,
                labels=labels,
                limits={k: v for k, v in problem.limits if k in ("min_stiffness", "min_frequency")},
                margins=problem.margin_map,
            )
        if not quiet:
            print(f"\nplot written to {args.plot}")
    if args.report:
        from ..report.htmlpages import solve_page

        write_html_report(args, quiet, solve_page, res, problem, text)
    if args.save_design:
        written = save_designs(res, args.save_design, args.top, args.problem, problem)
        if not written:
            print(f"axisopt: no design saved: the problem is {res.status}", file=sys.stderr)
        elif not quiet:
            print(
                f"\n{len(written)} design YAML written: {', '.join(written)}"
                if len(written) < 4
                else f"\n{len(written)} design YAMLs written to {args.save_design}"
            )
    return exit_code(res.status)


def _solve_drive_types(args, problem) -> int:
    """A problem with ``search.drive_types``: the drive types' search and its text (and --json)."""
    from ..errors import InputError
    from ..search.drivetype import solve_drive_types

    if args.method not in ("default", "exhaustive"):
        raise InputError(
            f"--method {args.method}: a search over drive types runs the default or exhaustive "
            "method",
            where="--method",
        )
    res = solve_drive_types(problem, args.method, top=args.top, time_limit=args.time_limit)
    return _show_drive_types(args, res)


def _show_drive_types(args, res) -> int:
    """The text (and --json) of a drive types' answer
    (:class:`axisopt.search.drivetype.DriveTypeResult`)."""
    from ..report.drivetype import format_drive_result

    quiet = stdout_taken(args.json, args.save_design)
    text = format_drive_result(res, top=args.top)
    if not quiet:
        show(text)
    if args.report:
        from ..report.drivehtml import drive_types_page

        write_html_report(args, quiet, drive_types_page, res, text)
    if args.json:
        write_json(res.to_dict(), args.json)
    if args.plot:
        from ..report.driveplot import plot_drive_designs

        plot_drive_designs(res, args.plot, top=args.top)
        wrote(args.plot, quiet)
    if args.save_design:
        written = save_drive_designs(res, args.save_design, args.top, args.problem)
        if not written:
            print(f"axisopt: no design saved: the problem is {res.status}", file=sys.stderr)
        elif not quiet:
            print(f"\n{len(written)} design YAML written: {', '.join(written)}")
    return exit_code(res.status)


def save_drive_designs(res, target: str, top: int, problem_path: str) -> list:
    """Write the best design of a drive types' answer to ``target`` (a .yaml file) or the shown
    designs into ``target`` (a directory: 1.yaml, 2.yaml, ...): a screw design as
    :func:`save_designs` writes it, a rack or linear-motor design as the problem file with its
    ``drive_design`` (search.drivefile).  Returns the paths written."""
    from pathlib import Path

    from ..fileio import make_output_dir, write_text_atomic
    from ..search.drivefile import drive_design_yaml

    designs = ([res.best] + list(res.runners_up))[:top] if res.best is not None else []
    if not designs:
        return []
    single = _single_file(target)
    if single:
        designs = designs[:1]
        paths = [Path(target)]
    else:
        make_output_dir(target)
        w = len(str(len(designs)))
        paths = [Path(target) / f"{i:0{w}d}.yaml" for i in range(1, len(designs) + 1)]
    out = []
    for rank, (d, path) in enumerate(zip(designs, paths), start=1):
        if d.drive_type == "screw":
            from ..design import design_to_yaml

            text = (
                f"# design {rank} of `axisopt solve {one_line(problem_path)}`: screw drive\n"
                + design_to_yaml(d.candidate.design)
            )
        else:
            text = drive_design_yaml(problem_path, d, rank)
        write_text_atomic(str(path), text, what="design YAML")
        out.append(str(path))
    return out


def save_designs(res, target: str, top: int, problem_path: str, problem=None) -> list:
    """Write the best design to ``target`` (a .yaml file) or the shown designs into ``target`` (a
    directory, ranks as 1.yaml, 2.yaml ...; Pareto points in front order).  Returns the paths
    written.

    The nut preload is written in round figures, rounded the way that keeps ``problem``'s limits met
    (:func:`axisopt.report.partslist.order_preload`), with a comment saying from what."""
    from dataclasses import replace
    from pathlib import Path

    from ..design import design_to_yaml
    from ..fileio import make_output_dir, write_text_atomic
    from ..report.partslist import order_preload

    cands = (
        list(res.pareto.points)
        if res.pareto is not None
        else ([res.best] + list(res.runners_up))[:top]
        if res.best is not None
        else []
    )
    cands = [c for c in cands if c is not None and c.design is not None]
    # a comment line: no line break in a file name may inject YAML
    problem_path = one_line(problem_path)
    if not cands:
        return []
    single = _single_file(target)
    out = []
    paths = (
        [Path(target)]
        if single
        else [Path(target) / f"{i:0{len(str(len(cands)))}d}.yaml" for i in range(1, len(cands) + 1)]
    )
    if not single:
        make_output_dir(target)
    for c, path in zip(cands if not single else cands[:1], paths):
        what = "Pareto point" if res.pareto is not None else f"rank {c.rank}"
        head = (
            (
                f"# written by axisopt solve {problem_path} ({res.method}, {res.status}): {what}, "
                f"{res.objective_label} = {c.objective:.6g} {res.objective_unit}\n"
            )
            if res.pareto is None
            else f"# written by axisopt solve {problem_path} ({res.method}, {res.status}): {what}\n"
        )
        ordered = order_preload(c.design, problem)
        design = replace(c.design, nut_preload=ordered.value) if ordered.moved else c.design
        # what the file evaluates to
        if ordered.moved and res.pareto is None and problem is not None:
            head = (
                f"# written by axisopt solve {problem_path} ({res.method}, {res.status}): {what}, "
                f"{res.objective_label} = {_file_objective(design, problem):.6g} "
                f"{res.objective_unit} with the preload as written ({c.objective:.6g} at the "
                f"search's {c.nut_preload:.5g} N)\n"
            )
        write_text_atomic(
            str(path),
            head + design_to_yaml(design, preload_note=ordered.note()),
            what="design YAML",
        )
        out.append(str(path))
    return out


def _file_objective(design, problem) -> float:
    """The objective of ``design`` as written (the nut preload rounded for ordering), evaluated by
    the model: the value ``axisopt evaluate`` of the saved file shows."""
    from ..model import evaluate
    from ..search.task.objective import objective_spec

    ob = problem.objective
    spec = objective_spec(ob.order[1] if ob.mode == "lexicographic" else ob.mode, problem)
    return spec.sign * float(spec.value(evaluate(design).values))


def _single_file(target: str) -> bool:
    """--save-design names one file (.yaml/.yml, or '-' for stdout), not a directory."""
    from ..fileio import is_stdout

    return target.lower().endswith((".yaml", ".yml")) or is_stdout(target)


def exit_code(status: str) -> int:
    """0 proven optimum, 1 proven infeasible, 3 anything unproven (Bonmin's point, time limit,
    failure)."""
    from ..search.result import INFEASIBLE, OPTIMAL

    return {OPTIMAL: EXIT_OK, INFEASIBLE: EXIT_NEGATIVE}.get(status, EXIT_UNPROVEN)


def format_pareto(front, top: int | None = None) -> str:
    """The Pareto front's table (made by :func:`axisopt.report.solve.format_pareto`; here for its
    importers)."""
    from ..report.solve import format_pareto as table

    return table(front, top)

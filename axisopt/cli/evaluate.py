"""``axisopt evaluate``: one design over the stroke."""

from __future__ import annotations

import sys

from .common import (
    EXIT_NEGATIVE,
    EXIT_OK,
    add_html_report,
    check_html_report,
    show,
    stdout_taken,
    write_html_report,
    write_json,
    wrote,
)


def register(sub) -> None:
    e = sub.add_parser("evaluate", help="evaluate one design over the stroke")
    e.add_argument("design", help="design YAML file")
    e.add_argument("--json", metavar="FILE", help="write results as JSON ('-' for stdout)")
    e.add_argument(
        "--plot", metavar="FILE.png", help="plot stiffness and frequency over the stroke"
    )
    e.add_argument(
        "--calibration", metavar="FILE.yaml", help="apply a calibration saved by 'diagnose'"
    )
    e.add_argument(
        "--methods",
        nargs="?",
        const="all",
        metavar="NAMES",
        help="stiffness of nut, bearings and screw by every method of the seed paper, or only the "
        "named ones (e.g. nut:hertz,bearings:palmgren)",
    )
    e.add_argument(
        "--frf",
        metavar="FILE.png",
        help="plot the table's dynamic compliance at stroke start, middle and end: motor held (the "
        "first frequency's model), motor free and with the tuned servo (also in --json)",
    )
    e.add_argument(
        "--ss",
        metavar="FILE.npz",
        help="write the linear state-space model (A, B, C, D; motor free and held) at stroke "
        "start, middle and end and the tuned servo gains as a numpy .npz",
    )
    e.add_argument(
        "--fail-on-check",
        action="store_true",
        help="exit 1 when any check fails (for scripts; default: exit 0 with FAIL in the table)",
    )
    add_html_report(e, "the evaluation")
    e.set_defaults(func=cmd_evaluate)


def cmd_evaluate(args) -> int:
    from ..design import load_design
    from ..model import evaluate
    from ..report import evaluation_dict, evaluation_table, plot_profiles

    check_html_report(args.report, args.plotly)
    if _drive_design_file(args.design):
        return _evaluate_drive_design(args)
    design = load_design(args.design)
    if args.calibration:
        from ..identify.calibration import apply_calibration

        design = apply_calibration(design, args.calibration)
    ev = evaluate(design)
    rows = resp = held = closed = None
    if args.methods:
        from ..model.methods import select_methods, stiffness_methods

        rows = select_methods(stiffness_methods(ev), args.methods, design.name)
    if args.frf:
        from ..model.frf import frf
        from ..report.methods import closed_loop_frf

        resp = frf(ev)
        held = frf(ev, resp["frequency_Hz"], motor_held=True)
        closed = closed_loop_frf(ev, resp["frequency_Hz"])
    if not stdout_taken(args.json):
        show(evaluation_table(ev))
        if rows is not None:
            from ..report.methods import methods_table

            print("\n" + methods_table(rows))
    if args.json:
        out = evaluation_dict(ev)
        if rows is not None:
            from ..report.methods import methods_dict

            out["stiffness_methods"] = methods_dict(rows)
        if resp is not None:
            from ..report.methods import frf_dict

            out["frf"] = frf_dict(resp, held, closed)
        write_json(out, args.json)
    if args.plot:
        plot_profiles([ev], args.plot)
        if not stdout_taken(args.json):
            print(f"\nplot written to {args.plot}")
    if args.frf:
        from ..report.methods import plot_frf

        plot_frf(resp, args.frf, held, closed)
        if not stdout_taken(args.json):
            print(f"\nFRF plot written to {args.frf}")
    if args.ss:
        from ..model.servo import tune
        from ..model.statespace import stroke_state_spaces
        from ..report.servo import write_state_space

        write_state_space(
            stroke_state_spaces(ev),
            tune(ev),
            args.ss,
            held=stroke_state_spaces(ev, motor_held=True),
        )
        if not stdout_taken(args.json):
            print(f"\nstate-space model written to {args.ss}")
    if args.report:
        from ..report.html import evaluation_page

        write_html_report(args, stdout_taken(args.json), evaluation_page, ev)
    if args.fail_on_check:
        from ..report.evaluation import check_rows

        failed = [r["check"] for r in check_rows(ev) if not r["pass"]]
        if failed:
            print(f"axisopt: {len(failed)} check(s) fail: {', '.join(failed)}", file=sys.stderr)
            return EXIT_NEGATIVE
    return EXIT_OK


def _drive_design_file(path) -> bool:
    """Whether ``path`` holds a rack-and-pinion or linear-motor design (a problem with
    ``drive_design``)."""
    from ..yamlio import read_yaml

    node = read_yaml(path)
    return isinstance(node.value, dict) and "drive_design" in node.value


def _evaluate_drive_design(args) -> int:
    """``axisopt evaluate`` of a rack-and-pinion or linear-motor design (search.drivefile): its text
    (and --json, --plot); the options made for screw designs are refused."""
    from ..errors import InputError
    from ..problem import load_problem
    from ..report.drivetype import format_drive_design
    from ..search.drivefile import evaluate_drive_design

    for opt in ("calibration", "methods", "frf", "ss"):
        if getattr(args, opt, None):
            name = "--" + opt.replace("_", "-")
            raise InputError(
                f"{name} is made for screw designs; this file holds a rack-and-pinion or "
                "linear-motor design",
                where=name,
            )
    problem = load_problem(args.design)
    d = evaluate_drive_design(problem)
    quiet = stdout_taken(args.json)
    text = format_drive_design(d, problem)
    if not quiet:
        show(text)
    if args.report:
        from ..report.drivehtml import drive_design_page

        write_html_report(args, quiet, drive_design_page, d, problem, text)
    if args.json:
        write_json({"problem": problem.name, **d.to_dict()}, args.json)
    if args.plot:
        from types import SimpleNamespace

        from ..report.driveplot import plot_drive_designs
        from ..search.drivedesigns import objective_of

        _, (name, _, unit, sense) = objective_of(problem)
        label = f"{'maximise' if sense == 'max' else 'minimise'} {name.replace('_', ' ')}"
        one = SimpleNamespace(
            best=d, runners_up=[], closest=[], objective_label=label, objective_unit=unit
        )
        plot_drive_designs(one, args.plot)
        wrote(args.plot, quiet)
    failed = any(v < 1.0 for v in d.margins.values())
    return EXIT_NEGATIVE if failed and args.fail_on_check else EXIT_OK

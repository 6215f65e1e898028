"""``axisopt machine solve MACHINE.yaml``: a whole machine's axes sized together, proven, with the
sequential sizing beside it; ``axisopt machine study STUDY.yaml``: sweeps over a machine file, one
joint solve per case, locally or on a Dask cluster (the axis study's runner)."""

from __future__ import annotations

from .common import (
    EXIT_NEGATIVE,
    EXIT_OK,
    add_html_report,
    check_html_report,
    show,
    write_html_report,
    write_json,
)
from .study import add_run_options


def register(sub) -> None:
    s = sub.add_parser(
        "machine",
        help="size every axis of a machine together (proven), beside the sequential sizing",
    )
    msub = s.add_subparsers(dest="machine_command", required=True)
    m = msub.add_parser(
        "solve", help="the joint optimum of a machine file and the sequential sizing beside it"
    )
    m.add_argument("machine", help="machine YAML file (top-level 'axes:')")
    m.add_argument(
        "--method",
        choices=("default", "exhaustive"),
        default="default",
        help="default: exact Pareto sets of what each axis offers the one below (proven); "
        "exhaustive: every combination of every axis (small catalogs only)",
    )
    m.add_argument("--json", metavar="FILE", help="write the result as JSON ('-' for stdout)")
    add_html_report(
        m, "the joint optimum, the stiffness chain at the tool and the sequential sizing"
    )
    m.set_defaults(func=cmd_machine_solve)
    e = msub.add_parser(
        "evaluate",
        help="a machine whose axes name one part per slot (catalog.require): the "
        "stiffness at the tool with every link, the frequencies, the machine limits",
    )
    e.add_argument("machine", help="machine YAML file, every axis's parts named")
    e.add_argument("--json", metavar="FILE", help="write the machine as JSON ('-' for stdout)")
    add_html_report(e, "the machine: the stiffness chain at the tool, every axis, the frequencies")
    e.set_defaults(func=cmd_machine_evaluate)
    c = msub.add_parser(
        "compare",
        help="machines side by side: each a machine file (solved now) or a machine "
        "result JSON (from machine solve --json)",
    )
    c.add_argument(
        "machines",
        nargs="+",
        metavar="FILE",
        help="machine YAML files or machine result JSON files",
    )
    c.add_argument(
        "--json",
        metavar="FILE",
        help="write the machines' results as one JSON list ('-' for stdout)",
    )
    c.set_defaults(func=cmd_machine_compare)
    st = msub.add_parser(
        "study",
        help="sweeps over a machine file: one joint solve per case, resumable, "
        "locally or on a Dask cluster",
    )
    st.add_argument("study", help="machine study YAML file (base: a machine file)")
    add_run_options(st)
    st.add_argument("--quiet", action="store_true", help="no progress bar")
    st.set_defaults(func=cmd_machine_study)


def cmd_machine_solve(args) -> int:
    from ..fileio import is_stdout
    from ..machine import load_machine, solve_machine
    from ..report.machine import format_machine, machine_dict

    check_html_report(args.report, args.plotly)
    machine = load_machine(args.machine)
    res = solve_machine(machine, args.method)
    text = format_machine(res)
    if not (args.json and is_stdout(args.json)):
        show(text)
    if args.json:
        write_json(machine_dict(res), args.json)
    if args.report:
        from ..report.machine_html import machine_page

        write_html_report(args, bool(args.json and is_stdout(args.json)), machine_page, res, text)
    return EXIT_OK if res.best is not None else EXIT_NEGATIVE


def cmd_machine_study(args) -> int:
    import sys

    from ..study.machine import load_machine_study, run_machine_study
    from .common import one_line
    from .study import check_run_options, run_with_progress

    check_run_options(args)
    study = load_machine_study(args.study)
    s, out = run_with_progress(args, "axisopt machine study", run_machine_study, study)
    if s is None:
        return 130
    print(
        f"machine study {study.name}: {s.total} cases; {s.solved} solved now on {s.backend}"
        + (f" ({s.workers} workers)" if s.workers else "")
        + (f", {s.resumed} kept from an earlier run" if s.resumed else "")
        + f"; {s.failed} without a machine"
    )
    for name, path in s.files.items():
        print(f"  {name}: {path}")
    if s.lost or s.died:
        print(
            one_line(
                f"note: {s.lost + s.died} cases not solved ({s.lost_reason or 'worker died'}); "
                f"rerun with 'axisopt machine study {args.study} --out {out} --resume'"
            ),
            file=sys.stderr,
        )
    return EXIT_NEGATIVE if s.lost or s.died or s.failed else EXIT_OK


def _machine_result(path: str) -> dict:
    """A machine result: a JSON file as written by machine solve --json, or a machine file solved
    now."""
    import json

    from ..errors import InputError
    from ..fileio import read_input
    from ..machine import load_machine, solve_machine
    from ..machine.record import result_dict
    from ..report.machine_compare import check_result

    if path.lower().endswith(".json"):
        try:
            d = json.loads(read_input(path, "case", what="machine result"))
        except ValueError as exc:
            raise InputError(f"not JSON ({exc})", source=path) from None
        return check_result(d, path)
    return result_dict(solve_machine(load_machine(path)))


def cmd_machine_compare(args) -> int:
    from ..report.machine_compare import format_compare

    results = [_machine_result(p) for p in args.machines]
    from ..fileio import is_stdout

    if not (args.json and is_stdout(args.json)):
        show(format_compare(results))
    if args.json:
        write_json(results, args.json)
    return EXIT_OK if all(r["best"] is not None for r in results) else EXIT_NEGATIVE


def cmd_machine_evaluate(args) -> int:
    from ..fileio import is_stdout
    from ..machine import load_machine
    from ..machine.evaluate import evaluate_machine
    from ..machine.record import design_dict
    from ..report.machine import format_evaluation

    check_html_report(args.report, args.plotly)
    ev = evaluate_machine(load_machine(args.machine))
    text = format_evaluation(ev)
    if not (args.json and is_stdout(args.json)):
        show(text)
    if args.json:
        write_json(
            {
                "machine": ev.machine.name,
                "failed": [{"axis": n, "carried_kg": c} for n, c in ev.failed],
                "design": None if ev.design is None else design_dict(ev.design),
            },
            args.json,
        )
    if args.report:
        from ..report.machine_html import evaluation_page

        quiet = bool(args.json and is_stdout(args.json))
        write_html_report(args, quiet, evaluation_page, ev, text)
    return EXIT_OK if ev.design is not None and ev.design.feasible else EXIT_NEGATIVE

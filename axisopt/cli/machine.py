"""``axisopt machine solve MACHINE.yaml``: a whole machine's axes sized together, proven, with the sequential
sizing beside it."""

from __future__ import annotations

from .common import EXIT_NEGATIVE, EXIT_OK, show, write_json


def register(sub) -> None:
    s = sub.add_parser("machine", help="size every axis of a machine together (proven), beside the sequential "
                       "sizing")
    msub = s.add_subparsers(dest="machine_command", required=True)
    m = msub.add_parser("solve", help="the joint optimum of a machine file and the sequential sizing beside it")
    m.add_argument("machine", help="machine YAML file (top-level 'axes:')")
    m.add_argument("--method", choices=("default", "exhaustive"), default="default",
                   help="default: exact Pareto sets of what each axis offers the one below (proven); exhaustive: "
                        "every combination of every axis (small catalogs only)")
    m.add_argument("--json", metavar="FILE", help="write the result as JSON ('-' for stdout)")
    m.set_defaults(func=cmd_machine_solve)


def cmd_machine_solve(args) -> int:
    from ..fileio import is_stdout
    from ..machine import load_machine, solve_machine
    from ..report.machine import format_machine, machine_dict

    machine = load_machine(args.machine)
    res = solve_machine(machine, args.method)
    if not (args.json and is_stdout(args.json)):
        show(format_machine(res))
    if args.json:
        write_json(machine_dict(res), args.json)
    return EXIT_OK if res.best is not None else EXIT_NEGATIVE

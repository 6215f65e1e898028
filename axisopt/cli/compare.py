"""``axisopt compare A.yaml B.yaml ...``: designs (or solved problems) side by side."""

from __future__ import annotations

from .common import (
    EXIT_NEGATIVE,
    EXIT_OK,
    add_html_report,
    check_html_report,
    error_line,
    show,
    stdout_taken,
    write_html_report,
    write_json,
)


def register(sub) -> None:
    c = sub.add_parser("compare", help="compare designs (or solved problems) side by side")
    c.add_argument(
        "files",
        nargs="+",
        metavar="FILE.yaml",
        help="design YAMLs, or problem YAMLs (solved with the default method; the best design is "
        "used)",
    )
    c.add_argument("--json", metavar="FILE", help="write the comparison as JSON ('-' for stdout)")
    c.add_argument("--csv", metavar="FILE", help="write one row per design as CSV")
    c.add_argument(
        "--plot", metavar="FILE.png", help="overlay stiffness and frequency over the stroke"
    )
    c.add_argument(
        "--time-limit",
        type=float,
        default=100.0,
        metavar="S",
        help="time limit [s] of each problem's solve (default 100, as solve's)",
    )
    add_html_report(c, "the comparison")
    c.set_defaults(func=cmd_compare)


def cmd_compare(args) -> int:
    import math

    from ..errors import InputError
    from ..report.compare import compare_dict, compare_table, write_compare_csv
    from ..study.compare import load_compared

    if not (math.isfinite(args.time_limit) and args.time_limit > 0):
        raise InputError(f"--time-limit must be positive, got {args.time_limit}")
    check_html_report(args.report, args.plotly)
    items = load_compared(args.files, time_limit=args.time_limit)
    text = compare_table(items)
    if not stdout_taken(args.json, args.csv):
        show(text)
    if args.json:
        write_json(compare_dict(items), args.json)
    if args.csv:
        write_compare_csv(items, args.csv)
    evs = [c for c in items if c.evaluation is not None]
    if args.plot and evs:
        from ..report import plot_profiles

        plot_profiles([c.evaluation for c in evs], args.plot, labels=[c.label for c in evs])
        if not stdout_taken(args.json, args.csv):
            print(f"\nplot written to {args.plot}")
    if args.report:
        from ..report.htmlpages import compare_page

        write_html_report(args, stdout_taken(args.json, args.csv), compare_page, items, text)
    failed = [c for c in items if not c.ok]
    for c in failed:
        error_line(f"{c.source}: problem has no design to compare (status {c.solve['status']})")
    return EXIT_NEGATIVE if failed else EXIT_OK

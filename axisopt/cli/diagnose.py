"""``axisopt diagnose DATA.csv [...] --design DESIGN.yaml [--report FILE.html|DIR] [--json FILE|-]
[--save-calibration FILE.yaml] [--effects a,b,...] [--max-effects N] [--gain '0.85 N.m/A']``

A first file with a ``time`` column (and no reduced-table columns) is a time record: the files go to
the inverse dynamic identification of :mod:`axisopt.identify.records.idim` (first file estimation,
others validation); the text and JSON of either diagnosis come from :mod:`axisopt.report`."""

from __future__ import annotations

from ..errors import InputError
from .common import EXIT_OK, PLOTLY_HELP, stdout_taken, write_html_report, write_json


def cmd_diagnose(args) -> int:
    from ..identify.records.record import is_time_record

    # time records: IDIM (LS and IV), axisopt.identify.records.idim
    if args.data and is_time_record(args.data[0]):
        return _cmd_diagnose_time(args)
    from ..design import load_design
    from ..identify import diagnose, plant_from_design, read_dataset
    from ..identify.calibration import save_calibration
    from ..identify.effects import library
    from ..report.diagfiles import write_report
    from ..report.diagnosis import diagnosis_dict, diagnosis_text

    html = args.report is not None and str(args.report).lower().endswith((".html", ".htm"))
    if html and args.plotly != "no":
        from ..report.html import require_plotly

        require_plotly()
    design = load_design(args.design)
    datasets = [read_dataset(p) for p in args.data]
    names = None
    if args.effects:
        names = [n.strip() for n in args.effects.split(",") if n.strip()]
        unknown = [n for n in names if n not in library()]
        if unknown:
            raise InputError(
                f"--effects: unknown effect '{unknown[0]}'; known: {', '.join(library())}"
            )
    if args.max_effects < 0:
        raise InputError("--max-effects must not be negative")
    diag = diagnose(
        datasets, plant_from_design(design), candidates=names, max_effects=args.max_effects
    )
    quiet = stdout_taken(args.json, args.save_calibration)
    text = diagnosis_text(diag)
    if not quiet:
        print(text)
    if html:
        from ..report.htmlpages import diagnose_page

        write_html_report(args, quiet, diagnose_page, diag, text)
    elif args.report:
        path = write_report(diag, args.report)
        if not quiet:
            print(f"report written to {path}")
    if args.save_calibration:
        _print_calibration(
            save_calibration(diag, args.save_calibration, design, args.data),
            args.save_calibration,
            quiet,
        )
    if args.json:
        write_json(diagnosis_dict(diag), args.json)
    return EXIT_OK


def _print_calibration(cal: dict, path, quiet: bool) -> None:
    if quiet:
        return
    import textwrap

    print(f"calibration written to {path}")
    for head, key in (("applied by evaluate", "applied"), ("not applied", "not_applied")):
        for a in cal.get(key, []):
            print("\n".join(textwrap.wrap(f"  {head}: {a}", 100, subsequent_indent="      ")))


def _cmd_diagnose_time(args) -> int:
    from ..design import load_design
    from ..identify import plant_from_design
    from ..identify.records.idim import diagnose_time_files
    from ..report.timediag import time_diagnosis_dict, time_diagnosis_text

    if args.report:
        raise InputError("--report is not available for time records (use --json)")
    # refused when malformed, whether or not the record is a current record
    if args.gain is not None:
        from ..identify.records.record import parse_gain

        parse_gain(args.gain, source="--gain")
    names = [n.strip() for n in args.effects.split(",") if n.strip()] if args.effects else None
    design = load_design(args.design)
    diag = diagnose_time_files(
        args.data,
        plant=plant_from_design(design),
        gain=args.gain,
        candidates=names,
        max_effects=args.max_effects,
    )
    quiet = stdout_taken(args.json, args.save_calibration)
    if not quiet:
        print(time_diagnosis_text(diag))
    if args.save_calibration:
        from ..identify.records.calibration import save_time_calibration

        _print_calibration(
            save_time_calibration(diag, args.save_calibration, design, args.data),
            args.save_calibration,
            quiet,
        )
    if args.json:
        write_json(time_diagnosis_dict(diag), args.json)
    return EXIT_OK


def register(sub) -> None:
    d = sub.add_parser(
        "diagnose", help="fit measured data, name what the model gets wrong, measure the gain"
    )
    d.add_argument("data", nargs="+", help="measured test CSV file(s) (units in headers)")
    d.add_argument("--design", required=True, help="design YAML of the measured axis")
    d.add_argument(
        "--report",
        metavar="FILE.html|DIR",
        help="a self-contained HTML report (FILE.html), or report.md with residual plots in DIR",
    )
    d.add_argument("--plotly", choices=("no", "inline", "cdn"), default="no", help=PLOTLY_HELP)
    d.add_argument("--json", metavar="FILE", help="write results as JSON ('-' for stdout)")
    d.add_argument(
        "--save-calibration", metavar="FILE.yaml", help="save the calibrated model for evaluate"
    )
    d.add_argument(
        "--effects", metavar="A,B", help="only consider these effects (default: the whole library)"
    )
    d.add_argument(
        "--max-effects", type=int, default=3, metavar="N", help="accept at most N effects (3)"
    )
    d.add_argument(
        "--gain",
        metavar="'0.85 N.m/A'",
        help="time records with a current column: torque (N.m/A) or force (N/A) per ampere, for "
        "files without a '# gain:' line",
    )
    d.set_defaults(func=cmd_diagnose)

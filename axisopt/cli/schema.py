"""``axisopt schema``: the JSON Schema of a design, problem, study or calibration YAML, for an
editor's YAML language server (written from the readers' own key tables, :mod:`axisopt.schema`)."""

from __future__ import annotations

import json

from ..schema import KINDS_OF_FILE as FILE_KINDS  # the schema module's list: one declaration
from .common import EXIT_OK


def register(sub) -> None:
    p = sub.add_parser(
        "schema",
        help="JSON Schema of a design, problem, study, calibration, machine or machine "
        "study YAML (for editors)",
    )
    p.add_argument("kind", choices=FILE_KINDS, help="the kind of YAML file")
    p.add_argument("--out", metavar="FILE", help="write the schema to FILE (default: print it)")
    p.set_defaults(func=cmd_schema)


def cmd_schema(args) -> int:
    from ..schema import json_schema

    text = json.dumps(json_schema(args.kind), indent=2, ensure_ascii=False)
    if args.out:
        from ..fileio import write_text_atomic

        write_text_atomic(args.out, text + "\n", what="schema")
    else:
        print(text)
    return EXIT_OK

"""``axisopt parts``: what the catalogs hold, by kind and vendor, and the rows themselves in vendor
units."""

from __future__ import annotations

import textwrap

from ..errors import InputError
from .common import EXIT_OK, stdout_taken, write_json

KINDS = ("screws", "nuts", "bearings", "guides", "motors", "couplings", "reductions")

# The text table per kind: (header, column or columns, factor from SI, format); fits 100 columns.
# All columns, with vendor, provenance and source, are in --json and --csv.
_TABLE = {
    "screws": (
        ("d [mm]", "nominal_diameter", 1e3, ".0f"),
        ("lead [mm]", "lead", 1e3, ".0f"),
        ("root [mm]", "root_diameter", 1e3, ".2f"),
        ("max L [mm]", "max_length", 1e3, ".0f"),
        ("end bore [mm]", ("support_bore_min", "support_bore_max"), 1e3, ".0f"),
        ("DN limit", "dn_limit", 1e3 * 60 / 6.283185307179586, ",.0f"),
    ),
    "nuts": (
        ("type", "type", None, ""),
        ("k [N/um]", "stiffness", 1e-6, ".0f"),
        ("preload [N]", ("preload_min", "preload_max"), 1.0, ".0f"),
        ("Ca [kN]", "dynamic_load_rating", 1e-3, ".1f"),
        ("C0a [kN]", "static_load_rating", 1e-3, ".1f"),
        ("play [mm]", "axial_play", 1e3, ".3f"),
    ),
    "bearings": (
        ("arr.", "arrangement", None, ""),
        ("bore [mm]", "bore", 1e3, ".0f"),
        ("class", "preload_class", None, ""),
        ("preload [N]", "preload", 1.0, ".0f"),
        ("k [N/um]", "axial_rigidity", 1e-6, ".0f"),
        ("Ca [kN]", "dynamic_load_rating", 1e-3, ".1f"),
        ("drag [N.m]", "starting_torque", 1.0, ".2f"),
    ),
    "guides": (
        ("type", "type", None, ""),
        ("size", "size", 1e3, ".0f"),
        ("class", "preload_class", None, ""),
        ("preload [N]", "preload", 1.0, ".0f"),
        ("k [N/um]", "normal_rigidity", 1e-6, ".0f"),
        ("C [kN]", "dynamic_load_rating", 1e-3, ".1f"),
        ("C0 [kN]", "static_load_rating", 1e-3, ".1f"),
    ),
    "motors": (
        ("rated [N.m]", "rated_torque", 1.0, ".3g"),
        ("peak [N.m]", "peak_torque", 1.0, ".3g"),
        ("max [rpm]", "max_speed", 60 / 6.283185307179586, ".0f"),
        ("rotor [kg.cm^2]", "rotor_inertia", 1e4, ".3g"),
        ("brake [N.m]", "brake_torque", 1.0, ".3g"),
    ),
    "couplings": (
        ("rated [N.m]", "rated_torque", 1.0, ".0f"),
        ("k [N.m/rad]", "torsional_stiffness", 1.0, ",.0f"),
        ("J [kg.cm^2]", "inertia", 1e4, ".3g"),
        ("bore [mm]", ("bore_min", "bore_max"), 1e3, ".0f"),
        ("max [rpm]", "max_speed", 60 / 6.283185307179586, ",.0f"),
    ),
    "reductions": (
        ("kind", "kind", None, ""),
        ("i", "ratio", 1.0, ".3g"),
        ("eta", "efficiency", 1.0, ".2f"),
        ("T2N [N.m]", "rated_torque", 1.0, ".0f"),
        ("T2B [N.m]", "accel_torque", 1.0, ".0f"),
        ("k [N.m/rad]", "torsional_stiffness", 1.0, ",.0f"),
        ("J1 [kg.cm^2]", "inertia", 1e4, ".3g"),
        ("n1max [rpm]", "max_input_speed", 60 / 6.283185307179586, ",.0f"),
    ),
}
# What each filter applies to.
_FITS = ("nuts", "bearings")
_SIZE = ("screws", "nuts")
_CLASS = ("bearings", "guides")


def register(sub) -> None:
    p = sub.add_parser(
        "parts",
        help="catalog contents: counts per kind and vendor, or the rows of one kind",
        description="Without a kind: rows per kind and vendor.  With a kind: its rows, filtered.",
    )
    p.add_argument(
        "kind", nargs="?", choices=KINDS, help="list the rows of this kind (default: counts only)"
    )
    p.add_argument(
        "--vendor", action="append", metavar="NAME", help="only this vendor (repeatable)"
    )
    p.add_argument(
        "--status", metavar="STATUS", help="only rows of this provenance (see catalogs/SOURCES.md)"
    )
    p.add_argument(
        "--fits",
        metavar="SCREW_ID",
        help="nuts made for this screw, or support bearings whose bore its end journal takes",
    )
    p.add_argument(
        "--diameter", metavar="MM", help="screws (and their nuts) of this nominal diameter [mm]"
    )
    p.add_argument("--lead", metavar="MM", help="screws (and their nuts) of this lead [mm]")
    p.add_argument(
        "--preload-class", metavar="CLASS", help="bearings or guides of this preload class"
    )
    p.add_argument(
        "--catalogs", nargs="+", default=(), metavar="DIR", help="user catalog directories to add"
    )
    p.add_argument(
        "--json", metavar="FILE", help="write the counts (or rows) as JSON ('-' for stdout)"
    )
    p.add_argument(
        "--csv", metavar="FILE", help="write the rows (all columns, vendor units) as CSV"
    )
    p.set_defaults(func=cmd_parts)


def _rows(table) -> list[dict]:
    """The rows of a table as records (a list from :func:`axisopt.catalog.loading.load_records`, or
    a pandas table)."""
    return table.to_dict("records") if hasattr(table, "to_dict") else list(table)


def _select(rows, vendors, status):
    return [
        r
        for r in rows
        if (not vendors or r["vendor"] in vendors) and (not status or r["status"] == status)
    ]


def _filtered(cat, kind, vendors, status):
    rows = _rows(cat.table(kind))
    have = {r["vendor"] for r in rows}
    unknown = sorted(set(vendors or ()) - have)
    if unknown:
        raise InputError(
            f"no {kind} of vendor '{unknown[0]}'; vendors are {', '.join(sorted(have))}",
            where="--vendor",
        )
    return _select(rows, vendors, status)


def counts(cat, vendors=None, status=None) -> list[dict]:
    """One record per (kind, vendor): rows by provenance."""
    from ..catalog.columns import STATUSES

    out = []
    for kind in KINDS:
        rows = _select(_rows(cat.table(kind)), vendors, status)
        for vendor in sorted({r["vendor"] for r in rows}):
            g = [r for r in rows if r["vendor"] == vendor]
            rec = {"kind": kind, "vendor": vendor, "rows": len(g)}
            for s in STATUSES:
                rec[s.replace("vendor", "vendor_data").replace("-", "_")] = sum(
                    r["status"] == s for r in g
                )
            out.append(rec)
    return out


def counts_table(records) -> str:
    head = (
        f"{'kind':<9} {'vendor':<16} {'rows':>5} {'vendor data':>12} {'stiffness derived':>18} "
        f"{'paper':>6} {'derived':>8} {'user':>5}"
    )
    lines = [head, "-" * len(head)]
    for r in records:
        lines.append(
            f"{r['kind']:<9} {r['vendor']:<16} {r['rows']:>5} {r['vendor_data']:>12} "
            f"{r['stiffness_derived']:>18} {r['paper']:>6} {r['derived']:>8} {r['user']:>5}"
        )
    lines += textwrap.wrap(
        "vendor data: a catalog part, stiffness and load ratings from the vendor's table; "
        "stiffness derived: a catalog part whose vendor gives no rigidity number (rule in "
        "catalogs/SOURCES.md); derived: the part or its ratings computed by a rule; prices are "
        "illustrative everywhere",
        100,
    )
    return "\n".join(lines)


def _cell(row, col, factor, fmt):
    if isinstance(col, tuple):  # a range: min-max (one value when they agree)
        lo, hi = (_cell(row, c, factor, fmt) for c in col)
        return lo if lo == hi else f"{lo}-{hi}"
    v = row[col]
    if factor is None:
        return str(v)
    if v != v:  # NaN: not listed by the vendor
        return "-"
    return format(v * factor, fmt)


def _grid(heads, body, right) -> list:
    widths = [
        max(len(h), *(len(b[i]) for b in body)) if body else len(h) for i, h in enumerate(heads)
    ]

    def line(cells):
        return "  ".join(
            c.rjust(w) if r else c.ljust(w) for c, w, r in zip(cells, widths, right)
        ).rstrip()

    return [line(heads), line(["-" * w for w in widths])] + [line(b) for b in body]


def rows_table(rows, kind, screws=None) -> str:
    """The rows of one kind as text; nuts are grouped under the screw they are made for."""
    cols = _TABLE[kind]
    heads = ["id"] + [h for h, _, _, _ in cols]
    right = [False] + [f is not None for _, _, f, _ in cols]
    rows = _rows(rows)
    body = [[str(r["id"])] + [_cell(r, c, f, fmt) for _, c, f, fmt in cols] for r in rows]
    # the lead accuracy grades each screw is made in (catalogs/screw_grades.csv)
    if kind == "screws" and rows:
        heads, right = heads + ["grades"], right + [False]
        body = [b + [_grades(r)] for b, r in zip(body, rows)]
    legend = []
    if kind == "nuts" and any(_rotating(r) for r in rows):
        body = [[b[0] + (" R" if _rotating(r) else "")] + b[1:] for b, r in zip(body, rows)]
        legend = textwrap.wrap(
            "R: a driven rotating-nut unit (the nut turns in its own bearings, driven by the "
            "motor; the screw stands, fixed at both ends; docs/catalogs.md)",
            100,
        )
    if kind != "nuts" or not rows:
        return "\n".join(_grid(heads, body, right) + legend)
    screws = {r["id"]: r for r in _rows(screws)} if screws is not None else {}
    grid = _grid(heads, body, right)
    lines = grid[:2]
    # screw id -> its nuts' lines, screws in order of first appearance
    groups: dict[str, list[list[str]]] = {}
    for r, line in zip(rows, grid[2:]):
        groups.setdefault(r["screw_id"], []).append(line)
    for screw_id, g in groups.items():
        s = screws.get(screw_id)
        size = (
            f" ({s['nominal_diameter'] * 1e3:.0f} x {s['lead'] * 1e3:g} mm)"
            if s is not None
            else ""
        )
        lines.append(f"screw {screw_id}{size}")
        lines.extend(g)
    return "\n".join(lines + legend)


def _rotating(row) -> bool:
    from ..design import rotating_nut

    return rotating_nut(row)


def _grades(row) -> str:
    """The grades a screw row is made in: 'C0-C5' when they run on in the table's order, else
    'C1,C3,C5'."""
    from ..catalog.grades import grade_table

    t = grade_table()
    have = t.orderable(str(row.get("vendor", "")), str(row.get("series", "")))
    pos = [t.names.index(g) for g in have if g in t.names]
    if len(have) > 2 and pos == list(range(pos[0], pos[0] + len(pos))):
        return f"{have[0]}-{have[-1]}"
    return ",".join(have)


def rows_dicts(rows, kind) -> list[dict]:
    """Every column of the rows, in vendor units (the unit in the key), with vendor, provenance and
    source."""
    from ..catalog.columns import SCHEMA

    out = []
    for r in _rows(rows):
        rec = {}
        for c, k in SCHEMA[kind].items():
            v = r[c]
            if k in ("str",):
                rec[c] = v
                continue
            unit, f = _vendor_unit(k)
            key = f"{c} [{unit}]" if unit else c
            rec[key] = None if v != v else (int(v) if k == "int" else float(f"{v * f:.10g}"))
        if kind == "screws":  # the lead accuracy grades the screw is made in
            from ..catalog.grades import grade_table

            rec["grades"] = ",".join(
                grade_table().orderable(str(r.get("vendor", "")), str(r.get("series", "")))
            )
        rec.update({"status": r["status"], "source": r["source"]})
        out.append(rec)
    return out


def _vendor_unit(kind: str) -> tuple:
    """(unit, factor from SI) a catalog column of ``kind`` is exported in: the display units, with
    rotor and coupling inertia in kg.cm^2 as motor catalogs list it."""
    from ..units import DISPLAY_UNITS, unit_factor

    unit = "kg.cm^2" if kind == "inertia" else DISPLAY_UNITS.get(kind)
    return ("", 1.0) if unit is None else (unit, 1.0 / unit_factor(unit, kind))


def _mm(text, flag) -> float:
    try:
        v = float(text)
    except ValueError:
        raise InputError(f"expected a number of millimetres, got '{text}'", where=flag) from None
    if not (0 < v < 1e4):
        raise InputError(f"expected a size in mm between 0 and 10 000, got {text}", where=flag)
    return v / 1e3


def apply_filters(cat, kind, rows, args):
    """The ``rows`` (kind ``kind``) that pass --fits, --diameter, --lead and --preload-class."""
    for flag, value, kinds in (
        ("--fits", args.fits, _FITS),
        ("--diameter", args.diameter, _SIZE),
        ("--lead", args.lead, _SIZE),
        ("--preload-class", args.preload_class, _CLASS),
    ):
        if value is not None and kind not in kinds:
            raise InputError(f"applies to {' and '.join(kinds)}, not {kind}", where=flag)
    screws = _rows(cat.table("screws"))
    if args.fits is not None:
        screw = cat.part("screws", args.fits, key="--fits")
        if kind == "nuts":
            rows = [r for r in rows if r["screw_id"] == screw["id"]]
        else:
            rows = [
                r
                for r in rows
                if screw["support_bore_min"] - 1e-9 <= r["bore"] <= screw["support_bore_max"] + 1e-9
            ]
    for flag, value, col in (
        ("--diameter", args.diameter, "nominal_diameter"),
        ("--lead", args.lead, "lead"),
    ):
        if value is None:
            continue
        v = _mm(value, flag)
        ok = {s["id"] for s in screws if abs(s[col] - v) < 1e-6}
        rows = [r for r in rows if r["id" if kind == "screws" else "screw_id"] in ok]
    if args.preload_class is not None:
        classes = sorted({str(r["preload_class"]) for r in rows})
        if args.preload_class not in classes:
            raise InputError(
                f"no {kind} of preload class '{args.preload_class}' here; classes are "
                f"{', '.join(classes)}",
                where="--preload-class",
            )
        rows = [r for r in rows if str(r["preload_class"]) == args.preload_class]
    return rows


def cmd_parts(args) -> int:
    from ..catalog.columns import STATUSES
    from ..catalog.loading import load_records

    if args.status is not None and args.status not in STATUSES:
        raise InputError(f"'{args.status}' is not one of {', '.join(STATUSES)}", where="--status")
    cat = load_records(args.catalogs)  # plain records: no pandas on this path
    quiet = stdout_taken(args.json, args.csv)
    if args.kind:
        rows = apply_filters(
            cat, args.kind, _filtered(cat, args.kind, args.vendor, args.status), args
        )
        if not quiet:
            print(rows_table(rows, args.kind, cat.table("screws")))
            print(f"\n{len(rows)} {args.kind}; all columns, vendor and source: --csv or --json")
        if args.json:
            write_json({"kind": args.kind, "rows": rows_dicts(rows, args.kind)}, args.json)
        if args.csv:
            import pandas as pd

            from ..fileio import csv_safe, open_output

            # text cells escaped against CSV injection
            with open_output(args.csv, "w", what="CSV") as fh:
                csv_safe(pd.DataFrame(rows_dicts(rows, args.kind))).to_csv(fh, index=False)
            if not quiet:
                print(f"rows written to {args.csv}")
        return EXIT_OK
    for flag in ("fits", "diameter", "lead", "preload_class", "csv"):
        if getattr(args, flag) is not None:
            raise InputError(
                "needs a kind (e.g. 'axisopt parts nuts --fits SCREW_ID')",
                where="--" + flag.replace("_", "-"),
            )
    for v in args.vendor or ():
        if not any(r["vendor"] == v for k in KINDS for r in cat.table(k)):
            raise InputError(f"no parts of vendor '{v}' in the catalogs", where="--vendor")
    recs = counts(cat, args.vendor, args.status)
    if not quiet:
        print(counts_table(recs))
    if args.json:
        write_json({"counts": recs}, args.json)
    return EXIT_OK

"""``axisopt parts``: what the catalogs hold, by kind and vendor, and the rows themselves in vendor units."""

from __future__ import annotations

from ..errors import InputError
from .common import EXIT_OK, write_json

KINDS = ("screws", "nuts", "bearings", "guides", "motors", "couplings")

# Columns shown per kind when listing rows: (column, unit shown, factor from SI, format).
_SHOWN = {
    "screws": (("nominal_diameter", "mm", 1e3, ".0f"), ("lead", "mm", 1e3, ".0f"),
               ("root_diameter", "mm", 1e3, ".2f"), ("max_length", "mm", 1e3, ".0f"),
               ("support_bore_min", "mm", 1e3, ".0f"), ("support_bore_max", "mm", 1e3, ".0f")),
    "nuts": (("screw_id", "", None, ""), ("type", "", None, ""), ("stiffness", "N/um", 1e-6, ".0f"),
             ("stiffness_preload", "N", 1.0, ".0f"), ("preload_max", "N", 1.0, ".0f"),
             ("dynamic_load_rating", "kN", 1e-3, ".1f"), ("static_load_rating", "kN", 1e-3, ".1f"),
             ("axial_play", "mm", 1e3, ".3f")),
    "bearings": (("arrangement", "", None, ""), ("bore", "mm", 1e3, ".0f"), ("preload_class", "", None, ""),
                 ("preload", "N", 1.0, ".0f"), ("axial_rigidity", "N/um", 1e-6, ".0f"),
                 ("dynamic_load_rating", "kN", 1e-3, ".1f"), ("starting_torque", "N.m", 1.0, ".2f")),
    "guides": (("type", "", None, ""), ("size", "mm", 1e3, ".0f"), ("preload_class", "", None, ""),
               ("preload", "N", 1.0, ".0f"), ("normal_rigidity", "N/um", 1e-6, ".0f"),
               ("dynamic_load_rating", "kN", 1e-3, ".1f"), ("static_load_rating", "kN", 1e-3, ".1f")),
    "motors": (("rated_torque", "N.m", 1.0, ".3g"), ("peak_torque", "N.m", 1.0, ".3g"),
               ("max_speed", "rpm", 60 / 6.283185307179586, ".0f"), ("rotor_inertia", "kg.cm^2", 1e4, ".3g"),
               ("brake_torque", "N.m", 1.0, ".3g")),
    "couplings": (("rated_torque", "N.m", 1.0, ".0f"), ("torsional_stiffness", "N.m/rad", 1.0, ".0f"),
                  ("inertia", "kg.cm^2", 1e4, ".3g"), ("bore_min", "mm", 1e3, ".0f"), ("bore_max", "mm", 1e3, ".0f")),
}


def register(sub) -> None:
    p = sub.add_parser("parts", help="catalog contents: counts per kind and vendor, or the rows of one kind")
    p.add_argument("kind", nargs="?", choices=KINDS, help="list the rows of this kind (default: counts only)")
    p.add_argument("--vendor", action="append", metavar="NAME", help="only this vendor (repeatable)")
    p.add_argument("--status", metavar="STATUS",
                   help="only rows of this provenance (see catalogs/SOURCES.md)")
    p.add_argument("--catalogs", nargs="+", default=(), metavar="DIR", help="user catalog directories to add")
    p.add_argument("--json", metavar="FILE", help="write the counts (or rows) as JSON ('-' for stdout)")
    p.set_defaults(func=cmd_parts)


def _select(df, vendors, status):
    if vendors:
        df = df[df["vendor"].isin(vendors)]
    if status:
        df = df[df["status"] == status]
    return df


def _filtered(cat, kind, vendors, status):
    df = cat.table(kind)
    unknown = sorted(set(vendors or ()) - set(df["vendor"]))
    if unknown:
        raise InputError(f"no {kind} of vendor '{unknown[0]}'; vendors are "
                         f"{', '.join(sorted(set(df['vendor'])))}", where="--vendor")
    return _select(df, vendors, status)


def counts(cat, vendors=None, status=None) -> list[dict]:
    """One record per (kind, vendor): rows by provenance."""
    from ..catalog import STATUSES

    out = []
    for kind in KINDS:
        df = _select(cat.table(kind), vendors, status)
        for vendor, g in df.groupby("vendor", sort=True):
            rec = {"kind": kind, "vendor": vendor, "rows": int(len(g))}
            for s in STATUSES:
                rec[s.replace("vendor", "vendor_data").replace("-", "_")] = int((g["status"] == s).sum())
            out.append(rec)
    return out


def counts_table(records) -> str:
    head = (f"{'kind':<9} {'vendor':<16} {'rows':>5} {'vendor data':>12} {'stiffness derived':>18} {'paper':>6} "
            f"{'derived':>8} {'user':>5}")
    lines = [head, "-" * len(head)]
    for r in records:
        lines.append(f"{r['kind']:<9} {r['vendor']:<16} {r['rows']:>5} {r['vendor_data']:>12} "
                     f"{r['stiffness_derived']:>18} {r['paper']:>6} {r['derived']:>8} {r['user']:>5}")
    lines.append("vendor data: a catalog part, stiffness and load ratings from the vendor's table; stiffness derived: "
                 "a catalog part whose vendor gives no rigidity number (rule in catalogs/SOURCES.md); derived: the "
                 "part or its ratings computed by a rule; prices are illustrative everywhere")
    return "\n".join(lines)


def _cell(row, col, factor, fmt):
    v = row[col]
    if factor is None:
        return str(v)
    if v != v:  # NaN: not listed by the vendor
        return "-"
    return format(v * factor, fmt)


def rows_table(df, kind) -> str:
    cols = _SHOWN[kind]
    heads = ["id", "vendor"] + [f"{c} [{u}]" if u else c for c, u, _, _ in cols] + ["status", "source"]
    body = [[r["id"], r["vendor"]] + [_cell(r, c, f, fmt) for c, _, f, fmt in cols] + [r["status"], r["source"]]
            for _, r in df.iterrows()]
    widths = [max(len(h), *(len(b[i]) for b in body)) if body else len(h) for i, h in enumerate(heads)]
    line = lambda cells: "  ".join(c.ljust(w) for c, w in zip(cells, widths)).rstrip()  # noqa: E731
    return "\n".join([line(heads), line(["-" * w for w in widths])] + [line(b) for b in body])


def rows_dicts(df, kind) -> list[dict]:
    out = []
    for _, r in df.iterrows():
        rec = {"id": r["id"], "vendor": r["vendor"], "status": r["status"], "source": r["source"]}
        for c, u, f, _ in _SHOWN[kind]:
            v = r[c]
            key = f"{c}_{u.replace('/', '_per_').replace('.', '')}" if u else c
            rec[key] = v if f is None else (None if v != v else float(v * f))
        out.append(rec)
    return out


def cmd_parts(args) -> int:
    from ..catalog import STATUSES, load_catalogs

    if args.status is not None and args.status not in STATUSES:
        raise InputError(f"'{args.status}' is not one of {', '.join(STATUSES)}", where="--status")
    cat = load_catalogs(args.catalogs)
    quiet = args.json == "-"
    if args.kind:
        df = _filtered(cat, args.kind, args.vendor, args.status)
        if not quiet:
            print(rows_table(df, args.kind))
            print(f"\n{len(df)} {args.kind}")
        if args.json:
            write_json({"kind": args.kind, "rows": rows_dicts(df, args.kind)}, args.json)
        return EXIT_OK
    for v in args.vendor or ():
        if not any(v in set(cat.table(k)["vendor"]) for k in KINDS):
            raise InputError(f"no parts of vendor '{v}' in the catalogs", where="--vendor")
    recs = counts(cat, args.vendor, args.status)
    if not quiet:
        print(counts_table(recs))
    if args.json:
        write_json({"counts": recs}, args.json)
    return EXIT_OK

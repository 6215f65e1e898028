"""Diagnosis output (:class:`axisopt.identify.tables.diagnose.Diagnosis`): JSON-ready dict, console text, Markdown
report with residual plots (Agg).
Nothing here prints."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..fileio import tidy_layout
from ..identify.tables.diagnose import param_rows, plausibility
from ..identify.tables.diagnose import split_by_observation as _split
from ..identify.tables.measure import Y_UNIT
from ..identify.tables.unexplained import display_value, residual_table, table_signature
from . import save_figure, write_text_atomic
from .text import fit_lines


def _rmse_units(diag, pred):
    out = []
    for o, pr in zip(diag.obs, _split(diag.obs, pred)):
        unit, f = Y_UNIT[o.kind]
        out.append((o, float(np.sqrt(np.mean(((pr - o.y) * f) ** 2))), unit))
    return out


def diagnosis_dict(diag) -> dict:
    owner = diag.param_owner
    d = {
        "design": diag.plant.name,
        "datasets": [
            {
                "file": o.dataset.source,
                "test": o.kind,
                "rows": o.dataset.n,
                "excluded_rows": [{"line": ln, "reason": why} for ln, why in o.dataset.excluded],
                "noise_floor": s * Y_UNIT[o.kind][1],
                "noise_method": o.noise_method,
                "data_notes": data_notes(o),
                "unit": Y_UNIT[o.kind][0],
                "cv_groups": o.group_name,
            }
            for o, s in zip(diag.obs, diag.noise)
        ],
        "baseline": {
            "parameters": param_rows(diag.baseline),
            "status": diag.baseline.status,
            "plausibility": _flags(diag.baseline),
        },
        "residuals_baseline": [
            residual_table(o, r)
            for o, r in zip(diag.obs, _split(diag.obs, diag.baseline.prediction - diag.y))
        ],
        "residuals_final": [
            residual_table(o, r) for o, r in zip(diag.obs, _split(diag.obs, diag.final.prediction - diag.y))
        ],
        "candidates": [
            [
                {
                    "effect": c.effect.name,
                    "dBIC": c.dbic,
                    "cv_gain_percent": c.cv_gain,
                    "parameters": param_rows(c.fit, c.names),
                }
                for c in rnd
            ]
            for rnd in diag.rounds
        ],
        "verdict": diag.verdict,
        "accepted": [],
        "holdout_rmse_baseline": diag.cv_baseline,
        "holdout_rmse_final": diag.cv_final,
        "gain_percent": diag.gain,
        "holdout_rmse_units": [
            {"file": o.dataset.source, "baseline": b, "final": a, "unit": u, "gain_percent": g}
            for (o, b, u), (_, a, _), g in zip(
                _rmse_units(diag, diag.holdout_baseline), _rmse_units(diag, diag.holdout_final),
                _file_gains(diag)
            )
        ],
        "final": {"parameters": param_rows(diag.final), "status": diag.final.status,
                  "plausibility": plausibility(diag.final, []) + unidentifiable(diag.final)},
        "rejected": [
            {"round": rnd, "effect": c.effect.name, "dBIC": c.dbic, "would_need": bad,
             "parameters": param_rows(c.fit, c.names)}
            for rnd, c, bad in diag.rejected
        ],
        "not_accepted": [
            {"round": i, "effect": c.effect.name, "dBIC": c.dbic, "cv_gain_percent": c.cv_gain, "reason": c.reason}
            for i, rnd in enumerate(diag.rounds, start=1) for c in rnd if c.reason
        ],
        "pairs": [
            {"round": e["round"], "effects": [e["a"].effect.name, e["b"].effect.name], "dBIC": e["dbic"],
             "cv_gain_percent": e["gain"], "accepted": not e["reason"], "reason": e["reason"]}
            for e in diag.pairs
        ],
        "unexplained": unexplained_dicts(diag),
        "other_explanations": other_explanations(diag),
        "frf_modes": frf_modes(diag),
        "quantity": quantity_notes(diag),
    }
    for a in diag.accepted:
        names = [n for n, e in owner.items() if e == a.effect.name]
        r = a.runner_up
        d["accepted"].append(
            {
                "effect": a.effect.name,
                "title": a.effect.title,
                # the numbers of the final joint fit (the one --save-calibration writes), not of the round
                # in which the effect was accepted
                "finding": a.effect.describe(diag.final.values(), diag.plant),
                "parameters": param_rows(diag.final, names),
                "dBIC": a.dbic,
                "cv_rmse_before": a.cv_before,
                "cv_rmse_after": a.cv_after,
                "gain_percent": a.gain,
                "together_with": a.together or None,
                "plausibility": plausibility(diag.final, [], names=names) + _undetermined(diag.final, names)
                + unidentifiable(diag.final, names),
                "runner_up": None
                if r is None
                else {"effect": r.effect.name, "dBIC": r.dbic, "margin": r.dbic - a.dbic},
            }
        )
    return d


def unexplained_dicts(diag) -> list:
    """Per dataset: is structure left in the final residual, and its signatures in words."""
    out = []
    for u in diag.unexplained:
        sigs = []
        for p in u.remaining:
            what, causes, measure = table_signature(p, display_value)
            sigs.append({"factor": p.kind, "share": p.share, "log10_p": p.log10_p, "signature": what,
                         "causes": causes, "to_separate": measure})
        out.append({"file": u.source, "test": u.kind, "rms_over_noise": u.rms, "remaining": bool(sigs),
                    "signatures": sigs})
    return out


def _why_none(d) -> str:
    first = [c for c in d["not_accepted"] if c["round"] == 1][:3]
    if not first:
        return "no candidate effect applies to these data"
    return "; ".join(f"{c['effect']}: {c['reason']}" for c in first)


def _file_gains(diag) -> list:
    """Held-out gain of each file [%]: the noise-weighted held-out RMSE of its own rows, baseline against final
    (the pooled gain weighs every file together)."""
    out = []
    for o, pb, pf in zip(diag.obs, _split(diag.obs, diag.holdout_baseline), _split(diag.obs, diag.holdout_final)):
        rb = float(np.sqrt(np.mean(((pb - o.y) * o.w) ** 2)))
        rf = float(np.sqrt(np.mean(((pf - o.y) * o.w) ** 2)))
        out.append(100.0 * (1.0 - rf / rb) if rb > 0 else 0.0)
    return out


def _flags(res):
    return plausibility(res, []) + unidentifiable(res)


def unidentifiable(res, names=None) -> list:
    """Parameters the data do not fix (infinite variance: a zero or dependent Jacobian column)."""
    return [f"{p.name} is not identifiable from these data: the fit does not change with it (it is reported "
            "at the value the search stopped at, without an uncertainty)"
            for p, s in zip(res.params, res.sigma) if not math.isfinite(s) and (names is None or p.name in names)]


def _undetermined(res, names) -> list:
    """Parameters whose standard deviation exceeds their value: the data do not fix them."""
    out = []
    for p, v, s in zip(res.params, res.theta, res.sigma):
        if p.name in names and math.isfinite(s) and v != 0 and s > abs(v):
            out.append(f"{p.name} not determined by these data (+-{p.show(s):.3g} on {p.show(v):.4g} {p.unit})")
    return out


def other_explanations(diag) -> list:
    """What else the fit points to: a screw modulus outside steel's range means the chain is softer (or
    stiffer) than the model, which a component off its catalog value explains as well; name each component
    and the stiffness it would need to carry the same compliance at mid-stroke."""
    out = []
    vals = diag.final.values()
    E = vals.get("screw_modulus")
    pl = diag.plant
    if E is None or 0.9 * pl.youngs_modulus <= E <= 1.1 * pl.youngs_modulus:
        return out
    x = pl.start_offset + 0.5 * pl.stroke
    dc = x / (E * pl.area) - x / (pl.youngs_modulus * pl.area)  # extra compliance the modulus absorbs [m/N]
    side = "softer" if dc > 0 else "stiffer"
    text = (f"the screw modulus fitted at {E / 1e9:.0f} GPa (steel {pl.youngs_modulus / 1e9:.0f} GPa) makes the chain "
            f"{abs(dc) * 1e9:.2f} um/kN {side} at mid-stroke; the same would follow from")
    alts = []
    for name, k in (("the support bearing set", pl.k_bearing), ("the nut", pl.k_nut)):
        c_new = 1.0 / k + dc
        if c_new > 0:
            alts.append(f"{name} at {1.0 / c_new / 1e6:,.0f} N/um instead of its catalog {k / 1e6:,.0f} N/um")
    alts.append("an unlisted compliance (housing, nut bracket, coupling) of "
                f"{1.0 / abs(dc) / 1e6:,.0f} N/um in series" if dc > 0 else "a stiffer structure than modelled")
    out.append(text + " " + "; or ".join(alts) + " (test: --effects compliance_offset)")
    return out


def quantity_notes(diag) -> list:
    """How a measured quantity was converted for the model (torque data are fitted as force at the table)."""
    out = []
    pl = diag.plant
    for o in diag.obs:
        if o.kind == "friction" and "drag_torque" in o.dataset.columns:
            out.append(f"{Path(o.dataset.source).name}: drag torque T fitted as table force F = 2 pi eta T / l "
                       f"(lead l = {pl.lead * 1e3:g} mm, screw efficiency eta = {pl.efficiency:g}, the "
                       f"model's value); forces below are also given as screw torque T = F l / (2 pi eta)")
    return out


def frf_peak(freq, mag):
    """Peak frequency of a sampled magnitude, refined by a parabola through the top three points in
    log-frequency.  Repeated readings at one frequency count once, with their largest magnitude."""
    freq, mag = np.asarray(freq, dtype=float), np.asarray(mag, dtype=float)
    u, inv = np.unique(freq, return_inverse=True)
    m = np.full(len(u), -np.inf)
    np.maximum.at(m, inv, mag)
    freq, mag = u, m
    i = int(np.argmax(mag))
    if 0 < i < len(mag) - 1 and np.all(freq[i - 1:i + 2] > 0) and np.all(mag[i - 1:i + 2] > 0):
        x = np.log(freq[i - 1:i + 2])
        y = np.log(mag[i - 1:i + 2])
        den = (x[0] - x[1]) * (x[0] - x[2]) * (x[1] - x[2])
        a = (x[2] * (y[1] - y[0]) + x[1] * (y[0] - y[2]) + x[0] * (y[2] - y[1])) / den
        b = (x[2] ** 2 * (y[0] - y[1]) + x[1] ** 2 * (y[2] - y[0]) + x[0] ** 2 * (y[1] - y[2])) / den
        if a < 0 and np.isfinite(b / a):
            return float(np.exp(-b / (2 * a)))
    return float(freq[i])


def frf_modes(diag) -> list:
    """Frequency-response data, by position: the measured resonance (peak of |G|) and |G| there, the
    baseline's and the final model's resonance, the fitted damping of the axial mode and any extra mode."""
    out = []
    vals = diag.final.values()
    for o, yb, yf in zip(diag.obs, _split(diag.obs, diag.baseline.prediction),
                         _split(diag.obs, diag.final.prediction)):
        if o.kind != "frf":
            continue
        n = o.n // 2
        pos = o.dataset.columns["position"]
        freq = o.Z[1, :n] / (2 * math.pi)

        def mag(y, n=n):
            return np.hypot(y[:n], y[n:])
        for p in np.unique(pos):
            sel = np.nonzero(pos == p)[0]
            sel = sel[np.argsort(freq[sel])]
            out.append({
                "file": o.dataset.source, "position_mm": float(p) * 1e3,
                "measured_peak_Hz": frf_peak(freq[sel], mag(o.y)[sel]),
                "measured_peak_um_per_N": float(np.max(mag(o.y)[sel])) * 1e6,
                "baseline_peak_Hz": frf_peak(freq[sel], mag(yb)[sel]),
                "model_peak_Hz": frf_peak(freq[sel], mag(yf)[sel]),
                "damping_ratio": vals.get("damping_ratio"),
                "extra_mode_Hz": vals.get("mode_frequency"), "extra_mode_damping": vals.get("mode_damping"),
            })
    return out


def data_notes(o) -> list:
    """What looks odd in the measured column itself: three or more consecutive identical readings (a held
    or copied value) are named with their lines; they are kept in the fit."""
    from ..identify.tables.measure import MEASURED_COLUMNS

    out = []
    for col in MEASURED_COLUMNS.get(o.kind, ()):
        v = o.dataset.columns.get(col)
        if v is None or len(v) < 3:
            continue
        i = 0
        while i < len(v):
            j = i
            while j + 1 < len(v) and v[j + 1] == v[i]:
                j += 1
            if j - i >= 2:
                lines = o.dataset.lines
                out.append(f"{col} repeats the same value on {j - i + 1} consecutive rows (lines "
                           f"{int(lines[i])}-{int(lines[j])}): a held or copied reading? kept in the fit")
            i = j + 1
    return out


def _torque_of(diag):
    """N at the table -> N.m at the screw, when a friction dataset was given as torque (else None)."""
    pl = diag.plant
    if any(o.kind == "friction" and "drag_torque" in o.dataset.columns for o in diag.obs):
        return pl.lead / (2.0 * math.pi * pl.efficiency)
    return None


def diagnosis_text(diag) -> str:
    d = diagnosis_dict(diag)
    torque = _torque_of(diag)

    def _nm(value, unit):
        return f" (= {value * torque:.3g} N.m)" if torque is not None and unit == "N" else ""
    L = [f"diagnose: {d['design']}"]
    for ds in d["datasets"]:
        L.append(
            f"  {ds['test']:9s} {ds['file']}: {ds['rows']} rows, noise floor {ds['noise_floor']:.3g} "
            f"{ds['unit']}{_nm(ds['noise_floor'], ds['unit'])}, held-out groups by {ds['cv_groups']}"
        )
        L.append(f"    noise floor from {ds['noise_method']}")
        for note in ds["data_notes"]:
            L.append(f"    note: {note}")
        for ex in ds["excluded_rows"]:
            L.append(f"    excluded line {ex['line']}: {ex['reason']}")
    def ptext(p):
        t = f"{p['name']} = {p['text']}"
        if torque is not None and p["unit"] == "N":
            t += f" (= {p['value'] * torque:.4g} N.m at the screw)"
        return t
    for q in d["quantity"]:
        L.append(f"  {q}")
    if d["baseline"]["parameters"]:
        L.append("baseline fit: " + ", ".join(ptext(p) for p in d["baseline"]["parameters"]))
    else:
        L.append("baseline fit: no free parameter for these data (the design's own model, as catalogued)")
    for f in d["baseline"]["plausibility"]:
        L.append(f"  check: {f}")
    for ds, rows in zip(d["datasets"], d["residuals_baseline"]):
        if rows:
            L.append(f"misfit of the baseline ({ds['test']}), share of residual variance by factor:")
            for r in rows[:4]:
                L.append(
                    f"  {r['factor']:12s} {100 * r['eta2']:5.1f} %   worst {r['worst_level']} "
                    f"({r['worst_rms']:.3g} {r['unit']} rms; overall {r['rms']:.3g})"
                )
    for i, rnd in enumerate(d["candidates"], start=1):
        L.append(f"candidates, round {i} (dBIC vs current model; accept < -10 with held-out gain):")
        for c in rnd:
            cv = f"  held-out gain {c['cv_gain_percent']:.0f} %" if c["cv_gain_percent"] is not None else ""
            ps = ", ".join(f"{p['name']} = {p['text']}" for p in c["parameters"])
            L.append(f"  {c['effect']:24s} {c['dBIC']:9.1f}{cv}   {ps}")
    for r in d["not_accepted"]:
        if r["dBIC"] < -10:  # the others all fail on BIC, said once below
            L.append(f"not accepted (round {r['round']}): {r['effect']} (dBIC {r['dBIC']:.1f}): {r['reason']}")
    rest = sum(1 for r in d["not_accepted"] if r["dBIC"] >= -10)
    if rest:
        L.append(f"not accepted: {rest} more candidate{'s' if rest > 1 else ''} with dBIC not below -10")
    for e in d["pairs"]:
        if e["accepted"] or e["dBIC"] < -10:
            g = f", held-out gain {e['cv_gain_percent']:.0f} %" if e["cv_gain_percent"] is not None else ""
            L.append(f"pair (round {e['round']}): {' + '.join(e['effects'])} (dBIC {e['dBIC']:.1f}{g}): "
                     + ("accepted, neither passes alone" if e["accepted"] else e["reason"]))
    L.append(f"verdict: {d['verdict']}" + ("  (values of the final joint fit, as saved by --save-calibration)"
                                             if d["accepted"] else f" -- {_why_none(d)}"))
    for a in d["accepted"]:
        tog = f" (together with {a['together_with']}: neither passes alone)" if a["together_with"] else ""
        L.append(f"  {a['effect']}: {a['finding']}{tog}")
        for p in a["parameters"]:
            L.append(f"    {ptext(p)}  ({p['label']})")
        for f in a["plausibility"]:
            L.append(f"    check: {f}")
        ru = a["runner_up"]
        beat = f"; beat {ru['effect']} (dBIC {ru['dBIC']:.1f}, margin {ru['margin']:.1f})" if ru else ""
        L.append(f"    dBIC {a['dBIC']:.1f}, held-out gain {a['gain_percent']:.0f} %{beat}")
    if d["accepted"]:
        base_final = [p for p in d["final"]["parameters"]
                      if p["name"] not in diag.param_owner]
        if base_final:
            L.append("  with it, the baseline: " + ", ".join(ptext(p) for p in base_final))
    for f in d["final"]["plausibility"]:
        if not any(f in a["plausibility"] for a in d["accepted"]):
            L.append(f"  check: {f}")
    for e in d["other_explanations"]:
        L.append(f"  also consider: {e}")
    if d["frf_modes"]:
        L.append(f"resonance by position (peak of |G|){'measured':>15}{'|G| um/N':>10}{'baseline':>11}{'model':>10}"
                 f"{'damping':>9}")
        for m in d["frf_modes"]:
            z = "-" if m["damping_ratio"] is None else f"{100 * m['damping_ratio']:.2f} %"
            L.append(f"  at {m['position_mm']:6.0f} mm{'':>24}{m['measured_peak_Hz']:>12.1f} Hz"
                     f"{m['measured_peak_um_per_N']:>10.3g}{m['baseline_peak_Hz']:>8.1f} Hz"
                     f"{m['model_peak_Hz']:>7.1f} Hz{z:>9}")
        m = d["frf_modes"][0]
        if m["extra_mode_Hz"] is not None:
            L.append(f"  extra mode {m['extra_mode_Hz']:.1f} Hz, damping {100 * m['extra_mode_damping']:.2f} % "
                     "(all positions)")
    for u in d["unexplained"]:
        name = Path(u["file"]).name
        if u["remaining"]:
            L.append(f"unexplained ({name}): the residual keeps structure beyond noise (RMS {u['rms_over_noise']:.2g}x "
                     "the noise floor):")
            for sg in u["signatures"]:
                L.append(f"  - residual {sg['signature']}: {100 * sg['share']:.0f} % of the residual variance. "
                         f"Candidates: {sg['causes']}. To separate them: {sg['to_separate']}.")
        elif u["rms_over_noise"] >= 1.5:
            L.append(f"unexplained ({name}): the residual is {u['rms_over_noise']:.2g}x the noise floor, but no "
                     "recorded factor holds a significant share of it")
        else:
            L.append(f"residual ({name}): at the noise floor ({u['rms_over_noise']:.2g}x), no structure along the "
                     "recorded factors")
    for h in d["holdout_rmse_units"]:
        L.append(
            f"held-out RMSE {Path(h['file']).name}: {h['baseline']:.3g} -> {h['final']:.3g} {h['unit']} "
            f"(gain {h['gain_percent']:.0f} %)"
            + (f"; {h['baseline'] * torque:.3g} -> {h['final'] * torque:.3g} N.m at the screw"
               if torque is not None and h["unit"] == "N" else "")
        )
    return fit_lines("\n".join(L))


# SI factor -> (display unit, scale, offset) for residual plots
FACTOR_DISPLAY = {
    "position": ("mm", 1e3, 0.0), "force": ("N", 1.0, 0.0), "velocity": ("mm/s", 1e3, 0.0),
    "speed": ("mm/s", 1e3, 0.0), "time": ("s", 1.0, 0.0), "temperature": ("degC", 1.0, -273.15),
    "frequency": ("Hz", 1.0, 0.0), "normal_load": ("N", 1.0, 0.0), "axial_load": ("N", 1.0, 0.0),
}


CATEGORICAL = {"direction": {-1.0: "-1", 1.0: "+1"}, "cycle": {},
               "mode": {}, "exclude": {}}


def categories(name: str, values) -> list | None:
    """[(value, tick label), ...] when a factor is categorical (direction, cycle, mode, or at most three
    distinct values), else None (plotted on a continuous axis)."""
    u = np.unique(np.asarray(values, dtype=float))
    if name not in CATEGORICAL and len(u) > 3:
        return None
    names = CATEGORICAL.get(name, {})
    return [(float(x), names.get(float(x), f"{x:g}")) for x in u]


def residual_figures(diag, verdict: str):
    """Per observation of ``diag``: (observation, matplotlib Figure of its residuals, model - measured, against
    each recorded factor, before (baseline) and after (with ``verdict``)); a category factor one tick each."""
    from ..figure import (
        Figure,  # outside pyplot: no backend is chosen (a notebook's stays as it was)
    )

    before = _split(diag.obs, diag.baseline.prediction - diag.y)
    after = _split(diag.obs, diag.final.prediction - diag.y)
    for o, rb, ra in zip(diag.obs, before, after):
        facs = [(n, v) for n, v in o.factors.items() if np.ptp(v) > 0] or [("row", np.arange(o.n))]
        unit, f = Y_UNIT[o.kind]
        fig = Figure(figsize=(3.6 * len(facs), 3.2))
        axes = fig.subplots(1, len(facs), squeeze=False)
        for ax, (name, v) in zip(axes[0], facs):
            fu, fs, fo = FACTOR_DISPLAY.get(name, ("", 1.0, 0.0))
            v = np.asarray(v) * fs + fo
            cats = categories(name, v)
            if cats is None:
                ax.plot(v, rb * f, ".", ms=3, alpha=0.6, label="baseline")
                ax.plot(v, ra * f, ".", ms=3, alpha=0.8, label=f"with {verdict}")
            else:  # a category per tick, baseline left and extended model right of it, points spread
                jit = np.random.default_rng(0).uniform(-0.08, 0.08, len(v))
                pos = np.searchsorted([c for c, _ in cats], v).astype(float)
                ax.plot(pos - 0.18 + jit, rb * f, ".", ms=3, alpha=0.6, label="baseline")
                ax.plot(pos + 0.18 + jit, ra * f, ".", ms=3, alpha=0.8, label=f"with {verdict}")
                ax.set_xticks(range(len(cats)), [lab for _, lab in cats])
                ax.set_xlim(-0.6, len(cats) - 0.4)
            ax.axhline(0.0, color="k", lw=0.5)
            ax.set_xlabel(f"{name} [{fu}]" if fu else name)
            ax.set_ylabel(f"model - measured [{unit}]")
        axes[0][0].legend(fontsize=7)
        tidy_layout(fig)
        yield o, fig


def write_report(diag, outdir) -> Path:
    """Markdown report with residual plots before/after; returns the report path."""
    from . import make_output_dir

    out = make_output_dir(outdir)
    d = diagnosis_dict(diag)
    md = [f"# Diagnosis of {d['design']}", "", f"**Verdict: {d['verdict']}**", ""]
    for a in d["accepted"]:
        md.append(
            f"- **{a['effect']}** — {a['finding']}. "
            + "; ".join(f"{p['name']} = {p['text']}" for p in a["parameters"])
            + f". dBIC {a['dBIC']:.1f}, held-out gain {a['gain_percent']:.0f} %"
            + (
                f", beat {a['runner_up']['effect']} by {a['runner_up']['margin']:.1f} BIC"
                if a["runner_up"]
                else ""
            )
        )
        md += [f"  - check: {f}" for f in a["plausibility"]]
    md += ["", "## Data", ""]
    for ds in d["datasets"]:
        md.append(
            f"- `{ds['file']}` ({ds['test']}): {ds['rows']} rows, noise floor {ds['noise_floor']:.3g} "
            f"{ds['unit']}; cross-validation leaves one {ds['cv_groups']} out"
        )
        md += [f"  - excluded line {e['line']}: {e['reason']}" for e in ds["excluded_rows"]]
    md += ["", "## Baseline fit", "", "| parameter | value |", "|---|---|"]
    md += [f"| {p['name']} | {p['text']} |" for p in d["baseline"]["parameters"]]
    md += [f"\ncheck: {f}" for f in d["baseline"]["plausibility"]]
    md += ["", "## Where the baseline misfits", ""]
    for ds, rows in zip(d["datasets"], d["residuals_baseline"]):
        md += [
            f"`{Path(ds['file']).name}`",
            "",
            "| factor | share of residual variance | worst level | rms there |",
            "|---|---|---|---|",
        ]
        md += [
            f"| {r['factor']} | {100 * r['eta2']:.1f} % | {r['worst_level']} "
            f"| {r['worst_rms']:.3g} {r['unit']} |"
            for r in rows
        ]
        md.append("")
    md += ["## Candidates", ""]
    for i, rnd in enumerate(d["candidates"], start=1):
        md += [f"Round {i}", "", "| effect | dBIC | held-out gain | parameters |", "|---|---|---|---|"]
        for c in rnd:
            g = f"{c['cv_gain_percent']:.0f} %" if c["cv_gain_percent"] is not None else "-"
            md.append(
                f"| {c['effect']} | {c['dBIC']:.1f} | {g} | "
                + "; ".join(f"{p['name']} = {p['text']}" for p in c["parameters"])
                + " |"
            )
        md.append("")
    md += ["## Gain", "", "| data | held-out RMSE before | after | gain |", "|---|---|---|---|"]
    md += [
        f"| {Path(h['file']).name} | {h['baseline']:.4g} {h['unit']} | {h['final']:.4g} {h['unit']} | "
        f"{h['gain_percent']:.0f} % |"
        for h in d["holdout_rmse_units"]
    ]
    md += [
        "",
        f"Gain {d['gain_percent']:.0f} % (grouped cross-validation, noise-weighted RMSE "
        f"{d['holdout_rmse_baseline']:.3g} -> {d['holdout_rmse_final']:.3g}; about 1 is the noise floor).",
        "",
    ]
    md += ["## What the final fit leaves", ""]
    for u in d["unexplained"]:
        name = Path(u["file"]).name
        if u["remaining"]:
            md.append(f"- `{name}`: **unexplained** structure (RMS {u['rms_over_noise']:.2g}x the noise floor)")
            md += [f"  - residual {sg['signature']}: {100 * sg['share']:.0f} % of the residual variance. Candidates: "
                   f"{sg['causes']}. To separate them: {sg['to_separate']}." for sg in u["signatures"]]
        else:
            md.append(f"- `{name}`: RMS {u['rms_over_noise']:.2g}x the noise floor, no structure along a recorded "
                      "factor")
    md += ["", "## Residual plots", ""]
    for k, (o, fig) in enumerate(residual_figures(diag, d["verdict"])):
        png = out / f"residuals_{k + 1}.png"
        save_figure(fig, png, dpi=90)
        md += [f"![residuals {Path(o.dataset.source).name}]({png.name})", ""]
    path = out / "report.md"
    write_text_atomic(path, "\n".join(md) + "\n", what="report")
    return path

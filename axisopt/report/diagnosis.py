"""Diagnosis output (:class:`axisopt.identify.tables.diagnose.Diagnosis`): JSON-ready dict, console
text, Markdown report with residual plots (Agg).  Nothing here prints."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..identify.tables.diagnose import param_rows, plausibility
from ..identify.tables.diagnose import split_by_observation as _split
from ..identify.tables.measure import Y_UNIT
from ..identify.tables.unexplained import residual_table
from .diagexplain import (
    other_explanations,
    plausibility_flags,
    undetermined_notes,
    unexplained_dicts,
    unidentifiable,
    why_none,
)
from .text import fit_lines, wrap_words


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
            "plausibility": plausibility_flags(diag.baseline),
        },
        "residuals_baseline": [
            residual_table(o, r)
            for o, r in zip(diag.obs, _split(diag.obs, diag.baseline.prediction - diag.y))
        ],
        "residuals_final": [
            residual_table(o, r)
            for o, r in zip(diag.obs, _split(diag.obs, diag.final.prediction - diag.y))
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
        "equivalent": [
            {
                "round": k,
                "named": a,
                "alternative": b,
                "percent_apart": apart,
                "text": equivalent_text(a, b, apart, eff, floor),
            }
            for k, a, b, apart, eff, floor in diag.equivalent
        ],
        "regime": list(diag.regime),
        "accepted": [],
        "holdout_rmse_baseline": diag.cv_baseline,
        "holdout_rmse_final": diag.cv_final,
        "gain_percent": diag.gain,
        "holdout_rmse_units": [
            {"file": o.dataset.source, "baseline": b, "final": a, "unit": u, "gain_percent": g}
            for (o, b, u), (_, a, _), g in zip(
                _rmse_units(diag, diag.holdout_baseline),
                _rmse_units(diag, diag.holdout_final),
                _file_gains(diag),
            )
        ],
        "final": {
            "parameters": param_rows(diag.final),
            "status": diag.final.status,
            "plausibility": plausibility(diag.final, []) + unidentifiable(diag.final),
        },
        "rejected": [
            {
                "round": rnd,
                "effect": c.effect.name,
                "dBIC": c.dbic,
                "would_need": bad,
                "parameters": param_rows(c.fit, c.names),
            }
            for rnd, c, bad in diag.rejected
        ],
        "not_accepted": [
            {
                "round": i,
                "effect": c.effect.name,
                "dBIC": c.dbic,
                "cv_gain_percent": c.cv_gain,
                "reason": c.reason,
            }
            for i, rnd in enumerate(diag.rounds, start=1)
            for c in rnd
            if c.reason
        ],
        "pairs": [
            {
                "round": e["round"],
                "effects": [e["a"].effect.name, e["b"].effect.name],
                "dBIC": e["dbic"],
                "cv_gain_percent": e["gain"],
                "accepted": not e["reason"],
                "reason": e["reason"],
            }
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
                # the numbers of the final joint fit (the one --save-calibration writes), not of the
                # round in which the effect was accepted
                "finding": a.effect.describe(diag.final.values(), diag.plant),
                "parameters": param_rows(diag.final, names),
                "dBIC": a.dbic,
                "cv_rmse_before": a.cv_before,
                "cv_rmse_after": a.cv_after,
                "gain_percent": a.gain,
                "together_with": a.together or None,
                "plausibility": plausibility(diag.final, [], names=names)
                + undetermined_notes(diag.final, names)
                + unidentifiable(diag.final, names),
                "runner_up": None
                if r is None
                else {"effect": r.effect.name, "dBIC": r.dbic, "margin": r.dbic - a.dbic},
            }
        )
    return d


def _file_gains(diag) -> list:
    """Held-out gain of each file [%]: the noise-weighted held-out RMSE of its own rows, baseline
    against final (the pooled gain weighs every file together)."""
    out = []
    for o, pb, pf in zip(
        diag.obs, _split(diag.obs, diag.holdout_baseline), _split(diag.obs, diag.holdout_final)
    ):
        rb = float(np.sqrt(np.mean(((pb - o.y) * o.w) ** 2)))
        rf = float(np.sqrt(np.mean(((pf - o.y) * o.w) ** 2)))
        out.append(100.0 * (1.0 - rf / rb) if rb > 0 else 0.0)
    return out


def quantity_notes(diag) -> list:
    """How a measured quantity was converted for the model (torque data are fitted as force at the
    table)."""
    out = []
    pl = diag.plant
    for o in diag.obs:
        if o.kind == "friction" and "drag_torque" in o.dataset.columns:
            out.append(
                f"{Path(o.dataset.source).name}: drag torque T fitted as table force F = 2 pi eta "
                f"T / l (lead l = {pl.lead * 1e3:g} mm, screw efficiency eta = {pl.efficiency:g}, "
                "the model's value); forces below are also given as screw torque T = F l / (2 pi "
                "eta)"
            )
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
    if 0 < i < len(mag) - 1 and np.all(freq[i - 1 : i + 2] > 0) and np.all(mag[i - 1 : i + 2] > 0):
        x = np.log(freq[i - 1 : i + 2])
        y = np.log(mag[i - 1 : i + 2])
        den = (x[0] - x[1]) * (x[0] - x[2]) * (x[1] - x[2])
        a = (x[2] * (y[1] - y[0]) + x[1] * (y[0] - y[2]) + x[0] * (y[2] - y[1])) / den
        b = (
            x[2] ** 2 * (y[0] - y[1]) + x[1] ** 2 * (y[2] - y[0]) + x[0] ** 2 * (y[1] - y[2])
        ) / den
        if a < 0 and np.isfinite(b / a):
            return float(np.exp(-b / (2 * a)))
    return float(freq[i])


def frf_modes(diag) -> list:
    """Frequency-response data, by position: the measured resonance (peak of |G|) and |G| there, the
    baseline's and the final model's resonance, the fitted damping of the axial mode and any extra
    mode."""
    out = []
    vals = diag.final.values()
    for o, yb, yf in zip(
        diag.obs,
        _split(diag.obs, diag.baseline.prediction),
        _split(diag.obs, diag.final.prediction),
    ):
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
            out.append(
                {
                    "file": o.dataset.source,
                    "position_mm": float(p) * 1e3,
                    "measured_peak_Hz": frf_peak(freq[sel], mag(o.y)[sel]),
                    "measured_peak_um_per_N": float(np.max(mag(o.y)[sel])) * 1e6,
                    "baseline_peak_Hz": frf_peak(freq[sel], mag(yb)[sel]),
                    "model_peak_Hz": frf_peak(freq[sel], mag(yf)[sel]),
                    "damping_ratio": vals.get("damping_ratio"),
                    "extra_mode_Hz": vals.get("mode_frequency"),
                    "extra_mode_damping": vals.get("mode_damping"),
                }
            )
    return out


def data_notes(o) -> list:
    """What looks odd in the measured column itself: three or more consecutive identical readings (a
    held or copied value) are named with their lines; they are kept in the fit."""
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
                out.append(
                    f"{col} repeats the same value on {j - i + 1} consecutive rows (lines "
                    f"{int(lines[i])}-{int(lines[j])}): a held or copied reading? kept in the fit"
                )
            i = j + 1
    return out


def _torque_of(diag):
    """N at the table -> N.m at the screw, when a friction dataset was given as torque (else
    None)."""
    pl = diag.plant
    if any(o.kind == "friction" and "drag_torque" in o.dataset.columns for o in diag.obs):
        return pl.lead / (2.0 * math.pi * pl.efficiency)
    return None


def equivalent_text(a: str, b: str, apart: float, effects, floor) -> str:
    """Two explanations of a table (effects or pairs) the held-out data do not tell apart, and what
    would;
    ``floor``: their held-out RMSE in noise floors when both are at it (else None: within the
    resolution)."""
    from ..identify.selection import TABLE_RULE

    ev = "; ".join(
        f"for {e.name}, "
        f"{getattr(e.time, 'evidence', '') or e.evidence or 'a test that shows it alone'}"
        for e in dict.fromkeys(effects)
    )
    why = (
        f"within the rule's {TABLE_RULE.resolution:g} % resolution"
        if floor is None
        else f"both at the noise floor ({floor[0]:.2f}x and {floor[1]:.2f}x)"
    )
    return (
        f"{a} and {b} explain the data equally well: held-out RMSE {apart:.2f} % apart, {why}; {a} "
        "is named for its lower dBIC, not because the data tell them apart. To separate them: "
        f"{ev}."
    )


def diagnosis_text(diag) -> str:
    d = diagnosis_dict(diag)
    torque = _torque_of(diag)

    def _nm(value, unit):
        return f" (= {value * torque:.3g} N.m)" if torque is not None and unit == "N" else ""

    L = [f"diagnose: {d['design']}"]
    for ds in d["datasets"]:
        L.append(
            f"  {ds['test']:9s} {ds['file']}: {ds['rows']} rows, noise floor "
            f"{ds['noise_floor']:.3g} {ds['unit']}{_nm(ds['noise_floor'], ds['unit'])}, held-out "
            f"groups by {ds['cv_groups']}"
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
        L.append(
            "baseline fit: no free parameter for these data (the design's own model, as catalogued)"
        )
    for f in d["baseline"]["plausibility"]:
        L.append(f"  check: {f}")
    for ds, rows in zip(d["datasets"], d["residuals_baseline"]):
        if rows:
            L.append(
                f"misfit of the baseline ({ds['test']}), share of residual variance by factor:"
            )
            for r in rows[:4]:
                L.append(
                    f"  {r['factor']:12s} {100 * r['eta2']:5.1f} %   worst {r['worst_level']} "
                    f"({r['worst_rms']:.3g} {r['unit']} rms; overall {r['rms']:.3g})"
                )
    for i, rnd in enumerate(d["candidates"], start=1):
        L.append(f"candidates, round {i} (dBIC vs current model; accept < -10 with held-out gain):")
        for c in rnd:
            cv = (
                f"  held-out gain {c['cv_gain_percent']:.0f} %"
                if c["cv_gain_percent"] is not None
                else ""
            )
            ps = ", ".join(f"{p['name']} = {p['text']}" for p in c["parameters"])
            L.append(f"  {c['effect']:24s} {c['dBIC']:9.1f}{cv}   {ps}")
    for r in d["not_accepted"]:
        if r["dBIC"] < -10:  # the others all fail on BIC, said once below
            L.append(
                f"not accepted (round {r['round']}): {r['effect']} (dBIC {r['dBIC']:.1f}): "
                f"{r['reason']}"
            )
    rest = sum(1 for r in d["not_accepted"] if r["dBIC"] >= -10)
    if rest:
        L.append(
            f"not accepted: {rest} more candidate{'s' if rest > 1 else ''} with dBIC not below -10"
        )
    for e in d["pairs"]:
        if e["accepted"] or e["dBIC"] < -10:
            g = (
                f", held-out gain {e['cv_gain_percent']:.0f} %"
                if e["cv_gain_percent"] is not None
                else ""
            )
            L.append(
                f"pair (round {e['round']}): {' + '.join(e['effects'])} (dBIC {e['dBIC']:.1f}{g}): "
                + ("accepted, neither passes alone" if e["accepted"] else e["reason"])
            )
    L.append(
        f"verdict: {d['verdict']}"
        + (
            "  (values of the final joint fit, as saved by --save-calibration)"
            if d["accepted"]
            else f" -- {why_none(d)}"
        )
    )
    for a in d["accepted"]:
        tog = (
            f" (together with {a['together_with']}: neither passes alone)"
            if a["together_with"]
            else ""
        )
        L.append(f"  {a['effect']}: {a['finding']}{tog}")
        for p in a["parameters"]:
            L.append(f"    {ptext(p)}  ({p['label']})")
        for f in a["plausibility"]:
            L.append(f"    check: {f}")
        ru = a["runner_up"]
        beat = (
            f"; beat {ru['effect']} (dBIC {ru['dBIC']:.1f}, margin {ru['margin']:.1f})"
            if ru
            else ""
        )
        L.append(f"    dBIC {a['dBIC']:.1f}, held-out gain {a['gain_percent']:.0f} %{beat}")
    if d["accepted"]:
        base_final = [p for p in d["final"]["parameters"] if p["name"] not in diag.param_owner]
        if base_final:
            L.append("  with it, the baseline: " + ", ".join(ptext(p) for p in base_final))
    for f in d["final"]["plausibility"]:
        if not any(f in a["plausibility"] for a in d["accepted"]):
            L.append(f"  check: {f}")
    for e in d["other_explanations"]:
        L.append(f"  also consider: {e}")
    for f in d["regime"]:
        L.append(f"  ! {f}")
    for e in d["equivalent"]:
        L += wrap_words("~ " + e["text"], indent="  ", cont="      ")
    if d["frf_modes"]:
        L.append(
            "resonance by position (peak of "
            f"|G|){'measured':>15}{'|G| um/N':>10}{'baseline':>11}{'model':>10}"
            f"{'damping':>9}"
        )
        for m in d["frf_modes"]:
            z = "-" if m["damping_ratio"] is None else f"{100 * m['damping_ratio']:.2f} %"
            L.append(
                f"  at {m['position_mm']:6.0f} mm{'':>24}{m['measured_peak_Hz']:>12.1f} Hz"
                f"{m['measured_peak_um_per_N']:>10.3g}{m['baseline_peak_Hz']:>8.1f} Hz"
                f"{m['model_peak_Hz']:>7.1f} Hz{z:>9}"
            )
        m = d["frf_modes"][0]
        if m["extra_mode_Hz"] is not None:
            L.append(
                f"  extra mode {m['extra_mode_Hz']:.1f} Hz, damping "
                f"{100 * m['extra_mode_damping']:.2f} % (all positions)"
            )
    for u in d["unexplained"]:
        name = Path(u["file"]).name
        if u["remaining"]:
            L.append(
                f"unexplained ({name}): the residual keeps structure beyond noise (RMS "
                f"{u['rms_over_noise']:.2g}x the noise floor):"
            )
            for sg in u["signatures"]:
                L.append(
                    f"  - residual {sg['signature']}: {100 * sg['share']:.0f} % of the residual "
                    f"variance. Candidates: {sg['causes']}. To separate them: {sg['to_separate']}."
                )
        elif u["rms_over_noise"] >= 1.5:
            L.append(
                f"unexplained ({name}): the residual is {u['rms_over_noise']:.2g}x the noise "
                "floor, but no recorded factor holds a significant share of it"
            )
        else:
            L.append(
                f"residual ({name}): at the noise floor ({u['rms_over_noise']:.2g}x), no structure "
                "along the recorded factors"
            )
    for h in d["holdout_rmse_units"]:
        L.append(
            f"held-out RMSE {Path(h['file']).name}: {h['baseline']:.3g} -> {h['final']:.3g} "
            f"{h['unit']} (gain {h['gain_percent']:.0f} %)"
            + (
                f"; {h['baseline'] * torque:.3g} -> {h['final'] * torque:.3g} N.m at the screw"
                if torque is not None and h["unit"] == "N"
                else ""
            )
        )
    return fit_lines("\n".join(L))

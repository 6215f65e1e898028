r"""Independent check of a rack-and-pinion or linear-motor axis by the vendors' printed selection
steps (issue 54).  Nothing here imports ``axisopt``: the problem is solved by the program
(``python -m axisopt solve P.yaml --json``), the chosen parts' rows are read straight from
``catalogs/*.csv`` (units from the headers), the axis from the problem's YAML, and every number is
recomputed here: the duty cycle sampled in time (trapezoidal moves; no jerk), the forces and torques
at each sample, peak and RMS from the samples.

Usage::

    python tools/vendor_check_drives.py problems/router_rack_problem.yaml
    python tools/vendor_check_drives.py problems/laser_lm_problem.yaml

Procedures: THK General Catalog A-241 (GSR-R "Checking Strength": thrust <= capacity / overload
factor);
Apex Dynamics rack sizing (F = m g mu + m a + F; T = F d / 2); Yaskawa Sigma-7 11.2.4 (rack load
torque, RMS torque); Beckhoff AG2400 (T2B, T2N, n1Max); HIWIN MM99TE07-1701 Appendix A (Fp, Fe,
Ie/Ic <= 0.7, peak for about 1 s, the attraction on the guides); THK LM Guide nominal life (C / (fw
P))^3 x 50 km, static safety C0 / P; THK A-704 Table 19 for fw.  Conventions shared with axisopt on
purpose (no vendor number; printed as CONV): the twin pinion's bias (15 % of the peak feed force per
pinion, half the feed force each), a motor without a catalog mass (2 kg + 0.7 kg per N m rated), an
iron-core motor without a listed attraction force (5 x its continuous force), the blocks evenly
loaded (centred load).  Exit 0: every check passes.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
G = 9.80665
UNITS = {
    "mm": 1e-3,
    "m": 1.0,
    "um": 1e-6,
    "kN": 1e3,
    "N": 1.0,
    "kg": 1.0,
    "EUR": 1.0,
    "EUR/m": 1.0,
    "kg/m": 1.0,
    "kg.cm^2": 1e-4,
    "N.m": 1.0,
    "rpm": 2 * math.pi / 60,
    "%": 0.01,
    "arcmin": math.pi / 180 / 60,
    "N.m/arcmin": 180 * 60 / math.pi,
    "N/um": 1e6,
    "km": 1e3,
    "N/A": 1.0,
    "A": 1.0,
    "deg": math.pi / 180,
    "-": 1.0,
    "W": 1.0,
    "N.s/m": 1.0,
}
QTY = {
    "mm": 1e-3,
    "m": 1.0,
    "kg": 1.0,
    "N": 1.0,
    "kN": 1e3,
    "m/min": 1 / 60,
    "m/s^2": 1.0,
    "s": 1.0,
    "h": 3600.0,
    "EUR": 1.0,
    "um": 1e-6,
    "N/um": 1e6,
    "Hz": 1.0,
    "m/s^3": 1.0,
}


def rows(table: str) -> dict:
    """A catalog CSV as {id: {column: SI value or text}}."""
    with open(ROOT / "catalogs" / f"{table}.csv", encoding="utf-8") as fh:
        reader = csv.reader(fh)
        head = next(reader)
        cols = []
        for h in head:
            name, _, unit = h.partition(" [")
            cols.append((name, UNITS[unit[:-1]] if unit else None))
        out = {}
        for r in reader:
            d = {}
            for (name, f), cell in zip(cols, r):
                d[name] = (float(cell) * f if cell else None) if f is not None else cell
            out[d["id"]] = d
    return out


def qty(text) -> float:
    if isinstance(text, (int, float)):
        return float(text)
    value, unit = str(text).split(maxsplit=1)
    return float(value) * QTY[unit.strip()]


def accel_times(v: float, a: float, jerk: float | None) -> tuple:
    """(t_j, t_a, a_peak) of one speed change from rest to ``v``: a trapezoid (t_j 0) without a
    jerk; with one, the jerk ramps a/j either side of the constant-acceleration stretch, or, where v
    < a^2/j, two ramps to sqrt(v j) (the S-curve every servo controller runs; written here from the
    kinematics alone)."""
    if not jerk:
        return 0.0, v / a, a
    if v >= a * a / jerk:
        return a / jerk, v / a - a / jerk, a
    ap = math.sqrt(v * jerk)
    return ap / jerk, 0.0, ap


def move_profile(d: float, v: float, a: float, jerk: float | None) -> tuple:
    """(v, t_j, t_a, a_peak, t_cruise) of a move of length ``d`` at most at speed ``v``: the speed
    lowered by bisection where the move is too short to reach it (the speed change covers v (t_a + 2
    t_j) / 2 each way)."""

    def span(x):
        tj, ta, _ = accel_times(x, a, jerk)
        return x * (ta + 2 * tj)

    if span(v) > d:
        lo, hi = 0.0, v
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if span(mid) <= d else (lo, mid)
        v = lo
    tj, ta, ap = accel_times(v, a, jerk)
    return v, tj, ta, ap, max(0.0, (d - span(v)) / v)


def _ramp(dt: float, tj: float, ta: float, ap: float) -> list:
    """Accelerations of one speed change sampled every ``dt``: up at the jerk, hold, down
    (trapezoid: hold)."""
    out = []
    t_end = ta + 2 * tj
    n = max(1, round(t_end / dt))
    step = t_end / n
    for k in range(n):
        t = (k + 0.5) * step
        if tj > 0 and t < tj:
            out.append((step, ap * t / tj))
        elif tj > 0 and t > tj + ta:
            out.append((step, ap * (t_end - t) / tj))
        else:
            out.append((step, ap))
    return out


def profile(axis: dict) -> list:
    """(duration, acceleration, direction, process force) samples of the duty cycle, dt = 0.2 ms;
    without a duty cycle the rapid move over the stroke and back.  Moves are trapezoids, or S-curves
    where the axis (or the move) gives a jerk (:func:`move_profile`).  The cutting force acts
    at feed: the steady thrust (:func:`check`), as Yaskawa's selection adds the load torque of the
    feed."""
    a = qty(axis["acceleration"])
    vmax = qty(axis["max_speed"])
    jerk_axis = qty(axis["jerk"]) if "jerk" in axis else None
    cycle = axis.get("duty_cycle") or [
        {"move": axis["stroke"]},
        {"move": "-" + str(axis["stroke"])},
    ]
    dt = 2e-4
    out = []
    for seg in cycle:
        if "dwell" in seg:
            n = max(1, round(qty(seg["dwell"]) / dt))
            out += [(dt, 0.0, 0.0, 0.0)] * n
            continue
        dist = qty(seg["move"])
        force = qty(seg.get("force", 0))  # a move's own process force (the rapids have none)
        v = qty(seg.get("speed", vmax * 60)) if "speed" in seg else vmax
        acc = qty(seg["acceleration"]) if "acceleration" in seg else a
        jerk = qty(seg["jerk"]) if "jerk" in seg else jerk_axis
        s = 1.0 if dist > 0 else -1.0
        v, tj, ta, ap, t_cruise = move_profile(abs(dist), v, acc, jerk)
        ramp = _ramp(dt, tj, ta, ap)
        out += [(h, s * x, s, force) for h, x in ramp]
        out += [(dt, 0.0, s, force)] * max(0, round(t_cruise / dt))
        out += [(h, -s * x, s, force) for h, x in ramp]
    return out


def peak_rms(samples, fn):
    vals = [(dt, fn(acc, s, q)) for dt, acc, s, q in samples]
    total = sum(dt for dt, _ in vals)
    return max(abs(v) for _, v in vals), math.sqrt(sum(dt * v * v for dt, v in vals) / total)


def _speeds(samples):
    """(dt, speed) of the samples, the speed integrated from the accelerations (each move starts at
    rest)."""
    v = 0.0
    for dt, acc, s, _ in samples:
        v = v + acc * dt if s != 0 else 0.0
        yield dt, v


def fw_thk(v: float) -> float:
    """THK A-704 Table 19, the upper end of the row of the top speed (m/s)."""
    return 1.2 if v <= 0.25 else 1.5 if v <= 1.0 else 2.0 if v <= 2.0 else 3.5


def check(problem: Path, res: dict | None = None) -> tuple[list, dict]:
    """(rows, the solve's JSON) of ``problem``'s optimum; ``res``: that JSON where the caller has
    solved it."""
    if res is not None:
        return _check(problem, res)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "r.json"
        subprocess.run(
            [
                sys.executable,
                "-m",
                "axisopt",
                "solve",
                str(problem),
                "--json",
                str(out),
                "--top",
                "1",
            ],
            check=False,
            capture_output=True,
        )
        res = json.loads(out.read_text(encoding="utf-8"))
    return _check(problem, res)


def _check(problem: Path, res: dict) -> tuple[list, dict]:
    best = res["best"]
    if best is None:
        return [], res
    doc = yaml.safe_load(problem.read_text(encoding="utf-8"))
    axis = doc["axis"]
    tw = axis.get("twin_drive")
    sides = 2 if tw else 1
    share = 0.5 + 0.5 * qty(tw["cross_stroke"]) / qty(tw["span"]) if tw else 1.0
    bridge = qty(axis["moving_mass"])
    m_axis = bridge / sides + (share * qty(tw.get("cross_mass", 0)) if tw else 0.0)
    blocks = 4 / sides
    guide = rows("guides")[best["parts"]["guide"]]
    samples = [(dt, acc, s, q * share) for dt, acc, s, q in profile(axis)]
    vmax = qty(axis["max_speed"])
    normal = qty(axis.get("normal_load", 0)) * share
    thrust = qty(axis.get("axial_load", 0)) * share  # the feed force at feed, this side's share
    mean_thrust = qty(axis.get("mean_axial_load", thrust / share / 3)) * share
    if "mean_speed" in axis:
        mean = qty(axis["mean_speed"])
    else:  # the cycle's travel over its time
        mean = sum(dt * abs(vel) for dt, vel in _speeds(samples)) / sum(dt for dt, *_ in samples)
    life_needed = qty(axis.get("required_life", "20000 h")) * mean
    lines = []

    def add(name, value, limit, margin_needed, model_key, sense="<="):
        margin = limit / value if sense == "<=" else value / limit
        model = best["margins"].get(model_key) if model_key else None
        ratio = (model / margin) if model else float("nan")
        ok = margin >= margin_needed * (1 - 1e-9)
        # a vendor rule the model has no margin of its own for: this checker's alone
        agree = "ONLY" if model_key is None else "AGREE" if abs(ratio - 1) < 5e-3 else "DIFF"
        lines.append((name, value, limit, margin, "PASS" if ok else "FAIL", model, agree))

    if best["drive_type"] == "rack_pinion":
        rk = rows("racks")[best["parts"]["rack"]]
        red = rows("reductions")[best["parts"]["reduction"]]
        mot = rows("motors")[best["parts"]["motor"]]
        twin = best["parts"]["twin_pinion"] == "yes"
        pinions = 2 if twin else 1
        m_motor = mot["mass"] if mot["mass"] else 2.0 + 0.7 * mot["rated_torque"]  # CONV
        m = m_axis + blocks * guide["block_mass"] + pinions * (m_motor + red["mass"])
        friction = (
            guide["friction_coefficient"] * (m * G + normal) + blocks * guide["friction_force"]
        )
        f_peak, f_rms = peak_rms(samples, lambda acc, s, q: m * acc + s * (friction + q))
        f_peak, f_rms = max(f_peak, friction + thrust), max(f_rms, friction + mean_thrust)
        h = 0.5 if twin else 1.0
        bias = 0.15 * f_peak if twin else 0.0  # CONV
        tooth = h * f_peak + bias
        k_o = {"uniform": 1.0, "medium": 1.25, "large": 1.75}[
            doc["search"].get("rack_pinion", {}).get("overload", "medium")
        ]
        add(
            "pinion thrust (THK A-241) [N]",
            tooth,
            rk["permissible_force"] / k_o,
            1.0,
            "pinion_tooth",
        )
        r = rk["pitch_diameter"] / 2
        i, eta = red["ratio"], red["efficiency"]
        j = mot["rotor_inertia"] + red["inertia"]
        tm_peak, tm_rms = peak_rms(
            samples,
            lambda acc, s, q: j * acc * i / r + h * (m * acc + s * (friction + q)) * r / (i * eta),
        )
        tm_peak = max(tm_peak, h * (friction + thrust) * r / (i * eta)) + bias * r / (i * eta)
        tm_rms = max(tm_rms, h * (friction + mean_thrust) * r / (i * eta)) + bias * r / (i * eta)
        add("motor peak torque (Yaskawa) [N m]", tm_peak, mot["peak_torque"], 1.0, "motor_peak")
        add(
            "motor RMS torque (0.8 rated) [N m]",
            tm_rms,
            0.8 * mot["rated_torque"],
            1.0,
            "motor_rms",
        )
        n_motor = vmax / r * i
        add("motor speed [rad/s]", n_motor, mot["max_speed"], 1.0, "motor_speed")
        add("gearbox speed n1Max [rad/s]", n_motor, red["max_input_speed"], 1.0, "gearbox_speed")
        add("gearbox output T2B [N m]", tooth * r, red["accel_torque"], 1.0, "gearbox_peak")
        add(
            "gearbox output T2N [N m]",
            (h * f_rms + bias) * r,
            red["rated_torque"],
            1.0,
            "gearbox_rated",
        )
        add(
            "inertia ratio [-]",
            h * m * r * r / i / i / mot["rotor_inertia"],
            5.0,
            1.0,
            "inertia_ratio",
        )
        attraction = 0.0
    else:
        lm = rows("linear_motors")[best["parts"]["linear_motor"]]
        n = int(best["parts"]["forcers"])
        fa = (
            lm["attraction_force"]
            if lm["attraction_force"] is not None
            else (5.0 * lm["continuous_force"] if lm["kind"] == "iron-core" else 0.0)
        )  # CONV
        attraction = n * fa
        m = m_axis + blocks * guide["block_mass"] + n * lm["forcer_mass"]
        friction = (
            guide["friction_coefficient"] * (m * G + attraction + normal)
            + blocks * guide["friction_force"]
        )
        f_peak, f_rms = peak_rms(samples, lambda acc, s, q: m * acc + s * (friction + q))
        f_peak, f_rms = max(f_peak, friction + thrust), max(f_rms, friction + mean_thrust)
        add("peak force (HIWIN Fp) [N]", f_peak, n * lm["peak_force"], 1.0, "motor_peak")
        add(
            "effective force (HIWIN Fe <= 0.7 Fc) [N]",
            f_rms,
            0.7 * n * lm["continuous_force"],
            1.0,
            "motor_rms",
        )
        # the thermal rating itself: Fc holds at 20 degC ambient, 80 degC winding, 100 % duty; Ie
        # must stay below Ic (H-LMS definitions and Appendix A; the 0.7 above is HIWIN's advised
        # reserve)
        add(
            "effective force (HIWIN Fe <= Fc, thermal) [N]",
            f_rms,
            n * lm["continuous_force"],
            1.0,
            None,
        )
        if lm[
            "force_constant"
        ]:  # H-LMS Appendix A: Ip = Fp / Kf below the peak current, Ie below Ic
            kf = lm["force_constant"] * n  # each forcer carries 1/n: its own current
            add("peak current Ip = Fp / Kf [A]", f_peak / kf, lm["peak_current"], 1.0, None)
            add(
                "effective current Ie = Fe / Kf [A]",
                f_rms / kf,
                lm["continuous_current"],
                1.0,
                None,
            )
        t_acc, run = (
            0.0,
            0.0,
        )  # CONV: a reversal (braking into accelerating back) is one stretch at peak
        for dt, acc, _, _ in samples:
            run = run + dt if acc != 0.0 else 0.0
            t_acc = max(t_acc, run)
        if f_peak > n * lm["continuous_force"]:
            add("acceleration time at peak force (HIWIN ~1 s) [s]", t_acc, 1.0, 1.0, "peak_time")
    load = (m * G + normal + attraction) / blocks
    if (
        attraction > 0
    ):  # H-LMS: the attraction "must be taken up by the guide": in both guide rows below
        lines.append(
            (
                "magnet attraction on the guides [N]",
                attraction,
                float("nan"),
                float("nan"),
                "INFO",
                None,
                "CONV" if lm["attraction_force"] is None else "ONLY",
            )
        )
    fw = fw_thk(vmax)
    life = (guide["dynamic_load_rating"] / (fw * load)) ** (
        10 / 3 if guide["type"] == "roller" else 3
    ) * guide["rating_distance"]
    if life_needed > 0:
        add("guide L10 travel [m]", life, life_needed, 1.0, "guide_life", sense=">=")
    add(
        "guide static safety C0/P [-]",
        guide["static_load_rating"] / load,
        5.0,
        1.0,
        "guide_static",
        sense=">=",
    )
    return lines, res


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("problem")
    args = ap.parse_args(argv)
    lines, res = check(Path(args.problem))
    if not lines:
        print(f"no design: {res['status']}")
        return 1
    b = res["best"]
    print(f"{b['drive_type']}: " + ", ".join(f"{k} {v}" for k, v in b["parts"].items()))
    print(f"{'check':50s} {'value':>12s} {'limit':>12s} {'margin':>7s}       axisopt")
    for name, value, limit, margin, verdict, model, agree in lines:
        print(
            f"{name:50s} {value:12.4g} {limit:12.4g} {margin:7.3f} {verdict}  "
            f"{model or float('nan'):7.3f} {agree}"
        )
    return 0 if all(v in ("PASS", "INFO") for *_, v, _m, _a in lines) else 1


if __name__ == "__main__":
    sys.exit(main())

"""What a time-record diagnosis leaves unexplained, in words (text and JSON): each residual
signature with its candidate causes and the measurement that would separate them
(:data:`SIGNATURE_WORDS`), the motor orders a periodic residual matches, and the residual above the
noise floor that no probe names.  Nothing here prints."""

from __future__ import annotations

import math

from ..identify.effects.orders import EXPECTED, PERIOD_SHAPES
from ..identify.records.idim import TimeDiagnosis
from ..identify.records.regression import UNITS
from .text import wrap_words


def order_statement(diag: TimeDiagnosis, period_mm: float) -> str:
    """A period in table travel [mm] per mm, per screw turn and per motor turn (through the design's
    reduction), '' without a lead."""
    lead_mm = diag.design.get("lead", 0.0) * 1e3
    if not (period_mm > 0 and lead_mm > 0):
        return ""
    red = diag.design.get("reduction", 1.0) or 1.0
    per_screw = lead_mm / period_mm
    return (
        f" = {1.0 / period_mm:.3g} per mm, order {per_screw:.3g} of the screw turn, order "
        f"{per_screw / red:.3g} of the motor turn (lead {lead_mm:.3g} mm, reduction {red:.3g}:1)"
    )


def order_lines(diag: TimeDiagnosis) -> list:
    """Each accepted line in motor or screw orders (:mod:`..identify.effects.orders`) stated per
    mm, per screw turn and per motor turn, with its expected order."""
    out = []
    for c in diag.accepted:
        key = PERIOD_SHAPES.get(c.effect.name)
        if key is None or key not in diag.final.shape:
            continue
        period = as_mm(diag, diag.final.shape[key])
        out += wrap_words(
            f"{c.effect.name}: period {period:.4g} mm"
            + order_statement(diag, period)
            + "; "
            + EXPECTED[c.effect.name].format(**vars(diag.estimation.proc)),
            indent="    ",
            cont="      ",
        )
    return out


def motor_orders(diag: TimeDiagnosis, period_mm: float) -> str:
    """A period in table travel stated in orders: per mm, per screw turn (the lead over the period)
    and per motor turn (through the design's reduction, motor turns per screw turn), with the
    sources an integer order
    names: motor cogging or torque ripple (an integer order of the motor turn, the slot count or a
    multiple of the pole pairs), the ball circulation or the lead (an order of the screw turn), a
    belt's tooth mesh (the pulley's tooth count per pulley turn)."""
    text = order_statement(diag, period_mm)
    if not text:
        return ""
    red = diag.design.get("reduction", 1.0) or 1.0
    per_screw = diag.design["lead"] * 1e3 / period_mm
    per_motor = per_screw / red
    near = [
        (name, o)
        for name, o in (("motor", per_motor), ("screw", per_screw))
        if o >= 1.5 and abs(o - round(o)) <= 0.03 + 0.005 * o
    ]
    for name, o in near:
        k = int(round(o))
        if name == "motor":
            text += (
                f"; order {k} of the motor turn: motor cogging or torque ripple ({k} slots, or a "
                "multiple of the pole pairs), or a belt's tooth mesh on the motor pulley if it has "
                + f"{k} teeth"
            )
        else:
            text += f"; order {k} of the screw turn: the lead or the ball circulation"
    return text


def as_mm(diag: TimeDiagnosis, q_len: float) -> float:
    """A length in the record's coordinate as table travel [mm]."""
    if diag.quantity == "force":
        return q_len * 1e3
    return q_len / (2.0 * math.pi) * diag.design.get("lead", 0.0) * 1e3


SIGNATURE_WORDS = {
    # kind -> (candidate causes, the measurement that separates them)
    "position_periodic_lead": (
        "lead error or ball recirculation (a circuit per turn), screw run-out or a bent screw",
        "repeat at two speeds and in both directions: a ripple fixed in millimetres stays while a "
        "resonance or the controller moves with speed; a friction ripple changes sign with the "
        "direction, a lead error or run-out does not; measure the lead error with a laser against "
        "the scale",
    ),
    "position_periodic": (
        "ball recirculation over a circuit of several turns, the guide's ball pitch, a coupling "
        "misalignment or motor cogging geared to this period",
        "repeat at two speeds (a period fixed in millimetres stays) and compare the period with "
        "the nut's circuit length, the guide-ball pitch and the motor's pole pitch through the "
        "lead",
    ),
    "velocity_v|v|": (
        "quadratic drag, e.g. seals or lubricant churning, or air drag on a large table",
        "a friction curve at constant speeds up to the maximum in both directions (v|v| against a "
        "steeper viscous slope), repeated warm: churning falls as the lubricant thins",
    ),
    "velocity_low_speed": (
        "a low-speed friction rise the fitted terms do not hold (a second Stribeck constant, "
        "breakaway)",
        "a friction curve with many constant speeds below 10 mm/s in both directions",
    ),
    "velocity_|v|": (
        "viscous friction that differs by direction (a seal or wiper lip, a gravity or cable-chain "
        "load)",
        "constant-speed runs at several speeds in both directions",
    ),
    "velocity": (
        "a velocity dependence of friction that none of the library's terms has",
        "a friction curve at constant speeds over the whole speed range in both directions",
    ),
    "position": (
        "friction or a force that varies along the stroke: guide misalignment, screw straightness, "
        "preload varying along the screw, a cable chain or hose",
        "a slow constant-speed run over the full stroke in both directions (a friction changes "
        "sign with the direction, a cable-chain or weight force does not)",
    ),
    "time": (
        "a drift within the run: warm-up (friction falls as the lubricant heats) or a load that "
        "changes",
        "repeat the run cold and warm, and with a temperature sensor on the nut",
    ),
    "run": (
        "runs that differ: temperature, lubrication or load changed between the estimation and "
        "validation runs",
        "repeat one run twice in a row and note the nut temperature",
    ),
    "load": (
        "a dependence on the process force: nut or guide friction growing with the load "
        "(efficiency), a compliant support that shifts under it, or an external_force column with "
        "a wrong sign or scale",
        "runs at one speed with different constant process forces, both directions, and a check of "
        "the force sensor's sign and calibration",
    ),
    "reversal": (
        "lost motion (backlash) between the motor and the table, or the impact of taking up the "
        "lost motion exciting the drive, or the elastic windup of a compliant transmission",
        "record the motor encoder's position beside the table position (a motor_position column): "
        "the diagnosis then measures the lost motion and the windup; or a reversal test per ISO "
        "230-2 at low speed",
    ),
    "line_fixed": (
        "a force periodic in time from a rotating or pulsing source coupled into the table (a "
        "pump, a spindle or a fan's unbalance: rpm/60 or a multiple), mains hum in the current "
        "sensor (50/60 Hz or twice that) or a resonance of the machine that the moves excite",
        "record the axis at rest in position control with the other sources running, then with "
        "each of them off: a disturbance stays at rest and goes with its source, a resonance the "
        "moves excite does not; compare the frequency with the spindle speed, the pump's stroke "
        "rate and the mains",
    ),
    "line_speed": (
        "a ripple fixed in position seen in time at v/P (ball recirculation, guide-ball pitch, "
        "motor cogging through the lead)",
        "repeat at two other speeds: a ripple fixed in millimetres moves its frequency in "
        "proportion to the speed; measure the position error or the force over a slow "
        "constant-speed pass",
    ),
    "spot": (
        "a local defect of the guide rail or the screw (a dent, a contaminated or dry spot, a chip "
        "under a wiper), a cable-chain kink or a hose that catches at this place",
        "a slow constant-speed pass over the spot in both directions at two speeds (a friction "
        "spot opposes the motion both ways and keeps its width in millimetres), then inspect the "
        "rail and the screw there and move the cable chain by hand",
    ),
    "decay": (
        "a warm-up of the lubricant (friction high at the start, settling as the nut and guides "
        "warm) or a load or temperature that settles within the run",
        "repeat the run cold and after a warm-up cycle with a temperature sensor on the nut: a "
        "warm-up drift is gone when warm and its time constant follows the heating",
    ),
    "acceleration": (
        "a dependence on acceleration beyond M a: a compliant transmission (the motor side lags), "
        "lost motion, or an inertia that differs by direction",
        "runs with the same speeds at different accelerations, and a second encoder on the motor",
    ),
}


def signature_text(diag: TimeDiagnosis, p) -> tuple:
    """(what the residual does, candidate causes, separating measurement) of a probe, in words."""
    d = p.detail
    unit = UNITS[diag.quantity]["effort"][0]
    if p.kind == "position_periodic":
        P = as_mm(diag, d["period"])
        lead_mm = as_mm(diag, diag.estimation.proc.lead_q)
        ratio = lead_mm / P if P > 0 else 0.0
        k = round(ratio)
        at_lead = k >= 1 and abs(ratio - k) < 0.02 * k
        name = "the lead" if k == 1 else f"the lead / {k}"
        kind = (
            "a friction (changes sign with the direction)"
            if d.get("friction_share", 0) > 0.5
            else "a force (the same sign both ways)"
        )
        what = (
            "periodic in position with period " + (f"{P:.1f}" if P >= 1.0 else f"{P:.3g}") + " mm"
        )
        what += (f" = {name}" if at_lead else f" (the lead is {lead_mm:.3g} mm)") + f", {kind}"
        what += motor_orders(diag, P)
        key = "position_periodic_lead" if at_lead else "position_periodic"
    elif p.kind == "velocity":
        shape = d.get("shape", "")
        sh = d.get("shape_share", 0.0)
        words = {
            "v|v|": "grows with v|v|",
            "low_speed": "rises at low speed",
            "|v|": "differs by direction, growing with speed",
            "sqrt": "grows with the square root of speed",
        }
        if sh >= 0.7 and shape in words:
            what = f"depends on velocity: {words[shape]}"
            key = f"velocity_{shape}" if f"velocity_{shape}" in SIGNATURE_WORDS else "velocity"
        else:
            what, key = "depends on velocity in a shape none of the library's terms has", "velocity"
    elif p.kind == "position":
        lo, hi = d.get("worst", (0.0, 0.0))
        what = (
            f"varies along the stroke (largest at {as_mm(diag, lo):.0f}-{as_mm(diag, hi):.0f} mm)"
        )
        key = "position"
    elif p.kind == "time":
        what, key = "drifts with time within a run", "time"
    elif p.kind == "line":
        f, a = d["frequency"], d["amplitude"]
        if d.get("fixed"):
            what = (
                f"holds a line at {f:.4g} Hz (amplitude {a:.3g} {unit}) that stays at that "
                "frequency at every speed (not tied to speed or position)"
            )
            key = "line_fixed"
            if f > d.get("fit_band", f):
                what += (
                    f"; above {d['fit_band']:.3g} Hz, 0.6x the position filter's cut-off, where "
                    "time_periodic is fitted (a record sampled faster, or a finer scale, raises "
                    "the cut-off)"
                )
        else:
            what = (
                f"holds a line at {f:.4g} Hz (amplitude {a:.3g} {unit}) seen only at speeds near "
                f"{as_mm(diag, d['speed']):.3g} mm/s: tied to speed, a period in position of "
                f"{as_mm(diag, d['period']):.3g} mm" + motor_orders(diag, as_mm(diag, d["period"]))
            )
            key = "line_speed"
    elif p.kind == "spot":
        x0, w = as_mm(diag, d["x0"]), as_mm(diag, d["width"])
        dirs = {"both": "in both directions", "+": "in + travel only", "-": "in - travel only"}[
            d["directions"]
        ]
        if d.get("crossed", "both") != "both":
            dirs = f"seen in {d['crossed']} travel (the record crosses it one way only)"
        kind = "a friction (opposes the motion)" if d.get("friction") else "a force of one sign"
        what = (
            f"has a bump at {x0:.1f} mm on the stroke, {w:.3g} mm wide (standard width), {dirs}, "
            f"{kind}: +{d['height_plus']:.3g} {unit} in + travel, {d['height_minus']:.3g} {unit} "
            "in - travel"
        )
        key = "spot"
    elif p.kind == "decay":
        kind = (
            "a friction (follows the direction)"
            if d.get("friction_share", 0) > 0.5
            else "a force (the same sign both ways)"
        )
        what = f"decays within each run like exp(-t/tau), tau {d['tau']:.2g} s, {kind}"
        key = "decay"
    elif p.kind == "run":
        what, key = "differs between the estimation and validation runs", "run"
    elif p.kind == "load":
        what, key = "depends on the external force", "load"
    elif p.kind == "reversal":
        what = (
            f"is concentrated in the first {as_mm(diag, d.get('scale', 0.0)):.2g} mm of travel "
            "after each direction reversal"
        )
        key = "reversal"
    else:
        what, key = "depends on acceleration beyond M a", "acceleration"
    causes, measure = SIGNATURE_WORDS[key]
    return what, causes, measure


# a residual this many times the noise floor is unexplained even when no probe names it
NOISE_RATIO = 2.0


def unexplained_lines(diag: TimeDiagnosis) -> list:
    u = diag.unexplained
    if u is None:
        return []
    unit = UNITS[diag.quantity]["effort"][0]
    L = []
    rem = u.remaining
    ratio = u.rms / u.noise if u.noise > 0 else float("inf")
    if rem:
        L += wrap_words(
            f"unexplained: the residual keeps structure beyond noise (RMS {u.rms:.3g} {unit} "
            f"against a {u.noise:.3g} {unit} noise floor, lag-1 correlation {u.lag1:.2f}):",
            indent="",
            cont="  ",
        )
        for p in rem:
            what, causes, measure = signature_text(diag, p)
            L += wrap_words(
                f"- residual {what}: {100 * p.share:.0f} % of the residual variance. Candidates: "
                f"{causes}. To separate them: {measure}.",
                indent="  ",
                cont="    ",
            )
    elif ratio > NOISE_RATIO:
        L += wrap_words(
            f"unexplained: the residual is {ratio:.1f} times the noise floor (RMS {u.rms:.3g} "
            f"{unit} against {u.noise:.3g} {unit}, lag-1 correlation {u.lag1:.2f}) but none of the "
            "tests over position, velocity, time, reversals and acceleration holds it: an effect "
            "outside the library (a resonance, a time delay, or lost motion"
            + (
                ""
                if diag.lost is not None
                else ": a motor_position column beside the table's position measures it"
            )
            + ")",
            indent="",
            cont="  ",
        )
    else:
        L += wrap_words(
            f"residual: no structure beyond noise (RMS {u.rms:.3g} {unit} against a {u.noise:.3g} "
            f"{unit} noise floor; tested over position incl. its period and spots, velocity, time "
            "incl. lines and decays, reversals and acceleration)",
            indent="",
            cont="  ",
        )
    return L


def unexplained_dict(diag: TimeDiagnosis) -> dict | None:
    u = diag.unexplained
    if u is None:
        return None
    out = []
    for p in u.remaining:
        what, causes, measure = signature_text(diag, p)
        det = {k: v for k, v in p.detail.items() if isinstance(v, (int, float, str))}
        for k in ("period", "x0", "width", "speed"):
            if k in det:
                det[f"{k}_mm" if k != "speed" else "speed_mm_s"] = as_mm(diag, det.pop(k))
        if "group_amplitudes" in p.detail:
            det["speed_group_amplitudes"] = list(p.detail["group_amplitudes"])
        out.append(
            {
                "kind": p.kind,
                "share": p.share,
                "log10_p": p.log10_p,
                "signature": what,
                "causes": causes,
                "to_separate": measure,
                **det,
            }
        )
    return {
        "remaining": bool(out) or (u.noise > 0 and u.rms / u.noise > NOISE_RATIO),
        "rms": u.rms,
        "noise_floor": u.noise,
        "lag1": u.lag1,
        "signatures": out,
    }

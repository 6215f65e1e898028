"""Time-record diagnosis output (:class:`axisopt.identify.records.idim.TimeDiagnosis`): console text, at most 100
columns, and a JSON-ready dict.  Nothing here prints.

Parameters are shown in the record's coordinate (:data:`axisopt.identify.records.regression.UNITS`); lengths of the
lost motion and of residual signatures as table travel through the lead.  A residual signature is put in words
with its candidate causes and the measurement that would separate them (:data:`SIGNATURE_WORDS`).
"""

from __future__ import annotations

import math
import textwrap

from ..identify.effects import time_effects
from ..identify.records.estimators import Estimate, mode_frequency, rel_error
from ..identify.records.idim import TimeDiagnosis
from ..identify.records.record import BUTTER_ORDER
from ..identify.records.regression import UNITS, shape_params, symbol, term, unit_of
from ..identify.selection import TIME_RULE


def _fmt(v, s=None):
    if s is None or not math.isfinite(s):
        return f"{v:.4g}"
    return f"{v:.4g} ± {s:.2g}"



def _param_lines(q, est: Estimate, only=None, indent="    ") -> list:
    out = []
    for t, v, s in zip(est.terms, est.theta, est.std):
        if only is not None and t not in only:
            continue
        u, f = unit_of(q, t)
        label = "moving inertia (motor side)" if (q, t) == ("torque", "M") else term(t).label
        out.append(f"{indent}{symbol(q, t):<7}{_fmt(v * f, s * f):>22} {u:<10} {label}".rstrip())
    if "vs" in est.shape and (only is None or "Fs" in only):
        u, f = UNITS[q]["speed"]
        out.append(f"{indent}{'vs':<7}{est.shape['vs'] * f:>22.4g} {u:<10} Stribeck velocity (1-D search)")
    for nm, (label, u, f) in _shapes(q, est, only):
        out.append(f"{indent}{nm:<7}{est.shape[nm] * f:>22.5g} {u:<10} {label}")
    for nm, v, u, label in _derived(q, est, only):
        out.append(f"{indent}{nm:<7}{v:>22.4g} {u:<10} {label}")
    fr = mode_frequency(est)
    if fr is not None and (only is None or "beta" in only):
        out.append(f"{indent}{'f_r':<7}{fr:>22.4g} {'Hz':<10} resonance sqrt(M/beta)/2pi")
    return out


SHAPES_APART = ("vs", "period")  # the Stribeck velocity has its own line; the ripple's period is the lead's


def _shapes(q, est: Estimate, only=None) -> list:
    """(name, (label, unit, factor)) of the searched shape parameters of ``est`` (the effects' own terms in
    ``only`` when given) shown beside its terms."""
    known = shape_params()
    owners = {}
    for eff in time_effects().values():
        if eff.shape is not None:
            for nm in (eff.shape.name, *(a[0] for a in eff.shape.also)):
                owners[nm] = eff.terms
    out = []
    for nm in est.shape:
        if nm in SHAPES_APART or nm not in known:
            continue
        if only is not None and not set(owners.get(nm, ())) & set(only):
            continue
        label, kind = known[nm]
        u, f = UNITS[q][kind]
        out.append((nm, (label, u, f)))
    return out


def _derived(q, est: Estimate, only=None) -> list:
    """(name, value, unit, label) of the quantities the effects of ``est`` derive from their terms."""
    out = []
    for eff in time_effects().values():
        if not eff.derived or not all(t in est.terms for t in eff.terms):
            continue
        if only is not None and not set(eff.terms) & set(only):
            continue
        for nm, label, kind, fn in eff.derived:
            u, f = UNITS[q][kind]
            out.append((nm, fn(est.value) * f, u, label))
    return out


def _errors(diag, est) -> str:
    parts = [f"estimation {100 * rel_error(diag.estimation, est):.2f} %"]
    parts += [f"{v.record.name} {100 * rel_error(v, est):.2f} %" for v in diag.validation]
    return ", ".join(parts)


WIDTH = 100


def _wrap(text: str, indent: str = "  ", cont: str = "      ") -> list:
    return textwrap.wrap(text, WIDTH, initial_indent=indent, subsequent_indent=cont, break_on_hyphens=False)


def _compact(q, est: Estimate, terms) -> str:
    out = []
    for t in terms:
        i = est.terms.index(t)
        u, f = unit_of(q, t)
        out.append(f"{symbol(q, t)} {_fmt(est.theta[i] * f, est.std[i] * f)} {u}")
    if "vs" in est.shape and "Fs" in terms:
        u, f = UNITS[q]["speed"]
        out.append(f"vs {est.shape['vs'] * f:.3g} {u}")
    for nm, (_label, u, f) in _shapes(q, est, terms):
        out.append(f"{nm} {est.shape[nm] * f:.5g} {u}")
    for nm, v, u, _label in _derived(q, est, terms):
        out.append(f"{nm} {v:.4g} {u}")
    fr = mode_frequency(est)
    if fr is not None and "beta" in terms:
        out.append(f"f_r {fr:.3g} Hz")
    return ", ".join(out)


def time_diagnosis_text(diag: TimeDiagnosis) -> str:
    """Console text, at most 100 columns (prose wrapped with indented continuation)."""
    q = diag.quantity
    er, p = diag.estimation, diag.estimation.proc
    rec = er.record
    unit_eff = UNITS[q]["effort"][0]
    spd_u, spd_f = UNITS[q]["speed"]
    L = [f"time-record identification (IDIM) of {diag.design.get('name', 'the axis')}: {q} data, "
         + ("table coordinate" if q == "force" else "motor angle coordinate")]
    L += _wrap(f"estimation  {rec.name}: {rec.n} samples at {p.fs:.6g} Hz, {er.n} regression rows"
               + (f"; {rec.gain_note}" if rec.gain_note else ""), cont="              ")
    for v in diag.validation:
        L.append(f"  validation  {v.record.name}: {v.record.n} samples, {v.n} regression rows")
    L += _wrap(f"filter      zero-phase Butterworth, order {BUTTER_ORDER} (|H|^2 by FFT, as forward-backward), "
               f"cut-off {p.fc:.1f} Hz: {p.rule}; motion bandwidth {p.f_motion:.1f} Hz", cont="              ")
    L += _wrap(f"decimation  parallel: every column and the {q} low-passed at {p.fdec:.1f} Hz, every {p.nd}th "
               f"row kept; rows below {p.vmin * spd_f:.3g} {spd_u} or at reversals left out",
               cont="              ")
    c = diag.controller
    if c is not None:
        L += _wrap(f"controller  PD fitted from the reference: Kp {c.kp:.4g}, Kd {c.kd:.4g}, feed-forward "
                   f"v {c.kv:.3g}, a {c.ka:.3g} (R2 {c.r2:.3f})", cont="              ")
    L.append("")
    L.append("baseline  f = M a + Fv v + Fc sgn(v) + offset" if q == "force" else
             "baseline  T = J a + Fv w + Fc sgn(w) + offset (motor side)")
    for est in (diag.baseline_ls, diag.baseline_iv):
        L += _wrap(f"{est.method}" + (f"  ({est.note})" if est.note else ""), cont="      ")
        L += _param_lines(q, est)
        L += _wrap(f"{q} error ||y - y_hat||/||y||: {_errors(diag, est)}", indent="    ")
    for f in diag.flags.get("baseline", []):
        L += _wrap(f"! {f}", indent="  ", cont="      ")
    if q == "torque" and diag.design.get("lead"):
        lead, eta = diag.design["lead"], diag.design.get("efficiency", 1.0)
        g = 2 * math.pi / lead
        b = diag.baseline_iv.as_dict()
        L += _wrap(f"table side through lead {lead * 1e3:g} mm and efficiency {eta:g} (F = T 2pi eta/p, "
                   f"M = J (2pi/p)^2 eta): M {b['M'] * g * g * eta:.4g} kg, Fv {b['Fv'] * g * g * eta:.4g} N.s/m, "
                   f"Fc {b['Fc'] * g * eta:.4g} N, offset {b['offset'] * g * eta:.4g} N")
    L.append("")
    rule = TIME_RULE
    L += _wrap(f"candidates, each fitted (LS) jointly with the baseline; dBIC on the estimation run, gain on the "
               f"{diag.validation_mode}; accepted if dBIC < {rule.accept_dbic:g} and gain >= {rule.min_gain:g} %",
               indent="", cont="  ")
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            L += _wrap(f"{k}  {cnd.effect.name:<20} dBIC {cnd.dbic:>8.1f}  gain {cnd.gain:>6.1f} %  "
                       + _compact(q, cnd.estimate, cnd.effect.terms), cont=" " * 52)
    for nm, why in diag.skipped.items():
        L += _wrap(f"-  {nm:<20} not tried: {why}", cont=" " * 26)
    for k, rnd in enumerate(diag.rounds, start=1):
        for cnd in rnd:
            if cnd.reason:
                L += _wrap(f"{k}  {cnd.effect.name:<20} not accepted: {cnd.reason}", cont=" " * 26)
    rest = 0
    for k, a, b, _est, dbic, gain, why in diag.pairs:
        if why and (dbic >= rule.accept_dbic or gain < rule.min_gain):
            rest += 1
            continue
        L += _wrap(f"{k}  pair {a.effect.name} + {b.effect.name}: dBIC {dbic:.1f}, gain {gain:.1f} %: "
                   + (f"not accepted: {why}" if why else "accepted (neither passes alone)"), cont=" " * 26)
    if rest:
        L += _wrap(f"-  {rest} pair{'s' if rest > 1 else ''} of these candidates tried together: none lowers BIC "
                   f"by {-rule.accept_dbic:g} and predicts the held-out data {rule.min_gain:g} % better", cont=" " * 26)
    L.append("")
    if diag.accepted:
        parts = []
        for c in diag.accepted:
            if c.together and parts and parts[-1].startswith(c.together):
                parts[-1] = parts[-1].replace(" (", f" together with {c.effect.name} (", 1)
                continue
            parts.append(f"{c.effect.name} ({c.effect.summary}; gain {c.gain:.0f} % on held-out data)")
        L += _wrap("verdict: " + ", then ".join(parts), indent="", cont="  ")
        L += _wrap(f"final fit ({diag.final.method}" + (f"; {diag.final.note}" if diag.final.note else "") + ")",
                   cont="    ")
        L += _param_lines(q, diag.final)
        L += _wrap(f"{q} error: {_errors(diag, diag.final)}", indent="    ")
        for f in diag.flags.get("final", []):
            L += _wrap(f"! {f}", indent="  ", cont="      ")
        L += _equivalent_lines(diag)
    elif not (diag.lost and diag.lost.accepted):
        L += _wrap("verdict: nothing named beyond the baseline: " + _why_none(diag), indent="", cont="  ")
    L += _lost_motion_lines(diag)
    L += _unexplained_lines(diag)
    L += _wrap(f"the offset [{unit_eff}] holds any Coulomb asymmetry (Fc+ - Fc-)/2: while the axis moves the two "
               "are the same column")
    return "\n".join(L)


def _equivalent_text(diag: TimeDiagnosis, a, b, apart: float) -> str:
    top = diag.top_speed
    notes = [f"{e.name}: {w}" for e in (a.effect, b.effect) if e.regime is not None for w in [e.regime(top)] if w]
    return (f"{a.effect.name} and {b.effect.name} explain the data equally well: held-out RMSE {apart:.2f} % "
            f"apart, within the rule's {TIME_RULE.resolution:g} % resolution (dBIC {a.dbic:.1f} against "
            f"{b.dbic:.1f}); {a.effect.name} is named for its lower dBIC, not because the data tell them apart. "
            + (" ".join(n[0].upper() + n[1:] + "." for n in notes) + " " if notes else "")
            + f"To separate them: for {a.effect.name}, {a.effect.evidence or 'a test that shows it alone'}; "
            f"for {b.effect.name}, {b.effect.evidence or 'a test that shows it alone'}.")


def _equivalent_lines(diag: TimeDiagnosis) -> list:
    out = []
    for _k, a, b, apart in diag.equivalent:
        out += _wrap("~ " + _equivalent_text(diag, a, b, apart), indent="  ", cont="      ")
    return out


def _lost_motion_lines(diag: TimeDiagnosis) -> list:
    lm = diag.lost
    if lm is None:
        return []
    q = diag.quantity
    b, sb = _mm(diag, lm.width) * 1e3, _mm(diag, lm.width_std) * 1e3
    what = (f"motor_position against position: e = e0 + (b/2) sgn(F) + F/k, F = {q} - m1 a1 the force the "
            f"transmission carries; b = {b:.3g} ± {sb:.2g} um of table travel")
    if math.isfinite(lm.stiffness) and lm.stiffness > 0:
        per_m = lm.stiffness / (_mm(diag, 1.0) * 1e-3)  # effort per metre of table travel
        k_txt = f"{per_m / 1e6:.3g} N/um" if q == "force" else f"{per_m / 1e6:.3g} N.m per um of table travel"
        what += f", windup stiffness k {k_txt}"
    m_u = UNITS[q]["mass"][0]
    what += (f", motor-side m1 {lm.motor_mass:.3g} {m_u}; held-out RMS of e {_mm(diag, lm.rms_before) * 1e3:.3g} -> "
             f"{_mm(diag, lm.rms_after) * 1e3:.3g} um (gain {lm.gain:.0f} %)")
    if lm.accepted:
        head = "verdict: backlash (lost motion between motor and table, measured by the two encoders): "
        return _wrap(head + what, indent="", cont="  ")
    return _wrap(f"lost motion between motor and table not named ({lm.reason}): {what}", indent="", cont="  ")


def _why_none(diag: TimeDiagnosis) -> str:
    """The true reason no effect was named: the best candidates and what stopped each."""
    if not diag.rounds:
        return "no candidate effect applies to this record"
    best = diag.rounds[0][:3]
    out = [f"{c.effect.name}: " + (f"dBIC {c.dbic:.1f} and gain {c.gain:.1f} %, but {c.reason}"
                                   if c.reason.startswith("would need") else c.reason) for c in best]
    return "; ".join(out)


def motor_orders(diag: TimeDiagnosis, period_mm: float) -> str:
    """A period in table travel stated in orders: per mm, per screw turn (the lead over the period) and per motor
    turn (through the design's reduction, motor turns per screw turn), with the sources an integer order
    names: motor cogging or torque ripple (an integer order of the motor turn, the slot count or a multiple of
    the pole pairs), the ball circulation or the lead (an order of the screw turn), a belt's tooth mesh (the
    pulley's tooth count per pulley turn)."""
    lead_mm = diag.design.get("lead", 0.0) * 1e3
    if not (period_mm > 0 and lead_mm > 0):
        return ""
    red = diag.design.get("reduction", 1.0) or 1.0
    per_screw = lead_mm / period_mm
    per_motor = per_screw / red
    text = (f" = {1.0 / period_mm:.3g} per mm, order {per_screw:.3g} of the screw turn, order {per_motor:.3g} "
            f"of the motor turn (lead {lead_mm:.3g} mm, reduction {red:.3g}:1)")
    near = [(name, o) for name, o in (("motor", per_motor), ("screw", per_screw))
            if o >= 1.5 and abs(o - round(o)) <= 0.03 + 0.005 * o]
    for name, o in near:
        k = int(round(o))
        if name == "motor":
            text += (f"; order {k} of the motor turn: motor cogging or torque ripple ({k} slots, or a multiple "
                     "of the pole pairs), or a belt's tooth mesh on the motor pulley if it has " + f"{k} teeth")
        else:
            text += f"; order {k} of the screw turn: the lead or the ball circulation"
    return text


def _mm(diag: TimeDiagnosis, q_len: float) -> float:
    """A length in the record's coordinate as table travel [mm]."""
    if diag.quantity == "force":
        return q_len * 1e3
    return q_len / (2.0 * math.pi) * diag.design.get("lead", 0.0) * 1e3


SIGNATURE_WORDS = {
    # kind -> (candidate causes, the measurement that separates them)
    "position_periodic_lead": (
        "lead error or ball recirculation (a circuit per turn), screw run-out or a bent screw",
        "repeat at two speeds and in both directions: a ripple fixed in millimetres stays while a resonance or "
        "the controller moves with speed; a friction ripple changes sign with the direction, a lead error or "
        "run-out does not; measure the lead error with a laser against the scale"),
    "position_periodic": (
        "ball recirculation over a circuit of several turns, the guide's ball pitch, a coupling misalignment "
        "or motor cogging geared to this period",
        "repeat at two speeds (a period fixed in millimetres stays) and compare the period with the nut's "
        "circuit length, the guide-ball pitch and the motor's pole pitch through the lead"),
    "velocity_v|v|": (
        "quadratic drag, e.g. seals or lubricant churning, or air drag on a large table",
        "a friction curve at constant speeds up to the maximum in both directions (v|v| against a steeper "
        "viscous slope), repeated warm: churning falls as the lubricant thins"),
    "velocity_low_speed": (
        "a low-speed friction rise the fitted terms do not hold (a second Stribeck constant, breakaway)",
        "a friction curve with many constant speeds below 10 mm/s in both directions"),
    "velocity_|v|": (
        "viscous friction that differs by direction (a seal or wiper lip, a gravity or cable-chain load)",
        "constant-speed runs at several speeds in both directions"),
    "velocity": (
        "a velocity dependence of friction that none of the library's terms has",
        "a friction curve at constant speeds over the whole speed range in both directions"),
    "position": (
        "friction or a force that varies along the stroke: guide misalignment, screw straightness, preload "
        "varying along the screw, a cable chain or hose",
        "a slow constant-speed run over the full stroke in both directions (a friction changes sign with the "
        "direction, a cable-chain or weight force does not)"),
    "time": (
        "a drift within the run: warm-up (friction falls as the lubricant heats) or a load that changes",
        "repeat the run cold and warm, and with a temperature sensor on the nut"),
    "run": (
        "runs that differ: temperature, lubrication or load changed between the estimation and validation "
        "runs",
        "repeat one run twice in a row and note the nut temperature"),
    "load": (
        "a dependence on the process force: nut or guide friction growing with the load (efficiency), a "
        "compliant support that shifts under it, or an external_force column with a wrong sign or scale",
        "runs at one speed with different constant process forces, both directions, and a check of the force "
        "sensor's sign and calibration"),
    "reversal": (
        "lost motion (backlash) between the motor and the table, or the impact of taking up the lost motion "
        "exciting the drive, or the elastic windup of a compliant transmission",
        "record the motor encoder's position beside the table position (a motor_position column): the "
        "diagnosis then measures the lost motion and the windup; or a reversal test per ISO 230-2 at low speed"),
    "line_fixed": (
        "a force periodic in time from a rotating or pulsing source coupled into the table (a pump, a spindle or "
        "a fan's unbalance: rpm/60 or a multiple), mains hum in the current sensor (50/60 Hz or twice that) or "
        "a resonance of the machine that the moves excite",
        "record the axis at rest in position control with the other sources running, then with each of them "
        "off: a disturbance stays at rest and goes with its source, a resonance the moves excite does not; "
        "compare the frequency with the spindle speed, the pump's stroke rate and the mains"),
    "line_speed": (
        "a ripple fixed in position seen in time at v/P (ball recirculation, guide-ball pitch, motor cogging "
        "through the lead)",
        "repeat at two other speeds: a ripple fixed in millimetres moves its frequency in proportion to the "
        "speed; measure the position error or the force over a slow constant-speed pass"),
    "spot": (
        "a local defect of the guide rail or the screw (a dent, a contaminated or dry spot, a chip under a "
        "wiper), a cable-chain kink or a hose that catches at this place",
        "a slow constant-speed pass over the spot in both directions at two speeds (a friction spot opposes "
        "the motion both ways and keeps its width in millimetres), then inspect the rail and the screw there "
        "and move the cable chain by hand"),
    "decay": (
        "a warm-up of the lubricant (friction high at the start, settling as the nut and guides warm) or a "
        "load or temperature that settles within the run",
        "repeat the run cold and after a warm-up cycle with a temperature sensor on the nut: a warm-up drift "
        "is gone when warm and its time constant follows the heating"),
    "acceleration": (
        "a dependence on acceleration beyond M a: a compliant transmission (the motor side lags), lost motion, "
        "or an inertia that differs by direction",
        "runs with the same speeds at different accelerations, and a second encoder on the motor"),
}


def signature_text(diag: TimeDiagnosis, p) -> tuple:
    """(what the residual does, candidate causes, separating measurement) of a probe, in words."""
    d = p.detail
    unit = UNITS[diag.quantity]["effort"][0]
    if p.kind == "position_periodic":
        P = _mm(diag, d["period"])
        lead_mm = _mm(diag, diag.estimation.proc.lead_q)
        ratio = lead_mm / P if P > 0 else 0.0
        k = round(ratio)
        at_lead = k >= 1 and abs(ratio - k) < 0.02 * k
        name = "the lead" if k == 1 else f"the lead / {k}"
        kind = ("a friction (changes sign with the direction)" if d.get("friction_share", 0) > 0.5 else
                "a force (the same sign both ways)")
        what = "periodic in position with period " + (f"{P:.1f}" if P >= 1.0 else f"{P:.3g}") + " mm"
        what += (f" = {name}" if at_lead else f" (the lead is {lead_mm:.3g} mm)") + f", {kind}"
        what += motor_orders(diag, P)
        key = "position_periodic_lead" if at_lead else "position_periodic"
    elif p.kind == "velocity":
        shape = d.get("shape", "")
        sh = d.get("shape_share", 0.0)
        words = {"v|v|": "grows with v|v|", "low_speed": "rises at low speed", "|v|": "differs by direction, "
                 "growing with speed", "sqrt": "grows with the square root of speed"}
        if sh >= 0.7 and shape in words:
            what = f"depends on velocity: {words[shape]}"
            key = f"velocity_{shape}" if f"velocity_{shape}" in SIGNATURE_WORDS else "velocity"
        else:
            what, key = "depends on velocity in a shape none of the library's terms has", "velocity"
    elif p.kind == "position":
        lo, hi = d.get("worst", (0.0, 0.0))
        what = f"varies along the stroke (largest at {_mm(diag, lo):.0f}-{_mm(diag, hi):.0f} mm)"
        key = "position"
    elif p.kind == "time":
        what, key = "drifts with time within a run", "time"
    elif p.kind == "line":
        f, a = d["frequency"], d["amplitude"]
        if d.get("fixed"):
            what = (f"holds a line at {f:.4g} Hz (amplitude {a:.3g} {unit}) that stays at that frequency at "
                    "every speed (not tied to speed or position)")
            key = "line_fixed"
            if f > d.get("fit_band", f):
                what += (f"; above {d['fit_band']:.3g} Hz, 0.6x the position filter's cut-off, where time_periodic "
                         "is fitted (a record sampled faster, or a finer scale, raises the cut-off)")
        else:
            what = (f"holds a line at {f:.4g} Hz (amplitude {a:.3g} {unit}) seen only at speeds near "
                    f"{_mm(diag, d['speed']):.3g} mm/s: tied to speed, a period in position of "
                    f"{_mm(diag, d['period']):.3g} mm" + motor_orders(diag, _mm(diag, d["period"])))
            key = "line_speed"
    elif p.kind == "spot":
        x0, w = _mm(diag, d["x0"]), _mm(diag, d["width"])
        dirs = {"both": "in both directions", "+": "in + travel only", "-": "in - travel only"}[d["directions"]]
        if d.get("crossed", "both") != "both":
            dirs = f"seen in {d['crossed']} travel (the record crosses it one way only)"
        kind = "a friction (opposes the motion)" if d.get("friction") else "a force of one sign"
        what = (f"has a bump at {x0:.1f} mm on the stroke, {w:.3g} mm wide (standard width), {dirs}, {kind}: "
                f"+{d['height_plus']:.3g} {unit} in + travel, {d['height_minus']:.3g} {unit} in - travel")
        key = "spot"
    elif p.kind == "decay":
        kind = ("a friction (follows the direction)" if d.get("friction_share", 0) > 0.5 else
                "a force (the same sign both ways)")
        what = f"decays within each run like exp(-t/tau), tau {d['tau']:.2g} s, {kind}"
        key = "decay"
    elif p.kind == "run":
        what, key = "differs between the estimation and validation runs", "run"
    elif p.kind == "load":
        what, key = "depends on the external force", "load"
    elif p.kind == "reversal":
        what = (f"is concentrated in the first {_mm(diag, d.get('scale', 0.0)):.2g} mm of travel after each "
                "direction reversal")
        key = "reversal"
    else:
        what, key = "depends on acceleration beyond M a", "acceleration"
    causes, measure = SIGNATURE_WORDS[key]
    return what, causes, measure


NOISE_RATIO = 2.0  # a residual this many times the noise floor is unexplained even when no probe names it


def _unexplained_lines(diag: TimeDiagnosis) -> list:
    u = diag.unexplained
    if u is None:
        return []
    unit = UNITS[diag.quantity]["effort"][0]
    L = []
    rem = u.remaining
    ratio = u.rms / u.noise if u.noise > 0 else float("inf")
    if rem:
        L += _wrap(f"unexplained: the residual keeps structure beyond noise (RMS {u.rms:.3g} {unit} against a "
                   f"{u.noise:.3g} {unit} noise floor, lag-1 correlation {u.lag1:.2f}):", indent="", cont="  ")
        for p in rem:
            what, causes, measure = signature_text(diag, p)
            L += _wrap(f"- residual {what}: {100 * p.share:.0f} % of the residual variance. Candidates: {causes}. "
                       f"To separate them: {measure}.", indent="  ", cont="    ")
    elif ratio > NOISE_RATIO:
        L += _wrap(f"unexplained: the residual is {ratio:.1f} times the noise floor (RMS {u.rms:.3g} {unit} "
                   f"against {u.noise:.3g} {unit}, lag-1 correlation {u.lag1:.2f}) but none of the tests over "
                   "position, velocity, time, reversals and acceleration holds it: an effect outside the "
                   "library (a resonance, a time delay, or lost motion"
                   + ("" if diag.lost is not None else ": a motor_position column beside the table's position "
                      "measures it") + ")", indent="", cont="  ")
    else:
        L += _wrap(f"residual: no structure beyond noise (RMS {u.rms:.3g} {unit} against a {u.noise:.3g} {unit} "
                   "noise floor; tested over position incl. its period and spots, velocity, time incl. lines and "
                   "decays, reversals and acceleration)",
                   indent="", cont="  ")
    return L


def _est_dict(q, est: Estimate) -> dict:
    d = {"method": est.method, "note": est.note, "iterations": est.iterations, "converged": est.converged,
         "parameters": [{"name": symbol(q, t), "value": float(v * unit_of(q, t)[1]), "std": float(s * unit_of(q, t)[1]),
                         "unit": unit_of(q, t)[0], "label": term(t).label} for t, v, s in
                        zip(est.terms, est.theta, est.std)]}
    if "vs" in est.shape:
        u, f = UNITS[q]["speed"]
        d["parameters"].append({"name": "vs", "value": est.shape["vs"] * f, "std": None, "unit": u,
                                "label": "Stribeck velocity (1-D search)"})
    for nm, (label, u, f) in _shapes(q, est):
        d["parameters"].append({"name": nm, "value": est.shape[nm] * f, "std": None, "unit": u, "label": label})
    for nm, v, u, label in _derived(q, est):
        d["parameters"].append({"name": nm, "value": v, "std": None, "unit": u, "label": label})
    fr = mode_frequency(est)
    if fr is not None:
        d["parameters"].append({"name": "f_r", "value": fr, "std": None, "unit": "Hz", "label": "resonance"})
    return d


def time_diagnosis_dict(diag: TimeDiagnosis) -> dict:
    q, p = diag.quantity, diag.estimation.proc
    runs = [diag.estimation] + diag.validation

    def errs(est):
        return {r.record.source: rel_error(r, est) for r in runs}

    return {
        "kind": "time_record",
        "design": diag.design.get("name"),
        "quantity": q,
        "files": [{"file": r.record.source, "role": "estimation" if i == 0 else "validation",
                   "samples": r.record.n, "rows": r.n} for i, r in enumerate(runs)],
        "processing": {"fs_Hz": p.fs, "cutoff_Hz": p.fc, "cutoff_rule": p.rule, "motion_bandwidth_Hz": p.f_motion,
                       "decimation": p.nd, "decimation_cutoff_Hz": p.fdec,
                       "filter": f"zero-phase Butterworth order {BUTTER_ORDER} (|H|^2 by FFT)"},
        "controller": diag.controller.as_dict() if diag.controller else None,
        "baseline": {"LS": {**_est_dict(q, diag.baseline_ls), "relative_error": errs(diag.baseline_ls)},
                     "IV": {**_est_dict(q, diag.baseline_iv), "relative_error": errs(diag.baseline_iv)}},
        "candidates": [[{"effect": c.effect.name, "dBIC": c.dbic, "gain_percent": c.gain,
                         **_est_dict(q, c.estimate)} for c in rnd] for rnd in diag.rounds],
        "skipped": diag.skipped,
        "verdict": diag.verdict,
        "rejected": [{"round": k, "effect": c.effect.name, "dBIC": c.dbic, "would_need": why}
                     for k, c, why in diag.rejected],
        "gain_percent": [c.gain for c in diag.accepted],
        "not_accepted": [{"round": k, "effect": c.effect.name, "dBIC": c.dbic, "gain_percent": c.gain,
                          "reason": c.reason} for k, rnd in enumerate(diag.rounds, start=1) for c in rnd if c.reason],
        "pairs": [{"round": k, "effects": [a.effect.name, b.effect.name], "dBIC": dbic, "gain_percent": gain,
                   "accepted": not why, "reason": why} for k, a, b, _e, dbic, gain, why in diag.pairs],
        "flags": diag.flags,
        "equivalent": [{"round": k, "named": a.effect.name, "alternative": b.effect.name, "percent_apart": apart,
                        "dBIC": [a.dbic, b.dbic], "text": _equivalent_text(diag, a, b, apart),
                        "to_separate": {a.effect.name: a.effect.evidence, b.effect.name: b.effect.evidence}}
                       for k, a, b, apart in diag.equivalent],
        "top_speed_mm_s": diag.top_speed * 1e3,
        "unexplained": _unexplained_dict(diag),
        "lost_motion": None if diag.lost is None else {
            "accepted": diag.lost.accepted, "reason": diag.lost.reason,
            "width_um": _mm(diag, diag.lost.width) * 1e3, "width_std_um": _mm(diag, diag.lost.width_std) * 1e3,
            "gain_percent": diag.lost.gain},
        "final": {**_est_dict(q, diag.final), "relative_error": errs(diag.final)},
        "seconds": diag.times,
    }


def _unexplained_dict(diag: TimeDiagnosis) -> dict | None:
    u = diag.unexplained
    if u is None:
        return None
    out = []
    for p in u.remaining:
        what, causes, measure = signature_text(diag, p)
        det = {k: v for k, v in p.detail.items() if isinstance(v, (int, float, str))}
        for k in ("period", "x0", "width", "speed"):
            if k in det:
                det[f"{k}_mm" if k != "speed" else "speed_mm_s"] = _mm(diag, det.pop(k))
        if "group_amplitudes" in p.detail:
            det["speed_group_amplitudes"] = list(p.detail["group_amplitudes"])
        out.append({"kind": p.kind, "share": p.share, "log10_p": p.log10_p, "signature": what, "causes": causes,
                    "to_separate": measure, **det})
    return {"remaining": bool(out) or (u.noise > 0 and u.rms / u.noise > NOISE_RATIO), "rms": u.rms,
            "noise_floor": u.noise, "lag1": u.lag1, "signatures": out}

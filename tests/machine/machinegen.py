"""Random small machines for the machine tests (small catalogs: a few screws and guides, no drive
search)."""

import numpy as np

SCREWS = ["HIWIN-G-32x20-b4p763", "HIWIN-G-40x20-b6p35", "HIWIN-G-50x20-b6p35"]
GUIDES = ["HIWIN-HG20-ZA", "HIWIN-HG25-ZA", "HIWIN-HG30-ZA"]
# the support bearings that fit each screw's journal (two of them per axis: a few designs, a cheap
# brute force)
BEARINGS = {
    SCREWS[0]: ["HIWIN-WBK20-DF", "HIWIN-WBK25-DF", "HIWIN-WBK25-DFD"],
    SCREWS[1]: ["HIWIN-WBK25-DF", "HIWIN-WBK30-DF", "HIWIN-WBK25-DFD", "HIWIN-WBK30-DFD"],
    SCREWS[2]: ["HIWIN-WBK40-DF", "HIWIN-WBK40-DFD", "HIWIN-WBK40-DFF"],
}


def _axis(
    rng,
    name,
    carried_by,
    direction,
    normal,
    *,
    vertical=False,
    counterweight=False,
    twin=False,
    frame=True,
    at=0.0,
):
    mass = float(rng.uniform(150, 400))
    screws = list(rng.choice(SCREWS, size=1))
    guides = list(rng.choice(GUIDES, size=2, replace=False))
    bearings = list(rng.choice(BEARINGS[screws[0]], size=2, replace=False))
    lines = [
        f"  {name}:",
        f"    carried_by: {carried_by}",
        f"    direction: {direction}",
        f"    normal: {normal}",
    ]
    if frame:
        kf = rng.uniform(500, 3000, 3)
        lines.append(
            f"    frame_stiffness: {{x: {kf[0]:.0f} N/um, y: {kf[1]:.0f} N/um, z: {kf[2]:.0f} "
            "N/um}"
        )
    else:
        lines.append("    frame_stiffness: estimate")
    if at:
        lines.append(f"    carried_at: {{height: {at:.0f} mm}}")
    lines += [
        "    problem:",
        "      axis:",
        f"        stroke: {rng.choice([400, 500, 600])} mm",
        f"        moving_mass: {mass:.0f} kg",
        "        mounting: fixed-supported",
        f"        max_speed: {rng.choice([15, 20])} m/min",
        f"        axial_load: {rng.uniform(500, 1500):.0f} N",
        "        acceleration: 2 m/s^2",
        "        cross_load: 1000 N",
        "        normal_load: 1000 N",
    ]
    if vertical:
        lines.append("        orientation: vertical")
    if counterweight:
        lines.append(f"        counterbalance: {{kind: counterweight, mass: {0.8 * mass:.0f} kg}}")
    if twin:
        lines += [
            "        table_width: 1500 mm",
            "        rail_spacing: 1400 mm",
            "        twin_drive: {span: 1200 mm, cross_stroke: 800 mm}",
        ]
    lines += [
        "      limits:",
        f"        min_life: {rng.choice([1000, 3000])} h",
        "      catalog:",
        "        vendors: [HIWIN]",
        "        nut_types: [double]",
        "        drive: no",
        f"        require: {{screw: [{', '.join(screws)}], guide: [{', '.join(guides)}],",
        f"                  bearing: [{', '.join(bearings)}]}}",
    ]
    return lines


def random_machine(seed: int) -> str:
    """The YAML text of a random machine: one chain of two or three axes, sometimes a second chain;
    a vertical counterweighted axis (at the top, or carrying another: the non-monotone case),
    sometimes a twin-drive base."""
    rng = np.random.default_rng(seed)
    depth = int(rng.choice([2, 2, 2, 3]))
    objective = str(rng.choice(["cost", "tool_stiffness", "frequency", "moving_mass"]))
    dirs = [("y", "z"), ("x", "z"), ("z", "y")]
    cw_at = int(rng.integers(0, depth + 1))  # the counterweighted axis (depth: none)
    twin = bool(rng.random() < 0.3)
    names = ["A", "B", "C"][:depth]
    lines = ["name: random", "machine:", f"  objective: {objective}", "  limits:"]
    lines.append(f"    min_tool_stiffness: {rng.uniform(5, 30):.0f} N/um")
    if rng.random() < 0.5:
        lines.append(f"    min_frequency: {rng.uniform(15, 45):.0f} Hz")
    lines.append("axes:")
    for i, n in enumerate(names):
        d, nrm = dirs[i]
        vertical = i == cw_at
        if vertical:
            d, nrm = "z", "y"
        lines += _axis(
            rng,
            n,
            "frame" if i == 0 else names[i - 1],
            d,
            nrm,
            vertical=vertical,
            counterweight=vertical,
            twin=twin and i == 0 and not vertical,
            frame=bool(rng.random() < 0.7),
            at=float(rng.uniform(0, 200)) if i else 0.0,
        )
    if rng.random() < 0.15:
        lines += _axis(rng, "W", "frame", "x" if dirs[0][0] != "x" else "y", "z")
    return "\n".join(lines) + "\n"


def check_default_equals_exhaustive(seed: int, tmp_path) -> None:
    """The default machine search against every combination of every axis on random machine
    ``seed``: the same status and optimum, both feasible, and never worse than the sequential sizing
    where that one is feasible."""
    import pytest

    from axisopt.machine import load_machine, solve_machine

    path = tmp_path / "machine.yaml"
    path.write_text(random_machine(seed))
    m = load_machine(path)
    a = solve_machine(m)
    b = solve_machine(m, "exhaustive")
    assert a.status == b.status
    if b.best is None:
        return
    va, vb = a.best.value(m.objective), b.best.value(m.objective)
    assert va == pytest.approx(vb, rel=1e-9)
    assert a.best.feasible and b.best.feasible
    if a.sequential is not None and a.sequential.feasible:
        assert a.gain >= -1e-9 * max(1.0, abs(va))

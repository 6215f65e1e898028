"""The dynamic compliance (model.frf, ``evaluate --frf``): static limit, peaks at the modes, the
dynamic stiffness form, the JSON and plot, bad frequencies refused."""

import json
import math
from pathlib import Path

import numpy as np
import numpy.polynomial.polynomial as P
import pytest
import yaml

from axisopt.design import load_design
from axisopt.errors import InputError
from axisopt.model import design_params, evaluate
from axisopt.model.frf import chain_at, frf
from axisopt.physics.dynamics import drive_train_compliance
from axisopt.report.methods import frf_dict, plot_frf

ROOT = Path(__file__).resolve().parents[2]


def _design_files():
    out = []
    for f in sorted(
        list((ROOT / "problems").glob("*.yaml")) + list((ROOT / "problems" / "data").glob("*.yaml"))
    ):
        doc = yaml.safe_load(f.read_text(encoding="utf-8"))
        if isinstance(doc, dict) and "parts" in doc:
            out.append(f)
    return out


DESIGNS = _design_files()


@pytest.fixture(scope="module")
def evals():
    return {f.name: evaluate(load_design(f)) for f in DESIGNS}


def test_frf_static_compliance_motor_held(evals):
    ev = evals["vmc_x_design.yaml"]
    res = frf(ev, freqs=[0.01], motor_held=True)
    assert len(res["positions"]) == 3
    for q in res["positions"]:
        i = q["index"]
        expect_um = 1e6 / ev.at("k_total", i)
        assert q["magnitude_um_per_N"][0] == pytest.approx(expect_um, rel=1e-6)


@pytest.mark.parametrize(
    "name", ["vmc_x_design.yaml", "teaching_design.yaml", "custom_parts_design.yaml"]
)
def test_frf_peaks_at_modes(evals, name):
    ev = evals[name]
    ref = frf(ev, freqs=[1.0])
    grids = []
    for q in ref["positions"]:
        for fm in q["modes_Hz"]:
            grids.append(np.linspace(0.97 * fm, 1.03 * fm, 1501))
    f = np.unique(np.concatenate(grids))

    def peaks(res):
        out = []
        for q in res["positions"]:
            h = q["magnitude_um_per_N"]
            k = np.where((h[1:-1] > h[:-2]) & (h[1:-1] > h[2:]))[0] + 1
            out.append(f[k])
        return out

    # lightly damped: a peak within 2 % of each mode, and every peak belongs to a mode
    light = frf(ev, freqs=f, damping_scale=0.01)
    for q, pk in zip(light["positions"], peaks(light)):
        for fm in q["modes_Hz"]:
            assert np.any(np.abs(pk / fm - 1.0) < 0.02), (fm, pk)
    # the model's damping: the first mode still peaks within 3 % (it shifts down with damping)
    real = frf(ev, freqs=f)
    for q, pk in zip(real["positions"], peaks(real)):
        f1 = q["modes_Hz"][0]
        assert np.any(np.abs(pk / f1 - 1.0) < 0.03), (f1, pk)


def test_frf_dynamic_stiffness_form(evals):
    """F/X of the free-motor model: s * (degree 5) / (degree 4); ~ c_g w at low and ~ m w^2 at high
    frequency."""
    ev = evals["vmc_x_design.yaml"]
    p = design_params(ev.design)
    i = 0
    m = chain_at(ev, p, i)
    r = m["lead"] / (2.0 * math.pi)
    kc, cc, k, ca, cg = (
        m["coupling_stiffness"],
        m["coupling_damping"],
        m["axial_stiffness"],
        m["chain_damping"],
        m["table_damping"],
    )
    a11 = [kc, cc, m["motor_inertia"]]
    a12 = [-kc, -cc]
    a22 = [kc + k * r**2, cc + ca * r**2, m["screw_inertia"]]
    a23 = [-k * r, -ca * r]
    a33 = [k, ca + cg, m["mass"]]
    det = P.polysub(
        P.polymul(a11, P.polysub(P.polymul(a22, a33), P.polymul(a23, a23))),
        P.polymul(P.polymul(a12, a12), a33),
    )
    cof = P.polysub(P.polymul(a11, a22), P.polymul(a12, a12))
    assert len(det) == 7 and len(cof) == 5
    assert abs(det[0]) < 1e-12 * kc**2 * k  # the rigid-body root s = 0 of the free motor
    det[0] = 0.0
    f = np.array([1e-4, 3.0, 150.0, 2000.0, 1e5])
    s = 2j * math.pi * f
    fx = 1.0 / frf(ev, freqs=f)["positions"][0]["compliance_m_per_N"]
    assert np.allclose(fx, P.polyval(s, det) / P.polyval(s, cof), rtol=1e-6)
    # asymptotes
    lo, hi = np.array([1e-6, 1e-5]), np.array([1e6, 1e7])
    z_lo = np.abs(1.0 / frf(ev, freqs=lo)["positions"][0]["compliance_m_per_N"])
    z_hi = np.abs(1.0 / frf(ev, freqs=hi)["positions"][0]["compliance_m_per_N"])
    assert math.log10(z_lo[1] / z_lo[0]) == pytest.approx(1.0, abs=1e-3)
    assert math.log10(z_hi[1] / z_hi[0]) == pytest.approx(2.0, abs=1e-3)
    assert z_lo[0] == pytest.approx(cg * 2 * math.pi * lo[0], rel=1e-3)
    assert z_hi[1] == pytest.approx(m["mass"] * (2 * math.pi * hi[1]) ** 2, rel=1e-2)
    # same dynamic stiffness straight from the physics function
    h = drive_train_compliance(hi, **m)
    assert np.allclose(np.abs(1.0 / h), z_hi)


def test_frf_default_grid_json_and_plot(evals, tmp_path):
    ev = evals["teaching_design.yaml"]
    res = frf(ev)
    f = res["frequency_Hz"]
    top = max(q["modes_Hz"][1] for q in res["positions"])
    assert len(f) == 800 and f[0] == pytest.approx(5.0) and f[-1] == pytest.approx(3.0 * top)
    assert [q["position_mm"] for q in res["positions"]][0] == pytest.approx(0.0)
    assert res["positions"][-1]["position_mm"] == pytest.approx(ev.design.axis.stroke * 1e3)
    js = frf_dict(res)
    text = json.dumps(js, allow_nan=False)
    assert "magnitude_um_per_N" in text and len(js["positions"][1]["phase_deg"]) == 800
    out = tmp_path / "frf.png"
    plot_frf(frf(ev, freqs=f[::40]), str(out))  # a coarse grid keeps the test fast
    assert out.stat().st_size > 1000
    with pytest.raises(InputError):
        plot_frf(res, str(tmp_path / "frf.txt"))


@pytest.mark.parametrize("bad", [[], [0.0, 1.0], [float("nan")], [[1.0, 2.0]]])
def test_frf_bad_frequencies(evals, bad):
    with pytest.raises(InputError):
        frf(evals["teaching_design.yaml"], freqs=bad)

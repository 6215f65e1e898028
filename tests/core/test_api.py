"""axisopt in a notebook (issue 30 item 3): ``import axisopt`` is light, its functions return
results with ``to_frame()`` (units in the column names), a short repr in engineering units and an
HTML table."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "problems"


def _python(code: str) -> str:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    out = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True, timeout=300
    )
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_import_axisopt_loads_no_heavy_module():
    out = _python(
        "import sys, axisopt\n"
        "print(sorted(m for m in ('pandas', 'casadi', 'numpy', 'matplotlib', 'axisopt.api') "
        "if m in sys.modules))\n"
        "print('evaluate' in dir(axisopt), callable(axisopt.load_design))"
    )
    assert out.splitlines() == ["[]", "True True"]


def test_unknown_attribute_is_an_attribute_error():
    import axisopt

    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        axisopt.nothing  # noqa: B018


NOTEBOOK = """
import json
import axisopt

ev = axisopt.evaluate("problems/teaching_design.yaml")
profile = ev.to_frame()
checks = ev.check_table()
res = axisopt.solve("problems/teaching_problem.yaml")
designs = res.to_frame()
print(json.dumps({
    "ev_repr": repr(ev), "res_repr": repr(res), "ev_html": ev._repr_html_(), "res_html": res._repr_html_(),
    "profile_columns": list(profile.columns), "rows": len(profile),
    "stiffness_min": float(profile["stiffness [N/um]"].min()),
    "summary_stiffness": ev.summary()["min_stiffness [N/um]"],
    "checks_columns": list(checks.columns), "checks": checks.to_dict("records"),
    "design_columns": list(designs.columns), "best": designs.iloc[0].to_dict(),
    "best_objective": res.best.objective, "n_designs": len(designs),
}))
"""  # noqa: E501


def test_notebook_session_in_a_fresh_interpreter():
    d = json.loads(_python(NOTEBOOK))
    # concise reprs in engineering units (today's dataclass dump was 23 kB of SI values)
    assert len(d["ev_repr"]) < 1000 and len(d["res_repr"]) < 1000
    assert d["ev_repr"].startswith("Evaluation('teaching axis 25x5', fixed-free")
    assert f"min stiffness {d['summary_stiffness']:.3g} N/um" in d["ev_repr"]
    assert " Hz" in d["ev_repr"] and " EUR" in d["ev_repr"] and "max_speed=" not in d["ev_repr"]
    # the shipped teaching design fails its nut life on purpose
    assert "FAIL nut_life" in d["ev_repr"]
    assert d["res_repr"].startswith("SolveResult(optimal, 'teaching'")
    assert f"{d['best_objective']:.3g} N/um" in d["res_repr"] and "proven yes" in d["res_repr"]
    # profile over the stroke, units in the column names
    assert d["profile_columns"][:4] == [
        "position [mm]",
        "stiffness [N/um]",
        "screw_stiffness [N/um]",
        "frequency [Hz]",
    ]
    assert d["stiffness_min"] == pytest.approx(d["summary_stiffness"])
    assert 20 < d["stiffness_min"] < 500  # N/um, not N/m
    # checks with available / needed / unit / margin
    assert d["checks_columns"] == [
        "check",
        "label",
        "available",
        "needed",
        "unit",
        "margin",
        "pass",
    ]
    life = next(r for r in d["checks"] if r["check"] == "nut_life")
    assert life["unit"] == "h" and life["pass"] is False
    assert life["margin"] == pytest.approx(life["available"] / life["needed"], rel=1e-6)
    speed = next(r for r in d["checks"] if r["check"] == "critical_speed")
    assert speed["unit"] == "rpm" and speed["available"] > speed["needed"] > 100
    # best design and runners-up
    assert d["n_designs"] == 5
    assert {
        "objective [N/um]",
        "min_stiffness [N/um]",
        "min_frequency [Hz]",
        "cost [EUR]",
        "nut_preload [N]",
        "drag_torque [N.m]",
        "life [h]",
        "motor",
        "coupling",
    } <= set(d["design_columns"])
    best = d["best"]
    assert best["rank"] == 1 and best["objective [N/um]"] == pytest.approx(d["best_objective"])
    # the problem's limits
    assert best["cost [EUR]"] <= 3500 and best["drag_torque [N.m]"] <= 1.2 + 1e-9
    assert "<table>" in d["ev_html"] and "N/um" in d["ev_html"] and "nut L10 life" in d["ev_html"]
    assert "<table>" in d["res_html"] and best["screw"] in d["res_html"]


def test_checks_keep_their_margins_for_existing_callers():
    import axisopt

    ev = axisopt.evaluate(PROBLEMS / "teaching_design.yaml")
    margins = ev.checks()
    assert set(margins) >= {"critical_speed", "nut_life"} and all(
        isinstance(v, float) for v in margins.values()
    )
    table = ev.check_table().set_index("check")
    assert table.loc["nut_life", "margin"] == pytest.approx(margins["nut_life"])


def test_pareto_front_is_a_sequence_with_a_frame_and_figure(tmp_path, monkeypatch):
    import axisopt

    res = axisopt.solve(PROBLEMS / "pareto_problem.yaml")
    front = res.pareto
    assert len(front) == len(front.points) > 1
    assert list(front)[0] is front[0]
    df = front.to_frame()
    assert len(df) == len(front)
    assert df["min_stiffness [N/um]"].tolist() == [p.min_stiffness for p in front]
    assert repr(front).startswith(f"ParetoFront({len(front)} non-dominated of")
    assert "[N/um]" in repr(front) and "[EUR]" in repr(front)
    # restored after the test: others read paths relative to the repository
    monkeypatch.chdir(tmp_path)
    fig = axisopt.plot_pareto(res)
    assert fig.axes and list(tmp_path.iterdir()) == []  # no file without a path
    axisopt.plot_pareto(front, tmp_path / "front.png")
    assert (tmp_path / "front.png").stat().st_size > 1000


def test_infeasible_result_frame_lists_the_misses():
    import axisopt

    res = axisopt.solve(PROBLEMS / "infeasible_problem.yaml", sensitivities=False)
    assert res.status == "infeasible" and res.best is None
    df = res.to_frame()
    assert len(df) == len(res.infeasibility.closest) > 0
    miss = [c for c in df.columns if c.startswith("miss ") and c.endswith(" [%]")]
    assert miss and df[miss[0]].iloc[0] > 0
    assert repr(res).startswith("SolveResult(infeasible, ") and len(repr(res)) < 1000
    assert "closest design misses" in repr(res)


def test_compare_designs_side_by_side():
    import axisopt

    cmp = axisopt.compare(
        PROBLEMS / "teaching_design.yaml", axisopt.load_design(PROBLEMS / "vmc_x_design.yaml")
    )
    assert len(cmp) == 2
    df = cmp.to_frame()
    assert df["label"].tolist() == ["teaching axis 25x5", "VMC X axis, 40x20 double nut"]
    ev = cmp[0].evaluation
    assert df["min_stiffness [N/um]"].iloc[0] == pytest.approx(ev.minimum("k_total")[0] / 1e6)
    assert f"{df['min_stiffness [N/um]'].iloc[1]:.3g} N/um" in repr(cmp)
    assert "teaching axis 25x5" in cmp._repr_html_() and "weakest" in cmp.text()


def test_diagnose_returns_a_diagnosis_with_its_parameters():
    import axisopt

    diag = axisopt.diagnose(
        PROBLEMS / "data" / "table_x_stiffness.csv", PROBLEMS / "data" / "table_x.yaml"
    )
    assert diag.verdict == "support_condition"
    df = diag.to_frame()
    row = df.set_index("parameter").loc["far_end_stiffness"]
    assert row["effect"] == "support_condition" and row["unit"] == "N/um" and row["value"] > 0
    assert repr(diag).startswith(
        "Diagnosis('table-x'; verdict support_condition; held-out error down "
    )


STUDY = """name: api-study
base:
  name: api-base
  axis: {stroke: 400 mm, moving_mass: 120 kg, mounting: fixed-supported, max_speed: 30 m/min,
         axial_load: 2000 N, acceleration: 3 m/s^2, mean_speed: 8 m/min}
  objective: stiffness
  limits: {max_cost: 2500 EUR, max_drag_torque: 1.2 N.m, min_life: 12000 h}
  catalog: {vendors: [HIWIN], nut_types: [double], mountings: [fixed-supported]}
  continuous:
    nut_preload: {min: 100 N, max: 10 kN}
sweep:
  axis.moving_mass: [80 kg, 200 kg]
"""


def test_study_runs_in_process_and_gives_its_table(tmp_path):
    import axisopt

    spec = tmp_path / "s.yaml"
    spec.write_text(STUDY)
    res = axisopt.study(spec, tmp_path / "out")
    df = res.to_frame()
    assert df["axis.moving_mass [kg]"].tolist() == [80.0, 200.0]
    assert set(df["status"]) == {"optimal"}
    assert (df["min_stiffness [N/um]"] > 10).all()
    assert repr(res).startswith("StudyResult('api-study'; cases 2; solved now 2")
    assert "min_stiffness [N/um]" in res._repr_html_()


def test_study_rerun_speaks_python(tmp_path):
    # issue 42: re-running axisopt.study(...) told the Python user to "pass --resume"
    import axisopt
    from axisopt.errors import InputError

    spec = tmp_path / "s.yaml"
    spec.write_text(STUDY)
    axisopt.study(spec, tmp_path / "out")
    with pytest.raises(InputError) as exc:
        axisopt.study(spec, tmp_path / "out")
    msg = str(exc.value)
    assert "resume=True" in msg and "overwrite=True" in msg and "--resume" not in msg
    assert repr(axisopt.study(spec, tmp_path / "out", resume=True)).startswith(
        "StudyResult('api-study'; cases 2; solved now 0; kept 2"
    )
    again = axisopt.study(spec, tmp_path / "out", overwrite=True)
    assert again.summary.solved == 2 and len(again.to_frame()) == 2
    with pytest.raises(InputError, match="give one of them"):
        axisopt.study(spec, tmp_path / "out", resume=True, overwrite=True)


def test_best_design_and_binding_limits_have_units_and_frames():
    # issue 42: res.best and res.binding had no units and no to_frame()
    import axisopt

    res = axisopt.solve(PROBLEMS / "teaching_problem.yaml")
    b = res.best
    assert repr(b).startswith(f"Candidate(rank 1, {b.mounting} {b.screw} / ")
    assert (
        f"min stiffness {b.min_stiffness:.3g} N/um" in repr(b)
        and " EUR" in repr(b)
        and "\n" not in repr(b)
    )
    row = b.to_frame()
    assert row.shape[0] == 1 and row["min_stiffness [N/um]"].iloc[0] == b.min_stiffness
    assert "cost [EUR]" in b._repr_html_()
    assert len(res.binding) >= 1 and repr(res.binding).startswith(
        f"Bindings({len(res.binding)} limits"
    )
    df = res.binding.to_frame()
    assert list(df.columns) == [
        "limit",
        "unit",
        "value",
        "at optimum",
        "relaxed to",
        "objective gain [N/um]",
        "binding",
    ]
    assert df["limit"].tolist() == [x.limit for x in res.binding] and df["unit"].tolist() == [
        x.unit for x in res.binding
    ]
    first = res.binding[0]
    assert repr(first).startswith(f"Binding({first.limit} ") and (first.unit in repr(first))
    assert f"value [{first.unit}]" in first.to_frame().columns
    assert [x.to_dict() for x in res.binding] == res.to_dict()["binding"]


def test_design_parts_table_in_vendor_units():
    # issue 42: every part has a unit-bearing table; the values as the catalog file quotes them
    import csv

    import axisopt

    d = axisopt.load_design(PROBLEMS / "vmc_x_design.yaml")
    df = d.to_frame()
    assert list(df.columns) == ["part", "id", "column", "value", "unit"]
    assert set(df["part"]) == set(d.part_ids())
    nut = df[(df["part"] == "nut") & (df["column"] == "stiffness")].iloc[0]
    with open(ROOT / "catalogs" / "nuts.csv", encoding="utf-8") as fh:
        row = next(r for r in csv.DictReader(fh) if r["id"] == nut["id"])
    assert nut["unit"] == "N/um" and nut["value"] == pytest.approx(float(row["stiffness [N/um]"]))
    lead = df[(df["part"] == "screw") & (df["column"] == "lead")].iloc[0]
    assert lead["unit"] == "mm" and lead["value"] == pytest.approx(d.screw["lead"] * 1e3)
    assert "N/um" in d._repr_html_()

"""Figures in Jupyter (issue 42 item 3): a notebook executed headless in a fresh kernel shows every
plot of axisopt as an image, with no ``%matplotlib`` magic and no pyplot import in the notebook.

nbformat, nbclient and ipykernel come with the ``test`` extra (pyproject.toml); without them the
test is skipped, unless AXISOPT_REQUIRE_NOTEBOOK=1 (as .ci/run sets) makes that a failure."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# one cell per public plot function; each cell ends with the figure, as a user would write it
CELLS = {
    "profiles": 'import axisopt\nev = axisopt.evaluate("problems/teaching_design.yaml")\n'
    "axisopt.plot_profiles(ev)",
    "profiles with a drive": 'axisopt.plot_profiles(axisopt.evaluate("problems/vmc_x_design.yaml"))',  # noqa: E501
    "pareto": 'res = axisopt.solve("problems/pareto_problem.yaml", sensitivities=False)\n'
    "axisopt.plot_pareto(res)",
    "frf": (
        "from axisopt.model.frf import frf\nfrom axisopt.report.methods import plot_frf\n"
        "plot_frf(frf(ev))"
    ),
    "no pyplot": 'import sys\nprint("matplotlib.pyplot" in sys.modules)',
}
IMAGE = ("image/png", "image/svg+xml")


@pytest.fixture(scope="module")
def notebook_modules():
    try:
        import nbclient
        import nbformat
    except ImportError as exc:
        if os.environ.get("AXISOPT_REQUIRE_NOTEBOOK") == "1":
            pytest.fail(f"AXISOPT_REQUIRE_NOTEBOOK=1 but {exc.name} is not installed")
        pytest.skip(f"{exc.name} not installed (pip install -e '.[test]')")
    try:
        import ipykernel  # noqa: F401
    except ImportError:
        if os.environ.get("AXISOPT_REQUIRE_NOTEBOOK") == "1":
            pytest.fail("AXISOPT_REQUIRE_NOTEBOOK=1 but ipykernel is not installed")
        pytest.skip("ipykernel not installed (pip install -e '.[test]')")
    return nbformat, nbclient


def test_every_plot_shows_as_an_image_in_a_fresh_kernel(notebook_modules):
    nbformat, nbclient = notebook_modules
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(src) for src in CELLS.values()]
    env = {"PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    client = nbclient.NotebookClient(
        nb, kernel_name="python3", timeout=120, resources={"metadata": {"path": str(ROOT)}}
    )
    old = {k: os.environ.get(k) for k in env}
    # the kernel inherits the environment: it imports this checkout's axisopt
    os.environ.update(env)
    try:
        client.execute()
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    for (name, _), cell in zip(CELLS.items(), nb.cells):
        errors = [o for o in cell.outputs if o.output_type == "error"]
        assert not errors, f"{name}: {errors[0].ename}: {errors[0].evalue}"
        if name == "no pyplot":
            # the plots never imported pyplot (so never chose a backend for the user)
            assert cell.outputs[0].text.strip() == "False"
            continue
        shown = [o for o in cell.outputs if o.output_type == "execute_result"]
        assert shown, f"{name}: the cell shows nothing"
        data = shown[0].data
        assert any(m in data for m in IMAGE), (
            f"{name}: shown as {data.get('text/plain')!r}, not as an image"
        )
        png = data.get("image/png", "")
        assert len(png) > 10_000, f"{name}: an image of only {len(png)} base64 characters"

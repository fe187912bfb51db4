"""The Python examples run as a user runs them, and the Jupyter notebook is executed, so none of
them can rot: each checks its own numbers (asserts inside) and writes its figures."""

import os
import pathlib
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples" / "python"


def run_example(script, *args):
    env = dict(os.environ, MPLBACKEND="Agg")
    result = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)],
                            capture_output=True, text=True, env=env, timeout=240)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_quarter_car_bode(tmp_path):
    out = run_example("quarter_car_bode.py", tmp_path)
    assert "DC gain 1" in out
    for name in ["quarter_car_bode.png", "quarter_car_step.png"]:
        assert (tmp_path / name).stat().st_size > 20_000  # a plot, not an empty canvas


def test_tennis_racket(tmp_path):
    out = run_example("tennis_racket.py", tmp_path)
    assert "splitting" in out
    assert (tmp_path / "tennis_racket.png").stat().st_size > 20_000


def test_mesh_mass_properties():
    out = run_example("mesh_mass_properties.py")
    lines = out.splitlines()
    assert lines[0].startswith("mesh")
    assert any(line.startswith("bus.stl") for line in lines)
    assert any(line.startswith("l_bracket.obj") for line in lines)


def test_franklin_notebook_executes(monkeypatch):
    # The kernel is another process started in the notebook's folder: give it absolute paths.
    paths = os.environ.get("PYTHONPATH", "").split(os.pathsep)
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(str(pathlib.Path(p).resolve()) for p in paths if p))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    monkeypatch.delenv("MPLBACKEND", raising=False)  # the kernel's inline backend shows figures
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    notebook = nbformat.read(EXAMPLES / "franklin_satellites.ipynb", as_version=4)
    client = nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3",
                                     resources={"metadata": {"path": str(EXAMPLES)}})
    client.execute()  # raises CellExecutionError, with the cell, on any failed assert
    images = [o for cell in notebook.cells if cell.cell_type == "code"
              for o in cell.get("outputs", []) if "image/png" in o.get("data", {})]
    assert len(images) >= 2

"""The Python examples run as a user runs them, and the Jupyter notebook is executed, so none of
them can rot: the numbers each script prints are checked here against an independent reference
(a closed form, scipy on the textbook's equations), the notebook's against the closed forms its
own cells assert, and the figures are written."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np
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
    # The step's figures against Y/R of the textbook's two-mass model (FPE ch. 2; the model
    # file's m1 = 20, m2 = 375 kg, ks = 130 kN/m, kw = 1 MN/m, b = 9.8 kN·s/m), stepped by scipy
    # on a 1 µs grid: each printed figure within half a unit of its last digit (plus the grid).
    from scipy import signal
    m1, m2, ks, kw, b = 20.0, 375.0, 130000.0, 1e6, 9800.0
    num = [kw * b / (m1 * m2), kw * ks / (m1 * m2)]
    den = [1, b / m1 + b / m2, ks / m1 + ks / m2 + kw / m1, kw * b / (m1 * m2), kw * ks / (m1 * m2)]
    t, y = signal.step((num, den), T=np.linspace(0.0, 3.0, 3_000_001))

    def crossing(level):
        i = int(np.argmax(y >= level))
        return t[i - 1] + (level - y[i - 1]) * (t[i] - t[i - 1]) / (y[i] - y[i - 1])

    reference = {"rise time": crossing(0.9) - crossing(0.1), "overshoot": (y.max() - 1) * 100,
                 "settling time": t[np.nonzero(np.abs(y - 1) > 0.02)[0][-1] + 1],
                 "peak": y.max(), "at": t[y.argmax()]}
    printed = re.search(r"rise time ([\d.]+) s, overshoot ([\d.]+) %, settling time ([\d.]+) s, "
                        r"peak ([\d.]+) at ([\d.]+) s", out)
    assert printed, out
    for (name, expected), text in zip(reference.items(), printed.groups()):
        decimals = len(text.split(".")[1])
        assert abs(float(text) - expected) <= 0.5 * 10.0**-decimals + 2e-6, (name, text, expected)


def test_tennis_racket(tmp_path):
    out = run_example("tennis_racket.py", tmp_path)
    assert "splitting" in out
    assert (tmp_path / "tennis_racket.png").stat().st_size > 20_000
    # ω_y = A sn(λ t) changes sign every 2K(k)/λ (Landau & Lifshitz §37; I = diag(1, 2, 3),
    # ω0 = (0.01, 2, 0.01) rad/s, H² > 2 T I2): 10.977573 s. The example prints the interval
    # to 1e-5 s; the splitting method at dt = 1e-3 s and the linear interpolation of each
    # crossing agree with it within that (3 units allowed).
    from scipy.special import ellipk
    inertia, w = np.array([1.0, 2.0, 3.0]), np.array([0.01, 2.0, 0.01])
    two_t, h2 = (inertia * w * w).sum(), ((inertia * w) ** 2).sum()
    i1, i2, i3 = inertia
    lam = np.sqrt((i3 - i2) * (h2 - two_t * i1) / (i1 * i2 * i3))
    k2 = (i2 - i1) * (two_t * i3 - h2) / ((i3 - i2) * (h2 - two_t * i1))
    printed = re.search(r"changes sign at t = ([\d., ]+) s: every ([\d.]+) s", out)
    assert printed, out
    assert len(printed.group(1).split(",")) >= 2
    assert abs(float(printed.group(2)) - 2 * ellipk(k2) / lam) <= 3e-5, printed.group(2)


def mesh_rows(out):
    """{mesh name: (units, mass, volume, [com], [principal moments])} from the example's table."""
    rows = {}
    for line in out.splitlines()[2:]:
        name, units, source, mass, volume, rest = line.split(None, 5)
        com, moments = rest.split("]")
        rows[name] = (units, float(mass), float(volume),
                      [float(x) for x in com.strip("[ ").split(",")],
                      [float(x) for x in moments.split(",")])
    return rows


def test_mesh_mass_properties_match_the_closed_forms():
    rows = mesh_rows(run_example("mesh_mass_properties.py"))
    # The bus: a 1.0 x 0.75 x 1.25 m aluminium box with a corner at the origin, read in metres
    # (its header says so): m = 2700 x 0.9375 kg, I = m (b² + c²)/12 about its centre.
    units, mass, volume, com, moments = rows["bus.stl"]
    m = 2700 * 1.0 * 0.75 * 1.25
    assert units == "m"
    assert volume == pytest.approx(0.9375, rel=1e-6)  # the table prints 6 significant digits
    assert mass == pytest.approx(m, rel=1e-6)
    assert com == pytest.approx([0.5, 0.375, 0.625], abs=5e-6)
    expected = sorted(m / 12 * (a * a + b * b) for a, b in [(0.75, 1.25), (1.0, 1.25), (1.0, 0.75)])
    assert sorted(moments) == pytest.approx(expected, rel=1e-6)
    # The L bracket, drawn in millimetres (its header says so): an 80 x 40 x 6 base leg and a
    # 6 x 40 x 60 upright, 33 600 mm³ of aluminium, 0.09072 kg.
    units, mass, volume, com, moments = rows["l_bracket.obj"]
    assert units == "mm"
    assert volume == pytest.approx(33600e-9, rel=1e-6)
    assert mass == pytest.approx(2700 * 33600e-9, rel=1e-6)
    # Centre of mass: the legs' centres (40, 0, 3) mm and (3, 0, 36) mm weighted 19 200 : 14 400.
    assert com == pytest.approx([(40 * 19200 + 3 * 14400) / 33600e3, 0,
                                 (3 * 19200 + 36 * 14400) / 33600e3], abs=5e-6)


def test_mesh_mass_properties_in_given_units_and_refusals(tmp_path):
    # --units mm for every file: the bus read as millimetres weighs a billionth as much.
    rows = mesh_rows(run_example("mesh_mass_properties.py", "--units", "mm"))
    assert rows["bus.stl"][1] == pytest.approx(2700 * 0.9375e-9, rel=1e-6)
    # A folder with no mesh is an error, not an empty table.
    result = subprocess.run([sys.executable, str(EXAMPLES / "mesh_mass_properties.py"), str(tmp_path)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 1
    assert "no .stl or .obj file in" in result.stderr


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
    assert len(images) >= 4  # the satellites two, the LQR pendulum two

"""Shared fixtures of the Python tests: where the sources and the momenta command are, and how to
run it, so each binding can be held against the C++ result on the same input."""

import csv
import io
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MOMENTA_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE_DIR / "examples"
# A 1 kg slider on a 1e8 N/m spring: RK4 at dt = 0.01 s (ω h = 100) overflows within 1 s.
STIFF_SPRING = SOURCE_DIR / "tests" / "data" / "models" / "stiff_spring.yaml"


def cli_path():
    path = os.environ.get("MOMENTA_CLI")
    if path:
        return path
    return str(SOURCE_DIR / "build" / "apps" / "momenta" / "momenta")


def dynamics_reference(model_path, **state):
    """The dynamics algorithms called directly from C++ (tests/python/dynamics_reference.cpp) on
    the model file and the state given (q, v, tau, vdot, body, point): a dict of every result."""
    exe = os.environ.get("MOMENTA_DYNAMICS_REFERENCE",
                         str(SOURCE_DIR / "build" / "tests" / "dynamics_reference"))
    as_lists = {k: np.asarray(x).tolist() for k, x in state.items()}
    result = subprocess.run([exe, str(model_path)], input=json.dumps(as_lists),
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def run_cli(*args):
    """Runs the momenta command, returns its standard output; fails the test on a non-zero exit."""
    result = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result.stdout


def cli_json(*args):
    return json.loads(run_cli(*args, "--json"))


def cli_csv(*args):
    """The CSV the command writes to standard output, as (header, rows × columns array)."""
    reader = csv.reader(io.StringIO(run_cli(*args)))
    header = next(reader)
    return header, np.array([[float(x) for x in row] for row in reader])


@pytest.fixture
def examples():
    return EXAMPLES

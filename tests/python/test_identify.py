"""momenta.inertial_regressor, base_parameters and estimate_inertia against RNEA (a second
algorithm), the textbook two-link arm's closed form computed here with numpy (an independent
route), and `momenta identify` on the same data."""

import numpy as np
import pytest

import momenta

from conftest import EXAMPLES, cli_json

ARM = EXAMPLES / "identification" / "two_link_arm.yaml"
LOG = EXAMPLES / "identification" / "two_link_arm_log.csv"


@pytest.mark.parametrize("name", ["cart_pendulum.yaml", "flyball_governor.yaml", "heavy_top.yaml"])
def test_regressor_times_the_parameters_is_rnea(name):
    model = momenta.load_model(EXAMPLES / name)
    pi, names = momenta.inertial_parameters(model)
    assert len(names) == len(pi) and names[0].endswith(".m")
    ws = momenta.Workspace(model)
    rng = np.random.default_rng(3)
    for _ in range(5):
        q = np.array(model.initial_q, dtype=float)
        v = rng.uniform(-1, 1, model.nv)
        vdot = rng.uniform(-2, 2, model.nv)
        tau = ws.rnea(q, v, vdot)
        assert np.max(np.abs(momenta.inertial_regressor(model, q, v, vdot) @ pi - tau)) <= 1e-12 * max(1.0, np.max(np.abs(tau)))


def spong_efforts(q, v, a, m1=2.0, l1=0.8, lc1=0.35, I1=0.12, m2=1.5, lc2=0.4, I2=0.06, g=9.81):
    """Spong, Hutchinson & Vidyasagar §7.4.1, angles from the downward vertical, rows of samples."""
    c2, h = np.cos(q[:, 1]), m2 * l1 * lc2 * np.sin(q[:, 1])
    d11 = m1 * lc1**2 + m2 * (l1**2 + lc2**2 + 2 * l1 * lc2 * c2) + I1 + I2
    d12 = m2 * (lc2**2 + l1 * lc2 * c2) + I2
    d22 = m2 * lc2**2 + I2
    g2 = m2 * lc2 * g * np.sin(q[:, 0] + q[:, 1])
    tau1 = d11 * a[:, 0] + d12 * a[:, 1] - h * (2 * v[:, 0] * v[:, 1] + v[:, 1]**2) \
        + (m1 * lc1 + m2 * l1) * g * np.sin(q[:, 0]) + g2
    tau2 = d12 * a[:, 0] + d22 * a[:, 1] + h * v[:, 0]**2 + g2
    return np.column_stack([tau1, tau2])


def test_the_arms_base_parameters_from_numpy_data():
    model = momenta.load_model(ARM)
    rng = np.random.default_rng(8)
    n = 300
    q, v, a = rng.uniform(-np.pi, np.pi, (n, 2)), rng.uniform(-2, 2, (n, 2)), rng.uniform(-5, 5, (n, 2))
    tau = spong_efforts(q, v, a) + rng.normal(0, 0.03, (n, 2))
    e = momenta.estimate_inertia(model, q, v, a, tau)
    built = np.array([0, -(2 * 0.35 + 1.5 * 0.8), 0.12 + 2 * 0.35**2 + 1.5 * 0.8**2, 0, -1.5 * 0.4,
                      0.06 + 1.5 * 0.4**2])
    assert e["names"][2] == "upper.I_yy + 0.64·lower.m"
    assert np.all(np.abs(e["estimate"] - built) < 4 * e["standard_error"])
    assert np.all((e["lower"] < e["estimate"]) & (e["estimate"] < e["upper"]))
    assert np.allclose(e["noise"], 0.03, rtol=0.15)
    assert e["degrees_of_freedom"] == 2 * n - 6
    assert e["consistency"] == {"upper": "consistent", "lower": "consistent"}
    assert np.max(np.abs(e["regrouping"] @ e["parameters"] - e["estimate"])) < 1e-12
    # The fitted efforts differ from the measured by the noise alone (5σ).
    assert np.max(np.abs(e["fitted"] - tau)) < 5 * 0.03


def test_estimate_is_the_command_lines():
    model = momenta.load_model(ARM)
    data = np.loadtxt(LOG, delimiter=",", skiprows=1)
    e = momenta.estimate_inertia(model, data[:, 1:3], data[:, 3:5], data[:, 5:7], data[:, 7:9])
    j = cli_json("identify", ARM, "--data", LOG)
    assert [p["estimate"] for p in j["base_parameters"]] == e["estimate"].tolist()
    assert [p["name"] for p in j["base_parameters"]] == e["names"]


def test_bad_samples_raise_naming_the_argument():
    model = momenta.load_model(ARM)
    with pytest.raises(ValueError, match="tau"):
        momenta.estimate_inertia(model, np.zeros((5, 2)), np.zeros((5, 2)), np.zeros((5, 2)), np.zeros((4, 2)))
    q = np.zeros((5, 2))
    q[3, 1] = np.nan
    with pytest.raises(momenta.InvalidArgument, match="q row 3 column 1 is nan"):
        momenta.estimate_inertia(model, q, np.zeros((5, 2)), np.zeros((5, 2)), np.zeros((5, 2)))

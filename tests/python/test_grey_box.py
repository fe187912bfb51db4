"""momenta.identify (grey-box fits of an identification file) on logs made here by SciPy from the
textbook's equation of a damped pendulum (solve_ivp, an independent route), with seeded noise:
the truth inside the 95 % intervals, the noise found, the identified model written and read back,
and the same numbers as `momenta identify --json`."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import momenta

from conftest import EXAMPLES, cli_json

C_TRUE, THETA0_TRUE, SIGMA = 0.12, 40.0, 0.002  # N·m·s/rad, deg, rad


@pytest.fixture
def experiment(tmp_path):
    # m L² θ̈ + c θ̇ + m g L sin θ = 0 with m = 1 kg, L = 1 m (damped_pendulum.yaml's rig).
    t = np.linspace(0.0, 20.0, 401)
    sol = solve_ivp(lambda s, z: [z[1], -9.81 * math.sin(z[0]) - C_TRUE * z[1]], (0.0, 20.0),
                    [math.radians(THETA0_TRUE), 0.0], t_eval=t, method="DOP853", rtol=1e-12,
                    atol=1e-14)
    angle = sol.y[0] + np.random.default_rng(11).normal(0.0, SIGMA, t.size)
    np.savetxt(tmp_path / "decay.csv", np.column_stack([t, angle]), delimiter=",",
               header="time,angle", comments="", fmt="%.12g")
    (tmp_path / "fit.yaml").write_text(
        f"model: {EXAMPLES / 'identification' / 'damped_pendulum.yaml'}\n"
        "parameters:\n"
        "  - {name: c, path: joints.pivot.damping}\n"
        "  - {name: theta0, path: joints.pivot.q0_deg, guess: 35, positive: false}\n"
        "experiments:\n"
        "  - {name: decay, data: decay.csv, outputs: [{column: angle, channel: theta}]}\n")
    return tmp_path


def test_the_truth_lies_in_the_intervals(experiment):
    r = momenta.identify(str(experiment / "fit.yaml"))
    assert r["converged"], r["termination"]
    assert r["identifiable"] and r["undetermined"] == []
    for i, truth in enumerate([C_TRUE, THETA0_TRUE]):
        assert r["lower"][i] <= truth <= r["upper"][i], (r["names"][i], r["estimate"][i])
        assert 0 < r["standard_error"][i] < 0.02 * abs(truth)
    (channel,) = r["channels"]
    assert channel["unit"] == "rad" and not channel["noise_given"]
    # σ from 401 residuals: relative spread 1/√(2·399) ≈ 3.5 %; 15 % is over four of them.
    assert abs(channel["noise"] - SIGMA) < 0.15 * SIGMA
    assert channel["whiteness_p"] > 0.01
    assert np.max(np.abs(channel["fitted"] - channel["measured"])) < 5 * SIGMA
    assert channel["time"].shape == channel["measured"].shape == (401,)


def test_the_identified_model_reads_back_and_matches_the_command_line(experiment):
    out = experiment / "identified.yaml"
    r = momenta.identify(str(experiment / "fit.yaml"), output=str(out))
    model = momenta.load_model(out)
    assert model.initial_q[0] == pytest.approx(math.radians(r["estimate"][1]), rel=1e-12)
    with pytest.raises(Exception, match="overwrite=True"):
        momenta.identify(str(experiment / "fit.yaml"), output=str(out))
    j = cli_json("identify", str(experiment / "fit.yaml"))
    assert [p["estimate"] for p in j["parameters"]] == list(r["estimate"])


def test_profile_intervals_match_the_command_line():
    # The short noisy drive: both intervals from the profile likelihood, as the CLI's JSON says.
    fit = str(EXAMPLES / "identification" / "cruise_control_short_identify.yaml")
    r = momenta.identify(fit)
    j = cli_json("identify", fit)
    assert r["profiled"] == [True, True]
    for i, p in enumerate(j["parameters"]):
        assert p["interval_from"] == "profile likelihood"
        assert p["interval_95"] == [r["lower"][i], r["upper"][i]]
        assert p["fisher_interval_95"] == [r["fisher_lower"][i], r["fisher_upper"][i]]
        assert p["bounded"] == [True, True]
        assert r["not_quadratic"][i] > 0.1
    assert j["interval_notes"] == r["interval_notes"]
    assert j["warnings"] == r["warnings"]


def test_a_bode_test_and_each_experiments_own_numbers_match_the_command_line():
    for name in ("quarter_car_shaker_identify.yaml", "damped_pendulum_releases_identify.yaml"):
        fit = str(EXAMPLES / "identification" / name)
        r = momenta.identify(fit)
        j = cli_json("identify", fit)
        assert r["converged"], r["termination"]
        assert [p["estimate"] for p in j["parameters"]] == list(r["estimate"])
        assert [p["experiment"] or "" for p in j["parameters"]] == r["experiments"]
        assert [c["abscissa"] for c in j["channels"]] == [c["abscissa"] for c in r["channels"]]
    shaker = momenta.identify(str(EXAMPLES / "identification" / "quarter_car_shaker_identify.yaml"))
    assert [c["abscissa"] for c in shaker["channels"]] == ["frequency", "frequency"]
    assert [c["unit"] for c in shaker["channels"]] == ["dB", "deg"]
    assert shaker["linearizations"] > 0 and shaker["evaluations"] == 0
    # The measured magnitude is the CSV's |G| in dB, against its frequencies.
    data = np.loadtxt(EXAMPLES / "identification" / "quarter_car_shaker_bode.csv", delimiter=",",
                      skiprows=1)
    np.testing.assert_array_equal(shaker["channels"][0]["time"], data[:, 0])
    np.testing.assert_allclose(shaker["channels"][0]["measured"], 20 * np.log10(data[:, 1]),
                               rtol=0, atol=1e-12)

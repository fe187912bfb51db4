"""Linear analysis from Python: linearize against `momenta linearize --json` (bit-identical),
Franklin's satellite and flexible satellite against their closed forms, Bode and step against
`momenta response`, equilibria, and StateSpace built from matrices."""

import numpy as np
import pytest

import momenta

from conftest import EXAMPLES, cli_csv, cli_json, run_cli


@pytest.mark.parametrize("name", ["satellite_attitude", "flexible_satellite", "quarter_car",
                                  "double_pendulum"])
def test_linearize_is_the_command_lines(name):
    path = EXAMPLES / f"{name}.yaml"
    linear = momenta.linearize(momenta.load_model(path))
    expected = cli_json("linearize", path)
    for key in "ABCD":
        np.testing.assert_array_equal(getattr(linear, key),
                                      np.array(expected[key]).reshape(getattr(linear, key).shape))
    assert linear.state_names == expected["state_names"]
    assert linear.input_names == expected["input_names"]
    assert linear.output_names == expected["output_names"]


def test_franklin_satellite_is_one_over_i_s_squared():
    linear = momenta.linearize(momenta.load_model(EXAMPLES / "satellite_attitude.yaml"),
                               outputs=["theta"])
    g = momenta.transfer_function(linear.system, "thrust", "theta")
    assert len(g.zeros) == 0 and len(g.poles) == 2
    np.testing.assert_array_equal(g.poles, [0, 0])
    assert g.gain == pytest.approx(1 / 5000, rel=1e-15)
    # G(jω) = −1/(I ω²): −180° and 1/(5000 ω²) at every frequency.
    bode = momenta.bode(linear.system, "thrust", "theta", frequencies=[0.1, 1.0, 10.0])
    np.testing.assert_allclose(bode.magnitude, 1 / (5000 * np.array([0.1, 1.0, 10.0])**2), rtol=1e-14)
    np.testing.assert_allclose(bode.phase_deg, -180.0, atol=1e-12)


def test_franklin_flexible_satellite_transfer_function():
    I1, I2, k, b = 1.0, 0.1, 0.091, 0.0036
    linear = momenta.linearize(momenta.load_model(EXAMPLES / "flexible_satellite.yaml"),
                               outputs=["theta2"])
    g = momenta.transfer_function(linear.system, "tc", "theta2")
    # θ2/Tc = (b s + k) / (I1 I2 s² (s² + b (I1 + I2)/(I1 I2) s + k (I1 + I2)/(I1 I2))).
    expected_zero = -k / b
    np.testing.assert_allclose(g.zeros, [expected_zero], rtol=1e-10)
    assert g.gain == pytest.approx(b / (I1 * I2), rel=1e-10)
    wn = np.sqrt(k * (I1 + I2) / (I1 * I2))
    zeta = b * (I1 + I2) / (2 * I1 * I2 * wn)
    flexible = [m for m in momenta.modes(linear) if m.natural_frequency > 0.5]
    assert len(flexible) == 2
    for mode in flexible:
        assert mode.natural_frequency == pytest.approx(wn, rel=1e-9)
        assert mode.damping_ratio == pytest.approx(zeta, rel=1e-8)
    # Against the closed form at a few frequencies.
    s = 1j * np.array([0.3, 1.2, 4.0])
    closed = (b * s + k) / (I1 * I2 * s**2 * (s**2 + b * (I1 + I2) / (I1 * I2) * s + k * (I1 + I2) / (I1 * I2)))
    bode = momenta.bode(linear.system, "tc", "theta2", frequencies=s.imag)
    np.testing.assert_allclose(bode.response, closed, rtol=1e-9)


def test_bode_and_step_are_the_command_lines():
    path = EXAMPLES / "quarter_car.yaml"
    linear = momenta.linearize(momenta.load_model(path))
    system = linear.system
    inp, out = system.input_names[0], system.output_names[0]
    bode = momenta.bode(system, inp, out, omega_min=1.0, omega_max=100.0, points=50)
    header, table = cli_csv("response", path, "--input", inp, "--output", out, "--bode", 1, 100,
                            "--points", 50, "--csv", "-")
    assert header == ["frequency_rad_s", "frequency_hz", "magnitude", "magnitude_db", "phase_deg",
                      "real", "imag"]
    np.testing.assert_array_equal(bode.frequency, table[:, 0])
    np.testing.assert_array_equal(bode.magnitude, table[:, 2])
    np.testing.assert_array_equal(bode.magnitude_db, table[:, 3])
    # The Nyquist plot's coordinates: G(jω) itself.
    np.testing.assert_array_equal(bode.response.real, table[:, 5])
    np.testing.assert_array_equal(bode.response.imag, table[:, 6])
    np.testing.assert_array_equal(bode.phase_deg, table[:, 4])
    step = momenta.step_response(system, inp)
    header, table = cli_csv("response", path, "--input", inp, "--output", out, "--step",
                            "--csv", "-")
    np.testing.assert_array_equal(step.time, table[:, 0])
    np.testing.assert_array_equal(step.outputs[:, system.output_names.index(out)], table[:, 1])


def test_margins_as_franklin_has_them_and_as_the_command_line_prints_them():
    """L = 1/(s (s + 1)(s + 2)): the phase crosses −180° at √2 where |L| = 1/6 (GM = 6); the
    quarter car's margins are the command line's `response --bode --json` to the bit."""
    A = [[0, 1, 0], [0, 0, 1], [0, -2, -3]]
    loop = momenta.StateSpace(A, [[0], [0], [1]], [[1, 0, 0]], None, [], ["u"], ["y"])
    m = momenta.margins(loop, "u", "y")
    assert m.phase_crossover == pytest.approx(np.sqrt(2.0), rel=1e-11)
    assert m.gain_margin == pytest.approx(6.0, rel=1e-10)
    assert len(m.gain_crossovers) == 1 and 0 < m.phase_margin_deg < 90
    path = EXAMPLES / "quarter_car.yaml"
    system = momenta.linearize(momenta.load_model(path)).system
    inp, out = system.input_names[0], system.output_names[0]
    ours = momenta.margins(system, inp, out, omega_min=0.1, omega_max=1000.0)
    cli = cli_json("response", path, "--input", inp, "--output", out, "--bode", 0.1, 1000)
    assert ours.gain_margin == cli["margins"]["gain_margin"]
    assert ours.phase_margin_deg == cli["margins"]["phase_margin_deg"]
    assert ours.gain_crossover == cli["margins"]["gain_crossover"]


def test_nyquist_count_against_the_closed_loop_and_the_command_line():
    """K/(s (s + 1)(s + 5)) (scipy's lti): stable below Routh's K = 30, two poles in the right
    half-plane above — Z = N + P against the closed loop's eigenvalues; the quarter car's count
    is `response --bode --json`'s."""
    import scipy.signal as sig
    for K, Z in ((10.0, 0), (50.0, 2)):
        n = momenta.nyquist(sig.lti([K], [1.0, 6.0, 5.0, 0.0]))
        closed = np.roots([1.0, 6.0, 5.0, K])
        assert (n.encirclements, n.open_loop_unstable, n.closed_loop_unstable) == (Z, 0, Z)
        assert n.closed_loop_unstable == int(np.sum(closed.real > 0))
        assert ("unstable" in repr(n)) == (Z > 0)
    path = EXAMPLES / "quarter_car.yaml"
    system = momenta.linearize(momenta.load_model(path)).system
    inp, out = system.input_names[0], system.output_names[0]
    ours = momenta.nyquist(system, inp, out)
    cli = cli_json("response", path, "--input", inp, "--output", out, "--bode", 0.1, 1000)
    assert cli["nyquist"]["closed_loop_unstable"] == ours.closed_loop_unstable
    assert cli["nyquist"]["encirclements"] == ours.encirclements


def test_state_space_from_matrices_mass_spring_damper_step():
    # m x'' + c x' + k x = u; x(∞) = 1/k; ωn, ζ as the textbook.
    m, c, k = 2.0, 0.8, 50.0
    A = [[0, 1], [-k / m, -c / m]]
    system = momenta.StateSpace(A, [[0], [1 / m]], [[1, 0]], None, ["x", "x_dot"], ["u"], ["x"])
    wn, zeta = np.sqrt(k / m), c / (2 * np.sqrt(k * m))
    modes = momenta.modes(system)
    for mode in modes:
        assert mode.natural_frequency == pytest.approx(wn, rel=1e-14)
        assert mode.damping_ratio == pytest.approx(zeta, rel=1e-13)
    step = momenta.step_response(system, "u", final_time=2.0, samples=401)
    t = step.time
    wd = wn * np.sqrt(1 - zeta**2)
    closed = (1 - np.exp(-zeta * wn * t) * (np.cos(wd * t) + zeta / np.sqrt(1 - zeta**2) * np.sin(wd * t))) / k
    np.testing.assert_allclose(step.outputs[:, 0], closed, rtol=0, atol=1e-14)
    info = momenta.step_info(system)
    assert info.final_value == pytest.approx(1 / k, rel=1e-14)
    # Exact figures (roots of the analytic response), not sampled ones.
    assert info.overshoot == pytest.approx(100 * np.exp(-zeta * np.pi / np.sqrt(1 - zeta**2)), rel=1e-12)
    assert info.peak_time == pytest.approx(np.pi / wd, rel=1e-13)


def test_state_space_checks_its_sizes():
    with pytest.raises(ValueError, match=r"B: expected a 2 × n matrix, got shape \(3, 1\)"):
        momenta.StateSpace(np.eye(2), np.zeros((3, 1)), np.zeros((1, 2)))
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'road'"):
        system = momenta.linearize(momenta.load_model(EXAMPLES / "quarter_car.yaml")).system
        momenta.transfer_function(system, "raod", system.output_names[0])


def test_equilibrium_of_the_pendulum_and_its_normal_mode():
    model = momenta.load_model(EXAMPLES / "pendulum.yaml")
    eq = momenta.find_equilibrium(model, q_guess=[0.3])
    np.testing.assert_allclose(eq.q, [0.0], atol=1e-10)
    assert eq.stable and eq.iterations >= 1
    normal = momenta.undamped_modes(eq.linear)
    expected = cli_json("modes", EXAMPLES / "pendulum.yaml", "--about", "equilibrium")
    assert len(normal) == 1
    assert normal[0].natural_frequency > 0
    # The same ωn as the eigenvalues of A at the equilibrium.
    omega = max(abs(m.eigenvalue.imag) for m in momenta.modes(eq.linear))
    assert normal[0].natural_frequency == pytest.approx(omega, rel=1e-9)
    assert expected["model"] == model.name


def test_steady_motion_of_the_sleeping_top():
    """examples/sleeping_top.yaml: stable above 2√(I₁ m g l)/I₃, precessing at the roots of
    I₁ σ² − I₃ ω₃ σ + m g l = 0 seen from space; the same numbers as `modes --about steady`."""
    model = momenta.load_model(EXAMPLES / "sleeping_top.yaml")
    r = momenta.steady_motion(model)
    I1, I3, mgl, w = 0.6 * 0.01 + 0.15 * 0.0025, 0.3 * 0.0025, 9.81 * 0.075, 300.0
    root = np.sqrt(I3**2 * w**2 - 4 * I1 * mgl)
    assert r.stable and r.residual == 0.0
    np.testing.assert_allclose(sorted(r.space_frequencies), [(I3 * w - root) / (2 * I1), (I3 * w + root) / (2 * I1)], rtol=1e-10)
    assert r.whirl == ["forward", "forward"]
    assert "gyroscopically stabilized" in r.verdict
    # Below the critical spin the same top falls: its growth rate is the closed form's.
    slow = momenta.steady_motion(model, v=[0.0, 0.0, 100.0])
    assert not slow.stable
    assert slow.growth_rate == pytest.approx(np.sqrt(4 * I1 * mgl - I3**2 * 100.0**2) / (2 * I1), rel=1e-10)
    heavy = momenta.load_model(EXAMPLES / "heavy_top.yaml")
    with pytest.raises(momenta.InvalidArgument, match="not in a steady motion"):
        momenta.steady_motion(heavy)
    # It precesses steadily at its tilt instead: the slow root its file states.
    p = momenta.steady_precession(heavy)
    assert p.slow == pytest.approx(3.618637, abs=5e-7) and p.residual < 1e-15
    assert p.gyroscopic == pytest.approx(p.mgl / (p.I3 * p.spin), rel=1e-15)


def test_campbell_diagram_is_momenta_campbells():
    """The Python diagram equals `momenta campbell --json` (rev/min there) bit for bit."""
    model = momenta.load_model(EXAMPLES / "sleeping_top.yaml")
    rpm = 2 * np.pi / 60
    expected = cli_json("campbell", EXAMPLES / "sleeping_top.yaml", "--speed-range", 2000, 6000, "--points", 9)
    d = momenta.campbell_diagram(model, 2000 * rpm, 6000 * rpm, 9)
    assert [p.speed for p in d.points] == [p["speed_rad_s"] for p in expected["points"]]
    assert [p.frequencies for p in d.points] == [p["frequencies_rad_s"] for p in expected["points"]]
    assert d.critical_speeds == [] and expected["critical_speeds"] == []


def test_rotor_in_joint_coordinates_about_its_steady_motion():
    """examples/rotor_on_bearings.yaml: the reduced linearization's frequencies and whirls, and its
    Campbell diagram, equal `momenta modes/campbell --about steady --json` bit for bit; the
    critical speeds are the closed form's (tests/validation/examples/campbell_examples_test.cpp)."""
    path = EXAMPLES / "rotor_on_bearings.yaml"
    model = momenta.load_model(path)
    s = momenta.joint_steady_motion(model)
    assert s.turning == ["spin.angle"]
    assert s.reduced.state_names[:4] == ["x.position", "y.position", "tilt.angle1", "tilt.angle2"]
    assert len(s.reduced.state_names) == 9 and s.stable
    expected = cli_json("modes", path, "--about", "steady")["steady_motion"]
    assert [m.frequency for m in s.modes] == [w["frequency_rad_s"] for w in expected["whirls"]]
    assert [m.whirl for m in s.modes] == ["backward", "forward", "backward", "forward"]
    rpm = 2 * np.pi / 60
    d = momenta.campbell_diagram(model, 500 * rpm, 5000 * rpm, 19)
    cli = cli_json("campbell", path, "--speed-range", 500, 5000, "--points", 19)
    assert [c.speed for c in d.critical_speeds] == [c["speed_rad_s"] for c in cli["critical_speeds"]]
    assert d.critical_speeds[0].speed / rpm == pytest.approx(1934.204401, abs=1e-6)
    with pytest.raises(momenta.InvalidArgument, match="nothing turns"):
        momenta.joint_steady_motion(model, v=np.zeros(5))


def test_find_steady_precession_is_momenta_steadys():
    """The solver at a chosen tilt and spin equals `momenta steady --json` bit for bit, and each
    state it gives is found on its root by steady_precession."""
    path = EXAMPLES / "heavy_top.yaml"
    model = momenta.load_model(path)
    found = momenta.find_steady_precession(model, 20 * np.pi / 180, 300.0)
    cli = cli_json("steady", path, "--tilt", 20, "--spin", 300)
    assert found.roots.slow == cli["slow"] and found.roots.fast == cli["fast"]
    assert found.roots.critical_spin == cli["critical_spin"]
    q, v = found.states[0]
    p = momenta.steady_precession(model, q=q, v=v)
    assert p.precession == pytest.approx(found.roots.slow, rel=1e-13)
    assert p.residual < 1e-15


def test_rolling_steady_motions_are_momenta_steadys():
    """The coin's steady circles at a lean and speed equal `momenta steady --json` bit for bit; a
    state found is recognised as steady, and its modes are `momenta modes --about steady`'s."""
    path = EXAMPLES / "constraints" / "rolling_coin.yaml"
    model = momenta.load_model(path)
    found = momenta.find_rolling_steady_motions(model, lean=20 * np.pi / 180, speed=1.0847887974793695)
    cli = cli_json("steady", path, "--lean", 20, "--speed", "1.0847887974793695")
    assert [m.precession for m in found] == [m["precession"] for m in cli["motions"]]
    assert found[0].radius == pytest.approx(0.5, rel=1e-12)
    assert found[0].contact_force[0] == pytest.approx(9.81, rel=1e-13)
    modes = momenta.rolling_steady_modes(model, q=found[0].q, v=found[0].v)
    assert modes.motion.precession == pytest.approx(found[0].precession, rel=1e-13)
    assert modes.stable and len(modes.eigenvalues) == 1
    expected = cli_json("modes", path, "--about", "steady")
    assert modes.eigenvalues[0].imag == pytest.approx(expected["eigenvalues"][0][1], rel=1e-9)
    with pytest.raises(momenta.InvalidArgument, match="exactly one"):
        momenta.find_rolling_steady_motions(model, lean=0.1, speed=1.0, radius=2.0)
    beer = momenta.load_model(EXAMPLES / "constraints" / "rolling_disk_on_axle.yaml")
    (disk,) = momenta.find_rolling_steady_motions(beer, spin=20.0)
    assert disk.precession == pytest.approx(-20.0 * 0.15 / 0.45, rel=1e-14)


def test_a_sweep_from_python_is_the_command_lines_file(tmp_path):
    """momenta.sweep gives the columns `momenta sweep` writes, every double the same, whatever
    the thread count; pandas makes a table of them."""
    path = EXAMPLES / "sweeps" / "quarter_car_poles.yaml"
    result = momenta.sweep(path, threads=2)
    assert momenta.sweep(path, threads=1)["pole1.re"].tolist() == result["pole1.re"].tolist()
    out = tmp_path / "poles.csv"
    run_cli("sweep", path, "-o", out, "--no-timing", "-q")
    import csv as csv_module
    with open(out) as f:
        rows = list(csv_module.DictReader(f))
    assert len(rows) == len(result["run"]) == 189
    assert result["ok"].all()
    for name in ["ks", "b", "m2", "pole1.re", "pole2.im", "wn4", "zeta3"]:
        assert [float(r[name]) for r in rows] == result[name].tolist(), name
    import pandas
    table = pandas.DataFrame(result)
    assert list(table.columns[:4]) == ["run", "ks", "b", "m2"]


def test_constrained_swing_in_its_independent_coordinate():
    """examples/constraints/parallelogram_swing.yaml: one coordinate, ω² = g (m₁/2 + m₃/2 + m₂) /
    (L (m₁/3 + m₃/3 + m₂)) from its energy; the same as `momenta modes --about equilibrium`."""
    path = EXAMPLES / "constraints" / "parallelogram_swing.yaml"
    model = momenta.load_model(path)
    equilibrium = momenta.find_equilibrium(model)
    g, L, m1, m2, m3 = 9.81, 0.25, 1.0, 2.0, 1.5
    w2 = g * (m1 / 2 + m3 / 2 + m2) / (L * (m1 / 3 + m3 / 3 + m2))
    linear = momenta.linearize(model, q=equilibrium.q, independent=["pivot2.angle"])
    assert linear.state_names == ["pivot2.angle", "pivot2.angle_rate"]
    assert len(linear.dependent_coordinates) == 2
    assert linear.A[1, 0] == pytest.approx(-w2, rel=1e-13)  # analytic: round-off
    # The differences the analytic derivatives are checked against, at a moving state.
    moving = momenta.linearize(model, v=[0.7, -0.7, 0.7])
    check = momenta.linearize(model, v=[0.7, -0.7, 0.7], derivatives="differences")
    np.testing.assert_allclose(check.A, moving.A, rtol=0, atol=1e-10 * abs(moving.A).max())
    with pytest.raises(momenta.InvalidArgument, match="neither 'analytic' nor 'differences'"):
        momenta.linearize(model, derivatives="exact")
    expected = cli_json("modes", path, "--about", "equilibrium")
    assert expected["state_names"] == ["pivot1.angle", "pivot1.angle_rate"]
    assert expected["modes"][0]["natural_frequency_rad_s"] == pytest.approx(w2 ** 0.5, rel=1e-9)


def test_results_print_as_the_command_line_does():
    # No "<momenta._core.X object at 0x…>": each result reads like the CLI's text, and the modes
    # table is the very table `momenta modes` prints (one function writes both).
    path = EXAMPLES / "flexible_satellite.yaml"
    linear = momenta.linearize(momenta.load_model(path))
    table = repr(momenta.modes(linear)).splitlines()
    assert table[0] == "<momenta.Modes: 4 modes of 4 states>"
    printed = run_cli("modes", path).splitlines()
    start = printed.index(table[1])
    assert printed[start:start + 5] == table[1:6]
    cruise = momenta.linearize(momenta.load_model(EXAMPLES / "cruise_control.yaml"), outputs=["speed"])
    info = repr(momenta.step_info(cruise.system, "u", "speed"))
    assert info.startswith("<momenta.StepInfo final value 0.02, rise time 43.94")  # F/b, 2.197 τ
    rigid = momenta.linearize(momenta.load_model(EXAMPLES / "satellite_attitude.yaml"), outputs=["theta"])
    assert "final value undefined" in repr(momenta.step_info(rigid.system, "thrust", "theta"))
    response = repr(momenta.step_response(cruise.system, "u"))
    assert response.startswith("<momenta.TimeResponse to 'u': ") and "outputs [speed]" in response
    hanging = momenta.find_equilibrium(momenta.load_model(EXAMPLES / "double_pendulum.yaml"))
    assert repr(hanging).startswith("<momenta.Equilibrium q = [") and ", stable (" in repr(hanging)
    normal = repr(momenta.undamped_modes(hanging.linear)).splitlines()
    assert normal[0] == "<momenta.NormalModes: 2 modes, K φ = ω² M φ>"
    assert normal[1].startswith("    1  ω² = 5.74656      ω = 2.3972 rad/s")
    for text in [info, response, repr(hanging)] + table + normal:
        assert "object at 0x" not in text and "nan" not in text


def test_results_show_as_html_in_a_notebook():
    # _repr_html_: the modes as a table of the cells `momenta modes` prints (the rigid-body pair as
    # 0), a run with the unit of every column and its first and last rows, the rest as their text.
    import html.parser

    class Cells(html.parser.HTMLParser):
        def __init__(self):
            super().__init__()
            self.rows, self.header = [], []
            self._cell = None

        def handle_starttag(self, tag, attrs):
            if tag == "tr":
                self.rows.append([])
            elif tag in ("td", "th"):
                self._cell = ""

        def handle_data(self, data):
            if self._cell is not None:
                self._cell += data

        def handle_endtag(self, tag):
            if tag in ("td", "th"):
                self.rows[-1].append(self._cell)
                self._cell = None

    def cells(markup):
        parser = Cells()
        parser.feed(markup)
        return parser.rows

    model = momenta.load_model(EXAMPLES / "flexible_satellite.yaml")
    modes = momenta.modes(momenta.linearize(model))
    table = cells(modes._repr_html_())
    assert table[0] == ["#", "eigenvalue 1/s", "ωn rad/s", "ωn Hz", "ζ", "largest shape entries"]
    assert [row[1] for row in table[1:3]] == ["0 (rigid-body mode)"] * 2
    assert len(table) == 1 + len(modes)
    for row in table[1:]:  # each row's figures are the text table's
        assert all(cell in repr(modes) for cell in row[1:5] if cell)
    run = momenta.simulate(model, duration=1.0)
    shown = cells(run._repr_html_())
    assert shown[0][:3] == ["time (s)", "theta1.angle (rad)", "theta2.angle (rad)"]
    assert "tc (N·m)" in shown[0]  # the thrusters' signal scales a torque of unit direction
    assert len(shown) == 1 + 7 and shown[4] == ["…"] * len(run.columns)
    assert float(shown[-1][0]) == pytest.approx(run.time[-1])
    assert momenta.find_equilibrium(momenta.load_model(EXAMPLES / "double_pendulum.yaml"))._repr_html_() \
        .startswith("<pre>&lt;momenta.Equilibrium q = [")

"""Control design from Python against SciPy's independent solvers and closed forms: the
inverted pendulum on a cart's open-loop poles (the characteristic polynomial's roots), its LQR
gain (scipy.linalg.solve_continuous_are / solve_discrete_are), c2d (scipy.signal.cont2discrete),
Lyapunov (scipy.linalg), `momenta lqr --json` equal to momenta.lqr, and state spaces handed to
and from scipy without conversion of names or layout."""

import subprocess

import numpy as np
import pytest
import scipy.linalg as la
import scipy.signal as sig

import momenta

from conftest import EXAMPLES, cli_json, cli_path

CART = EXAMPLES / "cart_pendulum.yaml"


@pytest.fixture(scope="module")
def cart():
    return momenta.linearize(momenta.load_model(CART)).system


def test_the_cart_pendulums_poles_are_its_characteristic_roots(cart):
    M, m, b, l, I, g = 0.5, 0.2, 0.1, 0.3, 0.006, 9.81
    q = I * (M + m) + M * m * l**2
    roots = np.roots([q, b * (I + m * l**2), -(M + m) * m * g * l, -b * m * g * l])
    expected = np.sort_complex(np.append(roots, 0.0))
    np.testing.assert_allclose(np.sort_complex(cart.poles()), expected, atol=1e-12)


def test_lqr_is_scipys_riccati_solution(cart):
    A, B, C, D = cart
    Q, R = np.diag([1.0, 1.0, 0.0, 0.0]), np.array([[1.0]])
    K, S, poles = momenta.lqr(cart, Q, R)
    X = la.solve_continuous_are(A, B, Q, R)
    np.testing.assert_allclose(S, X, rtol=1e-11, atol=1e-12 * abs(X).max())
    np.testing.assert_allclose(K, np.linalg.solve(R, B.T @ X), rtol=1e-11)
    np.testing.assert_allclose(np.sort_complex(poles), np.sort_complex(np.linalg.eigvals(A - B @ K)),
                               rtol=1e-10)
    assert all(p.real < 0 for p in poles)
    # Vectors and numbers as weights: the diagonal, the identity.
    np.testing.assert_array_equal(momenta.lqr(cart, [1, 1, 0, 0], 1).K, K)


def test_lqr_with_a_cross_weight_is_scipys(cart):
    A, B, _, _ = cart
    Q, R = np.diag([2.0, 5.0, 0.1, 0.1]), np.array([[0.5]])
    N = np.array([[0.1], [0.2], [0.0], [0.05]])
    X = la.solve_continuous_are(A, B, Q, R, s=N)
    d = momenta.lqr(cart, Q, R, N)
    np.testing.assert_allclose(d.S, X, rtol=1e-11, atol=1e-12 * abs(X).max())


def test_discrete_lqr_on_the_held_plant_is_scipys(cart):
    T = 0.01
    sampled = momenta.c2d(cart, T)
    assert sampled.dt == T and sampled.state_names == cart.state_names
    Ad, Bd, Cd, Dd, _ = sig.cont2discrete(tuple(cart), T, method="zoh")
    np.testing.assert_allclose(sampled.A, Ad, rtol=1e-13, atol=1e-15)
    np.testing.assert_allclose(sampled.B, Bd, rtol=1e-13, atol=1e-17)
    Q, R = np.diag([1.0, 1.0, 0.0, 0.0]), np.array([[1.0]])
    X = la.solve_discrete_are(sampled.A, sampled.B, Q, R)
    d = momenta.lqr(sampled, Q, R)
    # Two solvers (doubling here, SciPy's QZ) on a plant whose held poles crowd z = 1 (0.9986,
    # 1, 1.057 at T = 0.01 s): they agree to 1e-12 (measured 1.0e-12 in S, 1.3e-12 in K).
    np.testing.assert_allclose(d.S, X, rtol=1e-11)
    K = np.linalg.solve(R + sampled.B.T @ X @ sampled.B, sampled.B.T @ X @ sampled.A)
    np.testing.assert_allclose(d.K, K, rtol=1e-11)
    assert all(abs(z) < 1 for z in d.closed_loop_poles)


def test_tustin_is_scipys_bilinear(cart):
    Ad, Bd, Cd, Dd, _ = sig.cont2discrete(tuple(cart), 0.05, method="bilinear")
    d = momenta.c2d(cart, 0.05, method="tustin")
    for mine, theirs in zip(d, (Ad, Bd, Cd, Dd)):
        np.testing.assert_allclose(mine, theirs, rtol=1e-13, atol=1e-15)


def test_the_command_line_designs_the_same_regulator(cart):
    cli = cli_json("lqr", CART, "--Q", "x.position=1,tilt.angle=1", "--R", "1")
    d = momenta.lqr(cart, [1, 1, 0, 0], 1)
    np.testing.assert_array_equal(np.array(cli["K"]).reshape(1, 4), d.K)
    assert cli["state_names"] == cart.state_names and cli["input_names"] == ["force"]
    assert cli["controllable_rank"] == 4
    sampled = cli_json("lqr", CART, "--Q", "1,1,0,0", "--R", "1", "--sample-time", "0.01")
    np.testing.assert_allclose(np.array(sampled["K"]).reshape(1, 4),
                               momenta.lqr(momenta.c2d(cart, 0.01), [1, 1, 0, 0], 1).K, rtol=1e-14)


def test_the_command_line_names_a_bad_weight():
    result = subprocess.run([cli_path(), "lqr", str(CART), "--Q", "tilt=1", "--R", "1"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert "no state named 'tilt'" in result.stderr and "tilt.angle" in result.stderr
    result = subprocess.run([cli_path(), "lqr", str(CART), "--Q", "1,2,3", "--R", "1"],
                            capture_output=True, text=True)
    assert result.returncode == 2 and "3 weights for 4 states" in result.stderr


def test_controllability_and_observability(cart):
    c = momenta.controllability(cart)
    assert c.rank == 4 and c.complete and c.gramian is None  # upright is unstable
    tilt_only = cart.siso("force", "tilt_angle")
    o = momenta.observability(tilt_only)
    assert o.rank == 3 and not o.complete
    np.testing.assert_allclose(o.hidden_poles, [0.0], atol=1e-12)  # the cart's position


def test_lyapunov_solvers_are_scipys():
    rng = np.random.default_rng(7)
    A = rng.normal(size=(6, 6)) - 3 * np.eye(6)
    F = rng.normal(size=(6, 2))
    Q = F @ F.T
    # SciPy solves A X + X Aᴴ = Q; momenta A X + X Aᵀ + Q = 0.
    np.testing.assert_allclose(momenta.lyap(A, Q), la.solve_continuous_lyapunov(A, -Q),
                               rtol=1e-11, atol=1e-13)
    Ad = A / (1.1 * max(abs(np.linalg.eigvals(A))))
    np.testing.assert_allclose(momenta.dlyap(Ad, Q), la.solve_discrete_lyapunov(Ad, Q),
                               rtol=1e-11, atol=1e-13)
    B = rng.normal(size=(6, 2))
    np.testing.assert_allclose(momenta.care(A, B, Q + np.eye(6), np.eye(2)),
                               la.solve_continuous_are(A, B, Q + np.eye(6), np.eye(2)), rtol=1e-11)


def test_a_state_space_behaves_like_scipys(cart):
    A, B, C, D = cart
    assert (cart.nstates, cart.ninputs, cart.noutputs, cart.dt) == (4, 1, 2, 0.0)
    scipy_system = cart.to_scipy()
    assert isinstance(scipy_system, sig.StateSpace)
    np.testing.assert_array_equal(scipy_system.A, A)
    # scipy's systems go where momenta's do, with the same answers.
    mine = momenta.bode(cart, 0, 1, frequencies=[0.5, 2.0, 8.0])
    theirs = momenta.bode(scipy_system, 0, 1, frequencies=[0.5, 2.0, 8.0])
    np.testing.assert_array_equal(mine.response, theirs.response)
    first_order = momenta.step_response(sig.lti([2.0], [1.0, 4.0]), final_time=1.0, samples=11)
    np.testing.assert_allclose(first_order.outputs[:, 0], 0.5 * (1 - np.exp(-4 * first_order.time)),
                               atol=1e-15)
    discrete = momenta.c2d(cart, 0.1).to_scipy()
    assert discrete.dt == 0.1
    assert momenta.c2d(cart, 0.1).dt == pytest.approx(0.1)
    with pytest.raises(TypeError, match="expected a momenta.StateSpace"):
        momenta.bode("not a system", 0, 0)
    # Tilt over force has a zero at the origin: pushing the cart steadily does not tilt it.
    np.testing.assert_allclose(cart.siso("force", "tilt_angle").zeros(), [0.0], atol=1e-12)
    with pytest.raises(ValueError, match="single-input single-output"):
        cart.zeros()


def test_a_sampled_system_answers_at_its_samples(cart):
    held = momenta.c2d(cart, 0.01)
    # Held steps are exact: the sampled step equals the continuous one at t = k T.
    mine = momenta.step_response(held, final_time=0.5)
    continuous = momenta.step_response(cart, final_time=0.5, samples=51)
    np.testing.assert_allclose(mine.time, continuous.time, rtol=1e-13)
    np.testing.assert_allclose(mine.outputs, continuous.outputs, rtol=1e-10, atol=1e-14)
    # Bode of H(e^{jωT}) up to the Nyquist frequency against C (zI − A)⁻¹ B by a dense solve
    # (scipy's dfreqresp goes through polynomial coefficients, which these poles crowding z = 1
    # leave good to 1e-7 only: it warns so itself).
    w = np.array([0.1, 1.0, 10.0, 100.0, np.pi / 0.01])
    A, B, C, _ = held
    H = [(C[0] @ np.linalg.solve(np.exp(1j * x * 0.01) * np.eye(4) - A, B[:, 0])) for x in w]
    np.testing.assert_allclose(momenta.bode(held, 0, 0, frequencies=w).response, H, rtol=1e-11)
    with pytest.raises(momenta.InvalidArgument, match="above the Nyquist frequency"):
        momenta.bode(held, 0, 0, frequencies=[400.0])
    # Its modes: each z = e^(λT) of A shown as the λ it samples, the continuous plant's poles.
    sampled = [mode.eigenvalue for mode in momenta.modes(held).modes]
    np.testing.assert_allclose(np.sort_complex(sampled), np.sort_complex(cart.poles()),
                               rtol=0, atol=1e-10)
    for mode in momenta.modes(held).modes:
        assert abs(np.exp(mode.eigenvalue * 0.01) - mode.z) < 1e-14


def test_root_locus_branches_are_the_characteristic_roots():
    # 1/(s (s + 1)(s + 5)) from scipy: 1 + k G = 0 ⇔ s³ + 6 s² + 5 s + k = 0.
    locus = momenta.root_locus(sig.lti([1.0], [1.0, 6.0, 5.0, 0.0]), k_min=0.1, k_max=100, points=50)
    for k, poles in zip(locus.gains, locus.poles):
        np.testing.assert_allclose(np.sort_complex(poles), np.sort_complex(np.roots([1, 6, 5, k])),
                                   atol=1e-9 * max(1.0, k))
    (crossing,) = locus.crossings
    assert crossing.gain == pytest.approx(30.0, rel=1e-13)
    assert crossing.s == pytest.approx(np.sqrt(5.0) * 1j, rel=1e-13)
    (breakaway,) = locus.breakaway
    assert breakaway.s.real == pytest.approx((-12 + np.sqrt(84)) / 6, rel=1e-13)
    # Each column is one branch: no pole jumps between neighbouring gains.
    steps = np.abs(np.diff(locus.poles, axis=0)).max(axis=0)
    assert steps.max() < 2.0


def test_response_root_locus_on_the_command_line_is_pythons():
    quarter = EXAMPLES / "quarter_car.yaml"
    cli = cli_json("response", quarter, "--input", "road", "--output", "body_y",
                   "--root-locus", 0.01, 100, "--points", 20)
    system = momenta.linearize(momenta.load_model(quarter), inputs=["road"], outputs=["body_y"])
    locus = momenta.root_locus(system, "road", "body_y", k_min=0.01, k_max=100, points=20)
    np.testing.assert_array_equal(cli["samples"]["gain"], locus.gains)
    poles = np.array(cli["samples"]["poles"])
    np.testing.assert_array_equal(poles[..., 0] + 1j * poles[..., 1], locus.poles)
    assert [c["gain"] for c in cli["crossings"]] == [c.gain for c in locus.crossings]
    assert len(locus.crossings) == 1 and locus.crossings[0].gain > 0
    # At the crossing gain the closed loop has a pair on the axis: the stability limit.
    k = locus.crossings[0].gain
    A, B, C, D = system.system
    closed = np.linalg.eigvals(A - k * B @ C / (1 + k * D[0, 0]))
    assert min(abs(closed - locus.crossings[0].s)) < 1e-8 * abs(locus.crossings[0].s)


def test_a_misspelled_keyword_is_named_with_its_nearest():
    b = momenta.ModelBuilder("typo")
    with pytest.raises(TypeError, match=r"add_joint\(\): no keyword 'q00'; did you mean 'q0'\? "
                                        r"It takes name, type, parent, child"):
        b.add_joint("hinge", "revolute", parent="world", child="bob", q00=0.3)
    with pytest.raises(TypeError, match=r"no keyword 'pont_a'; did you mean 'point_a'"):
        b.add_spring_damper("s", body_a="a", pont_a=[0, 0, 0], body_b="b", point_b=[0, 0, 0])
    # A wrong type is still pybind11's own message.
    with pytest.raises(TypeError, match="incompatible function arguments"):
        b.add_joint("hinge", "revolute", parent="world", child=3)


def test_a_one_coordinate_joint_takes_a_number_and_degrees():
    def pendulum(**initial):
        b = momenta.ModelBuilder("pendulum")
        b.add_body("bob", momenta.inertia.point_mass(1.0).transformed(np.eye(3), [0, 0, -1]))
        b.add_joint("hinge", "revolute", parent="world", child="bob", axis=[0, 1, 0], **initial)
        return b.build()

    np.testing.assert_array_equal(pendulum(q0=0.5).initial_q, [0.5])
    np.testing.assert_allclose(pendulum(q0_deg=30).initial_q, [np.pi / 6], rtol=1e-15)
    np.testing.assert_allclose(pendulum(v0_deg=90).initial_v, [np.pi / 2], rtol=1e-15)
    with pytest.raises(ValueError, match="give q0 or q0_deg, not both"):
        pendulum(q0=0.1, q0_deg=5)
    b = momenta.ModelBuilder("slider")
    b.add_body("block", momenta.inertia.point_mass(1.0))
    with pytest.raises(ValueError, match="q0_deg: a prismatic joint's coordinates are not all angles"):
        b.add_joint("slide", "prismatic", parent="world", child="block", q0_deg=3)


def test_results_say_what_they_are(cart):
    bode = momenta.bode(cart, "force", "tilt_angle", omega_min=0.1, omega_max=100)
    assert repr(bode).startswith("<momenta.FrequencyResponse force → tilt_angle: 200 frequencies "
                                 "from 0.1 to 100 rad/s; peak")
    workspace = momenta.Workspace(momenta.load_model(CART))
    assert repr(workspace).startswith("<momenta.Workspace of 'cart pendulum': nq 2, nv 2, 2 bodies")
    text = repr(cart)
    assert "A =" in text and "tilt.angle_rate" in text and "force" in text
    assert "sampled every 0.01 s" in repr(momenta.c2d(cart, 0.01))
    assert "closed-loop poles" in repr(momenta.lqr(cart, [1, 1, 0, 0], 1))


def test_linearize_away_from_an_equilibrium_warns_and_round_off_is_zero():
    flat = momenta.load_model(EXAMPLES / "double_pendulum.yaml")  # the upper rod horizontal
    with pytest.warns(UserWarning, match="not an equilibrium .largest acceleration 9.81"):
        linear = momenta.linearize(flat)
    # Laid flat, gravity's stiffness is cos 90° = 0: K is round-off, and so are its ω².
    assert [mode.squared_frequency for mode in momenta.undamped_modes(linear)] == [0.0, 0.0]
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        at_rest = momenta.find_equilibrium(flat).linear
    frequencies = [mode.squared_frequency for mode in momenta.undamped_modes(at_rest)]
    assert all(w > 1.0 for w in frequencies)  # the hanging double pendulum's two modes


def test_pole_placement_is_scipys(cart):
    A, B, _, _ = cart
    poles = [-1, -2, -3 + 1j, -3 - 1j]
    placed = momenta.place_poles(cart, poles)
    # One input: the gain is unique, and SciPy's.
    theirs = sig.place_poles(A, B, poles).gain_matrix
    np.testing.assert_allclose(placed.K, theirs, rtol=1e-12)
    np.testing.assert_allclose(np.sort_complex(placed.closed_loop_poles), np.sort_complex(poles),
                               atol=1e-12)
    # Two inputs: the freedom spent on robustness as well as SciPy's (Tits–Yang with complex
    # poles, KNV0 with real ones), the poles where asked.
    rng = np.random.default_rng(3)
    A, B = rng.normal(size=(6, 6)), rng.normal(size=(6, 2))
    system = momenta.StateSpace(A, B, np.zeros((0, 6)))
    for wanted, method in [([-1, -2 + 1j, -2 - 1j, -3, -0.5 + 4j, -0.5 - 4j], "YT"),
                           ([-1, -2, -3, -4, -5, -6], "KNV0")]:
        mine = momenta.place_poles(system, wanted)
        np.testing.assert_allclose(np.sort_complex(np.linalg.eigvals(A - B @ mine.K)),
                                   np.sort_complex(wanted), atol=1e-12)
        reference = sig.place_poles(A, B, wanted, method=method)
        assert mine.eigenvector_condition < 1.01 * np.linalg.cond(reference.X)
    with pytest.raises(momenta.InvalidArgument, match="has no conjugate"):
        momenta.place_poles(cart, [-1, -2, -3 + 1j, -4])


def test_place_on_the_command_line_is_pythons(cart):
    cli = cli_json("place", CART, "--poles=-1,-2,-3+1j,-3-1j")
    np.testing.assert_array_equal(np.array(cli["K"]).reshape(1, 4),
                                  momenta.place_poles(cart, [-1, -2, -3 + 1j, -3 - 1j]).K)
    assert cli["requested_poles"] == [[-1, 0], [-2, 0], [-3, 1], [-3, -1]]
    result = subprocess.run([cli_path(), "place", str(CART), "--poles=-1,-2,-3+1j,-4"],
                            capture_output=True, text=True)
    assert result.returncode == 1 and "has no conjugate" in result.stderr
    result = subprocess.run([cli_path(), "place", str(CART), "--poles=-1,x,2,3"],
                            capture_output=True, text=True)
    assert result.returncode == 2 and "'x' is not a number or a complex a+bj" in result.stderr
    # An unstable design is placed as asked, and said.
    result = subprocess.run([cli_path(), "place", str(CART), "--poles=1,-2,-3+1j,-3-1j"],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert "warning: the design is not stable: 1 in the closed right half-plane" in result.stderr


def _cart_builder(name):
    """The cart pendulum of examples/cart_pendulum.yaml in code, from 10°: bodies and joints."""
    b = momenta.ModelBuilder(name)
    b.add_body("cart", momenta.inertia.point_mass(0.5))
    b.add_body("pendulum", momenta.inertia.MassProperties(
        0.2, [0, 0, 0.3], np.diag([0.006, 0.006, 0.0001])))
    b.add_joint("x", "prismatic", parent="world", child="cart", axis=[1, 0, 0], damping=0.1)
    b.add_joint("tilt", "revolute", parent="cart", child="pendulum", axis=[0, 1, 0], q0_deg=10)
    return b


def _cart_with_lqr(K):
    """The cart pendulum built in code, held by u = −K x."""
    b = _cart_builder("cart pendulum lqr")
    b.add_controller("balance", "state_feedback",
                     measure=["x.position", "tilt.angle", "x.position_rate", "tilt.angle_rate"],
                     gain=K, drives="force")
    b.add_force("push", body="cart", vector=[1, 0, 0], signal="force")
    return b.build()


def test_a_python_designed_lqr_closes_the_loop_in_the_model(cart):
    """momenta.lqr's K put into a ModelBuilder controller: the run is examples/
    cart_pendulum_lqr.yaml's (the same K, the same model) to round-off, and its closed-loop
    linearization has the designed poles."""
    K, S, poles = momenta.lqr(cart, np.diag([1.0, 1.0, 0.0, 0.0]), np.array([[1.0]]))
    model = _cart_with_lqr(K)
    ours = momenta.simulate(model, duration=3.0, dt=0.001)
    theirs = momenta.simulate(momenta.load_model(EXAMPLES / "cart_pendulum_lqr.yaml"),
                              duration=3.0, dt=0.001)
    np.testing.assert_allclose(ours["tilt.angle"], theirs["tilt.angle"], atol=1e-12)
    np.testing.assert_allclose(ours["balance.force"], theirs["balance.force"], atol=1e-10)
    assert abs(ours["tilt.angle"][-1]) < 0.01
    closed = momenta.linearize(model, q=[0.0, 0.0], v=[0.0, 0.0]).system
    np.testing.assert_allclose(np.sort_complex(closed.poles()), np.sort_complex(poles), rtol=1e-9)


def test_add_controller_names_what_is_wrong():
    with pytest.raises(TypeError, match=r"no keyword 'measured'; did you mean 'measure'"):
        momenta.ModelBuilder("m").add_controller("c", "pid", measured="x.position", drives="u")
    with pytest.raises(ValueError, match=r"unknown type 'pdi' \(did you mean 'pid'\?\)"):
        momenta.ModelBuilder("m").add_controller("c", "pdi", measure="x.position", drives="u")
    with pytest.raises(Exception, match=r"K is 1×2; it must be 1×4"):
        _cart_with_lqr([[1.0, 2.0]])


# --- a controller written in Python: simulate(model, controller=fn) --------------------------

LQR_K = np.array([-1.0, -18.70145874371149, -1.656513311485028, -3.460604945318623])


def test_a_python_state_feedback_is_the_model_files(cart):
    # The cart pendulum from 10° under u = −K x written in Python, against the same K as the
    # model file's state_feedback controller (examples/cart_pendulum_lqr.yaml): one law, one
    # arithmetic up to the order of the sum, so the runs agree to round-off growth.
    plant = momenta.load_model(CART)
    q0 = np.array([0.0, np.radians(10.0)])
    start = momenta.with_initial_state(plant, q0, np.zeros(2))
    calls = []

    def law(t, q, v):
        calls.append(t)
        return -LQR_K @ np.concatenate([q, v])

    mine = momenta.simulate(start, duration=8.0, dt=1e-3, controller=law)
    filed = momenta.simulate(momenta.load_model(EXAMPLES / "cart_pendulum_lqr.yaml"))
    for column in ["x.position", "tilt.angle", "tilt.angle_rate"]:
        np.testing.assert_allclose(mine[column], filed[column], rtol=0, atol=1e-12)
    np.testing.assert_allclose(mine["controller.force"], filed["balance.force"], rtol=0,
                               atol=1e-10)
    assert mine.units["controller.force"] == "N"
    # Continuous: four evaluations per RK4 step, and the rows' own.
    assert len(calls) >= 4 * 8000
    # Back upright, as the linear loop predicts.
    assert abs(mine["tilt.angle"][-1]) < 1e-3


def test_a_python_pd_sampled_at_10_hz_is_the_model_files():
    # The satellite's discrete PD (examples/satellite_attitude_pd.yaml) written as a Python
    # closure: the derivative by backward difference, u held between samples. fn is called
    # once per sample, at t = kT exactly, and the runs agree to round-off.
    plant = momenta.load_model(EXAMPLES / "satellite_attitude.yaml")
    T, kp, kd, r = 0.1, 1250.0, 3500.0, 0.1
    seen = {"times": [], "last": None}

    def pd(t, q, v):
        e = r - q[0]
        last = e if seen["last"] is None else seen["last"]
        seen["last"] = e
        seen["times"].append(t)
        return [kp * e + kd * (e - last) / T]

    mine = momenta.simulate(plant, duration=20.0, dt=0.01, integrator="rk4", controller=pd,
                            drives=["thrust"], sample_time=T)
    filed = momenta.simulate(momenta.load_model(EXAMPLES / "satellite_attitude_pd.yaml"))
    np.testing.assert_allclose(mine["attitude.angle"], filed["attitude.angle"], rtol=0,
                               atol=1e-12)
    np.testing.assert_allclose(mine["controller.thrust"], filed["attitude_pd.thrust"], rtol=0,
                               atol=1e-9)
    np.testing.assert_allclose(seen["times"], T * np.arange(201), rtol=0, atol=1e-12)


def test_a_python_controller_saturates_and_leaves_the_model_as_it_was():
    plant = momenta.load_model(EXAMPLES / "satellite_attitude.yaml")
    run = momenta.simulate(plant, duration=1.0, controller=lambda t, q, v: 500.0, u_max=200.0)
    np.testing.assert_array_equal(run["controller.thrust"], 200.0)
    # θ = ½ (u/I) t² under the clamped torque.
    np.testing.assert_allclose(run["attitude.angle"][-1], 0.5 * 200.0 / 5000.0, rtol=1e-12)
    assert "controller.thrust" not in momenta.simulate(plant, duration=0.1)


def test_a_python_controller_names_what_is_wrong():
    plant = momenta.load_model(EXAMPLES / "satellite_attitude.yaml")
    with pytest.raises(momenta.InvalidArgument, match=r"returned 2 numbers .* drives 1 \(thrust\)"):
        momenta.simulate(plant, duration=0.1, controller=lambda t, q, v: [1.0, 2.0])
    with pytest.raises(ZeroDivisionError):
        momenta.simulate(plant, duration=0.1, controller=lambda t, q, v: 1 / 0)
    with pytest.raises(momenta.NumericalError, match=r"controller 'controller' gave thrust = nan"):
        momenta.simulate(plant, duration=0.1, controller=lambda t, q, v: float("nan"))
    with pytest.raises(TypeError, match="must be a function"):
        momenta.simulate(plant, duration=0.1, controller=3.0)
    with pytest.raises(momenta.InvalidArgument, match="pass controller=fn too"):
        momenta.simulate(plant, duration=0.1, sample_time=0.1)
    with pytest.raises(momenta.InvalidArgument, match=r"no input of the model.*did you mean"):
        momenta.simulate(plant, duration=0.1, controller=lambda t, q, v: 0.0, drives=["thrus"])
    with pytest.raises(momenta.InvalidArgument, match="sample_time -1 s must be positive"):
        momenta.simulate(plant, duration=0.1, controller=lambda t, q, v: 0.0, sample_time=-1)
    looped = momenta.load_model(EXAMPLES / "satellite_attitude_pd.yaml")
    with pytest.raises(momenta.InvalidArgument, match="no input for it to drive"):
        momenta.simulate(looped, duration=0.1, controller=lambda t, q, v: 0.0)
    with pytest.raises(momenta.InvalidArgument, match="which controller 'attitude_pd' drives too"):
        momenta.simulate(looped, duration=0.1, controller=lambda t, q, v: 0.0, drives=["thrust"])


# --- the state derivative for scipy: model.dynamics(t, x, u) ----------------------------------

def test_solve_ivp_on_model_dynamics_is_simulate():
    # The cart pendulum's LQR loop closed around model.dynamics by scipy's own integrator
    # (DOP853, tight tolerances) against momenta's dopri5 run of the model file's controller.
    from scipy.integrate import solve_ivp
    plant = momenta.load_model(CART)
    assert plant.input_names == ["force"]
    x0 = np.array([0.0, np.radians(10.0), 0.0, 0.0])
    loop = solve_ivp(lambda t, x: plant.dynamics(t, x, [-LQR_K @ x]), (0.0, 4.0), x0,
                     method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True)
    filed = momenta.simulate(momenta.load_model(EXAMPLES / "cart_pendulum_lqr.yaml"),
                             duration=4.0, rtol=1e-12, atol=1e-12, integrator="dopri5")
    x = loop.sol(filed.time)
    np.testing.assert_allclose(x[1], filed["tilt.angle"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(x[0], filed["x.position"], rtol=0, atol=1e-9)


def test_model_dynamics_is_the_closed_form_and_checks_its_arguments():
    # The cart pendulum's equations (Franklin's, b the cart's damping), solved for the two
    # accelerations by hand at a state away from rest.
    plant = momenta.load_model(CART)
    M, m, b, l, I, g = 0.5, 0.2, 0.1, 0.3, 0.006, 9.81
    x, phi, xd, phid, u = 0.3, 0.4, -0.2, 0.7, 1.5
    # (M + m) ẍ + b ẋ + m l (φ̈ cos φ − φ̇² sin φ) = u ;  (I + m l²) φ̈ + m l ẍ cos φ = m g l sin φ
    A = np.array([[M + m, m * l * np.cos(phi)], [m * l * np.cos(phi), I + m * l**2]])
    rhs = np.array([u - b * xd + m * l * phid**2 * np.sin(phi), m * g * l * np.sin(phi)])
    acc = np.linalg.solve(A, rhs)
    xdot = plant.dynamics(0.0, [x, phi, xd, phid], [u])
    np.testing.assert_allclose(xdot, [xd, phid, *acc], rtol=1e-13, atol=1e-14)
    with pytest.raises(ValueError, match=r"x: expected a vector of 4 numbers"):
        plant.dynamics(0.0, [0.0, 0.0])
    np.testing.assert_array_equal(plant.dynamics(0.0, [x, phi, xd, phid], [[u]]), xdot)  # any shape
    with pytest.raises(ValueError, match=r"u: expected 1 number \(one per input: force\), got 2"):
        plant.dynamics(0.0, np.zeros(4), [1.0, 2.0])
    with pytest.raises(momenta.InvalidArgument, match=r"u\[0\] \(force\) is nan"):
        plant.dynamics(0.0, np.zeros(4), [float("nan")])


def test_a_commanded_joint_takes_its_acceleration_from_u():
    """examples/cart_pendulum_servo.yaml: its controller commands the cart's acceleration a, so
    dynamics() takes a in u, and ẍ = a, J φ̈ = m g l sin φ − m l a cos φ (J = I + m l²)."""
    servo = momenta.load_model(EXAMPLES / "cart_pendulum_servo.yaml")
    assert servo.input_names == ["cart_drive"]
    m, l, I, g = 0.2, 0.3, 0.006, 9.81
    x, phi, xd, phid, a = 0.3, 0.4, -0.2, 0.7, 1.5
    xdot = servo.dynamics(0.0, [x, phi, xd, phid], [a])
    phidd = (m * g * l * np.sin(phi) - m * l * a * np.cos(phi)) / (I + m * l**2)
    np.testing.assert_allclose(xdot, [xd, phid, a, phidd], rtol=1e-13, atol=1e-14)


def test_linearize_over_a_list_of_operating_points():
    # Gain scheduling: the pendulum (L = 1 m point mass) linearized at θ = 0, 0.5, π at once,
    # each A's ∂θ̈/∂θ = −(g/L) cos θ; θ = 0.5 is no equilibrium and the warning says which.
    model = momenta.load_model(EXAMPLES / "pendulum.yaml")
    angles = np.array([0.0, 0.5, np.pi])
    with pytest.warns(UserWarning, match=r"operating point 1 of 3 is not an equilibrium"):
        models = momenta.linearize(model, q=angles[:, None], v=[0.0])
    assert len(models) == 3
    for theta, linear in zip(angles, models):
        np.testing.assert_allclose(linear.system.A, [[0, 1], [-9.81 * np.cos(theta), 0]],
                                   rtol=0, atol=1e-12)
        one = momenta.linearize(model, q=[theta]) if theta != 0.5 else None
        if one is not None:
            np.testing.assert_array_equal(linear.system.A, one.system.A)
    with pytest.raises(ValueError, match="q has 3 rows and v 2"):
        momenta.linearize(model, q=angles[:, None], v=np.zeros((2, 1)))


def test_units_travel_with_the_linear_model():
    # Each state, input and output carries its SI unit from the model: coordinates and their
    # rates, the force's N, a controller's reference in the unit of what it measures, a PI's
    # integral in its drive's unit; c2d keeps them and a response reports them.
    cart_model = momenta.linearize(momenta.load_model(CART)).system
    assert cart_model.units == {"x.position": "m", "tilt.angle": "rad", "x.position_rate": "m/s",
                                "tilt.angle_rate": "rad/s", "force": "N", "cart_position": "m",
                                "tilt_angle": "rad"}
    assert "force [N]" in repr(cart_model)
    cruise = momenta.linearize(momenta.load_model(EXAMPLES / "cruise_control_pi.yaml")).system
    assert cruise.units["target_speed"] == "m/s" and cruise.units["cruise.integral"] == "N"
    assert momenta.c2d(cruise, 0.1).units == cruise.units
    step = momenta.step_response(cruise)
    assert step.units == {"target_speed": "m/s", "speed": "m/s", "x.position": "m",
                          "x.position_rate": "m/s", "cruise.integral": "N"}
    top = momenta.linearize(momenta.load_model(EXAMPLES / "heavy_top.yaml")).system
    assert top.units["tip.rx"] == "rad" and top.units["tip.wz"] == "rad/s"
    assert momenta.StateSpace([[0.0]], [[1.0]], [[1.0]], None).units == {}


def test_a_built_model_has_outputs_and_a_controller_may_measure_one():
    # ModelBuilder.add_output: the pendulum's tip x, 0.3 m up the rod from the pivot on the cart,
    # is x + 0.3 sin φ; the LQR built on the coordinates runs as the model file's, and the
    # output column equals its closed form. A PD on a cart's own position measured as a body
    # output runs as the PD on the coordinate.
    K = LQR_K.reshape(1, 4)
    b = _cart_builder("cart")
    b.add_output("tip_x", body="pendulum", quantity="position", point=np.array([0, 0, 0.3]),
                 component="x")
    b.add_output("cart_x", joint="x", quantity="position")
    b.add_controller("balance", "state_feedback",
                     measure=["cart_x", "tilt.angle", "x.position_rate", "tilt.angle_rate"],
                     gain=K, drives="force")
    b.add_force("push", body="cart", vector=[1, 0, 0], signal="force")
    model = b.build()
    assert model.output_names == ["tip_x", "cart_x"]
    run = momenta.simulate(model, duration=3.0, dt=0.001)
    filed = momenta.simulate(momenta.load_model(EXAMPLES / "cart_pendulum_lqr.yaml"),
                             duration=3.0, dt=0.001)
    np.testing.assert_allclose(run["tilt.angle"], filed["tilt.angle"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(run["tip_x"], run["x.position"] + 0.3 * np.sin(run["tilt.angle"]),
                               rtol=0, atol=1e-14)
    assert run.units["tip_x"] == "m"
    closed = momenta.linearize(model, q=[0.0, 0.0], v=[0.0, 0.0]).system
    open_loop = momenta.linearize(model, q=[0.0, 0.0], v=[0.0, 0.0], open_loop=True).system
    A, B = open_loop.A, open_loop.B[:, [0]]
    np.testing.assert_allclose(closed.A, A - B @ K, rtol=0, atol=1e-11)
    bad = momenta.ModelBuilder("cart")
    bad.add_body("cart", momenta.inertia.point_mass(0.5))
    bad.add_joint("x", "prismatic", parent="world", child="cart", axis=[1, 0, 0])
    bad.add_output("a", body="cart", quantity="acceleration", component="x")
    bad.add_controller("c", "pid", measure="a", drives="force", kp=1.0)
    bad.add_force("push", body="cart", vector=[1, 0, 0], signal="force")
    with pytest.raises(momenta.InvalidArgument, match="measures output 'a', which depends on the "
                                                      "accelerations"):
        bad.build()
    typo = momenta.ModelBuilder("cart")
    typo.add_body("cart", momenta.inertia.point_mass(0.5))
    typo.add_joint("x", "prismatic", parent="world", child="cart", axis=[1, 0, 0])
    typo.add_output("a", body="crt", quantity="position")
    with pytest.raises(momenta.ParseError, match="did you mean 'cart'"):
        typo.build()

"""The dynamics algorithms from Python: bit for bit the C++ call's results on the same state,
identities between them (RNEA inverts ABA, CRBA is RNEA's columns, T = ½ vᵀ M v, the Jacobian
maps v to the point's velocity), numpy in and out without surprises, bad arguments, no leaks."""

import gc
import resource
import tracemalloc

import numpy as np
import pytest

import momenta

from conftest import EXAMPLES, dynamics_reference

TOL = 1e-12  # relative; the algorithms agree to round-off on these small models


EXAMPLE_MODELS = ["double_pendulum", "heavy_top", "gyroscope", "quarter_car"]


@pytest.fixture(scope="module", params=EXAMPLE_MODELS)
def case(request):
    model = momenta.load_model(EXAMPLES / f"{request.param}.yaml")
    rng = np.random.default_rng(7)
    # A random configuration where every coordinate is an angle or a length; the model's own
    # (tilted, unit-quaternion) initial pose where quaternions are.
    q = model.initial_q + rng.standard_normal(model.nq) if model.nq == model.nv else model.initial_q
    v = rng.standard_normal(model.nv)
    return model, momenta.Workspace(model), q, v, rng


@pytest.mark.parametrize("name", EXAMPLE_MODELS + ["rotating_shaft_bent_rod", "free_body_tennis_racket"])
def test_every_algorithm_is_the_cpp_call_bit_for_bit(name):
    # Same compiled algorithms, same doubles in: the binding adds no arithmetic, so the results
    # are identical, not merely close — for every algorithm, array shape and dict entry.
    path = EXAMPLES / f"{name}.yaml"
    model = momenta.load_model(path)
    ws = momenta.Workspace(model)
    rng = np.random.default_rng(11)
    q = model.initial_q + rng.standard_normal(model.nq) if model.nq == model.nv else model.initial_q
    v, tau, vdot = (rng.standard_normal(model.nv) for _ in range(3))
    body, point = len(model.body_names) - 1, rng.standard_normal(3)
    ref = dynamics_reference(path, q=q, v=v, tau=tau, vdot=vdot, body=body, point=point)

    def same(actual, expected):
        expected = np.asarray(expected, dtype=float)
        assert np.shape(actual) == expected.shape
        np.testing.assert_array_equal(actual, expected)

    same(ws.aba(q, v, tau), ref["aba"])
    same(ws.rnea(q, v, vdot), ref["rnea"])
    same(ws.crba(q), ref["crba"])
    for actual, expected in zip(ws.rnea_derivatives(q, v, vdot), ref["rnea_derivatives"]):
        same(actual, expected)
    for actual, expected in zip(ws.aba_derivatives(q, v, tau), ref["aba_derivatives"]):
        same(actual, expected)
    same(ws.nonlinear_effects(q, v), ref["nonlinear_effects"])
    same(ws.generalized_gravity(q), ref["generalized_gravity"])
    for frame, expected in ref["joint_reactions"].items():
        forces, moments = ws.joint_reactions(q, v, vdot, frame=frame)
        same(forces, expected["forces"])
        same(moments, expected["moments"])
    ws.forward_kinematics(q, v, vdot)
    for b in range(len(model.body_names)):
        R, p = ws.body_pose(b)
        same(R, ref["body_poses"][b][0])
        same(p, ref["body_poses"][b][1])
        same(ws.body_velocity(b), ref["body_velocities"][b])
        same(ws.body_acceleration(b), ref["body_accelerations"][b])
    k = ws.point_kinematics(body, point, q, v, vdot)
    assert k.keys() == ref["point_kinematics"].keys()
    for key, expected in ref["point_kinematics"].items():
        same(k[key], expected)
    same(ws.frame_jacobian(body, point, q), ref["frame_jacobian"])
    assert ws.kinetic_energy(q, v) == ref["kinetic_energy"]
    assert ws.potential_energy(q) == ref["potential_energy"]
    same(ws.center_of_mass(q), ref["center_of_mass"])
    p = ws.momentum(q, v)
    assert p.keys() == ref["momentum"].keys()
    assert p["mass"] == ref["momentum"]["mass"]
    for key in ("center_of_mass", "center_of_mass_velocity", "linear", "angular_about_com"):
        same(p[key], ref["momentum"][key])


def test_rnea_inverts_aba(case):
    model, ws, q, v, rng = case
    tau = rng.standard_normal(model.nv)
    vdot = ws.aba(q, v, tau)
    np.testing.assert_allclose(ws.rnea(q, v, vdot), tau, rtol=0, atol=TOL * (1 + np.abs(tau).max()))


def test_derivatives_are_those_of_rnea_and_aba():
    # The double pendulum (every coordinate an angle, so q + h e_k is the tangent step): central
    # differences at h = 1e-5 (truncation h²/6 |f‴| ~ 1e-11, round-off ε|f|/h ~ 1e-11) against
    # the analytic ∂/∂q to 1e-8 of the scale; τ and v̇ are quadratic in v, so ∂/∂v differences
    # of step 1 are exact (round-off); M and M⁻¹ against crba.
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    rng = np.random.default_rng(3)
    q, v, vdot, tau = (rng.standard_normal(model.nv) for _ in range(4))
    dtau_dq, dtau_dv, M = ws.rnea_derivatives(q, v, vdot)
    dvdot_dq, dvdot_dv, Minv = ws.aba_derivatives(q, v, tau)
    assert all(x.shape == (model.nv, model.nv) for x in (dtau_dq, dtau_dv, M, dvdot_dq, dvdot_dv, Minv))
    h = 1e-5
    for k in range(model.nv):
        e = np.zeros(model.nv)
        e[k] = 1.0
        d_tau = (ws.rnea(q + h * e, v, vdot) - ws.rnea(q - h * e, v, vdot)) / (2 * h)
        d_vdot = (ws.aba(q + h * e, v, tau) - ws.aba(q - h * e, v, tau)) / (2 * h)
        np.testing.assert_allclose(dtau_dq[:, k], d_tau, rtol=0, atol=1e-8 * np.abs(dtau_dq).max())
        np.testing.assert_allclose(dvdot_dq[:, k], d_vdot, rtol=0, atol=1e-8 * np.abs(dvdot_dq).max())
        d_tau_v = (ws.rnea(q, v + e, vdot) - ws.rnea(q, v - e, vdot)) / 2
        d_vdot_v = (ws.aba(q, v + e, tau) - ws.aba(q, v - e, tau)) / 2
        np.testing.assert_allclose(dtau_dv[:, k], d_tau_v, rtol=0, atol=1e-12 * np.abs(dtau_dv).max())
        np.testing.assert_allclose(dvdot_dv[:, k], d_vdot_v, rtol=0, atol=1e-12 * np.abs(dvdot_dv).max())
    np.testing.assert_allclose(M, ws.crba(q), rtol=0, atol=1e-14 * np.abs(M).max())
    np.testing.assert_allclose(Minv @ M, np.eye(model.nv), rtol=0, atol=1e-13)


def test_mass_matrix_columns_are_rnea_differences(case):
    model, ws, q, v, _ = case
    M = ws.crba(q)
    assert M.shape == (model.nv, model.nv)
    np.testing.assert_array_equal(M, M.T)
    bias = ws.rnea(q, v, np.zeros(model.nv))
    np.testing.assert_allclose(bias, ws.nonlinear_effects(q, v), rtol=0, atol=1e-13 * (1 + np.abs(bias).max()))
    for k in range(model.nv):
        e = np.zeros(model.nv)
        e[k] = 1.0
        column = ws.rnea(q, v, e) - bias
        np.testing.assert_allclose(column, M[:, k], rtol=0, atol=TOL * np.abs(M).max())


def test_kinetic_energy_is_half_v_m_v(case):
    model, ws, q, v, _ = case
    T = ws.kinetic_energy(q, v)
    assert T == pytest.approx(0.5 * v @ ws.crba(q) @ v, rel=TOL)


def test_frame_jacobian_maps_v_to_the_point_velocity(case):
    model, ws, q, v, _ = case
    body, point = model.body_names[-1], [0.1, -0.2, 0.3]
    J = ws.frame_jacobian(body, point, q)
    k = ws.point_kinematics(body, point, q, v, np.zeros(model.nv))
    np.testing.assert_allclose(J[3:] @ v, k["velocity"], rtol=0, atol=TOL * (1 + np.abs(k["velocity"]).max()))
    # The acceleration's two decompositions agree.
    np.testing.assert_allclose(k["origin_acceleration"] + k["tangential"] + k["centripetal"],
                               k["from_vdot"] + k["velocity_product"], atol=1e-12)


def test_external_wrench_enters_as_its_jacobian_transpose():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    q, v = np.array([0.3, -0.4]), np.array([0.1, 0.2])
    f_ext = np.zeros((len(model.body_names), 6))
    f_ext[2, 3:] = [1.0, 0.0, 2.0]  # a force on mass2 at its origin, in its frame
    tau0 = ws.rnea(q, v, np.zeros(2))
    tau1 = ws.rnea(q, v, np.zeros(2), f_ext)
    ws.forward_kinematics(q)
    R, _ = ws.body_pose("mass2")
    J = ws.frame_jacobian("mass2", [0, 0, 0], q)
    np.testing.assert_allclose(tau0 - tau1, J[3:].T @ (R @ f_ext[2, 3:]), atol=1e-14)


def test_reactions_balance_gravity_at_rest():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    q = np.zeros(2)  # hanging straight down, at rest
    forces, moments = ws.joint_reactions(q, np.zeros(2), np.zeros(2))
    assert forces.shape == (2, 3) and moments.shape == (2, 3)
    np.testing.assert_allclose(forces[0], [0, 0, 2 * 9.81], atol=1e-13)
    np.testing.assert_allclose(forces[1], [0, 0, 9.81], atol=1e-13)


def test_momentum_and_center_of_mass():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    p = ws.momentum([0.0, 0.0], [1.0, 0.0])
    # Both masses turn about the pivot at 1 rad/s: L = m1 (1 m/s) + m2 (2 m/s) along x.
    np.testing.assert_allclose(np.abs(p["linear"]), [3.0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(ws.center_of_mass([0.0, 0.0]), [0, 0, -1.5], atol=1e-15)
    assert p["mass"] == 2.0


def test_inputs_of_any_real_dtype_and_layout():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    expected = ws.aba(np.array([1.0, 0.0]), np.zeros(2), np.zeros(2))
    np.testing.assert_array_equal(ws.aba([1, 0], [0, 0], [0, 0]), expected)        # lists of ints
    np.testing.assert_array_equal(ws.aba(np.array([1, 0], dtype=np.int32), np.zeros(2, np.float32),
                                         np.zeros(2)), expected)
    strided = np.array([1.0, 9.0, 0.0, 9.0])[::2]                                   # not contiguous
    np.testing.assert_array_equal(ws.aba(strided, np.zeros(2), np.zeros(2)), expected)
    out = ws.aba(np.array([1.0, 0.0]), np.zeros(2), np.zeros(2))
    assert out.dtype == np.float64 and out.flags.c_contiguous and out.flags.owndata


def test_results_are_not_views_of_the_workspace():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    first = ws.aba([1.0, 0.0], [0, 0], [0, 0])
    kept = first.copy()
    ws.aba([0.2, 0.1], [0, 0], [0, 0])
    np.testing.assert_array_equal(first, kept)


@pytest.mark.parametrize("q, message", [
    ([1.0, 2.0, 3.0], r"q: expected a vector of 2 numbers \(the model's nq\) or an \(N, 2\) array "
                      r"of N of them, got shape \(3,\)"),
    (np.zeros((2, 1)), r"q: expected a vector of 2 numbers .* got shape \(2, 1\)"),
    (np.zeros(2, dtype=complex), "q: expected an array of real numbers"),
    ("ab", "q: expected an array of real numbers"),
])
def test_bad_state_arguments_raise_value_error(q, message):
    ws = momenta.Workspace(momenta.load_model(EXAMPLES / "double_pendulum.yaml"))
    with pytest.raises(ValueError, match=message):
        ws.aba(q, [0, 0], [0, 0])


def test_bad_other_arguments():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    with pytest.raises(ValueError, match=r"tau: expected a vector of 2 numbers \(the model's nv\)"):
        ws.aba([0, 0], [0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match=r"f_ext: expected a 3 × 6 matrix"):
        ws.rnea([0, 0], [0, 0], [0, 0], np.zeros((2, 6)))
    with pytest.raises(momenta.InvalidArgument, match="did you mean"):
        ws.body_pose("mass")
    with pytest.raises(TypeError):
        ws.body_pose(1.5)


def test_no_leaks_over_many_calls():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    ws = momenta.Workspace(model)
    q, v, tau = np.array([0.1, 0.2]), np.zeros(2), np.zeros(2)

    def calls(n):
        for _ in range(n):
            ws.aba(q, v, tau)
            ws.crba(q)
            ws.rnea([0.1, 0.2], v, tau)

    calls(1000)
    gc.collect()
    tracemalloc.start()
    before_traced = tracemalloc.get_traced_memory()[0]
    before_rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    calls(100_000)
    gc.collect()
    after_traced = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    after_rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    # 3·10⁵ calls: a leak of even one 16-byte array per call would be 4.8 MB.
    assert after_traced - before_traced < 64 * 1024
    assert after_rss - before_rss < 2 * 1024  # kB


# --- batched calls: (N, n) arrays of states ----------------------------------------------------

def test_batched_calls_are_the_single_calls_row_by_row(case):
    model, ws, q, v, rng = case
    n = 7
    Q = np.tile(q, (n, 1))
    if model.nq == model.nv:
        Q = Q + 0.3 * rng.standard_normal(Q.shape)
    V = rng.standard_normal((n, model.nv))
    tau = rng.standard_normal(model.nv)  # one vector, used for every row
    A = ws.aba(Q, V, tau)
    taus = ws.rnea(Q, V, A)
    M = ws.crba(Q)
    assert A.shape == (n, model.nv) and taus.shape == (n, model.nv)
    assert M.shape == (n, model.nv, model.nv)
    for i in range(n):
        np.testing.assert_array_equal(A[i], ws.aba(Q[i], V[i], tau))
        np.testing.assert_array_equal(M[i], ws.crba(Q[i]))
        # RNEA inverts ABA row by row.
        np.testing.assert_allclose(taus[i], tau, rtol=0, atol=1e-10 * max(1.0, abs(tau).max()))


def test_batched_arguments_must_agree():
    ws = momenta.Workspace(momenta.load_model(EXAMPLES / "double_pendulum.yaml"))
    with pytest.raises(ValueError, match=r"v: 2 rows, where q has 3"):
        ws.aba(np.zeros((3, 2)), np.zeros((2, 2)), [0, 0])
    with pytest.raises(ValueError, match=r"q: expected a vector of 2 numbers .* or an \(N, 2\) array"):
        ws.crba(np.zeros((3, 3)))


def test_model_dynamics_on_quaternions_is_half_q_times_omega():
    # The heavy top: q̇ of its ball joint's quaternion is ½ q ⊗ [0; ω] with ω in the body frame,
    # and v̇ is aba's with the simulator's forces (none but gravity here: tau = 0).
    model = momenta.load_model(EXAMPLES / "heavy_top.yaml")
    ws = momenta.Workspace(model)
    q, v = model.initial_q, np.array([0.3, -0.2, 40.0])
    xdot = model.dynamics(0.0, np.concatenate([q, v]))
    w, x, y, z = q
    omega = np.concatenate([[0.0], v])
    product = np.array([
        w * omega[0] - x * omega[1] - y * omega[2] - z * omega[3],
        w * omega[1] + x * omega[0] + y * omega[3] - z * omega[2],
        w * omega[2] - x * omega[3] + y * omega[0] + z * omega[1],
        w * omega[3] + x * omega[2] - y * omega[1] + z * omega[0],
    ])
    np.testing.assert_allclose(xdot[:4], 0.5 * product, rtol=0, atol=1e-14)
    np.testing.assert_allclose(xdot[4:], ws.aba(q, v, np.zeros(3)), rtol=1e-13, atol=1e-13)

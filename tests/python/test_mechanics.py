"""The textbook's method from Python: free-body diagrams against `momenta diagram --json`
(bit-identical), the pendulum's rod tension and a contact's force, rotating-frame kinematics against
`momenta kinematics --json`, equations and transfer functions in symbols against the command
line and the numeric linearization."""

import json

import numpy as np
import pytest

import momenta

from conftest import EXAMPLES, cli_json, run_cli

needs_symbolic = pytest.mark.skipif(not momenta.with_symbolic,
                                    reason="built with MOMENTA_WITH_SYMBOLIC=OFF")


def test_free_body_diagram_is_the_command_lines():
    # The four-bar's coupler at its initial state: pin, closure and weight.
    path = EXAMPLES / "constraints" / "four_bar.yaml"
    d = momenta.free_body_diagram(momenta.load_model(path), "coupler")
    expected = json.loads(run_cli("diagram", path, "--body", "coupler", "--json"))
    assert [load["name"] for load in d["loads"]] == [load["name"] for load in expected["loads"]]
    for mine, theirs in zip(d["loads"], expected["loads"]):
        assert mine["kind"] == theirs["kind"]
        np.testing.assert_array_equal(mine["force"], theirs["force"])
        np.testing.assert_array_equal(mine["point"], theirs["point"])
        np.testing.assert_array_equal(mine["couple"], theirs["couple"])
    np.testing.assert_array_equal(d["m_a_G"], expected["kinetic"]["m_a_G"])
    assert d["svg"].startswith("<svg")


def test_pendulum_rod_pulls_with_mg_cos_theta_plus_ml_theta_dot_squared():
    model = momenta.load_model(EXAMPLES / "pendulum.yaml")
    theta, rate = 0.9, -1.7
    d = momenta.free_body_diagram(model, "bob", q=[theta], v=[rate])
    pin = next(load for load in d["loads"] if load["name"] == "pivot")
    assert pin["kind"] == "reaction" and pin["joint"] == "pivot"
    tension = 9.81 * np.cos(theta) + rate**2
    np.testing.assert_allclose(pin["force"], -tension * d["com"], rtol=1e-13, atol=1e-13)
    assert np.linalg.norm(d["force_residual"]) <= 1e-13 * 10
    assert abs(abs(d["plane_normal"][1]) - 1) <= 1e-15


def test_a_contact_the_body_rests_on_pushes_and_rubs_as_the_command_line_says():
    # The bowling ball set down skidding: N = m g and μk m g against the slip at the contact point.
    path = EXAMPLES / "skidding_ball.yaml"
    d = momenta.free_body_diagram(momenta.load_model(path), "ball")
    lane = next(load for load in d["loads"] if load["name"] == "lane")
    weight = 7.0 * 9.81
    np.testing.assert_allclose(lane["force"], [-0.1 * weight, 0, weight], rtol=0, atol=1e-12 * weight)
    np.testing.assert_allclose(lane["point"], [0, 0, 0], atol=1e-15)
    expected = json.loads(run_cli("diagram", path, "--body", "ball", "--json"))
    theirs = next(load for load in expected["loads"] if load["name"] == "lane")
    np.testing.assert_array_equal(lane["force"], theirs["force"])


def test_relative_kinematics_is_the_command_lines():
    path = EXAMPLES / "kinematics" / "turntable_bead.yaml"
    model = momenta.load_model(path)
    k = momenta.relative_kinematics(model, "bead", frame="turntable", q=[0.3, 0.1], v=[2.0, 0.5],
                                    t=0.15)
    # v_rel = [0.5, 0, 0] in the slot, Coriolis 2 Ω × v_rel = [0, 2, 0].
    np.testing.assert_allclose(k["v_relative"], [0.5, 0, 0], atol=1e-15)
    np.testing.assert_allclose(k["a_coriolis"], [0, 2.0, 0], atol=1e-14)
    np.testing.assert_allclose(k["a_centripetal"], [-0.4, 0, 0], atol=1e-14)


def test_impulsive_motion_is_the_command_lines():
    """The struck rod at its tip: the same numbers as `momenta impact --json` (ω = 2.5 rad/s, the
    pin's impulse 2 N·s along the blow), and Kelvin's work equal to the energy gained."""
    path = EXAMPLES / "struck_rod.yaml"
    ws = momenta.Workspace(momenta.load_model(path))
    r = ws.impulsive_motion([0.0], [0.0], [("rod", [0, 0, -1.2], [4.0, 0, 0])])
    cli = cli_json("impact", path, "--at", "rod:0,0,-1.2", "--impulse", "4,0,0")
    assert r["v_after"][0] == cli["v_after"]["pin.angle_rate"]
    np.testing.assert_allclose(r["v_after"], [-2.5], rtol=1e-15)
    np.testing.assert_allclose(r["joint_impulse_forces"][0], [2.0, 0, 0], atol=1e-14)
    assert r["joint_impulse_forces"][0][0] == cli["joint_impulses"]["pin"]["force"][0]
    assert r["impulse_work"] == pytest.approx(r["kinetic_after"] - r["kinetic_before"], rel=1e-14)
    with pytest.raises(ValueError, match="triples"):
        ws.impulsive_motion([0.0], [0.0], [("rod", [0, 0, 0])])


def test_restitution_impact_is_the_command_lines():
    """The eccentric impact example: a sphere at 3 m/s strikes the hanging rod with e = 0.6."""
    path = EXAMPLES / "eccentric_impact.yaml"
    ws = momenta.Workspace(momenta.load_model(path))
    r = ws.restitution_impact([0.0, 0.0], [0.0, 3.0], "sphere", [0, 0, 0], "rod", [0, 0, -1.1],
                              [1, 0, 0], 0.6)
    cli = cli_json("impact", path, "--between", "sphere", "rod:0,0,-1.1", "--normal", "1,0,0",
                   "--restitution", 0.6)
    assert r["normal_impulse"] == cli["normal_impulse"]
    np.testing.assert_array_equal(r["v_after"], [cli["v_after"]["pin.angle_rate"],
                                                 cli["v_after"]["slide.position_rate"]])
    assert r["separation_speed"] == pytest.approx(1.8, rel=1e-15)


def test_impulse_momentum_diagram_is_the_command_lines():
    """The struck rod hit at its tip (4 N·s at 1.2 m): the pin pushes back 2 N·s along the blow;
    the rod at rest before, m v̄ = 6 N·s after; the same numbers as `momenta diagram --at`."""
    path = EXAMPLES / "struck_rod.yaml"
    d = momenta.impulse_momentum_diagram(momenta.load_model(path), "rod",
                                         [("rod", [0, 0, -1.2], [4.0, 0, 0])])
    cli = cli_json("diagram", path, "--body", "rod", "--at", "rod:0,0,-1.2", "--impulse", "4,0,0")
    assert [p["name"] for p in d["impulses"]] == [p["name"] for p in cli["impulses"]]
    for mine, theirs in zip(d["impulses"], cli["impulses"]):
        np.testing.assert_array_equal(mine["impulse"], theirs["impulse"])
    np.testing.assert_allclose(d["impulses"][1]["impulse"], [2.0, 0, 0], atol=1e-14)
    np.testing.assert_array_equal(d["linear_before"], [0, 0, 0])
    np.testing.assert_allclose(d["linear_after"], [6.0, 0, 0], rtol=1e-14)
    assert np.linalg.norm(d["linear_residual"]) < 1e-14 * 6
    assert d["svg"].startswith("<svg") and 'data-panel="impulses"' in d["svg"]
    with pytest.raises(ValueError, match="triples"):
        momenta.impulse_momentum_diagram(momenta.load_model(path), "rod", [("rod", [0, 0, 0])])


def same_expression(a, b, names):
    """Two expressions as GiNaC prints them are equal at random values of their symbols (GiNaC's
    order of terms can differ from process to process)."""
    rng = np.random.default_rng(3)
    for _ in range(3):
        values = {name: complex(*rng.uniform(0.5, 2.0, 2)) for name in names}
        left = eval(a.replace("^", "**"), {}, values)
        right = eval(b.replace("^", "**"), {}, values)
        if abs(left - right) > 1e-12 * abs(right):
            return False
    return True


@needs_symbolic
def test_equations_and_transfer_functions_in_symbols():
    path = EXAMPLES / "cruise_control.yaml"
    model = momenta.load_model(path)
    names = ["m_car", "c_road", "u", "road_dot", "road_ddot", "s"]
    (equation,) = momenta.equations(model, all_symbols=True)
    printed = run_cli("equations", path, "--all-symbols").splitlines()[1]
    for mine, theirs in zip(equation.split(" = "), printed.split(" = ")):
        assert same_expression(mine, theirs, names), (equation, printed)
    # 1/(m s + b), as the command line prints it and as Franklin writes it.
    g = momenta.symbolic_transfer_function(model, "u", "road", rate=True, all_symbols=True)
    line = run_cli("equations", path, "--all-symbols", "--transfer", "u:speed").strip()
    assert same_expression(g, line.split(" = ")[-1], names)
    assert same_expression(g, "1/(m_car*s + c_road)", names)
    assert same_expression(momenta.symbolic_transfer_function(model, "u", "road", rate=True),
                           "1/(1000*s + 50)", names)
    rows = momenta.equations(momenta.load_model(EXAMPLES / "pendulum.yaml"), form="newton-euler")
    assert any(row.startswith("joint pivot: along pivot_dot") for row in rows)
    with pytest.raises(momenta.InvalidArgument, match="no parameter named 'm'"):
        momenta.equations(model, symbols=["m"])


@needs_symbolic
def test_equations_in_the_textbooks_symbols():
    # m L² θ̈ + m g L sin θ = 0: L the bob's positive distance, the names given, θ on request.
    model = momenta.load_model(EXAMPLES / "pendulum.yaml")
    (plain,) = momenta.equations(model, all_symbols=True)
    assert plain == "L_bob^2*m_bob*pivot_ddot + L_bob*g*m_bob*sin(pivot) = 0", plain
    (named,) = momenta.equations(model, all_symbols=True, greek=True,
                                 names={"m_bob": "m", "L_bob": "L"})
    assert named == "L^2*m*\u03b8\u0308 + L*g*m*sin(\u03b8) = 0", named
    (latex,) = momenta.equations(model, symbols=["L_bob"], greek=True, format="latex")
    assert latex == "L_{\\mathrm{bob}}^{2} \\ddot{\\theta} + 9.81 L_{\\mathrm{bob}} \\sin(\\theta) = 0", latex
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'm_bob'"):
        momenta.equations(model, names={"m_bb": "m"})


@needs_symbolic
@needs_symbolic
def test_equations_too_large_to_print_say_what_to_use_in_python_words():
    """The ten-link chain's equations print as trees of millions of terms: refused at once, with
    what to use instead as Python has it (the CLI says --cpp / `momenta linearize`)."""
    chain = momenta.load_model(EXAMPLES.parent / "bench" / "models" / "chain10.yaml")
    with pytest.raises(momenta.InvalidArgument, match=r"written as code \(the command line's"):
        momenta.equations(chain)
    with pytest.raises(momenta.InvalidArgument,
                       match=r"numeric linearization \(momenta\.linearize\(\)\)"):
        momenta.symbolic_transfer_function(chain, "u", "q")


def test_equations_of_a_constrained_model_carry_its_forces_and_rows():
    # The geared pair: I_p θ̈_p = λ, I_w θ̈_w − T = −n λ, then the coupler's row θ_p − n θ_w = 0.
    path = EXAMPLES / "constraints" / "geared_pair.yaml"
    lines = momenta.equations(momenta.load_model(path), all_symbols=True)
    names = ["I_pinion_zz", "I_wheel_zz", "F_drive", "n_mesh", "lambda_mesh_ratio",
             "pinion_axle", "wheel_axle", "pinion_axle_ddot", "wheel_axle_ddot"]
    expected = ["I_pinion_zz*pinion_axle_ddot = lambda_mesh_ratio",
                "I_wheel_zz*wheel_axle_ddot - F_drive = -n_mesh*lambda_mesh_ratio",
                "pinion_axle - n_mesh*wheel_axle = 0"]
    assert len(lines) == 3 and lines[2].startswith("mesh.ratio: "), lines
    for line, textbook in zip(lines, expected):
        mine_left, mine_right = line.split(": ", 1)[-1].split(" = ")
        book_left, book_right = textbook.split(" = ")
        assert same_expression(f"({mine_left})-({mine_right})", f"({book_left})-({book_right})",
                               names), (line, textbook)


@needs_symbolic
def test_newton_euler_rows_in_principal_axes(tmp_path):
    # A plate with products of inertia: its rows in its principal axes, named after the body.
    path = tmp_path / "plate.yaml"
    path.write_text(
        "name: skewed plate\n"
        "bodies:\n"
        "  - {name: plate, mass: 3, inertia: [[0.3, -0.05, 0], [-0.05, 0.4, 0], [0, 0, 0.6]]}\n"
        "joints:\n"
        "  - {name: bearing, type: revolute, parent: world, child: plate, axis: [0, 0, 1]}\n")
    model = momenta.load_model(path)
    body_axes = momenta.equations(model, form="newton-euler")
    principal = momenta.equations(model, form="newton-euler", principal_axes=True)
    assert not any("principal axes" in row for row in body_axes)
    assert sum(row.startswith("plate (principal axes e1 = ") for row in principal) >= 3, principal


@needs_symbolic
def test_a_top_in_euler_angles_as_the_command_line_writes_it():
    # The heavy top's equations in precession, nutation and spin (ZXZ), as
    # `momenta equations --coordinates euler:ZXZ` prints them.
    path = EXAMPLES / "heavy_top.yaml"
    model = momenta.load_model(path)
    mine = momenta.equations(model, coordinates="euler:ZXZ")
    printed = run_cli("equations", path, "--coordinates", "euler:ZXZ").splitlines()[1:]
    assert " ".join(mine) == " ".join(line.strip() for line in printed)
    assert any("theta_ddot" in line for line in mine) and not any("_qw" in line for line in mine)
    with pytest.raises(momenta.InvalidArgument, match="euler:SEQUENCE"):
        momenta.equations(model, coordinates="angles")


@needs_symbolic
def test_equations_as_sympy_are_lagranges_by_hand():
    sympy = pytest.importorskip("sympy")
    from sympy.physics.vector import dynamicsymbols
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    eqs = momenta.equations(model, format="sympy", all_symbols=True)
    assert len(eqs) == 2 and all(isinstance(e, sympy.Eq) and e.rhs == 0 for e in eqs)
    # The double pendulum's Lagrangian by hand (point masses m1 on L1, m2 on L2 hung from the
    # first): the relative angle θ2 is measured from the upper rod.
    t = dynamicsymbols._t
    th1, th2 = dynamicsymbols("upper lower")
    m1, m2, L1, L2, g = sympy.symbols("m_mass1 m_mass2 L_mass1 L_mass2 g", real=True)
    # The model's symbols for the lower joint's offset and the masses' distances.
    Lj = sympy.Symbol("L_lower", real=True)
    x1, z1 = L1 * sympy.sin(th1), -L1 * sympy.cos(th1)
    x2 = Lj * sympy.sin(th1) + L2 * sympy.sin(th1 + th2)
    z2 = -Lj * sympy.cos(th1) - L2 * sympy.cos(th1 + th2)
    T = (m1 * (x1.diff(t)**2 + z1.diff(t)**2) + m2 * (x2.diff(t)**2 + z2.diff(t)**2)) / 2
    V = g * (m1 * z1 + m2 * z2)
    Lagrangian = T - V
    for q, equation in zip([th1, th2], eqs):
        by_hand = Lagrangian.diff(q.diff(t)).diff(t) - Lagrangian.diff(q)
        assert sympy.simplify(sympy.expand_trig(equation.lhs - by_hand)) == 0
    # The matrix form: M v̇ + h = the equations; M's values at the file's numbers.
    residual = eqs.M * eqs.accelerations + eqs.h - sympy.Matrix([e.lhs for e in eqs])
    assert sympy.simplify(residual) == sympy.zeros(2, 1)
    values = eqs.values()
    at = {th1: 0.3, th2: -0.7}
    numeric = np.array(eqs.M.subs(values).subs(at).evalf(), dtype=float)
    np.testing.assert_allclose(numeric, momenta.Workspace(model).crba([0.3, -0.7]), rtol=1e-14)
    assert eqs.units[sympy.Symbol("g", real=True)] == "m/s²"
    assert eqs._repr_latex_().startswith(r"$\begin{aligned}") and r"\ddot{upper}" in eqs._repr_latex_()
    assert "= 0" in repr(eqs)


@needs_symbolic
def test_sympy_equations_carry_the_inputs_and_a_spinning_bodys_own_speeds():
    sympy = pytest.importorskip("sympy")
    cruise = momenta.equations(momenta.load_model(EXAMPLES / "cruise_control.yaml"), format="sympy",
                               all_symbols=True)
    (u,) = cruise.inputs
    assert cruise.B.shape == (1, 1) and cruise.B[0, 0] == 1  # the engine's force along the road
    top = momenta.equations(momenta.load_model(EXAMPLES / "heavy_top.yaml"), format="sympy")
    assert len(top) == 3 and len(top.coordinates) == 7  # a quaternion and the body's ω
    with pytest.raises(TypeError, match="format='sympy'"):
        momenta.equations(momenta.load_model(EXAMPLES / "pendulum.yaml"), format="sympy",
                          greek=True)


@needs_symbolic
def test_matrix_form_and_generated_code_as_the_command_line_writes_them():
    # form='matrix' is --form matrix's lines, format='python' its --python module, and that
    # module's M(q) and b(q, v, 0, u) are CRBA's and RNEA's at a random state.
    path = EXAMPLES / "double_pendulum.yaml"
    model = momenta.load_model(path)
    lines = momenta.equations(model, form="matrix")
    printed = run_cli("equations", path, "--form", "matrix").splitlines()
    assert lines == printed[2:], (lines, printed)
    assert lines[0].startswith("M[0,0] = ") and any(l.startswith("(C v)[1] = ") for l in lines)
    code = momenta.equations(model, format="python")
    assert code == run_cli("equations", path, "--python")
    module = {}
    exec(compile(code, "double_pendulum_equations.py", "exec"), module)
    ws = momenta.Workspace(model)
    rng = np.random.default_rng(3)
    q, v = rng.standard_normal(2), rng.standard_normal(2)
    np.testing.assert_allclose(module["mass_matrix"](q), ws.crba(q), rtol=1e-14, atol=1e-14)
    # b = C v + g − Q with Q = 0 here: RNEA's τ at v̇ = 0.
    np.testing.assert_allclose(module["bias"](q, v, [0, 0], []), ws.rnea(q, v, np.zeros(2)),
                               rtol=1e-13, atol=1e-13)
    assert "mass_matrix" in momenta.equations(model, format="cpp")
    with pytest.raises(momenta.InvalidArgument, match="expected 'lagrange', 'matrix' or"):
        momenta.equations(model, form="matrices")

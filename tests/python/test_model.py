"""Models from Python: load_model against `momenta info --json`, the builder against a model file
of the same system, and errors that say where."""

import numpy as np
import pytest

import momenta
from momenta import inertia

from conftest import EXAMPLES, SOURCE_DIR, cli_json


@pytest.mark.parametrize("name", ["double_pendulum", "heavy_top", "quarter_car", "gyroscope"])
def test_load_model_names_everything_as_info_does(name):
    path = EXAMPLES / f"{name}.yaml"
    model = momenta.load_model(path)
    expected = cli_json("info", path)
    assert model.name == expected["name"]
    assert (model.nq, model.nv) == (expected["nq"], expected["nv"])
    assert model.total_mass == expected["total_mass"]
    np.testing.assert_array_equal(model.gravity, expected["gravity"])
    assert model.body_names[1:] == [b["name"] for b in expected["bodies"]]
    info = model.info()
    for body, want in zip(info["bodies"], expected["bodies"]):
        assert body["mass"] == want["mass"]
        np.testing.assert_array_equal(body["center_of_mass"], want["com"])
        np.testing.assert_array_equal(body["inertia_about_com"], want["inertia_com"])
    assert len(model.q_names) == model.nq and len(model.v_names) == model.nv
    assert model.initial_q.shape == (model.nq,) and model.initial_q.dtype == np.float64


def pendulum_by_builder(length=1.0, mass=1.0):
    b = momenta.ModelBuilder("pendulum")
    b.add_body("bob", inertia.point_mass(mass).transformed(np.eye(3), [0, 0, -length]))
    b.add_joint("hinge", "revolute", parent="world", child="bob", axis=[0, 1, 0], q0=[0.5])
    return b.build()


def test_builder_makes_the_model_a_file_makes():
    built = pendulum_by_builder()
    assert built.name == "pendulum" and built.file == ""
    assert built.q_names == ["hinge.angle"] and built.nv == 1
    np.testing.assert_array_equal(built.initial_q, [0.5])
    # Small oscillations: ω² = g / L; the mass matrix is m L².
    ws = momenta.Workspace(built)
    np.testing.assert_allclose(ws.crba([0.0]), [[1.0]], rtol=1e-15)
    np.testing.assert_allclose(ws.generalized_gravity([1e-3]), [9.81 * np.sin(1e-3)], rtol=1e-14)


def test_builder_takes_a_joints_armature():
    """armature= adds a rotor's reflected inertia to the joint's diagonal of M: m L² + I_a."""
    b = momenta.ModelBuilder("motor pendulum")
    b.add_body("bob", inertia.point_mass(2.0).transformed(np.eye(3), [0, 0, -0.5]))
    b.add_joint("hinge", "revolute", parent="world", child="bob", axis=[0, 1, 0], armature=0.3)
    ws = momenta.Workspace(b.build())
    np.testing.assert_allclose(ws.crba([0.7]), [[2.0 * 0.25 + 0.3]], rtol=1e-15)
    with pytest.raises(momenta.InvalidArgument, match="armature -1 must be zero or positive"):
        b2 = momenta.ModelBuilder("bad")
        b2.add_body("bob", inertia.point_mass(1.0).transformed(np.eye(3), [0, 0, -1]))
        b2.add_joint("hinge", "revolute", parent="world", child="bob", armature=-1.0)
        b2.build()


def test_builder_takes_a_tendon():
    """add_tendon: L = offset + Σ cᵢ qᵢ with a spring along it. Two hinges with no gravity, released
    from rest: the spring's energy ½ k (L − rest)² is all the energy there is, and it is kept."""
    b = momenta.ModelBuilder("tendon")
    b.set_gravity([0, 0, 0])
    b.add_body("a", inertia.point_mass(1.0).transformed(np.eye(3), [0, 0, -1]))
    b.add_body("b", inertia.point_mass(0.5).transformed(np.eye(3), [0, 0, -0.5]))
    b.add_joint("ja", "revolute", parent="world", child="a", axis=[0, 1, 0], q0=[0.4])
    b.add_joint("jb", "revolute", parent="a", child="b", axis=[0, 1, 0], q0=[-0.3],
                in_parent={"position": [0, 0, -1]})
    b.add_tendon("cord", joints=[("ja", 1.0), ("jb", -0.5)], stiffness=3.0, rest_length=0.1,
                 offset=0.05)
    model = b.build()
    assert model.force_element_names == ["cord"]
    run = momenta.simulate(model, duration=0.5, dt=1e-3)
    L0 = 0.05 + 0.4 + 0.15
    np.testing.assert_allclose(run["energy_total"][0], 0.5 * 3.0 * (L0 - 0.1) ** 2, rtol=1e-14)
    # RK4 at 1 ms on a motion of period ~1 s: an energy error far below 1e-9 of it.
    assert np.max(np.abs(run["energy_total"] - run["energy_total"][0])) < 1e-9
    with pytest.raises(momenta.InvalidArgument, match="joint 'ja' is listed twice"):
        b.add_tendon("twice", joints=[("ja", 1.0), ("ja", 2.0)])
        b.build()


def test_builder_takes_signals_and_force_elements():
    b = momenta.ModelBuilder("cart")
    b.set_gravity([0, 0, 0])
    b.add_body("cart", inertia.point_mass(2.0))
    b.add_joint("slide", "prismatic", parent="world", child="cart", axis=[1, 0, 0])
    b.add_signal("push", "step", final=4.0, start=0.0)
    b.add_force("motor", body="cart", vector=[1, 0, 0], signal="push")
    b.add_spring_damper("spring", body_a="world", point_a=[0, 0, 0], body_b="cart",
                        point_b=[0, 0, 0], stiffness=8.0, damping=0.0, free_length=0.0)
    model = b.build()
    assert model.signal_names == ["push"]
    assert model.force_element_names == ["motor", "spring"]
    # x'' = (4 − 8 x)/2: the static deflection is 0.5 m.
    eq = momenta.find_equilibrium(model, q_guess=[0.1])
    np.testing.assert_allclose(eq.q, [0.5], rtol=1e-10)
    assert eq.stable


def test_builder_errors_name_the_item():
    b = momenta.ModelBuilder()
    b.add_body("link", inertia.point_mass(1.0))
    b.add_joint("hinge", "revolute", parent="wrold", child="link")
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'world'"):
        b.build()
    with pytest.raises(momenta.InvalidArgument, match="unknown type 'stepp'.*did you mean 'step'"):
        momenta.ModelBuilder().add_signal("u", "stepp")
    with pytest.raises(momenta.InvalidArgument, match="no parameter 'amplitud'.*did you mean 'amplitude'"):
        momenta.ModelBuilder().add_signal("u", "sine", amplitud=1.0)
    with pytest.raises(momenta.InvalidArgument, match="joint type"):
        momenta.ModelBuilder().add_joint("j", "hinj", parent="world", child="x")
    with pytest.raises(ValueError, match=r"in_parent\['position'\]: expected a vector of 3"):
        momenta.ModelBuilder().add_joint("j", "fixed", parent="world", child="x",
                                         in_parent={"position": [1, 2]})


def test_parse_errors_carry_file_line_and_column(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nbodies:\n  - name: a\n    mass: -1\njoints: []\n")
    with pytest.raises(momenta.ParseError) as caught:
        momenta.load_model(path)
    error = caught.value
    assert error.file.endswith("bad.yaml")
    assert (error.line, error.column) == (4, 11)
    assert str(error).startswith(f"{error.file}:4:11:")
    assert isinstance(error, momenta.Error) and isinstance(error, ValueError)


def test_a_singular_model_is_reported_at_its_joint(tmp_path):
    path = tmp_path / "rod.yaml"
    path.write_text(
        "bodies:\n  - {name: rod, mass: 1, inertia: [1, 1, 0]}\n"
        "joints:\n  - {name: spin, type: revolute, parent: world, child: rod, axis: [0, 0, 1]}\n")
    with pytest.raises(momenta.ParseError, match="singular") as caught:
        momenta.load_model(path)
    assert caught.value.line == 4


def test_bodies_by_name_or_index():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    assert model.body_index("mass2") == 2
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'mass2'"):
        model.body_index("mas2")
    assert model.body_mass_properties("mass1").mass == 1.0
    with pytest.raises(IndexError):
        model.body_mass_properties(7)


def test_an_mjcf_file_loads_as_a_model(tmp_path):
    """momenta.load_model takes MJCF (docs/model-formats.md): the double pendulum written for
    MuJoCo hangs with its YAML twin's normal modes; the arm's motors are inputs; a bad file is a
    ParseError at its line and column."""
    data = EXAMPLES.parent / "tests" / "data" / "models" / "mjcf"
    model = momenta.load_model(data / "double_pendulum.xml")
    equilibrium = momenta.find_equilibrium(model)
    squared = sorted(m.squared_frequency for m in momenta.undamped_modes(equilibrium.linear))
    assert squared == pytest.approx([9.81 * (2 - 2 ** 0.5), 9.81 * (2 + 2 ** 0.5)], rel=1e-11)
    assert momenta.load_model(data / "arm7.xml").nv == 7
    bad = tmp_path / "bad.xml"
    bad.write_text("<mujoco>\n<worldbody>\n<body><jiont/></body>\n</worldbody>\n</mujoco>\n")
    with pytest.raises(momenta.ParseError, match=r"bad.xml:3:7: <jiont> in body 'body1'"):
        momenta.load_model(bad)


KEYED_MJCF = SOURCE_DIR / "tests" / "data" / "models" / "mjcf" / "keyed_box.xml"


def test_an_mjcf_keyframe_is_the_initial_state_asked_for():
    """keyframe= starts the model from a key's state, in momenta's layout (the hinge's q is qpos −
    ref, the free joint's speeds [ω; v]), as `momenta --keyframe` does; info lists the keys."""
    path = KEYED_MJCF
    drawn = momenta.load_model(path)
    assert np.array_equal(drawn.initial_v, np.zeros(7))
    (key,) = drawn.info()["keyframes"]
    assert key["name"] == "tilted"
    keyed = momenta.load_model(path, keyframe="tilted")
    assert np.array_equal(keyed.initial_q, key["q"])
    assert keyed.initial_q[7] == pytest.approx(2 - np.pi / 2, abs=1e-15)
    assert np.array_equal(keyed.initial_v, [4, 5, 6, 1, 2, 3, 7])
    with pytest.raises(momenta.InvalidArgument, match=r"keyframe 'tiltd': .*did you mean 'tilted'"):
        momenta.load_model(path, keyframe="tiltd")


def test_a_urdf_with_meshes_on_a_package_path(monkeypatch):
    """A URDF's package:// meshes are found on package_path, its links without <inertial> weighed
    at link_density (the mesh arm: four solids' closed forms at 2700 kg/m³ and a 0.5 kg payload,
    to the COLLADA hand's single precision); without the path, a ParseError saying what to give."""
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    packages = EXAMPLES.parent / "tests" / "data" / "models" / "urdf" / "packages"
    arm = packages / "mesh_arm" / "urdf" / "mesh_arm.urdf"
    model = momenta.load_model(arm, package_path=[packages], link_density=2700.0)
    solids = 0.25 * 0.25 * 0.125 + 1.5 * 3 ** 0.5 * 0.04 ** 2 * 0.375 + 0.3125 * 0.0625 ** 2 \
        + 0.05 * 0.08 * 0.03
    total = sum(body["mass"] for body in model.info()["bodies"])
    assert total == pytest.approx(2700 * solids + 0.5, rel=1e-7)
    assert momenta.load_model(arm, package_path=[packages]).info()["bodies"][1]["mass"] == 0.0
    # The hint in Python's words, not the command line's.
    with pytest.raises(momenta.ParseError, match=r"mesh_arm.urdf:16: .* package_path= ") as refused:
        momenta.load_model(arm, link_density=2700.0)
    assert "--" not in str(refused.value)
    with pytest.raises(momenta.InvalidArgument, match="link density -1"):
        momenta.load_model(arm, package_path=[packages], link_density=-1.0)


def test_models_written_as_mjcf_and_urdf_read_back(tmp_path):
    """momenta.to_mjcf / to_urdf write what `momenta export` writes: the double pendulum read back
    from either has its YAML twin's normal modes; what a format cannot keep is said."""
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    for name, text in (("dp.xml", momenta.to_mjcf(model)), ("dp.urdf", momenta.to_urdf(model))):
        path = tmp_path / name
        path.write_text(text)
        back = momenta.find_equilibrium(momenta.load_model(path))
        squared = sorted(m.squared_frequency for m in momenta.undamped_modes(back.linear))
        assert squared == pytest.approx([9.81 * (2 - 2 ** 0.5), 9.81 * (2 + 2 ** 0.5)], rel=1e-11)
    with pytest.warns(UserWarning, match="not written: the prescribed motion of joint 'crank_pin'"):
        momenta.to_mjcf(momenta.load_model(EXAMPLES / "constraints" / "four_bar.yaml"))
    with pytest.raises(momenta.InvalidArgument, match=r"URDF has no such joint; write MJCF \(to_mjcf\(\)\)"):
        momenta.to_urdf(momenta.load_model(EXAMPLES / "heavy_top.yaml"))


def test_a_urdf_file_loads_as_a_model():
    """momenta.load_model takes a URDF (docs/model-formats.md): the double pendulum hangs with the
    normal modes of its YAML twin, ω² = (g/l)(2 ∓ √2); a bad file is a ParseError at its line."""
    urdf = EXAMPLES.parent / "tests" / "data" / "models" / "urdf" / "double_pendulum.urdf"
    model = momenta.load_model(urdf)
    equilibrium = momenta.find_equilibrium(model)
    squared = sorted(m.squared_frequency for m in momenta.undamped_modes(equilibrium.linear))
    assert squared == pytest.approx([9.81 * (2 - 2 ** 0.5), 9.81 * (2 + 2 ** 0.5)], rel=1e-11)
    assert momenta.simulate(model, duration=0.1).time[-1] == pytest.approx(0.1)


def test_a_model_starts_from_a_given_state_as_simulate_state_does(tmp_path):
    # momenta.with_initial_state is `momenta simulate --state`: the first row is the state.
    pendulum = momenta.load_model(EXAMPLES / "pendulum.yaml")
    started = momenta.with_initial_state(pendulum, [0.5], [0.25])
    result = momenta.simulate(started, duration=0.01)
    first = dict(zip(result.columns, result.data[0]))
    assert first["pivot.angle"] == 0.5 and first["pivot.angle_rate"] == 0.25
    assert momenta.simulate(pendulum, duration=0.01).data[0][1] != 0.5  # the original unchanged
    with pytest.raises(ValueError, match="q"):
        momenta.with_initial_state(pendulum, [0.5, 1.0], [0.0])
    with pytest.raises(momenta.InvalidArgument, match="initial coordinate pivot.angle is nan"):
        momenta.with_initial_state(pendulum, [float("nan")], [0.0])

"""momenta.simulate against `momenta simulate` on the same model: the same columns and the same
numbers, bit for bit (both are the one C++ run loop), the audit, and the options' merge."""

import subprocess

import numpy as np
import pytest

import momenta

from conftest import EXAMPLES, STIFF_SPRING, cli_csv, cli_path


@pytest.mark.parametrize("name, args", [
    ("double_pendulum", dict(duration=2.0)),
    ("heavy_top", dict(duration=1.0, integrator="splitting", dt=1e-3)),
    ("quarter_car", dict(duration=1.0, rtol=1e-9, atol=1e-12)),
    ("flexible_satellite", dict(duration=3.0, every=10, reactions=True)),
])
def test_the_table_is_the_command_lines_bit_for_bit(name, args):
    path = EXAMPLES / f"{name}.yaml"
    run = momenta.simulate(momenta.load_model(path), **args)
    flags = []
    for key, value in args.items():
        option = {"dt": "--dt"}.get(key, "--" + key)
        flags += [option] if value is True else [option, value]
    header, table = cli_csv("simulate", path, "--quiet", *flags)
    assert run.columns == header
    assert run.data.shape == table.shape
    np.testing.assert_array_equal(run.data, table)


def test_columns_are_views_and_named():
    run = momenta.simulate(momenta.load_model(EXAMPLES / "double_pendulum.yaml"), duration=0.5)
    assert run.data.dtype == np.float64 and run.data.flags.c_contiguous
    # The file's step is 0.5 ms.
    assert run.time[0] == 0.0 and run.time[-1] == 0.5 and len(run) == 1001
    assert "energy_total" in run and "nothing" not in run
    np.testing.assert_array_equal(run["upper.angle"], run.data[:, run.columns.index("upper.angle")])
    with pytest.raises(KeyError, match="no column 'energy'"):
        run["energy"]


def test_a_coordinate_has_one_name_and_its_unit():
    # The run's columns are the model's coordinate names (as `info` and the report name them),
    # each with its SI unit.
    model = momenta.load_model(EXAMPLES / "quarter_car.yaml")
    run = momenta.simulate(model, duration=0.1)
    assert run.columns[1:1 + model.nq] == model.q_names
    assert run.columns[1 + model.nq:1 + model.nq + model.nv] == model.v_names
    units = run.units
    assert list(units) == run.columns
    assert units["time"] == "s" and units["energy_total"] == "J" and units["H_x"] == "kg·m²/s"
    assert units["body_travel.position"] == "m" and units["body_travel.position_rate"] == "m/s"
    # The file's outputs: a joint position, a road signal prescribing a length, spring tensions.
    assert units["body_y"] == "m" and units["r"] == "m" and units["tyre_force"] == "N"
    pendulum = momenta.simulate(momenta.load_model(EXAMPLES / "double_pendulum.yaml"), duration=0.1)
    assert pendulum.units["upper.angle"] == "rad" and pendulum.units["theta1"] == "rad"
    assert pendulum.units["tip.x"] == "m" and pendulum.units["audit.energy_drift"] == "1"


def test_degrees_of_freedom_count_after_constraints():
    four_bar = momenta.load_model(EXAMPLES / "constraints" / "four_bar.yaml")
    assert four_bar.nv == 3 and four_bar.degrees_of_freedom == 0  # driven by its crank
    assert momenta.load_model(EXAMPLES / "double_pendulum.yaml").degrees_of_freedom == 2


def test_energy_audit_of_the_double_pendulum_is_at_round_off():
    run = momenta.simulate(momenta.load_model(EXAMPLES / "double_pendulum.yaml"), duration=2.0)
    audit = {entry["name"]: entry for entry in run.audit}
    # RK4 at the file's 0.5 ms on a motion with periods near 2 s: the energy error is O(h⁴),
    # 4e-13 of the scale here.
    assert abs(audit["energy"]["max_drift"]) < 1e-11
    assert audit["energy"]["records"] == 4001
    assert run.summary["integrator"] == "rk4" and run.summary["steps"] == 4000
    assert "energy" in run.summary_text


def test_to_pandas_is_indexed_by_time():
    pandas = pytest.importorskip("pandas")
    run = momenta.simulate(momenta.load_model(EXAMPLES / "pendulum.yaml"), duration=0.1)
    frame = run.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert frame.index.name == "time" and list(frame.columns) == run.columns[1:]
    np.testing.assert_array_equal(frame.index.to_numpy(), run.time)


def test_options_merge_as_on_the_command_line():
    model = momenta.load_model(EXAMPLES / "double_pendulum.yaml")
    assert momenta.simulate(model, duration=0.1, rtol=1e-8).summary["integrator"] == "dopri5"
    long = momenta.simulate(model, duration=20.0)
    assert len(long) == 10001 and "every 4 of 40000 steps" in long.thinning_note
    with pytest.raises(momenta.InvalidArgument, match="fixed step"):
        momenta.simulate(model, duration=0.1, integrator="rk4", rtol=1e-8)
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'dopri5'"):
        momenta.simulate(model, integrator="dopri")
    with pytest.raises(momenta.InvalidArgument, match="duration"):
        momenta.simulate(model, duration=-1.0)


def test_a_run_that_blows_up_names_the_time(tmp_path):
    path = STIFF_SPRING
    with pytest.raises(momenta.NumericalError, match="t = "):
        momenta.simulate(momenta.load_model(path), duration=2.0, dt=0.01)
    # The rows up to the failure come with the error, as the command line keeps them in its CSV:
    # all finite, ending before the time the message names.
    with pytest.raises(momenta.NumericalError) as failure:
        momenta.simulate(momenta.load_model(path), duration=2.0, dt=0.01)
    partial = failure.value.result
    assert isinstance(partial, momenta.SimulationResult)
    assert len(partial) >= 2 and partial.columns[0] == "time"
    assert np.isfinite(partial.data).all()
    np.testing.assert_allclose(np.diff(partial.time), 0.01, rtol=1e-12)
    failed_at = float(str(failure.value).split("t = ")[1].split()[0])
    # What to try, in Python's words: a smaller dt=, or integrator='dopri5' (the command line
    # says --dt and --integrator dopri5 for the same run).
    message = str(failure.value)
    assert "a smaller dt=" in message and "integrator='dopri5'" in message, message
    assert "--dt" not in message and "--integrator" not in message, message
    cli = subprocess.run([cli_path(), "simulate", str(path), "--duration", "2", "--dt", "0.01", "-q",
                          "-o", str(tmp_path / "blown.csv")], capture_output=True, text=True)
    assert cli.returncode == 1
    assert "a smaller --dt, or --integrator dopri5" in cli.stderr, cli.stderr
    assert "dt=" not in cli.stderr, cli.stderr
    assert partial.time[-1] < failed_at
    assert partial.summary["t_end"] == partial.time[-1]


def test_stiff_models_run_with_the_implicit_integrators():
    # The flyball governor (IFToMM A05): bdf at the file's settings in a few thousand steps, the
    # same table as the command line's; dopri5 says it was held by stability.
    path = EXAMPLES / "flyball_governor.yaml"
    model = momenta.load_model(path)
    run = momenta.simulate(model, duration=2.0)
    assert run.summary["integrator"] == "bdf" and run.summary["steps"] < 2000
    assert run.summary["stiffness"] is None
    header, table = cli_csv("simulate", path, "--quiet", "--duration", 2.0)
    np.testing.assert_array_equal(run.data, table)
    # s(2 s) of the independent Radau solution (scripts/reference/flyball_governor.py).
    assert abs(run["s.position"][-1] - 0.505909294297) < 5e-6
    fixed = momenta.simulate(model, duration=0.5, integrator="sdirk3", dt=0.005)
    assert fixed.summary["integrator"] == "sdirk3" and fixed.summary["steps"] == 100
    explicit = momenta.simulate(model, duration=0.2, integrator="dopri5", rtol=1e-3)
    assert "held by stability" in explicit.summary["stiffness"]
    # Named as Python writes it (the command line's summary says --integrator bdf).
    assert "integrator='bdf'" in explicit.summary["stiffness"]
    assert "--" not in explicit.summary["stiffness"]


def test_events_are_rows_and_entries_of_the_summary():
    # The rod's wire goes slack (the file's stop event) at t_s = (15 − ω_s) I_z / 20, ω_s² =
    # 3 g / (2 L cos β) (examples/constraints/rod_on_shaft_spinning_down.yaml): the same table as
    # the command line's, ending on the event's row.
    path = EXAMPLES / "constraints" / "rod_on_shaft_spinning_down.yaml"
    run = momenta.simulate(momenta.load_model(path))
    omega_s = np.sqrt(3 * 9.81 / (2 * 2.0 * np.cos(np.pi / 6)))
    t_s = (15.0 - omega_s) * (0.5 * 5.0 * 0.03**2 + 20.0 * 4.0 * 0.25 / 3) / 20.0
    [slack] = run.summary["events"]
    assert slack["name"] == "slack" and slack["condition"] == "tension < 0"
    assert slack["action"] == "stop"
    assert abs(slack["time"] - t_s) < 1e-10 * t_s
    assert run["time"][-1] == slack["time"] == run.summary["t_end"]
    assert abs(run["shaft_speed"][-1] - omega_s) < 1e-10 * omega_s
    header, table = cli_csv("simulate", path, "--quiet")
    np.testing.assert_array_equal(run.data, table)
    # From the caller: a record event each time the pendulum passes the bottom, a stop when it
    # first swings back up.
    pendulum = momenta.load_model(EXAMPLES / "pendulum.yaml")
    swings = momenta.simulate(pendulum, duration=2.0, dt=0.01, events=["pivot.angle = 0"],
                              stop_when=["pivot.angle_rate > 0"])
    assert [e["name"] for e in swings.summary["events"]] == ["pivot.angle = 0",
                                                              "pivot.angle_rate > 0"]
    assert [e["action"] for e in swings.summary["events"]] == ["record", "stop"]
    with pytest.raises(momenta.InvalidArgument, match="no comparison"):
        momenta.simulate(pendulum, events=["pivot.angle"])
    with pytest.raises(momenta.InvalidArgument, match="did you mean 'pivot.angle'"):
        momenta.simulate(pendulum, stop_when=["pivot.angel < 0"])


def test_a_singular_start_is_said_in_the_summary():
    # The N-four-bar with every link horizontal: each loop's row along the links depends on the
    # others there (docs/constraints.md); a regular start says nothing.
    path = STIFF_SPRING.parent / "n_four_bar_horizontal.yaml"
    run = momenta.simulate(momenta.load_model(path), duration=0.01)
    assert run.summary["singular_start"].startswith(
        "the initial configuration is singular: rows loop0.x, loop1.x, loop2.x, loop3.x")
    plain = momenta.simulate(momenta.load_model(EXAMPLES / "pendulum.yaml"), duration=0.01)
    assert plain.summary["singular_start"] is None


def test_a_file_name_where_a_model_belongs_says_what_to_pass():
    # pybind11 would list C++ signatures ("incompatible function arguments"); the message says
    # how to make the Model, and the stubs keep `model: Model`.
    with pytest.raises(TypeError, match=r"simulate\(\) takes a momenta.Model as its first argument, "
                       r"got str: load the file first, momenta.simulate\(momenta.load_model\('x.yaml'\)\)"):
        momenta.simulate("x.yaml")
    with pytest.raises(TypeError, match=r"linearize\(\) takes a momenta.Model .* got int \(momenta.load_model"):
        momenta.linearize(3)
    assert momenta.simulate.__doc__.startswith("simulate(model: momenta._core.Model")



def test_joint_stops_are_entries_of_the_summary():
    # A 1 kg ball dropped from 1 m on a slide whose lower stop is the floor, e = 0.5, built in
    # Python: the same run as the command line's examples/bouncing_ball.yaml form, its bounces at
    # t₁ (1 + 2e + … ) and rest at t₁ (1 + e)/(1 − e), t₁ = √(2h/g) (docs/contacts.md).
    b = momenta.ModelBuilder("ball")
    b.set_gravity([0, 0, -9.81])
    b.add_body("ball", momenta.inertia.point_mass(1.0))
    b.add_joint("drop", "prismatic", parent="world", child="ball", axis=[0, 0, 1], q0=1.0,
                limits={"lower": 0.0, "restitution": 0.5})
    run = momenta.simulate(b.build(), duration=4.0, dt=1e-3)
    stops = run.summary["stops"]
    t1 = np.sqrt(2 / 9.81)
    first = stops[0]
    assert first["kind"] == "impact" and first["joint"] == "drop" and first["stop"] == "lower"
    assert abs(first["time"] - t1) < 1e-12
    assert abs(first["rate_after"] + 0.5 * first["rate_before"]) < 1e-14
    assert abs(first["impulse"] - (first["rate_after"] - first["rate_before"])) < 1e-14
    assert stops[-1]["kind"] == "rest"
    assert abs(stops[-1]["rest_time"] - t1 * 1.5 / 0.5) < 1e-10
    assert run["drop.position"].min() >= 0.0 and run["drop.position"][-1] == 0.0
    with pytest.raises(ValueError, match="unknown key 'lowr'"):
        b.add_joint("other", "prismatic", parent="world", child="ball", limits={"lowr": 0})
    with pytest.raises(ValueError, match="outside \\[0, 1\\]"):
        bad = momenta.ModelBuilder("bad")
        bad.add_body("b", momenta.inertia.point_mass(1.0))
        bad.add_joint("j", "prismatic", parent="world", child="b", limits={"lower": 0,
                                                                          "restitution": 2})
        bad.build()


def test_contacts_are_entries_of_the_summary():
    # A free 1 kg ball of radius 0.1 m dropped from 1 m (its lowest point) on the ground plane
    # through a contact with e = 0.5, built in Python: its first impact at t₁ = √(2h/g), the
    # rebound −e times the speed it arrives with √(2gh), the impulse m Δv, and rest at the Zeno
    # limit t₁ (1 + e)/(1 − e) within the 1e-8 s a centre's round-off allows (docs/contacts.md).
    b = momenta.ModelBuilder("ball")
    b.set_gravity([0, 0, -9.81])
    b.add_body("ball", momenta.inertia.solid_sphere(0.1, mass=1.0))
    b.add_joint("free", "free", parent="world", child="ball", q0=[0, 0, 1.1, 1, 0, 0, 0])
    b.add_contact("floor", body="ball", radius=0.1, restitution=0.5)
    run = momenta.simulate(b.build(), duration=4.0, dt=1e-3)
    stops = run.summary["stops"]
    t1 = np.sqrt(2 / 9.81)
    first = stops[0]
    assert first["kind"] == "impact" and first["contact"] == "floor" and first["joint"] == ""
    assert abs(first["time"] - t1) < 1e-12
    assert abs(first["rate_before"] + np.sqrt(2 * 9.81)) < 1e-11
    assert abs(first["rate_after"] + 0.5 * first["rate_before"]) < 1e-14
    assert abs(first["impulse"] - (first["rate_after"] - first["rate_before"])) < 1e-14
    assert stops[-1]["kind"] == "rest"
    assert abs(stops[-1]["rest_time"] - t1 * 1.5 / 0.5) < 1e-8
    assert run["free.z"].min() >= 0.1 - 1e-12 and abs(run["free.z"][-1] - 0.1) < 1e-15
    with pytest.raises(ValueError, match="restitution must be in \\[0, 1\\]"):
        bad = momenta.ModelBuilder("bad")
        bad.add_body("b", momenta.inertia.solid_sphere(0.1, mass=1.0))
        bad.add_joint("j", "free", parent="world", child="b")
        bad.add_contact("floor", body="b", restitution=2)
        bad.build()


def test_a_skidding_ball_built_in_python_rolls_when_friction_says():
    # A 1 kg ball of radius 0.1 m set down at 2 m/s without spin, μk = 0.2 (μs the same when
    # kinetic_friction is left out, 0.15 here): it slides, then sticks (rolls) at
    # t = 2 v₀ / (7 μk g) with 5 v₀ / 7, as the command line's skidding ball (docs/contacts.md).
    b = momenta.ModelBuilder("ball")
    b.set_gravity([0, 0, -9.81])
    b.add_body("ball", momenta.inertia.solid_sphere(0.1, mass=1.0))
    b.add_joint("free", "free", parent="world", child="ball", q0=[0, 0, 0.1, 1, 0, 0, 0],
                v0=[0, 0, 0, 2, 0, 0])
    b.add_contact("floor", body="ball", radius=0.1, friction=0.2, kinetic_friction=0.15)
    run = momenta.simulate(b.build(), duration=1.0, dt=1e-3)
    stops = run.summary["stops"]
    assert [(s["kind"], s["friction"]) for s in stops] == [("rest", "sliding"), ("stick", "sticking")]
    t_roll = 2 * 2 / (7 * 0.15 * 9.81)
    assert abs(stops[1]["time"] - t_roll) < 1e-12 * t_roll
    assert abs(stops[1]["friction_limit"] - 0.2 * 9.81) < 1e-12
    assert abs(run["free.vx"][-1] - 5 * 2 / 7) < 1e-12
    with pytest.raises(ValueError, match="kinetic friction coefficient 0.3 must be in \\[0"):
        bad = momenta.ModelBuilder("bad")
        bad.add_body("b", momenta.inertia.solid_sphere(0.1, mass=1.0))
        bad.add_joint("j", "free", parent="world", child="b")
        bad.add_contact("floor", body="b", friction=0.2, kinetic_friction=0.3)
        bad.build()


def test_a_wheel_built_in_python_touches_with_its_rim():
    # A 1 kg thin disk of radius 0.2 m standing upright (its axis, body z, along world y: the body
    # turned −90° about x), set down at 3 m/s without spin, μk = 0.25: it slides, then rolls at
    # t = v₀ / (3 μk g) with 2 v₀ / 3 (I = m r² / 2; docs/contacts.md, a disk's rim).
    b = momenta.ModelBuilder("wheel")
    b.set_gravity([0, 0, -9.81])
    b.add_body("wheel", momenta.inertia.thin_disk(0.2, mass=1.0))
    h = 0.5 ** 0.5
    b.add_joint("free", "free", parent="world", child="wheel", q0=[0, 0, 0.2, h, -h, 0, 0],
                v0=[0, 0, 0, 3, 0, 0])
    b.add_contact("floor", body="wheel", shape="disk", axis=[0, 0, 1], radius=0.2, friction=0.25)
    run = momenta.simulate(b.build(), duration=1.0, dt=1e-3)
    stops = run.summary["stops"]
    assert [(s["kind"], s["friction"]) for s in stops] == [("rest", "sliding"), ("stick", "sticking")]
    t_roll = 3 / (3 * 0.25 * 9.81)
    assert abs(stops[1]["time"] - t_roll) < 1e-12 * t_roll
    assert abs(run["free.vx"][-1] - 2) < 1e-12
    with pytest.raises(ValueError, match="unknown shape 'disc'"):
        b.add_contact("rim", body="wheel", shape="disc", radius=0.2)
    with pytest.raises(ValueError, match="a disk's radius must be positive"):
        bad = momenta.ModelBuilder("bad")
        bad.add_body("b", momenta.inertia.thin_disk(0.2, mass=1.0))
        bad.add_joint("j", "free", parent="world", child="b")
        bad.add_contact("floor", body="b", shape="disk")
        bad.build()


def test_a_coin_built_in_python_falls_flat_on_a_ball():
    # A 1 kg coin of radius 0.1 m falls flat from 0.2 m onto a fixed ball (r = 0.05 m), its centre
    # ρ = 0.05 m off the ball's top, e = 0.5: struck on its face, P = (1 + e) m v / (1 + 4 ρ² / R²)
    # and it turns about its diameter at ρ P / (m R² / 4) (docs/contacts.md, a disk against a
    # sphere).
    b = momenta.ModelBuilder("coin on a ball")
    b.set_gravity([0, 0, -9.81])
    b.add_body("coin", momenta.inertia.thin_disk(0.1, mass=1.0))
    b.add_body("post", momenta.inertia.solid_sphere(0.05, mass=1.0))
    b.add_joint("free", "free", parent="world", child="coin", q0=[0.05, 0, 0.25, 1, 0, 0, 0])
    b.add_joint("mount", "fixed", parent="world", child="post")
    b.add_contact("hit", body="coin", shape="disk", axis=[0, 0, 1], radius=0.1,
                  other_body="post", other_radius=0.05, restitution=0.5)
    t_hit = (2 * 0.2 / 9.81) ** 0.5
    run = momenta.simulate(b.build(), duration=t_hit + 0.005, dt=1e-3, integrator="dopri5",
                           rtol=1e-12, atol=1e-14)
    stops = run.summary["stops"]
    assert [s["kind"] for s in stops] == ["impact"]
    v = (2 * 9.81 * 0.2) ** 0.5
    P = 1.5 * v / 2
    assert abs(stops[0]["time"] - t_hit) < 1e-12 * t_hit
    assert abs(stops[0]["impulse"] - P) < 1e-12 * P
    assert abs(run["free.wy"][-1] - 0.05 * P / 0.0025) < 1e-12 * v / 0.1

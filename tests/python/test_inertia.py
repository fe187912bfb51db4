"""momenta.inertia from Python: primitives against their closed forms, part files and meshes
against `momenta inertia --json` (the same C++ path, so bit-identical), and bad arguments."""

import numpy as np
import pytest

import momenta
from momenta import inertia

from conftest import EXAMPLES, cli_json

ROUND_OFF = 4 * np.finfo(float).eps


def test_solid_cylinder_matches_its_closed_form():
    m, r, L = 2.0, 0.1, 0.5
    c = inertia.solid_cylinder(r, L, mass=m)
    transverse = m * (3 * r**2 + L**2) / 12
    expected = np.diag([transverse, transverse, m * r**2 / 2])
    np.testing.assert_allclose(c.inertia_about_com, expected, rtol=ROUND_OFF, atol=0)
    assert c.mass == m
    assert c.volume == pytest.approx(np.pi * r**2 * L, rel=ROUND_OFF)
    np.testing.assert_array_equal(c.center_of_mass, np.zeros(3))


def test_density_gives_mass_from_the_volume():
    rho, a = 7850.0, np.array([0.1, 0.2, 0.3])
    b = inertia.box(a, density=rho)
    assert b.mass == pytest.approx(rho * a.prod(), rel=ROUND_OFF)
    expected = b.mass / 12 * np.diag([a[1]**2 + a[2]**2, a[0]**2 + a[2]**2, a[0]**2 + a[1]**2])
    np.testing.assert_allclose(b.inertia_about_com, expected, rtol=ROUND_OFF, atol=0)


def test_a_hole_removes_what_it_adds():
    disk = inertia.solid_cylinder(0.1, 0.02, density=7850)
    hole = inertia.solid_cylinder(0.01, 0.02, density=7850).transformed(np.eye(3), [0.05, 0, 0])
    part = disk - hole
    back = part + hole
    assert back.mass == pytest.approx(disk.mass, rel=ROUND_OFF)
    np.testing.assert_allclose(back.inertia_about_com, disk.inertia_about_com, rtol=0,
                               atol=ROUND_OFF * np.abs(disk.inertia_about_com).max())
    # The centre of mass moves away from the hole: m_part x = −m_hole 0.05.
    assert part.center_of_mass[0] == pytest.approx(-hole.mass * 0.05 / part.mass, rel=1e-14)


def test_parallel_axis_about_a_point():
    rod = inertia.slender_rod(1.0, mass=3.0)  # along z
    about_end = rod.inertia_about([0, 0, 0.5])
    np.testing.assert_allclose(about_end, np.diag([1.0, 1.0, 0.0]), rtol=ROUND_OFF, atol=1e-16)
    # from_inertia_about goes back to the centre of mass.
    back = inertia.MassProperties.from_inertia_about(3.0, [0, 0, 0], about_end, [0, 0, 0.5])
    np.testing.assert_allclose(back.inertia_about_com, rod.inertia_about_com, atol=1e-15)


def test_principal_axes_of_a_turned_box():
    b = inertia.box([0.1, 0.2, 0.4], mass=1.0)
    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    moments, axes = b.re_expressed(R).principal_axes()
    np.testing.assert_allclose(moments, np.sort(np.diag(b.inertia_about_com)), rtol=1e-14)
    assert axes.shape == (3, 3) and np.linalg.det(axes) == pytest.approx(1.0, abs=1e-14)
    # Each axis is an eigenvector: I a = λ a.
    I = b.re_expressed(R).inertia_about_com
    for k in range(3):
        np.testing.assert_allclose(I @ axes[:, k], moments[k] * axes[:, k], atol=1e-16)


def test_part_file_is_what_the_command_line_prints():
    path = EXAMPLES / "parts" / "flanged_shaft.yaml"
    part = inertia.part(path)
    expected = cli_json("inertia", path)
    assert part.name == expected["name"]
    assert part.total.mass == expected["mass"]
    np.testing.assert_array_equal(part.total.center_of_mass, expected["com"])
    np.testing.assert_array_equal(part.total.inertia_about_com, expected["inertia_com"])
    assert [p.name for p in part.parts] == [p["name"] for p in expected["parts"]]
    assert [p.hole for p in part.parts] == [p["hole"] for p in expected["parts"]]
    assert [p.line for p in part.parts] == [p["line"] for p in expected["parts"]]


def test_meshes_are_what_the_command_line_prints():
    meshes = sorted((EXAMPLES / "parts" / "meshes").glob("*.stl")) + sorted(
        (EXAMPLES / "parts" / "meshes").glob("*.obj"))
    assert meshes, "the examples hold meshes"
    for path in meshes:
        props = inertia.mesh(path, density=1000.0)
        expected = cli_json("inertia", path, "--density", 1000)
        assert props.mass == expected["mass"], path
        np.testing.assert_array_equal(props.center_of_mass, expected["com"])
        np.testing.assert_array_equal(props.inertia_about_com, expected["inertia_com"])


def test_exactly_one_amount():
    with pytest.raises(ValueError, match="exactly one of mass= .* or density="):
        inertia.solid_sphere(0.1)
    with pytest.raises(ValueError, match="exactly one"):
        inertia.solid_sphere(0.1, mass=1, density=2)


def test_unphysical_sizes_raise_invalid_argument_with_the_value():
    with pytest.raises(momenta.InvalidArgument, match="radius"):
        inertia.solid_sphere(-0.1, mass=1.0)
    with pytest.raises(ValueError):  # InvalidArgument is a ValueError too
        inertia.solid_cylinder(0.1, 0.0, mass=1.0)


def test_check_physical_names_the_body():
    bad = inertia.MassProperties(1.0, [0, 0, 0], np.diag([1.0, 1.0, 3.0]))
    with pytest.raises(momenta.InvalidInertia, match="blade"):
        bad.check_physical("blade")


def test_wrong_shapes_name_the_argument():
    with pytest.raises(ValueError, match="size: expected a vector of 3 numbers"):
        inertia.box([1.0, 2.0], mass=1.0)
    with pytest.raises(ValueError, match=r"inertia_about_com: expected a 3 × 3 matrix, got shape \(2, 2\)"):
        inertia.MassProperties(1.0, [0, 0, 0], np.eye(2))
    with pytest.raises(ValueError, match="center_of_mass: expected an array of real numbers"):
        inertia.MassProperties(1.0, ["a", "b", "c"], np.eye(3))
    with pytest.raises(ValueError, match="real numbers"):
        inertia.MassProperties(1.0, np.zeros(3, dtype=complex), np.eye(3))


def test_a_missing_mesh_is_a_file_error():
    with pytest.raises(momenta.FileError, match="nothing.stl"):
        inertia.mesh("nothing.stl", density=1.0)
    with pytest.raises(OSError):
        inertia.mesh("nothing.stl", density=1.0)


def test_balancing_is_what_momenta_balance_prints():
    """The unbalance, reactions, correction and grade equal `momenta balance --json` bit for bit."""
    path = EXAMPLES / "parts" / "two_disk_shaft.yaml"
    expected = cli_json("balance", path, "--bearings", 0, 1, "--speed", 3000,
                        "--planes", 0.25, 0.75, "--radius", 0.15, "--grade", 2.5)
    u = inertia.unbalance(inertia.part(path).total)
    assert u.mass == expected["mass"]
    shown = expected["unbalance"]
    assert list(u.static_unbalance) == [shown["static_unbalance"]["x"], shown["static_unbalance"]["y"]]
    assert list(u.couple_unbalance) == [shown["couple_unbalance"]["x"], shown["couple_unbalance"]["y"]]
    omega = expected["reactions"][0]["omega"]
    r = inertia.bearing_reactions(u, 0.0, 1.0, omega)
    assert list(r.A) == [expected["reactions"][0]["A"]["x"], expected["reactions"][0]["A"]["y"]]
    assert list(r.B) == [expected["reactions"][0]["B"]["x"], expected["reactions"][0]["B"]["y"]]
    corrections = inertia.two_plane_correction(u, 0.25, 0.75)
    assert [c.mass_at(0.15) for c in corrections] == [m["mass"] for m in expected["correction"]["masses"]]
    after = inertia.with_corrections(u, corrections)
    np.testing.assert_allclose(after.static_unbalance, 0.0, atol=1e-18)
    np.testing.assert_allclose(after.products, 0.0, atol=1e-18)
    grade = inertia.check_grade(u, 2.5, omega, 0.0, 1.0)
    assert grade.permissible == expected["grade"]["permissible"]
    assert grade.passed is False and inertia.check_grade(after, 2.5, omega, 0.0, 1.0).passed
    with pytest.raises(momenta.InvalidArgument, match="coincide"):
        inertia.two_plane_correction(u, 0.5, 0.5)
    with pytest.raises(ValueError, match="axis"):
        inertia.unbalance(inertia.part(path).total, axis=[0, 0])

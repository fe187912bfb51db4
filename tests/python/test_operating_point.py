"""The operating point a linear analysis is taken about is one rule (analysis::
linear_analysis_about) that the command line's --about, the report's linear panel and
momenta.linear_analysis share: on the heavy top (in steady precession), the sleeping top, the
double pendulum (released off its equilibrium) and the rolling coin, each front end's 'auto'
chooses the same point, says the same sentence and shows the same poles."""

import json
import re
import subprocess

import pytest

import momenta

from conftest import EXAMPLES, cli_json, cli_path


def page_linear(path):
    html = path.read_text()
    match = re.search(r'<script type="application/json" id="momenta-data">(.*?)</script>', html, re.S)
    assert match, "no momenta-data in the page"
    return json.loads(match.group(1))["linear"]


def upper_poles(poles):
    """The poles with a positive imaginary part, as complex numbers sorted by it; a pole within
    1e-6 of the largest |λ| of zero (the report's and `modes`' round-off rule: a Jordan block's
    zero split by the square root of the round-off) left out."""
    values = [p if isinstance(p, complex) else complex(*p) for p in poles]
    largest = max((abs(z) for z in values), default=0.0)
    return sorted((z for z in values if z.imag > 0 and abs(z) > 1e-6 * largest), key=lambda z: z.imag)


def report_linear(tmp_path, name, **settings):
    model = momenta.load_model(EXAMPLES / name)
    result = momenta.simulate(model, duration=0.002)
    page = tmp_path / (name.replace("/", "_") + ".html")
    result.report(page, **settings)
    return page_linear(page)


@pytest.mark.parametrize("name, kind", [
    ("heavy_top.yaml", "steady_precession"),
    ("sleeping_top.yaml", "spinning_body"),
    ("double_pendulum.yaml", "joint_coordinates"),
    ("constraints/rolling_coin.yaml", "rolling_steady"),
])
def test_cli_report_and_python_choose_the_same_point(tmp_path, name, kind):
    analysis = momenta.linear_analysis(momenta.load_model(EXAMPLES / name))
    assert analysis.kind == kind
    python_poles = upper_poles(momenta.modes(analysis.linear.system).eigenvalues)
    linear = report_linear(tmp_path, name)
    assert linear["available"]
    assert linear["about"] == analysis.about
    assert upper_poles(linear["poles"]) == pytest.approx(python_poles, rel=1e-12, abs=1e-12)
    cli = cli_json("modes", EXAMPLES / name, "--about", "auto")
    if kind == "steady_precession":
        # Its nutation about the slow root: ±i ω_n.
        assert [z.imag for z in python_poles] == pytest.approx([cli["slow_nutation"]], rel=1e-12)
    elif kind == "spinning_body":
        assert python_poles == pytest.approx(upper_poles(cli["eigenvalues_body"]), rel=1e-12)
    elif kind == "rolling_steady":
        assert upper_poles(cli["eigenvalues"] + cli["circle_shift"]) == pytest.approx(python_poles, rel=1e-12)
    else:
        # The double pendulum's hanging modes, ω² = (2 ∓ √2) g/L; the CLI adds the iterations.
        assert cli["about"].startswith(analysis.about)
        assert upper_poles(cli["modes"][k]["eigenvalue"] for k in range(len(cli["modes"]))) == \
            pytest.approx(python_poles, rel=1e-12)
        assert [z.imag ** 2 for z in python_poles] == pytest.approx(
            [(2 - 2 ** 0.5) * 9.81, (2 + 2 ** 0.5) * 9.81], rel=1e-6)


def test_the_named_choices_agree_too(tmp_path):
    # 'steady' on the heavy top: the same precession in all three (the report refused it before).
    analysis = momenta.linear_analysis(momenta.load_model(EXAMPLES / "heavy_top.yaml"), "steady")
    linear = report_linear(tmp_path, "heavy_top.yaml", about="steady")
    assert linear["about"] == analysis.about
    assert "steady precession of the symmetric top 'top'" in analysis.about
    assert analysis.precession.slow_nutation == pytest.approx(
        cli_json("modes", EXAMPLES / "heavy_top.yaml", "--about", "steady")["slow_nutation"], rel=1e-15)
    # 'initial' keeps the moving top where it is.
    initial = momenta.linear_analysis(momenta.load_model(EXAMPLES / "heavy_top.yaml"), "initial")
    assert initial.kind == "joint_coordinates" and initial.largest_speed > 1


def test_python_speaks_its_own_keywords():
    model = momenta.load_model(EXAMPLES / "pendulum.yaml")
    with pytest.raises(momenta.InvalidArgument, match=r"about='halfway'"):
        momenta.linear_analysis(model, "halfway")
    with pytest.raises(momenta.InvalidArgument, match=r"q= and v= are for about='given'"):
        momenta.linear_analysis(model, "initial", q=[0.1])
    given = momenta.linear_analysis(model, q=[0.1])
    assert given.kind == "joint_coordinates" and given.about == "the given state"
    assert given.linear.q[0] == 0.1


def test_a_response_about_a_spinning_body_is_refused_with_the_reason():
    # A spinning body's steady motion has no inputs or outputs to respond with.
    result = subprocess.run([cli_path(), "response", str(EXAMPLES / "sleeping_top.yaml"), "--about", "steady",
                             "--input", "x", "--output", "y", "--step"], capture_output=True, text=True)
    assert result.returncode != 0
    assert "Euler–Poisson variables, which have no inputs or outputs" in result.stderr

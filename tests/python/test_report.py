"""SimulationResult.report: the page `momenta simulate --report` writes, from Python. The page's
data (every number the page shows) equals the command line's for the same run but for the wall
time; an existing file is kept without force=True; a run stopped by a non-finite state still
gets its page, with the reason."""

import json
import re

import pytest

import momenta

from conftest import EXAMPLES, STIFF_SPRING, run_cli


def page_data(path):
    """The JSON the report embeds (its <script id="momenta-data">), parsed."""
    html = path.read_text()
    match = re.search(r'<script type="application/json" id="momenta-data">(.*?)</script>', html, re.S)
    assert match, "no momenta-data in the page"
    return json.loads(match.group(1))


def without_wall_time(data):
    data["summary"] = {k: v for k, v in data["summary"].items() if "wall" not in k}
    return data


@pytest.mark.parametrize("name, options", [
    ("double_pendulum.yaml", {"duration": 2.0}),
    ("quarter_car.yaml", {"duration": 0.5, "reactions": True}),
])
def test_the_page_is_the_command_lines(tmp_path, name, options):
    model = EXAMPLES / name
    result = momenta.simulate(momenta.load_model(model), **options)
    written = result.report(tmp_path / "python.html")
    assert written == tmp_path / "python.html"
    cli = ["simulate", model, "--duration", str(options["duration"]), "--report", tmp_path / "cli.html", "-q"]
    if options.get("reactions"):
        cli.append("--reactions")
    run_cli(*cli)
    python_page = without_wall_time(page_data(tmp_path / "python.html"))
    cli_page = without_wall_time(page_data(tmp_path / "cli.html"))
    assert python_page.keys() == cli_page.keys()
    for key in cli_page:
        assert python_page[key] == cli_page[key], key


def test_the_linear_panel_moves_off_a_state_in_motion(tmp_path):
    # The double pendulum starts with its upper rod horizontal: not an equilibrium. By default the
    # panel linearizes about the equilibrium found from it (hanging straight down) and says why;
    # its poles are the small oscillations' ±jω with ω² = (2 ∓ √2) g/L (m = 1 kg, L = 1 m each).
    result = momenta.simulate(momenta.load_model(EXAMPLES / "double_pendulum.yaml"), duration=0.2)
    result.report(tmp_path / "auto.html")
    linear = page_data(tmp_path / "auto.html")["linear"]
    assert linear["about"].startswith("the static equilibrium found from the initial state (the "
                                      "initial state is not one: its largest acceleration is")
    omegas = sorted(abs(im) for re_, im in linear["poles"])
    expected = sorted([(2 - 2 ** 0.5) * 9.81, (2 + 2 ** 0.5) * 9.81] * 2)
    # Central differences of an exact model: the poles to about 1e-7 relative.
    assert omegas == pytest.approx([w ** 0.5 for w in expected], rel=1e-6)
    assert all(abs(re_) < 1e-6 for re_, im in linear["poles"])
    # Asked for the initial state, it keeps it and says the poles are of that instant only.
    result.report(tmp_path / "initial.html", about="initial")
    linear = page_data(tmp_path / "initial.html")["linear"]
    assert linear["about"].startswith("the initial state, which is not an equilibrium")


def test_linear_settings_reach_the_page(tmp_path):
    result = momenta.simulate(momenta.load_model(EXAMPLES / "quarter_car.yaml"), duration=0.2)
    result.report(tmp_path / "r.html", about="equilibrium", outputs=["body_y"])
    linear = page_data(tmp_path / "r.html")["linear"]
    assert linear["available"] and linear["about"] == "the static equilibrium"
    assert linear["outputs"] == ["body_y"]
    # A channel the model does not have: the page says so in the linear panel, as the command
    # line's does (the run and its plots are still worth having).
    result.report(tmp_path / "typo.html", outputs=["body_why"])
    linear = page_data(tmp_path / "typo.html")["linear"]
    assert not linear["available"] and "body_why" in linear["reason"]
    with pytest.raises(momenta.InvalidArgument, match="about"):
        result.report(tmp_path / "bad.html", about="halfway")
    assert not (tmp_path / "bad.html").exists()


def test_an_existing_file_is_kept_without_force(tmp_path):
    target = tmp_path / "mine.html"
    target.write_text("keep me")
    result = momenta.simulate(momenta.load_model(EXAMPLES / "pendulum.yaml"), duration=0.1)
    with pytest.raises(momenta.FileError, match="pass force=True to overwrite it"):
        result.report(target)
    assert target.read_text() == "keep me"
    result.report(str(target), force=True)
    assert page_data(target)["kind"] == "simulation"


def test_a_stopped_run_reports_its_reason(tmp_path):
    path = STIFF_SPRING
    with pytest.raises(momenta.NumericalError) as failure:
        momenta.simulate(momenta.load_model(path), duration=2.0, dt=0.01)
    partial = failure.value.result
    assert "non-finite" in partial.stop_reason
    partial.report(tmp_path / "stopped.html")
    summary = page_data(tmp_path / "stopped.html")["summary"]
    assert "non-finite" in summary["stop_reason"]
    assert summary["rows"] == len(partial)

"""Every output says where it came from: JSON objects and figure files carry the coinflight
version and, when a command made them, its command line (coinflight._provenance)."""

from __future__ import annotations

import json
import shlex
import xml.etree.ElementTree as ET

from PIL import Image
from typer.testing import CliRunner

from coinflight import __version__
from coinflight._provenance import command_line, invoked, provenance
from coinflight.cli import app
from coinflight.plotting.style import new_figure, save_figure

runner = CliRunner()
DC = "{http://purl.org/dc/elements/1.1/}"


def _run(*argv: str):
    result = runner.invoke(app, list(argv))
    assert result.exit_code == 0, result.output
    return result


def test_toss_json_carries_the_version_and_its_command_line():
    argv = ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--json"]
    payload = json.loads(_run(*argv).stdout)
    assert payload["coinflight_version"] == __version__
    assert payload["command"] == "coinflight toss --omega 80 0 0 --flight-time 0.7 --json"
    assert shlex.split(payload["command"]) == ["coinflight", *argv]  # the argv, quoted


def test_a_list_answer_carries_it_in_every_object():
    argv = ["edge", "--ratios", "0.1,0.5", "--json"]
    rows = json.loads(_run(*argv).stdout)
    assert len(rows) == 2
    for row in rows:
        assert (row["coinflight_version"], row["command"]) == (__version__, command_line(argv))


def test_an_argument_with_spaces_is_quoted_as_a_shell_reads_it():
    assert command_line(["plot", "toss", "--out", "my figure"]) == (
        "coinflight plot toss --out 'my figure'"
    )


def test_provenance_outside_a_command_is_the_version_alone():
    assert provenance() == {"coinflight_version": __version__}
    with invoked("GET /api/toss?omega=80,0,0"):
        assert provenance()["command"] == "GET /api/toss?omega=80,0,0"
    assert "command" not in provenance()


def test_figures_drawn_by_a_command_carry_it_in_their_metadata(tmp_path):
    argv = ["plot", "toss", "--flight-time", "0.7", "--out", str(tmp_path / "toss")]
    _run(*argv)
    png = Image.open(tmp_path / "toss.png").text
    assert png["Software"].startswith(f"coinflight {__version__} (Matplotlib ")
    assert png["Command"] == command_line(argv)
    svg = ET.parse(tmp_path / "toss.svg").getroot()
    assert next(svg.iter(DC + "source")).text == command_line(argv)
    creator = next(svg.iter(DC + "creator"))
    assert next(creator.iter(DC + "title")).text.startswith(f"coinflight {__version__} ")


def test_figures_saved_from_python_carry_the_version_alone(tmp_path):
    fig = new_figure()
    fig.add_subplot().plot([0, 1], [0, 1])
    png, svg = save_figure(fig, tmp_path / "line")
    text = Image.open(png).text
    assert text["Software"].startswith(f"coinflight {__version__} ") and "Command" not in text
    assert not list(ET.parse(svg).getroot().iter(DC + "source"))

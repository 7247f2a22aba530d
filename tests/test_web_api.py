"""The JSON API of ``coinflight serve`` (coinflight.web): the same answers as the command line's
``--json``, the same one-line errors, every request's work bounded, and a real server."""

from __future__ import annotations

import json

import pytest
from fastapi.testclient import TestClient
from typer.testing import CliRunner

from coinflight.cli import app as cli_app
from coinflight.report.paper import ROTATION_CASES
from coinflight.web import create_app

cli = CliRunner()


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app()) as c:
        yield c


def cli_json(*args: str) -> dict:
    result = cli.invoke(cli_app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def cli_error(*args: str) -> str:
    result = cli.invoke(cli_app, list(args))
    assert result.exit_code == 2
    (line,) = result.stderr.strip().splitlines()
    prefix = "coinflight: error: "
    assert line.startswith(prefix)
    return line[len(prefix) :]


def api_error(client: TestClient, url: str, status: int = 422) -> str:
    response = client.get(url)
    assert response.status_code == status, response.text
    detail = response.json()["detail"]
    assert isinstance(detail, str) and "\n" not in detail
    return detail


# --- /api/toss ---------------------------------------------------------------------------------
@pytest.mark.parametrize("case", ROTATION_CASES, ids=lambda c: c.figure)
def test_toss_json_equals_the_command_line_for_the_papers_six_tosses(client, case):
    """Stefan & Cheche's six tosses (Figs 2c-d, 3c-f): the API's object is the CLI's, key for key
    and number for number (one implementation, coinflight.queries.toss)."""
    wx, wy, t = case.omega_x, case.omega_y, case.flight_time
    response = client.get(f"/api/toss?omega={wx},{wy},0&flight_time={t}&coin=us-quarter")
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/json"
    expected = cli_json(
        "toss", "--omega", str(wx), str(wy), "0", "--flight-time", str(t), "--coin", "us-quarter"
    )
    assert response.json() == expected
    assert round(response.json()["rotations"], case.decimals) == case.paper_rotations


def test_toss_on_a_table_equals_the_command_line(client):
    url = "/api/toss?omega=80,0,0&flight_time=0.7&surface=table&drop_height=0.3&bounces=1"
    expected = cli_json(
        "toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--surface", "table",
        "--drop-height", "0.3", "--bounces", "1",
    )  # fmt: skip
    assert client.get(url).json() == expected


@pytest.mark.parametrize(
    ("query", "cli_args"),
    [
        ("flight_time=abc", ["--flight-time", "abc"]),
        ("flight_time=-1", ["--flight-time", "-1"]),
        ("flight_time=0.7&coin=foo", ["--flight-time", "0.7", "--coin", "foo"]),
        ("flight_time=0.7&start=up", ["--flight-time", "0.7", "--start", "up"]),
        ("omega=80,x,0&flight_time=0.7", ["--omega", "80", "x", "0", "--flight-time", "0.7"]),
        ("flight_time=0.7&launch_speed=3", ["--flight-time", "0.7", "--launch-speed", "3"]),
        ("flight_time=0.7&drop_height=0.3", ["--flight-time", "0.7", "--drop-height", "0.3"]),
        ("flight_time=0.7&g=-1", ["--flight-time", "0.7", "--g", "-1"]),
        ("flight_time=0.7&radius=0.01", ["--flight-time", "0.7", "--radius", "0.01"]),
    ],
)
def test_toss_bad_values_are_one_line_422_in_the_command_lines_words(client, query, cli_args):
    detail = api_error(client, f"/api/toss?{query}")
    said = cli_error("toss", *cli_args)
    # typer names an option with its alias ('--flight-time' / '-T'); the API by its name only
    assert detail == said.replace("'--flight-time' / '-T'", "'--flight-time'")


def test_toss_omega_takes_three_numbers(client):
    assert api_error(client, "/api/toss?omega=80,0&flight_time=0.7") == (
        "--omega takes 3 comma-separated numbers WX,WY,WZ; got '80,0'"
    )

"""The JSON API of ``coinflight serve`` (coinflight.web): the same answers as the command line's
``--json``, the same one-line errors, every request's work bounded, and a real server."""

from __future__ import annotations

import json
import math
import time

import numpy as np
import pytest
from fastapi.testclient import TestClient
from scipy.spatial.transform import Rotation
from typer.testing import CliRunner

from coinflight.cli import app as cli_app
from coinflight.report.paper import PROBABILITY_CASES, ROTATION_CASES
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


def test_toss_trajectory_is_the_closed_form_flight(client):
    """trajectory=K samples Flight.at: it starts heads up, ends on the catch's normal, keeps
    n on its cone about S (n·Ŝ = cos ψ), its quaternion turns the body z axis onto n, and the
    height is the parabola v0 t − g t²/2 (0 at launch and at catch)."""
    body = client.get("/api/toss?omega=90,30,10&flight_time=0.65&trajectory=41").json()
    traj = body["trajectory"]
    normal = np.array(traj["normal"])
    quat = np.array(traj["quaternion"])
    t = np.array(traj["t"])
    assert normal.shape == (41, 3) and quat.shape == (41, 4) and t.shape == (41,)
    assert t[0] == 0.0 and t[-1] == pytest.approx(0.65, abs=1e-15)
    np.testing.assert_allclose(normal[0], [0, 0, 1], atol=1e-12)
    np.testing.assert_allclose(normal[-1], body["normal"], atol=1e-12)
    axis = np.array(traj["axis"])
    assert np.linalg.norm(axis) == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(axis, np.array(body["angular_momentum"]) / np.linalg.norm(
        body["angular_momentum"]), atol=1e-12)  # fmt: skip
    cos_psi = math.cos(math.radians(traj["cone_half_angle_deg"]))
    np.testing.assert_allclose(normal @ axis, cos_psi, atol=1e-9)
    np.testing.assert_allclose(Rotation.from_quat(quat).apply([0, 0, 1]), normal, atol=1e-12)
    v0, g = body["launch_speed"], body["g"]
    np.testing.assert_allclose(traj["height"], v0 * t - g * t**2 / 2, atol=1e-12)


@pytest.mark.parametrize(
    ("query", "message"),
    [
        ("trajectory=1", "trajectory must be a whole number from 2 to 2000, got 1"),
        ("trajectory=2001", "trajectory must be a whole number from 2 to 2000, got 2001"),
        ("trajectory=x", "Invalid value for '--trajectory': 'x' is not a valid integer"),
        (
            "trajectory=10&surface=table",
            "trajectory draws the catch in the hand (the closed form); leave out --surface "
            "table, --drag and --spin-damping, or trajectory",
        ),
    ],
)
def test_trajectory_is_bounded(client, query, message):
    assert api_error(client, f"/api/toss?flight_time=0.7&{query}") == message


# --- /api/probability --------------------------------------------------------------------------
def _box(case) -> tuple[list[str], str]:
    """The paper's box as command-line options and as the API's query."""
    wx = f"{case.omega_x[0]:g}:{case.omega_x[1]:g}"
    t = f"{case.flight_time[0]:g}:{case.flight_time[1]:g}"
    wy = f"{case.omega_y:g}"
    args = ["--omega-x", wx, "--omega-y", wy, "--flight-time", t]
    return args, f"omega_x={wx}&omega_y={wy}&flight_time={t}"


def _without_timing(payload: dict) -> dict:
    return {k: v for k, v in payload.items() if k != "elapsed"}


@pytest.mark.parametrize("case", PROBABILITY_CASES, ids=lambda c: c.figure)
@pytest.mark.parametrize(("method", "extra"), [("exact", ""), ("monte-carlo", "&n=20000&seed=7")])
def test_probability_json_equals_the_command_line_for_the_papers_four_boxes(
    client, case, method, extra
):
    """Stefan & Cheche's Figs 2a, 2b, 3a, 3b: the same object as ``coinflight probability
    --json``, all but the run's own ``elapsed`` time; exact to the last digit, Monte Carlo from
    the same seed (the server's one thread gives the CLI's answer, whatever its threads)."""
    args, query = _box(case)
    response = client.get(f"/api/probability?{query}&method={method}{extra}")
    assert response.status_code == 200, response.text
    cli_args = ["probability", *args, "--method", method, "-q"]
    if extra:
        cli_args += ["--n", "20000", "--seed", "7"]
    expected = cli_json(*cli_args)
    got = response.json()
    assert _without_timing(got) == _without_timing(expected)
    assert got["elapsed"] > 0
    assert got["p_heads"] == pytest.approx(0.5, abs=0.02)  # "tends to the unbiased value of 50%"


def test_probability_preset_with_an_override_equals_the_command_line(client):
    query = "preset=human&flight_time=0.4:0.6&method=monte-carlo&n=5000&seed=11"
    expected = cli_json(
        "probability", "--preset", "human", "--flight-time", "0.4:0.6", "--method",
        "monte-carlo", "--n", "5000", "--seed", "11", "-q",
    )  # fmt: skip
    got = client.get(f"/api/probability?{query}").json()
    assert _without_timing(got) == _without_timing(expected)
    assert got["inputs"]["--flight-time"] == "0.4:0.6" and got["inputs"]["--preset"] == "human"


@pytest.mark.parametrize(
    ("query", "cli_args"),
    [
        ("omega_x=60:x&flight_time=0.6:0.9", ["--omega-x", "60:x", "--flight-time", "0.6:0.9"]),
        ("flight_time=0.6:0.9&method=foo", ["--flight-time", "0.6:0.9", "-m", "foo"]),
        ("flight_time=0.6:0.9&seed=3", ["--flight-time", "0.6:0.9", "--seed", "3"]),
        ("flight_time=0.6:0.9&method=exact&grid_cells=5",
         ["--flight-time", "0.6:0.9", "--grid-cells", "5"]),
        ("omega_x=60:90", ["--omega-x", "60:90"]),
        ("flight_time=normal:0.7", ["--flight-time", "normal:0.7"]),
        ("flight_time=0.6:0.9&method=grid&n=100000000",
         ["--flight-time", "0.6:0.9", "-m", "grid", "--n", "100000000"]),
        ("flight_time=0.6:0.9&method=monte-carlo&n=0",
         ["--flight-time", "0.6:0.9", "-m", "monte-carlo", "--n", "0"]),
    ],
)  # fmt: skip
def test_probability_bad_values_are_one_line_422_in_the_command_lines_words(
    client, query, cli_args
):
    assert api_error(client, f"/api/probability?{query}") == cli_error(
        "probability", *cli_args, "-q"
    )


def test_probability_work_beyond_the_servers_budget_is_refused_before_it_starts(client):
    """A size the command line would run (within its hour) but this server would not answer in
    time: refused at once, with the estimate, the limit and the way on."""
    n = 10**9  # 40 s at 2.5e7 tosses/s: within the CLI's hour, beyond half of 30 s
    started = time.perf_counter()
    detail = api_error(client, f"/api/probability?flight_time=0.6:0.9&method=monte-carlo&n={n}")
    assert time.perf_counter() - started < 5
    assert detail.startswith(f"monte-carlo with n = {n} is 40 s of estimated work, more than ")
    assert "use a smaller n (this server answers within 30 s)" in detail

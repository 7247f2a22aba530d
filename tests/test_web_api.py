"""The JSON API of ``coinflight serve`` (coinflight.web): the same answers as the command line's
``--json``, the same one-line errors, every request's work bounded, and a real server."""

from __future__ import annotations

import json
import math
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation
from typer.testing import CliRunner

from _web_server import WAIT, serving
from coinflight import __version__
from coinflight._provenance import command_line
from coinflight.cli import app as cli_app
from coinflight.model.surface import MAX_FRICTION
from coinflight.report.paper import PROBABILITY_CASES, ROTATION_CASES
from coinflight.web import create_app

cli = CliRunner()


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app()) as c:
        yield c


def asked(payload: dict | list, command: str) -> dict | list:
    """The answer as both front ends give it: each object's ``command`` (the one field that
    differs by front end: the command line, or the request) checked to be ``command`` and
    left out; everything else, ``coinflight_version`` included, kept for the comparison."""
    objects = payload if isinstance(payload, list) else [payload]
    for obj in objects:
        assert obj.pop("command") == command
        assert obj["coinflight_version"] == __version__
    return payload


def cli_json(*args: str) -> dict:
    """``coinflight ARGS --json``'s object (:func:`asked`: its command line checked)."""
    result = cli.invoke(cli_app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    return asked(json.loads(result.stdout), command_line([*args, "--json"]))


def api_json(response) -> dict:
    """The API's object (:func:`asked`: its request, as sent, checked)."""
    assert response.status_code == 200, response.text
    return asked(response.json(), "GET " + response.request.url.raw_path.decode())


def cli_error(*args: str) -> str:
    result = cli.invoke(cli_app, list(args))
    assert result.exit_code == 2
    (line,) = result.stderr.strip().splitlines()
    prefix = "coinflight: error: "
    assert line.startswith(prefix)
    return line[len(prefix) :]


TOO_MUCH_FRICTION = f"{MAX_FRICTION + 0.5:g}"  # beyond the largest μ a Surface takes


def api_error(client: TestClient, url: str, status: int = 422) -> str:
    response = client.get(url)
    assert response.status_code == status, response.text
    detail = response.json()["detail"]
    assert isinstance(detail, str) and "\n" not in detail
    return detail


@pytest.fixture
def in_process(monkeypatch):
    """Requests computed in the test process instead of the server's worker processes (there a
    monkeypatch cannot reach), for tests that make the work fail the test if called."""
    from coinflight.web.runner import Runner

    async def here(_runner: Runner, fn, *args, long=False):
        return fn(*args)

    monkeypatch.setattr(Runner, "run", here)
    return monkeypatch


def never_called(where: str):
    """A stand-in for the work ``where`` that fails the test if called."""

    def fail(*_args, **_kwargs):
        raise AssertionError(f"{where} ran before the refusal")

    return fail


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
    assert api_json(response) == expected
    assert round(response.json()["rotations"], case.decimals) == case.paper_rotations


def test_toss_on_a_table_equals_the_command_line(client):
    url = "/api/toss?omega=80,0,0&flight_time=0.7&surface=table&drop_height=0.3&bounces=1"
    expected = cli_json(
        "toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--surface", "table",
        "--drop-height", "0.3", "--bounces", "1",
    )  # fmt: skip
    assert api_json(client.get(url)) == expected


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
        (f"flight_time=0.7&surface=table&friction={TOO_MUCH_FRICTION}",
         ["--flight-time", "0.7", "--surface", "table", "--friction", TOO_MUCH_FRICTION]),
    ],
)  # fmt: skip
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
    got = api_json(response)
    assert _without_timing(got) == _without_timing(expected)
    assert got["elapsed"] > 0
    assert got["p_heads"] == pytest.approx(0.5, abs=0.02)  # "tends to the unbiased value of 50%"


def test_probability_preset_with_an_override_equals_the_command_line(client):
    query = "preset=human&flight_time=0.4:0.6&method=monte-carlo&n=5000&seed=11"
    expected = cli_json(
        "probability", "--preset", "human", "--flight-time", "0.4:0.6", "--method",
        "monte-carlo", "--n", "5000", "--seed", "11", "-q",
    )  # fmt: skip
    got = api_json(client.get(f"/api/probability?{query}"))
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
        ("flight_time=0.6:0.9&surface=table&friction=0.3:12",
         ["--flight-time", "0.6:0.9", "--surface", "table", "--friction", "0.3:12"]),
    ],
)  # fmt: skip
def test_probability_bad_values_are_one_line_422_in_the_command_lines_words(
    client, query, cli_args
):
    assert api_error(client, f"/api/probability?{query}") == cli_error(
        "probability", *cli_args, "-q"
    )


def test_probability_work_beyond_the_servers_budget_is_refused_before_it_starts(client, in_process):
    """A size the command line would run (within its hour) but this server would not answer in
    time: refused before the estimate runs (made to fail the test if called, not timed: the
    machine is shared), with the estimate, the limit and the way on."""
    from coinflight._validation import MAX_RUN_SECONDS
    from coinflight.outcomes.hand import HAND_CATCH
    from coinflight.queries import probability as q
    from coinflight.web.endpoints import BUDGET_SHARE
    from coinflight.web.runner import DEFAULT_TIME_LIMIT  # the client's: create_app()'s default

    n = round(40 * HAND_CATCH.rate)  # 40 s at the hand catch's rate: the one the bound uses
    # Beyond the server's budget (half of its 30 s), within the command line's hour.
    assert BUDGET_SHARE * DEFAULT_TIME_LIMIT < n / HAND_CATCH.rate <= MAX_RUN_SECONDS
    in_process.setattr(q, "run", never_called("the estimate"))
    detail = api_error(client, f"/api/probability?flight_time=0.6:0.9&method=monte-carlo&n={n}")
    assert detail.startswith(f"monte-carlo with n = {n} is 40 s of estimated work, more than ")
    assert f"use a smaller n (this server answers within {DEFAULT_TIME_LIMIT:g} s)" in detail


# --- /api/basin, /api/bias, /api/data ----------------------------------------------------------
def test_basin_is_the_map_the_command_line_draws(client, tmp_path):
    """The JSON map is basin_map's grid: the CLI's printed P(heads) on the grid, its shape
    (rows along the spin), and each pixel the face of the toss at its cell's centre."""
    body = client.get("/api/basin?omega_x=60:90&flight_time=0.6:0.9&resolution=40x30").json()
    face = np.array(body["face"])
    assert face.shape == (30, 40) and body["resolution"] == [40, 30]
    assert body["faces"] == {"0": "tails", "1": "heads", "2": "edge"}
    out = cli.invoke(cli_app, [
        "plot", "basin", "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--resolution",
        "40x30", "--out", str(tmp_path / "basin.png"),
    ])  # fmt: skip
    assert out.exit_code == 0, out.output
    assert f"P(heads) on the 40×30 grid = {body['heads_fraction']:.6f}" in out.stdout
    for i, j in [(0, 0), (7, 31), (29, 39)]:
        w, t = body["spin"][i], body["flight_time"][j]
        toss = client.get(f"/api/toss?omega={w!r},0,0&flight_time={t!r}").json()
        assert face[i, j] == (1 if toss["outcome"] == "heads" else 0)


def test_basin_boundaries_are_kellers_hyperbolas(client):
    """Planar spin: each boundary satisfies ω T = (2k ± ½)π (Keller 1986; REFERENCES §3)."""
    body = client.get("/api/basin?resolution=10&boundaries=true").json()
    assert body["planar"] and body["boundaries"]
    for curve in body["boundaries"]:
        points = [(t, w) for t, w in zip(curve["flight_time"], curve["spin"], strict=True) if t]
        assert points
        for t, w in points:
            assert math.cos(w * t) == pytest.approx(0.0, abs=1e-9)  # ω T = (2k ± ½)π


@pytest.mark.parametrize(
    ("query", "message"),
    [
        ("resolution=2000", "a map of 2,000×2,000 cells is 4,000,000 cells, more than the limit of "
         "640,000 cells; use a coarser resolution (e.g. 400 or 600x300)"),
        ("resolution=10x", "--resolution must be N or NTxNW with whole numbers, such as 500 or "
         "600x400; got '10x'"),
        ("omega_x=60", "--omega-x must be a range LO:HI such as 60:90 for a map; got '60' "
         "(60 rad/s)"),
    ],
)  # fmt: skip
def test_basin_bad_values_and_sizes_are_refused(client, query, message):
    assert api_error(client, f"/api/basin?{query}") == message


def test_basin_boundaries_beyond_their_limit_are_refused_before_the_map(client, in_process):
    """The web's map asks for its analytic boundaries: too many curves are refused from the box
    alone, before the map's grid (made to fail the test if called) is laid out, in the library's
    words."""
    from coinflight.outcomes.hand import HandCatch
    from coinflight.studies import basin

    in_process.setattr(basin, "midpoints", never_called("the map's grid"))
    in_process.setattr(HandCatch, "faces", never_called("the map's catches"))
    detail = api_error(
        client, "/api/basin?omega_x=60:100000&flight_time=0.6:0.9&resolution=10&boundaries=true"
    )
    # bands k = 0 .. int(1e5 × 0.9 / 2π) + 1 = 14,325, two curves each: 28,650 curves
    assert detail == (
        "drawing the analytic boundaries of a map up to 1e+05 rad/s × 0.9 s is 28,650 curves, "
        "more than the limit of 2,000 curves; draw the map without them (--no-boundaries, "
        "boundaries=False) or map smaller spins or flight times"
    )


def test_basin_boundaries_on_a_table_are_refused_before_the_map(client, in_process):
    """Only the catch in the hand has analytic boundaries: asked for on a table, the request is
    refused before the map's grid (made to fail the test if called) is laid out."""
    from coinflight.outcomes.hand import HandCatch
    from coinflight.studies import basin

    in_process.setattr(basin, "midpoints", never_called("the map's grid"))
    in_process.setattr(HandCatch, "faces", never_called("the map's catches"))
    detail = api_error(client, "/api/basin?surface=table&resolution=10&boundaries=true")
    assert detail == (
        "the analytic boundaries belong to the catch in the hand; leave out --boundaries with "
        "--surface table"
    )


@pytest.mark.parametrize(
    "args",
    [
        ["--psi", "80"],
        ["--psi-dist", "normal:80,5"],
        ["--psi", "75", "--monte-carlo", "20000", "--seed", "5"],
        ["--preset", "human"],
    ],
)
def test_bias_json_equals_the_command_line(client, args):
    pairs = zip(args[::2], args[1::2], strict=True)
    query = "&".join(f"{k.lstrip('-').replace('-', '_')}={v}" for k, v in pairs)
    assert api_json(client.get(f"/api/bias?{query}")) == cli_json("bias", *args)


def test_bias_at_several_psi_in_one_request_is_the_command_lines_answer_for_each(client):
    """``psis`` (the page's curve p(ψ) in one request): for each ψ, in the order given, the
    object of ``coinflight bias --psi ψ --json``; documented in the schema; refused in one line
    with another way of giving ψ, beyond its bound, or with a value out of range."""
    psis = ["90", "0", "45.3", "134.9", "180"]
    got = api_json(client.get("/api/bias", params={"psis": ",".join(psis), "coin": "eur-1"}))
    assert got == [cli_json("bias", "--psi", psi, "--coin", "eur-1") for psi in psis]
    assert got[1]["p_same_side"] == 1.0 and got[0]["p_same_side"] == 0.5  # DHM 2007, eq. (2)
    documented = client.get("/openapi.json").json()["paths"]["/api/bias"]["get"]["parameters"]
    assert "psis=0,5,10" in next(q for q in documented if q["name"] == "psis")["description"]
    assert api_error(client, "/api/bias?psis=10,200") == cli_error("bias", "--psi", "200")
    assert (
        api_error(client, "/api/bias?psis=10,x")
        == "Invalid value for '--psis': 'x' is not a number"
    )
    assert api_error(client, "/api/bias?psis=10&psi=3&monte_carlo=10") == (
        "psis is the closed form at each ψ: leave out psi, monte_carlo"
    )
    assert api_error(client, "/api/bias?psis=" + ",".join(["1"] * 2001)).startswith(
        "a curve of 2001 values of ψ"
    )


def test_bias_monte_carlo_beyond_the_servers_budget_is_refused(client):
    detail = api_error(client, "/api/bias?psi=80&monte_carlo=1000000000")
    assert detail.startswith("a Monte Carlo check of 1000000000 tosses is 250 s of estimated work")
    assert api_error(client, "/api/bias?psi=80&psi_dist=normal:80,5") == cli_error(
        "bias", "--psi", "80", "--psi-dist", "normal:80,5"
    )


def test_data_json_equals_the_command_line_and_reads_only_the_package(client):
    """Bartoš et al.'s 350,757 flips and the ψ that explains them: the CLI's object."""
    got = api_json(client.get("/api/data?interval=wilson&psi_sd=5&seed=7&repeats=3"))
    assert got == cli_json(
        "data", "--interval", "wilson", "--psi-sd", "5", "--seed", "7", "--repeats", "3"
    )
    assert got["heterogeneity"]["seed"] == 7 and got["heterogeneity"]["repeats"] == 3
    # the held-out check's estimated work against the server's budget, before any fit
    assert api_error(client, "/api/data?folds=48&repeats=1000").startswith(
        "a held-out check of 48 people in 48 folds × 1000 splits is 960 s of estimated work"
    )
    assert (got["flips"], got["same"], got["plot"]) == (350_757, 178_078, [])
    assert api_error(client, "/api/data?psi_sd=-1") == cli_error("data", "--psi-sd", "-1")
    # no request reads a file: --counts FILE is the command line's alone
    assert api_error(client, "/api/data?counts=/etc/passwd") == "No such option: --counts"


# --- time, the page, the schema ----------------------------------------------------------------
def test_a_request_over_its_time_limit_is_503_and_its_worker_is_ended():
    """An exact integral that takes the library 17 s by its own estimate (its interpolant alone
    took 23 s on the loaded 2-core machine:
    a normal ωx of sd 0.01 beside wide ωy, ω_z, T, whose plane density the (Ω, ψ) rule
    interpolates in 1,670 pieces, within its bound of 4,000; the server does not budget exact)
    is answered 503 with one line when the 3 s limit is up; its worker is ended and replaced,
    so that with one worker the next request is answered within its limit. (Until the narrow-range
    check this request was ωx in 60:60.000000000001, now refused in milliseconds.)"""
    slow = (
        "/api/probability?omega_x=normal:60,0.01&omega_y=-60:60&omega_z=-40:40"
        "&flight_time=0.5:1&method=exact"
    )
    # Checked without a clock (the machine is shared): the 503 is the runner's timeout at the
    # limit (asyncio.wait_for), the worker's process id changes (ended mid-work, not after it),
    # and the next request is answered, within its own 3 s limit waiting included.
    import functools
    import os

    with TestClient(create_app(time_limit=3, workers=1)) as c:
        pid = functools.partial(c.app.state.runner.run, os.getpid, long=True)
        worker = c.portal.call(pid)
        detail = api_error(c, slow, status=503)
        assert detail == (
            "the request ran over the server's time limit of 3 s; ask for less work "
            "(a smaller n, a coarser resolution)"
        )
        assert c.portal.call(pid) != worker  # ended, replaced
        assert c.get("/api/toss?flight_time=0.7").json()["outcome"] == "heads"
        assert c.get("/api/bias?psi=80").status_code == 200


def test_a_spin_range_too_narrow_for_exact_is_refused_at_once(client, in_process):
    """The old slow request (ωx 1e-12 wide beside wide ranges) is now the library's one-line
    refusal, before the (Ω, ψ) rule's plan (its interpolant: the slow part) is built (made to
    fail the test if called, not timed), the command line's words."""
    from coinflight.probability.exact import omega_psi

    args = {"omega_x": "60:60.000000000001", "omega_y": "-60:60", "omega_z": "-40:40"}
    in_process.setattr(omega_psi, "_PolarPlan", never_called("the (Ω, ψ) rule's plan"))
    detail = api_error(
        client,
        "/api/probability?" + "&".join(f"{k}={v}" for k, v in args.items())
        + "&flight_time=0.5:1&method=exact",
    )  # fmt: skip
    assert detail.startswith("the exact (Ω, ψ) rule cannot resolve omega_x = 60:60.000000000001 ")
    options = [x for k, v in args.items() for x in ("--" + k.replace("_", "-"), v)]
    assert detail == cli_error(
        "probability", *options, "--flight-time", "0.5:1", "--method", "exact"
    )


def test_every_worker_taken_is_503_busy_at_once():
    """No queue without end: with one worker and no backlog, a second request while the first
    runs is refused at once; the slot comes back when the first ends."""
    import asyncio
    import os

    from coinflight.web.runner import Overloaded, Runner

    async def scenario() -> str:
        runner = Runner(workers=1, time_limit=30, backlog=0)
        await runner.start()
        first = asyncio.ensure_future(runner.run(time.sleep, 1.0))
        await asyncio.sleep(0.1)
        try:
            await runner.run(os.getpid)
        except Overloaded as exc:
            message = str(exc)
        else:
            message = ""
        assert await first is None
        assert isinstance(await runner.run(os.getpid), int)  # the slot came back
        runner.close()
        return message

    assert asyncio.run(scenario()) == (
        "the server is busy (every worker is taken); try again in a few seconds"
    )


def test_long_requests_have_their_own_lane_and_unstarted_work_is_busy_not_over_time():
    """A short request runs while every long worker is taken; a long request still waiting
    for a worker when its time is up is "busy" (it never ran, and never will: it is dropped),
    the one that ran is "over the time limit"."""
    import asyncio
    import os

    from coinflight.web.runner import Overloaded, Runner

    async def outcome(coroutine) -> str:
        try:
            await coroutine
        except Overloaded as exc:
            return str(exc)
        return "answered"

    async def scenario() -> list[str]:
        runner = Runner(workers=1, time_limit=2, backlog=2)
        await runner.start()
        # three at once: the first runs, the next two wait for the one worker; the last of
        # them cannot start before its time is up (the one before it holds the worker)
        three = [
            asyncio.ensure_future(outcome(runner.run(time.sleep, 30.0, long=True)))
            for _ in range(3)
        ]
        await asyncio.sleep(0.2)  # each has taken its slot
        full = await outcome(runner.run(os.getpid, long=True))
        short = await outcome(runner.run(os.getpid))  # its own lane: answered at once
        assert not any(f.done() for f in three)
        first, second, third = [await f for f in three]
        assert second in (first, third)
        assert isinstance(await runner.run(os.getpid, long=True), int)  # the lane came back
        runner.close()
        return [first, third, full, short]

    assert asyncio.run(scenario()) == [
        "the request ran over the server's time limit of 2 s; ask for less work "
        "(a smaller n, a coarser resolution)",
        "the server is busy: the request waited 2 s for a worker and did not start; try again "
        "in a few seconds",
        "the server is busy with other long requests (every worker for them is taken); try "
        "again in a few seconds",
        "answered",
    ]


def test_requests_whose_estimated_work_is_small_stay_in_the_short_lane():
    """The triage (coinflight.web.endpoints.triage): read and refused in the short lane, then
    moved to the long one when the estimate is beyond SHORT_SECONDS or unknown."""
    from coinflight.queries.values import AirArgs, CoinArgs, DistArgs, TableArgs
    from coinflight.web import endpoints

    coin, hand, air = CoinArgs(), TableArgs("hand", None, None, None, None), AirArgs(None, None)
    table = TableArgs("table", None, None, None, None)

    def tosses(wx, wy="0", wz="0"):
        return DistArgs(wx, wy, wz, "0.5:1", None, "heads", 9.81)

    cheap = endpoints.probability(coin, tosses("60:90"), hand, air, {"method": "exact"}, 30, True)
    assert 0 < cheap["p_heads"] < 1
    slow = tosses("normal:60,0.01", "-60:60", "-40:40")  # 17 s by exact's own estimate
    with pytest.raises(endpoints.LongWork):
        endpoints.probability(coin, slow, hand, air, {"method": "exact"}, 30, True)
    many = {"method": "monte-carlo", "n": 100_000_000}  # 4 s by the estimate
    with pytest.raises(endpoints.LongWork):
        endpoints.probability(coin, tosses("60:90"), hand, air, many, 30, True)
    with pytest.raises(ValueError, match="more than the limit"):  # refused where it is read
        endpoints.probability(coin, tosses("60:90"), hand, air, {**many, "n": 10**9}, 30, True)
    assert endpoints.basin(coin, {"resolution": "800"}, hand, None, False, 30, True)["face"]
    # 30×30 landings carried to rest: 13 s at 70/s, beyond the short lane, within the limit
    with pytest.raises(endpoints.LongWork):
        endpoints.basin(coin, {"resolution": "30"}, table, None, False, 30, True)
    with pytest.raises(endpoints.LongWork):
        endpoints.bias(coin, 80.0, None, None, 10_000_000, 1, 30, True)
    assert endpoints.bias(coin, 80.0, None, None, 1000, 1, 30, True)["p_same_side"] > 0.5


def test_the_hosts_a_server_answers_and_errors_repeat_little_of_a_request():
    from coinflight.web.app import DETAIL_LIMIT, shortened
    from coinflight.web.server import allowed_hosts

    assert allowed_hosts("127.0.0.1") == ["127.0.0.1", "localhost", "[::1]"]
    assert allowed_hosts("::1") == ["[::1]", "localhost", "127.0.0.1"]
    assert allowed_hosts("192.168.1.20") == ["192.168.1.20"]
    assert allowed_hosts("0.0.0.0") == ["*"]
    assert allowed_hosts("0.0.0.0", ["Coins.example.org"]) == ["coins.example.org"]
    assert allowed_hosts("127.0.0.1", ["*"])[0] == "*"
    assert allowed_hosts("127.0.0.1", ["*.example.org"])[0] == "*.example.org"
    for bad in ("", "a/b", "a b", "x*.org", "*example.org"):
        with pytest.raises(ValueError, match="--allowed-host"):
            allowed_hosts("127.0.0.1", [bad])
    assert cli_error("serve", "--allowed-host", "a b").startswith("--allowed-host 'a b'")
    with TestClient(create_app(allowed_hosts=["127.0.0.1"]), base_url="http://evil.test") as c:
        assert c.get("/api/toss?flight_time=0.7").status_code == 400
    value = "7" * 100_000
    line = shortened(f"--omega {value!r}: no; also {value}", ["omega", value])
    assert len(line) < 600 and line.count("…") == 2 and "7" * 201 not in line
    assert len(shortened("z" * 10_000, [])) == DETAIL_LIMIT - 1


def test_the_page_its_static_files_and_the_openapi_schema_are_served(client):
    page = client.get("/")
    assert page.status_code == 200 and page.headers["content-type"].startswith("text/html")
    assert "<html" in page.text.lower()
    assert client.get("/static/index.html").text == page.text
    for escape in (
        "/static/%2e%2e/app.py",
        "/static/..%2fapp.py",
        "/static/%2e%2e/%2e%2e/_files.py",
    ):
        assert client.get(escape).status_code == 404  # nothing outside static/ is served
    schema = client.get("/openapi.json").json()
    assert set(schema["paths"]) >= {f"/api/{e}" for e in ("toss", "probability", "basin",
                                                          "bias", "data")}  # fmt: skip
    toss = schema["paths"]["/api/toss"]["get"]
    assert {"omega", "flight_time", "coin", "trajectory"} <= {p["name"] for p in toss["parameters"]}
    refusal = toss["responses"]["422"]["content"]["application/json"]["schema"]["$ref"]
    assert schema["components"]["schemas"][refusal.rsplit("/", 1)[1]]["properties"] == {
        "detail": {"type": "string", "title": "Detail"}
    }
    # FastAPI's /docs and /redoc pages load Swagger UI and ReDoc from a CDN: not served offline.
    assert client.get("/docs").status_code == 404
    assert client.get("/redoc").status_code == 404


def test_the_coin_table_and_air_parameters_are_one_definition_in_every_endpoint(client):
    """The coin's, the table's and the air's parameters come from one dependency each
    (coinflight.web.params): the same names, schemas and words wherever they are taken, read
    and refused as the command line does."""
    paths = client.get("/openapi.json").json()["paths"]
    documented = {
        path.rsplit("/", 1)[1]: {q["name"]: q for q in op["get"].get("parameters", [])}
        for path, op in paths.items()
    }
    groups = {
        ("coin", "radius", "thickness", "mass"): ("toss", "probability", "basin", "bias"),
        (
            "surface",
            "drop_height",
            "restitution",
            "friction",
            "rolling_resistance",
            "pivoting_resistance",
            "corner_radius",
        ): ("toss", "probability", "basin"),
        ("drag", "spin_damping"): ("toss", "probability"),
    }
    for names, endpoints in groups.items():
        for name in names:
            first = documented[endpoints[0]][name]
            assert all(documented[e][name] == first for e in endpoints), name
    assert api_error(client, "/api/bias?psi=10&mass=x") == cli_error(
        "bias", "--psi", "10", "--mass", "x"
    )
    assert api_error(client, "/api/bias?psi=10&drag=1") == "No such option: --drag"


MILLIMETRES = ["--radius", "12.13", "--thickness", "0.00175", "--mass", "0.00567"]
"""A quarter's radius given in millimetres: allowed, and warned about (a PlausibilityWarning)."""


@pytest.mark.parametrize(
    ("command", "args", "query"),
    [
        ("toss", ["--omega", "80", "0", "0", "--flight-time", "0.7"],
         "omega=80,0,0&flight_time=0.7"),
        ("probability", ["--omega-x", "60:90", "--flight-time", "0.6:0.9"],
         "omega_x=60:90&flight_time=0.6:0.9"),
        ("bias", ["--psi", "80"], "psi=80"),
    ],
)  # fmt: skip
def test_plausibility_warnings_are_in_the_answer_as_in_the_command_lines_json(
    client, command, args, query
):
    """The library's warnings reach the API's caller (not only the worker's stderr): the
    command line prints each once on stderr and carries it in ``--json``'s ``"warnings"``;
    the API's answer is that same object."""
    argv = [command, *args, *MILLIMETRES, "--json"]
    result = cli.invoke(cli_app, argv)
    assert result.exit_code == 0, result.output
    expected = asked(json.loads(result.stdout), command_line(argv))
    (line,) = result.stderr.splitlines()
    prefix = "coinflight: warning: "
    assert line.startswith(prefix + "radius 12.13 m is not a coin's size (1 mm to 10 cm)")
    assert expected["warnings"] == [line[len(prefix) :]]
    coin = "radius=12.13&thickness=0.00175&mass=0.00567"
    got = api_json(client.get(f"/api/{command}?{query}&{coin}"))
    got.pop("elapsed", None), expected.pop("elapsed", None)
    assert got == expected
    if command == "bias":
        assert api_json(client.get(f"/api/bias?psis=80&{coin}")) == [expected]


def test_an_answer_without_warnings_has_no_new_key(client):
    """No warning, no ``"warnings"`` key where there was none (the JSON of ``toss`` and ``bias``
    is as before); ``probability`` keeps its list (empty)."""
    assert "warnings" not in client.get("/api/toss?flight_time=0.7").json()
    assert "warnings" not in client.get("/api/bias?psi=80").json()
    assert client.get("/api/probability?flight_time=0.6:0.9").json()["warnings"] == []


def test_an_unknown_parameter_is_an_error_as_an_unknown_option(client):
    assert api_error(client, "/api/toss?flight-time=0.7") == "No such option: --flight-time"
    assert cli_error("toss", "--flight-tim", "0.7").startswith("No such option: --flight-tim")


# --- a real server -------------------------------------------------------------------------------
def test_coinflight_serve_answers_over_http_on_loopback():
    """``coinflight serve --port 0`` binds 127.0.0.1 on a free port, prints its address, answers
    the CLI's JSON over real HTTP, refuses a second server on its port (one line, exit 2) and
    stops on Ctrl-C."""
    import httpx2

    with serving() as server:
        assert server.url.startswith("http://127.0.0.1:")
        with httpx2.Client(base_url=server.url, timeout=60) as http:
            got = http.get("/api/toss", params={"omega": "90,30,0", "flight_time": "0.65"})
            assert api_json(got) == cli_json("toss", "--omega", "90", "30", "0", "--flight-time",
                                          "0.65")  # fmt: skip
            assert http.get("/").status_code == 200
            bad = http.get("/api/toss", params={"flight_time": "abc"})
            assert (bad.status_code, bad.json()) == (
                422, {"detail": "Invalid value for '--flight-time': 'abc' is not a number"}
            )  # fmt: skip
        second = subprocess.run(
            [sys.executable, "-m", "coinflight", "serve", "--port", str(server.port)],
            capture_output=True, text=True, timeout=60,
        )  # fmt: skip
        assert second.returncode == 2
        assert second.stderr == (
            f"coinflight: error: port {server.port} on 127.0.0.1 is in use; choose another "
            "with --port (0: any free port)\n"
        )
        server.process.send_signal(signal.SIGINT)
        assert server.process.wait(timeout=WAIT) in (0, 130)


def test_serve_on_every_address_warns_and_a_bad_port_is_one_line():
    with serving("--host", "0.0.0.0", "--port", "0") as server:  # answering: started
        assert server.url.startswith("http://0.0.0.0:")
        server.process.send_signal(signal.SIGINT)
        assert server.process.wait(timeout=WAIT) in (0, 130)
        warning = server.process.stderr.read().splitlines()[0]
    assert warning.startswith("coinflight: warning: --host 0.0.0.0 serves coinflight to every ")
    result = cli.invoke(cli_app, ["serve", "--port", "70000"])
    assert result.exit_code == 2
    assert result.stderr.strip().splitlines() == [
        "coinflight: error: Invalid value for '--port': '70000' must be at most 65535"
    ]


# --- generated hostile requests ----------------------------------------------------------------
HOSTILE = [
    "nan", "inf", "-inf", "1e308", "-1e308", "1e-320", "0", "-1", "abc", "", " ", "1,2", "60:",
    ":", "90:60", "normal:80,-1", "normal:", "60:90:120", "½", "9223372036854775808", "2.5",
    "%00", "../etc/passwd", "x" * 300,
]  # fmt: skip
ENDPOINTS = {
    "toss": {
        "omega": ["80,0,0", "90,30,10", "1e308,0,0", "nan,0,0", "80,0"],
        "flight_time": ["0.7", "0.3", "1e4"], "launch_speed": ["3"], "start": ["heads", "tails"],
        "g": ["9.81", "1.62"], "coin": ["eur-1", "us-dime"], "surface": ["hand", "table"],
        "drop_height": ["0.3"], "bounces": ["0", "3"], "trajectory": ["2", "50", "2000"],
        "corner_radius": ["0.0003", "0.001"],
        "rolling_resistance": ["1e-4", "1e-5:1e-3"],
    },
    "probability": {
        "omega_x": ["60:90", "normal:240,24", "80"], "omega_y": ["0", "0:20"],
        "omega_z": ["0", "0:5"], "flight_time": ["0.6:0.9", "normal:0.5,0.05", "0.7"],
        "method": ["exact", "grid", "monte-carlo", "qmc"], "n": ["50", "2000", "10000000000000"],
        "seed": ["1", "-5"], "preset": ["human"], "grid_cells": ["10"],
        "surface": ["table"], "corner_radius": ["0.0003"],
    },
    "basin": {
        "omega_x": ["60:90", "100:200"], "flight_time": ["0.6:0.9"], "omega_z": ["0", "20"],
        "psi": ["60", "90"], "precession_rate": ["100:200"], "resolution": ["20", "30x10"],
        "boundaries": ["true", "false"],
    },
    "bias": {
        "psi": ["80", "45", "180"], "psis": ["0,45,90", "46.5", "5,x"],
        "psi_dist": ["normal:80,5", "70:90"], "preset": ["human"],
        "monte_carlo": ["100", "5000"], "seed": ["3"],
    },
    "data": {
        "interval": ["exact", "wilson"], "psi_sd": ["0", "5", "80"], "dataset": ["bartos2023"],
        "seed": ["1", "-5"], "folds": ["2", "5", "49"], "repeats": ["1", "3", "0"],
    },
}  # fmt: skip


BASE = {
    "toss": {"flight_time": "0.7"},
    "probability": {"omega_x": "60:90", "flight_time": "0.6:0.9"},
    "bias": {"psi": "80"},
}
"""What each request starts from, so that most generated requests reach the physics."""


@st.composite
def _request(draw, endpoint: str) -> dict[str, str]:
    options = ENDPOINTS[endpoint]
    names = draw(st.lists(st.sampled_from(sorted(options)), max_size=4, unique=True))
    return BASE.get(endpoint, {}) | {
        name: draw(st.one_of(st.sampled_from(options[name]), st.sampled_from(options[name]),
                             st.sampled_from(HOSTILE)))
        for name in names
    }  # fmt: skip


def _probabilities(payload, key: str = ""):
    if isinstance(payload, dict):
        for k, value in payload.items():
            yield from _probabilities(value, str(k))
    elif isinstance(payload, list):
        for value in payload:
            yield from _probabilities(value, key)
    elif key.startswith("p_") and isinstance(payload, float):
        yield key, payload


GENERATED_TIME_LIMIT = 5.0
"""The time limit of the server the generated requests meet: heavy requests the budget lets
through (an exact quadrature over a preset's spins) end as 503 after it, not after 30 s."""


@pytest.fixture(scope="module")
def quick_client():
    with TestClient(create_app(time_limit=GENERATED_TIME_LIMIT)) as c:
        yield c


@pytest.mark.slow
@pytest.mark.parametrize("endpoint", sorted(ENDPOINTS))
def test_generated_requests_are_answered_or_refused_in_one_line(quick_client, endpoint):
    """Whatever a hostile client sends: 200 with finite JSON and probabilities in [0, 1], 422
    with one line, or 503 with the time limit's line; never a 500, never a traceback."""
    client = quick_client

    @settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(params=_request(endpoint))
    def run(params):
        response = client.get(f"/api/{endpoint}", params=params)
        context = f"/api/{endpoint} {params}: {response.status_code} {response.text[:300]}"
        assert response.status_code in (200, 422, 503), context
        body = response.json()
        if response.status_code == 503:
            assert body["detail"].startswith(
                f"the request ran over the server's time limit of {GENERATED_TIME_LIMIT:g} s;"
            ), context
            return
        if response.status_code == 422:
            assert isinstance(body["detail"], str) and body["detail"], context
            assert "\n" not in body["detail"] and "Traceback" not in body["detail"], context
            return
        for key, p in _probabilities(body):
            assert 0.0 <= p <= 1.0, f"{context}\n{key} = {p}"

    run()


def test_each_surface_proposes_tosses_its_server_answers(client):
    """/api/surfaces gives each kind the number of random tosses the page proposes there
    (suggested_n): the hand's page default, a table's far fewer (a landing carried to rest
    takes thousands of times as long as a catch). The table's is answered by Monte Carlo (the
    work bound counts it within the budget), ten times as many are refused with the way on."""
    from coinflight.queries.landing import SUGGESTED_MOST

    kinds = {k["name"]: k for k in api_json(client.get("/api/surfaces"))["surfaces"]}
    assert kinds["hand"]["suggested_n"] == SUGGESTED_MOST
    n = kinds["table"]["suggested_n"]
    assert 10 <= n < SUGGESTED_MOST
    query = "/api/probability?omega_x=150:300&flight_time=0.4:0.6&surface=table&method=monte-carlo"
    answer = api_json(client.get(f"{query}&n={n}&seed=3"))
    assert answer["n"] == n and 0.0 <= answer["p_edge"] <= 1.0
    refused = client.get(f"{query}&n={10 * n}&seed=3")
    assert refused.status_code == 422
    assert "use a smaller n" in refused.json()["detail"]

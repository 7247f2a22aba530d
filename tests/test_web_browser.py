"""The page of ``coinflight serve`` in a real browser: Debian's Chromium driven by Playwright.

A real ``coinflight serve --port 0`` runs for the module on a free loopback port; Chromium
(``/usr/bin/chromium``, installed by ``make chromium``, part of ``make test``; never Playwright's
own download) opens the page headless with a fresh profile. The tests check what a student sees
against what the JSON API and the command line answer.

Screenshots of every panel, and of the whole page on a phone and a projector, are the run's
artefacts, in the test's own temporary folder ``web-screenshots0/`` (pytest keeps the last three
runs under ``/tmp/pytest-of-USER/``); to keep them in the repository, for a look or a CI upload:
``pytest --basetemp=test-artefacts tests/test_web_browser.py`` (``test-artefacts/`` is ignored
by git).

Without Chromium or Playwright the tests skip on a workstation and fail in CI (``CI`` set), so
a CI machine that lost the browser cannot pass silently.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
import urllib.error
import urllib.parse
import urllib.request
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from tests._chromium import browser_or_skip, chromium
from tests._cli import runner
from tests._images import assert_nontrivial, colour_fraction, load_rgb

from coinflight.cli import app

HEADS = "#0072B2"  # coinflight.plotting.style.HEADS_COLOR, the page's heads colour
TAILS = "#E69F00"  # TAILS_COLOR
WAIT_MS = 60_000  # a first request compiles numba kernels: seconds on a busy machine


# --------------------------------------------------------------------------- the server
@pytest.fixture(scope="module")
def server(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """``coinflight serve`` on a free loopback port; its address (``http://127.0.0.1:PORT``)."""
    browser_or_skip()
    log = tmp_path_factory.mktemp("serve") / "serve.log"
    with log.open("w") as out:
        proc = subprocess.Popen(
            [sys.executable, "-m", "coinflight", "serve", "--host", "127.0.0.1", "--port", "0"],
            stdout=out,
            stderr=subprocess.STDOUT,
        )
    try:
        # "coinflight serving on http://127.0.0.1:PORT/ (Ctrl-C to stop)", then answers.
        deadline = time.monotonic() + 60
        while not (found := re.search(r"http://127\.0\.0\.1:\d+", log.read_text())):
            assert proc.poll() is None, f"coinflight serve stopped: {log.read_text()}"
            assert time.monotonic() < deadline, "coinflight serve did not announce its address"
            time.sleep(0.1)
        url = found.group(0)
        while True:
            try:
                with urllib.request.urlopen(f"{url}/", timeout=5) as response:
                    assert response.status == 200
                break
            except OSError:
                assert time.monotonic() < deadline, "coinflight serve did not answer in 60 s"
                time.sleep(0.2)
        yield url
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


def api(server: str, path: str, **params: object) -> dict[str, Any]:
    """The JSON the server answers to GET ``path`` (an HTTP error raises)."""
    query = urllib.parse.urlencode(params)
    with urllib.request.urlopen(f"{server}{path}?{query}", timeout=60) as response:
        result: dict[str, Any] = json.load(response)
        return result


def refusal(server: str, path: str, **params: object) -> tuple[int, str]:
    """The status and one line of a request the server refuses."""
    query = urllib.parse.urlencode(params)
    with pytest.raises(urllib.error.HTTPError) as caught:
        urllib.request.urlopen(f"{server}{path}?{query}", timeout=60)
    return caught.value.code, json.loads(caught.value.read())["detail"]


# --------------------------------------------------------------------------- the browser
@pytest.fixture(scope="module")
def browser_context(server: str) -> Iterator[Any]:
    """Chromium with a fresh profile in a temporary folder, deleted afterwards."""
    with chromium(viewport={"width": 1400, "height": 900}, base_url=server) as context:
        yield context


class Problems:
    """Console errors, uncaught exceptions and failed requests of a page."""

    def __init__(self, page: Any) -> None:
        self.messages: list[str] = []
        page.on(
            "console",
            lambda m: (
                self.messages.append(f"console {m.type}: {m.text}") if m.type == "error" else None
            ),
        )
        page.on("pageerror", lambda e: self.messages.append(f"uncaught: {e}"))
        # A request the page cancels itself (a newer slider position replaced it) is no fault.
        page.on(
            "requestfailed",
            lambda r: (
                self.messages.append(f"request failed: {r.url} ({r.failure})")
                if "ERR_ABORTED" not in (r.failure or "")
                else None
            ),
        )
        page.on(
            "response",
            lambda r: (
                self.messages.append(f"HTTP {r.status}: {r.url}") if r.status >= 400 else None
            ),
        )


@pytest.fixture
def page(browser_context: Any) -> Iterator[Any]:
    """The page loaded and every panel answered; the problems met on the way in ``.problems``."""
    page = browser_context.new_page()
    page.set_default_timeout(WAIT_MS)
    page.problems = Problems(page)
    page.api_requests = []  # the API's URLs the page asked, in order
    page.on("request", lambda r: page.api_requests.append(r.url) if "/api/" in r.url else None)
    page.goto("/")
    page.wait_for_selector("body[data-ready=true]")
    yield page
    page.close()


def ready(page: Any, panel: str) -> None:
    """Wait until the panel ``#panel`` has its answer (or its error) on screen."""
    page.wait_for_selector(f"#{panel}:not([data-state=loading])")


@pytest.fixture(scope="module")
def shots(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder that keeps this run's screenshots (the tests' artefacts)."""
    return tmp_path_factory.mktemp("web-screenshots")


# --------------------------------------------------------------------------- the tests
def test_page_loads_with_every_panel_and_no_console_errors(page: Any) -> None:
    for panel in ("explorer", "basin", "probability", "same-side"):
        assert page.locator(f"#{panel}").get_attribute("data-state") == "ready", panel
    assert page.problems.messages == []
    # Offline: every script, style and picture came from this server.
    origins = page.evaluate(
        "() => [...new Set(performance.getEntriesByType('resource')"
        ".map(e => new URL(e.name).origin))]"
    )
    assert origins == [page.evaluate("location.origin")]
    # WebGL drew the coin (the fallback message is for browsers without it).
    assert page.locator("#scene-fallback").is_hidden()


def test_the_coin_menu_is_the_librarys_presets(page: Any) -> None:
    from coinflight.model.coin import PRESETS

    options = page.eval_on_selector_all(
        "#coin option", "os => os.map(o => [o.value, o.textContent])"
    )
    assert options == [[key, coin.name] for key, coin in PRESETS.items()]


def test_the_surface_menu_is_the_servers_registry(page: Any, server: str) -> None:
    """The probability panel's surface menu is the server's registered surface kinds (GET
    /api/surfaces: served, not written in the page), their one lines as titles; a landing on a
    table is printed as ``coinflight probability --surface table`` prints it, P(edge) included,
    all but the line describing the table (the JSON does not carry it)."""
    ready(page, "probability")
    kinds = api(server, "/api/surfaces")["surfaces"]
    assert [kind["name"] for kind in kinds][:2] == ["hand", "table"]
    options = page.eval_on_selector_all(
        "#prob-surface option", "os => os.map(o => [o.value, o.title])"
    )
    assert options == [[kind["name"], kind["summary"]] for kind in kinds]
    assert page.input_value("#prob-surface") == "hand"
    page.select_option("#prob-method", "monte-carlo")
    page.fill("#prob-n", "1000")
    page.fill("#prob-seed", "5")
    page.select_option("#prob-surface", "table")  # asks at once
    page.wait_for_function(
        "() => document.querySelector('#prob-text').textContent.includes('P(edge)')"
    )
    page.wait_for_selector("#buildup[data-state=ready]")  # no exact value asked: no closed form
    args = ["--omega-x", "60:90", "--flight-time", "0.6:0.9", "--coin", "us-quarter"]
    mc = ["--method", "monte-carlo", "--n", "1000", "--seed", "5", "--surface", "table"]
    cli = runner.invoke(app, ["probability", *args, *mc])
    assert cli.exit_code == 0, cli.output
    text = page.locator("#prob-text").text_content()
    drop = ("method ", "landing on a table")
    assert _lines(text, drop=drop) == _lines(cli.stdout, drop=drop)
    page.select_option("#prob-method", "exact")
    page.select_option("#prob-surface", "hand")  # asks at once
    page.wait_for_function(
        "() => !document.querySelector('#prob-text').textContent.includes('P(edge)')"
    )
    assert page.problems.messages == []


def test_a_table_proposes_the_tosses_the_server_answers(page: Any, server: str) -> None:
    """Choosing the table puts its suggested number of tosses (/api/surfaces) in the tosses
    field in place of the hand's 100,000, which the server would refuse there, and the answer
    comes; back in the hand, the hand's number returns. A number typed by hand is kept."""
    ready(page, "probability")
    kinds = {kind["name"]: kind for kind in api(server, "/api/surfaces")["surfaces"]}
    page.select_option("#prob-method", "monte-carlo")
    assert page.input_value("#prob-n") == str(kinds["hand"]["suggested_n"])
    page.select_option("#prob-surface", "table")  # asks at once
    assert page.input_value("#prob-n") == str(kinds["table"]["suggested_n"])
    page.wait_for_function(
        "() => document.querySelector('#prob-text').textContent.includes('P(edge)')"
    )
    page.select_option("#prob-surface", "hand")
    assert page.input_value("#prob-n") == str(kinds["hand"]["suggested_n"])
    page.fill("#prob-n", "300")
    page.select_option("#prob-surface", "table")
    assert page.input_value("#prob-n") == "300"
    page.wait_for_function(
        "() => document.querySelector('#prob-text').textContent.includes('P(edge)')"
    )
    assert page.problems.messages == []


def test_toss_face_and_rotations_are_the_command_lines(page: Any, server: str) -> None:
    """The paper's first toss (ω = (80, 0, 0) rad/s, T = 0.7 s): the page prints what
    ``coinflight toss`` prints, character for character."""
    cli = runner.invoke(
        app,
        ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--coin", "us-quarter"],
    )
    assert cli.exit_code == 0, cli.output
    assert page.locator("#toss-text").text_content() == cli.stdout.rstrip("\n")
    answer = api(server, "/api/toss", omega="80,0,0", flight_time=0.7, coin="us-quarter")
    assert page.locator("#toss-face").text_content() == answer["outcome"].upper() == "HEADS"
    assert page.locator("#toss-rotations").text_content() == f"{answer['rotations']:.4f}"
    # The coin drawn at the catch shows that face.
    assert page.locator("#scene").get_attribute("data-face-up") == answer["outcome"]


@pytest.mark.parametrize("control", ["number", "slider"])
def test_changing_the_spin_shows_the_face_the_api_gives(
    page: Any, server: str, control: str
) -> None:
    before = page.locator("#toss-result").get_attribute("data-outcome")
    assert before == "heads"
    # A spin that lands the other face (the API decides; T stays 0.7 s).
    for wx in (84.5, 85.0, 86.0, 88.0, 90.0):
        answer = api(server, "/api/toss", omega=f"{wx},0,0", flight_time=0.7, coin="us-quarter")
        if answer["outcome"] != before:
            break
    assert answer["outcome"] != before, "no spin among the candidates lands the other face"
    if control == "number":
        page.fill("#wx", str(wx))
    else:
        page.eval_on_selector(
            "#wx-range",
            "(el, v) => { el.value = v; el.dispatchEvent(new Event('input', {bubbles: true})); }",
            str(wx),
        )
    page.wait_for_selector(f"#toss-result[data-outcome={answer['outcome']}]")
    ready(page, "explorer")
    assert page.locator("#wx").input_value() == str(wx)
    assert page.locator("#toss-face").text_content() == answer["outcome"].upper()
    assert page.locator("#toss-rotations").text_content() == f"{answer['rotations']:.4f}"
    assert page.locator("#scene").get_attribute("data-face-up") == answer["outcome"]
    cli = runner.invoke(app, ["toss", "--omega", str(wx), "0", "0", "--flight-time", "0.7"])
    assert cli.exit_code == 0, cli.output
    assert page.locator("#toss-text").text_content() == cli.stdout.rstrip("\n")
    # The time slider walks the flight: at launch the coin shows its start face.
    page.eval_on_selector(
        "#time", "el => { el.value = 0; el.dispatchEvent(new Event('input', {bubbles: true})); }"
    )
    assert page.locator("#face-now").text_content() == "HEADS"
    assert page.problems.messages == []


def test_launch_speed_gives_the_command_lines_toss(page: Any) -> None:
    """v0 instead of T: the paper's toss again (v0 = g T / 2 = 3.4335 m/s)."""
    page.check("input[name=by][value=v0]")
    page.fill("#v0", "3.4335")
    page.wait_for_function(
        "() => document.querySelector('#toss-text').textContent.includes('launch speed 3.43 m/s')"
        " && document.querySelector('#explorer').dataset.state === 'ready'"
    )
    cli = runner.invoke(app, ["toss", "--omega", "80", "0", "0", "--launch-speed", "3.4335"])
    assert cli.exit_code == 0, cli.output
    assert page.locator("#toss-text").text_content() == cli.stdout.rstrip("\n")
    assert page.problems.messages == []


def test_play_runs_the_flight_from_launch_to_the_catch(page: Any) -> None:
    page.select_option("#speed", "1")  # real time: 0.7 s
    page.click("#play")
    assert page.locator("#play").get_attribute("aria-pressed") == "true"
    page.wait_for_selector("#play[aria-pressed=false]")  # stops by itself at the catch
    assert page.locator("#time-readout").text_content() == "t = 0.700 s of T = 0.700 s"
    assert page.locator("#face-now").text_content() == "HEADS"
    # Pause in the middle: the time stays where it was.
    page.select_option("#speed", "0.03")
    page.click("#play")
    page.wait_for_timeout(500)
    page.click("#play")
    shown = page.locator("#time-readout").text_content()
    page.wait_for_timeout(300)
    assert page.locator("#time-readout").text_content() == shown
    assert shown != "t = 0.700 s of T = 0.700 s"
    assert page.problems.messages == []


REFUSALS = {
    # panel: (inputs to fill, button to press, the same request to the API, the error line)
    "explorer": ({"#T": "0"}, None, ("/api/toss", {"omega": "80,0,0", "flight_time": "0"}), "toss"),
    "basin": (
        {"#basin-T-lo": "1.5"},
        "#basin-run",
        ("/api/basin", {"flight_time": "1.5:1.0", "omega_x": "0:100", "resolution": "200"}),
        "basin",
    ),
    "probability": (
        {"#prob-n": "100000000000"},
        "#prob-run",
        (
            "/api/probability",
            {
                "omega_x": "60:90",
                "flight_time": "0.6:0.9",
                "method": "monte-carlo",
                "n": "100000000000",
            },
        ),
        "prob",
    ),
    "same-side": ({"#psi": "200"}, None, ("/api/bias", {"psi": "200"}), "psi"),
}


@pytest.mark.parametrize("panel", list(REFUSALS))
def test_an_api_refusal_is_shown_in_the_page(page: Any, server: str, panel: str) -> None:
    """Bad input: the server's one line (HTTP 422) appears in the panel, the last answer is
    greyed (the panel's state "error"), and goes when the input is put right."""
    ready(page, panel)
    fills, button, (path, params), prefix = REFUSALS[panel]
    status, line = refusal(server, path, **params)
    assert status == 422
    assert "\n" not in line
    if panel == "probability":
        page.select_option("#prob-method", "monte-carlo")
    before = {selector: page.locator(selector).input_value() for selector in fills}
    for selector, value in fills.items():
        page.fill(selector, value)
    if button:
        page.click(button)
    error = page.locator(f"#{prefix}-error")
    error.wait_for(state="visible")
    assert error.text_content() == line
    assert page.locator(f"#{panel}").get_attribute("data-state") == "error"
    # Put right, the error goes.
    for selector, value in before.items():
        page.fill(selector, value)
    if button:
        page.click(button)
    error.wait_for(state="hidden")
    ready(page, panel)
    assert page.locator(f"#{panel}").get_attribute("data-state") == "ready"


@pytest.mark.parametrize("panel", ["explorer", "basin", "probability", "sameSide"])
def test_a_request_replaced_by_a_newer_one_is_no_error(page: Any, panel: str) -> None:
    # Each panel asks only for its latest answer (api.js latest): a second update() aborts
    # the first one's request, and that abort is no error (api.js unlessSuperseded): both
    # updates resolve, and the page logs nothing.
    aborted: list[str] = []
    page.on(
        "requestfailed",
        lambda r: aborted.append(r.url) if "ERR_ABORTED" in (r.failure or "") else None,
    )
    page.evaluate(
        "async (name) => { const p = window.coinflight[name];"
        " await Promise.all([p.update(), p.update()]); }",
        panel,
    )
    assert aborted, "the first request was not replaced"
    assert page.problems.messages == []


def test_a_click_on_the_basin_map_tosses_that_point(page: Any, server: str) -> None:
    ready(page, "basin")
    target_t, target_w = 0.65, 42.0
    x, y = page.evaluate("([t, w]) => window.coinflight.basin.pixelOf(t, w)", [target_t, target_w])
    page.locator("#basin-canvas").click(position={"x": x, "y": y})
    picked = json.loads(page.wait_for_selector("#basin[data-picked]").get_attribute("data-picked"))
    # The point clicked is the one aimed at, to within a pixel of the map.
    assert picked["flight_time"] == pytest.approx(target_t, abs=0.01)
    assert picked["omega_x"] == pytest.approx(target_w, abs=1.0)
    page.wait_for_function(
        "p => document.querySelector('#toss-result').dataset.flightTime == String(p)",
        arg=picked["flight_time"],
    )
    ready(page, "explorer")
    assert float(page.locator("#wx").input_value()) == picked["omega_x"]
    assert float(page.locator("#T").input_value()) == picked["flight_time"]
    answer = api(
        server,
        "/api/toss",
        omega=f"{picked['omega_x']},0,0",
        flight_time=picked["flight_time"],
        coin="us-quarter",
    )
    assert page.locator("#toss-face").text_content() == answer["outcome"].upper()
    assert page.locator("#toss-rotations").text_content() == f"{answer['rotations']:.4f}"
    assert page.problems.messages == []


def test_probability_is_printed_as_the_command_line_prints_it(page: Any) -> None:
    """Monte Carlo with a seed: the page's P(heads) line, uncertainty included, is the CLI's."""
    ready(page, "probability")
    args = ["--omega-x", "60:90", "--flight-time", "0.6:0.9", "--coin", "us-quarter"]
    exact = runner.invoke(app, ["probability", *args, "--method", "exact"])
    assert exact.exit_code == 0, exact.output
    text = page.locator("#prob-text").text_content()
    assert _p_line(text) == _p_line(exact.stdout)
    page.select_option("#prob-method", "monte-carlo")
    page.fill("#prob-n", "20000")
    page.fill("#prob-seed", "1")
    page.click("#prob-run")
    page.wait_for_function(
        "() => document.querySelector('#prob-text').textContent.includes('seed 1')"
    )
    mc = runner.invoke(
        app, ["probability", *args, "--method", "monte-carlo", "--n", "20000", "--seed", "1"]
    )
    assert mc.exit_code == 0, mc.output
    text = page.locator("#prob-text").text_content()
    assert _p_line(text) == _p_line(mc.stdout)
    assert "± " in _p_line(text) and "95 % CI" in _p_line(text)
    # Every line but the timing is the command line's, the coin's first.
    assert text.splitlines()[0].startswith("US quarter (d = 24.26 mm")
    assert _lines(text, drop=("method ",)) == _lines(mc.stdout, drop=("method ",))
    assert page.problems.messages == []


def test_the_monte_carlo_estimate_builds_up_from_one_run(page: Any, server: str) -> None:
    """The build-up's points are the API's answers for fewer tosses from the answer's own seed
    (the library makes a shorter run the start of a longer one; its streams are tested in
    test_streams.py); here the heads counts are at least consistent with that."""
    ready(page, "probability")
    page.select_option("#prob-method", "monte-carlo")
    page.fill("#prob-n", "20000")
    page.fill("#prob-seed", "3")
    page.click("#prob-run")
    page.wait_for_selector("#buildup[data-state=ready]")
    points = sorted(page.evaluate("window.coinflight.probability.points.map(p => [p[0], p[1]])"))
    # n / 2^k for k = 8…0, of at least 100 tosses (20000 / 2^8 = 78 is left out).
    assert [n for n, _ in points] == [156, 312, 625, 1250, 2500, 5000, 10000, 20000]
    box = {"omega_x": "60:90", "flight_time": "0.6:0.9", "coin": "us-quarter"}
    heads = []
    for n, p in points:
        answer = api(server, "/api/probability", **box, method="monte-carlo", n=n, seed=3)
        assert p == answer["p_heads"]
        heads.append(answer["counts"]["heads"])
    exact = api(server, "/api/probability", **box, method="exact")["p_heads"]
    assert f"exact value {exact:.6f}" in page.locator("#buildup-text").text_content()
    # Necessary for prefixes of one run: a longer run has at least the heads of a shorter one,
    # and at most as many more as it has more tosses.
    for (n0, _), (n1, _), h0, h1 in zip(points, points[1:], heads, heads[1:], strict=False):
        assert 0 <= h1 - h0 <= n1 - n0
    assert page.problems.messages == []


def test_a_seed_drawn_by_the_server_is_kept_to_the_last_digit(page: Any, server: str) -> None:
    """No seed given: the server draws one (up to 128 bits, beyond JavaScript's exact
    integers); the page prints it and asks for the same run with it, digit for digit."""
    ready(page, "probability")
    page.select_option("#prob-method", "monte-carlo")
    page.fill("#prob-n", "2000")
    page.click("#prob-run")
    page.wait_for_selector("#buildup[data-state=ready]")
    seed = re.search(r"seed (\d+);", page.locator("#prob-text").text_content())
    assert seed, page.locator("#prob-text").text_content()
    box = {"omega_x": "60:90", "flight_time": "0.6:0.9", "coin": "us-quarter"}
    again = api(server, "/api/probability", **box, method="monte-carlo", n=2000, seed=seed[1])
    assert page.locator("#prob-result").get_attribute("data-p-heads") == repr(again["p_heads"])
    assert page.problems.messages == []


def _p_line(text: str) -> str:
    return next(line for line in text.splitlines() if line.startswith("P(heads)"))


def _lines(text: str, drop: tuple[str, ...]) -> list[str]:
    return [line for line in text.splitlines() if not line.startswith(drop)]


def test_same_side_follows_the_psi_slider_and_shows_the_real_flips(page: Any, server: str) -> None:
    ready(page, "same-side")
    page.fill("#psi", "60")
    answer = api(server, "/api/bias", psi=60)
    page.wait_for_function(
        "v => document.querySelector('#psi-p').dataset.value == String(v)",
        arg=answer["p_same_side"],
    )
    assert page.locator("#psi-p").text_content() == f"{answer['p_same_side']:.6f}"
    data = api(server, "/api/data")
    text = page.locator("#data-text").text_content()
    assert "350,757 flips by 48 people" in text
    assert f"ψ = {data['psi_deg']:.1f}°" in text
    page.click("#psi-data")
    page.wait_for_function(
        "v => document.querySelector('#psi').value == v", arg=f"{data['psi_deg']:.1f}"
    )
    assert page.problems.messages == []


def test_the_curve_p_of_psi_is_one_request(page: Any) -> None:
    """The curve p(ψ) is drawn from one request (``/api/bias?psis=…``, not one a ψ); the zoom
    near 90° asks once more, for the ψ it lacks."""
    ready(page, "same-side")
    curves = [u for u in page.api_requests if "/api/bias" in u and "psis=" in u]
    assert len(curves) == 1
    psis = urllib.parse.parse_qs(urllib.parse.urlparse(curves[0]).query)["psis"][0].split(",")
    assert len(psis) > 40 and {"0", "45.1", "90", "180"} <= set(psis)
    singles = [u for u in page.api_requests if "/api/bias" in u and "psis=" not in u]
    assert len(singles) == 1  # the slider's ψ
    page.check("input[name=psi-view][value=near]")
    page.wait_for_function(
        "() => performance.getEntriesByType('resource')"
        ".filter(e => e.name.includes('psis=')).length == 2"
    )
    assert len([u for u in page.api_requests if "psis=" in u]) == 2
    assert page.problems.messages == []


PANELS = ["explorer", "basin", "probability", "same-side"]


@pytest.mark.parametrize("panel", PANELS)
def test_panel_screenshots_are_not_blank(page: Any, shots: Path, panel: str) -> None:
    ready(page, panel)
    path = shots / f"{panel}.png"
    page.locator(f"#{panel}").screenshot(path=str(path))
    assert_nontrivial(path, min_side=300)


VERMILLION = "#D55E00"  # S, the angular momentum
CONE = "#EEDCE4"  # the cone: reddish purple #CC79A7 at 22 % over the scene's #F8F8F5
GREEN = "#009E73"  # the real flips
DRAWINGS = {
    # element: {colour: least share of its pixels}; each colour is drawn there, not a legend's
    "scene": {HEADS: 0.005, VERMILLION: 0.001, CONE: 0.01},  # coin face up, S, the cone
    "height-canvas": {HEADS: 0.01, TAILS: 0.01},  # the face-up strip along the flight
    "basin-canvas": {HEADS: 0.15, TAILS: 0.15},  # the map
    "psi-canvas": {HEADS: 0.002, GREEN: 0.001},  # p(ψ) and the flips' rate
    "prob-bar": {HEADS: 0.3, TAILS: 0.3},  # P(heads) ≈ 0.497 of the bar
}


@pytest.mark.parametrize("element", list(DRAWINGS))
def test_every_drawing_shows_what_it_draws(page: Any, shots: Path, element: str) -> None:
    """The 3-D view (WebGL), the canvases and the bar each show their own colours."""
    for panel in PANELS:
        ready(page, panel)
    if element == "scene":  # at launch: the coin lies flat, its heads face up to the camera
        page.eval_on_selector(
            "#time",
            "el => { el.value = 0; el.dispatchEvent(new Event('input', {bubbles: true})); }",
        )
    path = shots / f"drawing-{element}.png"
    page.locator(f"#{element}").screenshot(path=str(path))
    rgb = load_rgb(path)
    if element != "prob-bar":  # a bar a line high
        assert_nontrivial(path, min_side=100)
    for colour, share in DRAWINGS[element].items():
        assert colour_fraction(rgb, colour, tol=20) > share, (element, colour)


@pytest.mark.parametrize(
    ("name", "width", "height"), [("phone", 390, 844), ("projector", 1920, 1080)]
)
def test_the_page_fits_a_phone_and_a_projector(
    browser_context: Any, shots: Path, name: str, width: int, height: int
) -> None:
    page = browser_context.new_page()
    page.set_viewport_size({"width": width, "height": height})
    page.set_default_timeout(WAIT_MS)
    problems = Problems(page)
    try:
        page.goto("/")
        page.wait_for_selector("body[data-ready=true]")
        # Nothing wider than the screen: no sideways scrolling.
        assert page.evaluate("document.documentElement.scrollWidth") <= width
        path = shots / f"page-{name}.png"
        page.screenshot(path=str(path), full_page=True)
        assert load_rgb(path).shape[1] == width
        assert_nontrivial(path, min_side=min(width, 300))
        assert problems.messages == []
    finally:
        page.close()


# Python's format specification "g", and the page's copy of it (static/format.js), on numbers
# where the two could part: rounding up a digit, the switch to exponents at 1e-4 and 10^p.
NUMBERS = [
    0.0035355179959943635,
    80.0,
    1e-5,
    0.0001,
    0.00012345,
    123456789.0,
    0.5,
    2.5e-7,
    9.9999999,
    999999.5,
    1234567.0,
    -3.14159265,
    1e16,
    0.1 + 0.2,
    42.0,
    3.4335,
    0.6008625,
]


@pytest.mark.parametrize("digits", [1, 2, 3, 4, 6])
def test_the_page_writes_numbers_as_python_does(page: Any, digits: int) -> None:
    written = page.evaluate(
        "async ([xs, p]) => { const m = await import('/static/format.js');"
        " return xs.map(x => m.fmtG(x, p)); }",
        [NUMBERS, digits],
    )
    assert written == [format(x, f".{digits}g") for x in NUMBERS]
    counts = [0, 7, 999, 1000, 350757, 1234567890]
    grouped = page.evaluate(
        "async (ns) => { const m = await import('/static/format.js');"
        " return ns.map(n => m.thousands(n)); }",
        counts,
    )
    assert grouped == [f"{n:,}" for n in counts]

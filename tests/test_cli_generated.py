"""Generated command lines: every command and option, hostile values included.

What a hostile user types (nan, ±inf, 1e308, 1e-320, huge integers, malformed ranges, wrong
paths) must end as promised: exit code 0 with a sound answer, or exit code 2 with one line on
stderr naming the value; never a traceback, never a probability outside [0, 1].

Each command gets its own hypothesis test over the options it takes; values are drawn from a
pool of hostile texts and from plausible ones, so that most runs reach the physics. Commands that
take several seconds however they are called (``paper``, ``animate``) have their own tests
elsewhere. ``COINFLIGHT_GENERATED_EXAMPLES`` raises the number of command lines per command (the
default keeps the suite within CI's time); ``COINFLIGHT_GENERATED_LOG=FILE`` appends one JSON line
per run (command line, outcome, seconds) for a report, and ``COINFLIGHT_GENERATED_SURVEY=1`` with
it records failures instead of stopping at the first (a survey, not a test).
"""

from __future__ import annotations

import itertools
import json
import math
import os
import re
import signal
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from _work import command_work, never_run
from coinflight.cli import app

runner = CliRunner()
EXAMPLES = int(os.environ.get("COINFLIGHT_GENERATED_EXAMPLES", "25"))
LOG = os.environ.get("COINFLIGHT_GENERATED_LOG")
# With a log, COINFLIGHT_GENERATED_SURVEY=1 records failures instead of stopping at the first.
SURVEY = bool(LOG and os.environ.get("COINFLIGHT_GENERATED_SURVEY"))
# No single generated command line may take longer than this (the slowest legitimate ones are
# exact quadratures that give up after their budget, ~25 s, on a loaded machine).
SECONDS_PER_RUN = int(os.environ.get("COINFLIGHT_GENERATED_SECONDS", "60"))
# Most work a generated line may ask for, s on the reference machine by the package's own
# estimates: a third of the time limit, for a machine busier than the reference. The library
# accepts up to an hour (``MAX_RUN_SECONDS``): `sweep --method monte-carlo --n 20000` over
# hand,table with two restitutions is 20,000 landings carried to rest a row, ~290 s a row at
# the rigid ending's 70/s, accepted and far beyond any test. Such lines are discarded
# (hypothesis' ``reject``) before any work.
BUDGET_SECONDS = SECONDS_PER_RUN / 3

# Texts no number option should accept, or should accept only with a correct answer.
HOSTILE_NUMBERS = [
    "nan", "inf", "-inf", "1e308", "-1e308", "1e-320", "-1e-320", "0", "-0", "-1",
    "1e9", "99999999999999999999999", "9223372036854775808", "abc", "", " ", "1,2", "0x10",
    "1e", "--", "½",
]  # fmt: skip
HOSTILE_COUNTS = [
    "-1", "0", "1", "2", "2.5", "1e3", "9223372036854775807", "9223372036854775808",
    "99999999999999999999999", "10000000000000", "nan", "abc", "",
]  # fmt: skip
HOSTILE_RANGES = [
    "60:90", "90:60", "60:", ":90", ":", "60:60", "0.7:0.7000000000000002", "-1e9:1e9",
    "1e308:inf", "nan:1", "normal:80,0", "normal:80,-1", "normal:nan,1", "normal:1e308,1e308",
    "normal:80", "normal:", "uniform:1,2", "60:90:120", "1e-320:2e-320",
]  # fmt: skip
# Never a path outside the test's own folder that the run could write: the suite may run as
# root, and "/" once left /convergence.*, "/dev/full" /dev/full.png (a suffix is added to a
# bare name). /proc refuses new files even to root. (Full devices: tests/test_cli_streams.py.)
HOSTILE_PATHS = [
    "", ".", "sub/", "/proc/coinflight-test", "/proc/version", "no/such/dir/x.png", "x.unknown",
]  # fmt: skip
# A folder that exists (made in the test's own folder): an output file named by it once became
# FOLDER.png beside it.
EXISTING_FOLDER = "an-existing-folder"
# Counts beyond any machine: a thread pool of them was once accepted.
ABSURD_COUNTS = {"99999999999999999999999", "9223372036854775808", "9223372036854775807"}
# Options whose value is an output file (never a folder; convergence's --out is a prefix).
FILE_OPTIONS = {"--out", "--plot"}


def _number(low: float, high: float) -> st.SearchStrategy[str]:
    plausible = st.floats(low, high, allow_nan=False).map(lambda x: f"{x:.6g}")
    return st.one_of(plausible, plausible, plausible, st.sampled_from(HOSTILE_NUMBERS))


def _count(low: int, high: int) -> st.SearchStrategy[str]:
    return st.one_of(st.integers(low, high).map(str), st.sampled_from(HOSTILE_COUNTS))


def _dist(low: float, high: float) -> st.SearchStrategy[str]:
    a = st.floats(low, high, allow_nan=False)
    uniform = st.tuples(a, a).map(lambda p: f"{min(p):.6g}:{max(p):.6g}")
    normal = st.tuples(a, st.floats(0, (high - low) / 4)).map(
        lambda p: f"normal:{p[0]:.6g},{p[1]:.3g}"
    )
    return st.one_of(a.map(lambda x: f"{x:.6g}"), uniform, normal, st.sampled_from(HOSTILE_RANGES))


def _omega3() -> st.SearchStrategy[list[str]]:
    one = _number(-300, 300)
    return st.lists(one, min_size=3, max_size=3)


COIN = {
    "--coin": st.sampled_from(
        ["us-quarter", "eur-1", "us-nickel", "gbp-1", "pound", "", "US-Cent"]
    ),
    # A custom coin takes all three dimensions; one option draws them together.
    "--radius": st.tuples(_number(0.005, 0.03), _number(0.0005, 0.005), _number(0.001, 0.02)).map(
        lambda rhm: [rhm[0], "--thickness", rhm[1], "--mass", rhm[2]]
    ),
    "--g": _number(1, 30),
    "--start": st.sampled_from(["heads", "tails", "edge", "HEADS", ""]),
}
TABLE = {
    "--surface": st.sampled_from(["hand", "table", "sand", ""]),
    "--drop-height": _number(0, 1.5),
    "--restitution": _number(0, 1),
    "--friction": _number(0, 1),
    "--rolling-resistance": _number(0, 0.01),
    "--pivoting-resistance": _dist(0, 0.01),
    "--corner-radius": _number(0, 0.001),
    "--contact-duration": _dist(0, 1e-3),
}
FLIGHT = {"--flight-time": _number(0.2, 1.0), "--launch-speed": _number(1, 5)}

OPTIONS: dict[str, dict[str, st.SearchStrategy]] = {
    "toss": {
        "--omega": _omega3(),
        **FLIGHT,
        **COIN,
        **TABLE,
        "--drag": _number(0, 2),
        "--spin-damping": _number(0, 1e-5),
        "--bounces": _count(0, 5),
        "--json": st.just(None),
    },
    "probability": {
        "--omega-x": _dist(0, 300),
        "--omega-y": _dist(-50, 50),
        "--omega-z": _dist(-50, 50),
        "--flight-time": _dist(0.2, 1.0),
        "--launch-speed": _dist(1, 5),
        **COIN,
        **TABLE,
        "--preset": st.sampled_from(["human", "robot", ""]),
        "--method": st.sampled_from(["grid", "monte-carlo", "qmc", "exact", "fast", ""]),
        "--n": _count(1, 2000),
        "--seed": _count(0, 2**32),
        "--grid-cells": _count(0, 200),
        "--threads": _count(1, 4),
        "--json": st.just(None),
    },
    "convergence": {
        "--omega-x": _dist(0, 300),
        "--flight-time": _dist(0.2, 1.0),
        **COIN,
        "--methods": st.sampled_from(["grid", "monte-carlo", "qmc", "grid,qmc", "exact", ",", ""]),
        "--grid-sizes": st.sampled_from(
            ["5,10", "10", "0", "-5", "99999999999", "a,b", "", "5,,6"]
        ),
        "--event-sizes": st.sampled_from(["100,1000", "100", "0", "1e30", "x", ""]),
        "--qmc-sizes": st.sampled_from(["64,128", "16", "100", "0", ""]),
        "--seed": _count(0, 2**32),
        "--json": st.just(None),
    },
    "sweep": {
        "--omega-x": _dist(0, 300),
        "--omega-x-mean": st.sampled_from(["60,80", "60:90:3", "0:1:0", "a", "", "1e308"]),
        "--omega-x-sd": st.sampled_from(["0,5", "1", "-1", "nan", ""]),
        "--omega-y": _dist(-50, 50),
        "--flight-time": _dist(0.2, 1.0),
        "--launch-speed": _dist(1, 5),
        "--coin": st.sampled_from(["us-quarter,eur-1", "us-cent", "peso", ",", ""]),
        "--start": st.sampled_from(["heads,tails", "tails", "edge", ""]),
        "--surface": st.sampled_from(["hand", "hand,table", "table", "sand", ""]),
        "--restitution": st.sampled_from(["0.3,0.6", "0.5", "2", "nan", ""]),
        "--rolling-resistance": st.sampled_from(["1e-5,1e-3", "1e-4", "-1", "0.02", ""]),
        "--corner-radius": st.sampled_from(["0,3e-4", "1e-4", "0.001", "-1", ""]),
        "--method": st.sampled_from(["monte-carlo", "qmc", "grid", "exact", ""]),
        "--n": _count(1, 500),
        "--seed": _count(0, 2**32),
        "--json": st.just(None),
    },
    "bias": {
        "--psi": _number(0, 180),
        "--psi-dist": _dist(0, 180),
        "--preset": st.sampled_from(["human", "robot", ""]),
        "--monte-carlo": _count(1, 2000),
        "--seed": _count(0, 2**32),
        **COIN,
        "--json": st.just(None),
    },
    "data": {
        "--dataset": st.sampled_from(["bartos2023", "bartos2024", ""]),
        "--counts": st.sampled_from(["/dev/zero", "/proc/version", "no/such/file.txt", "", "."]),
        "--interval": st.sampled_from(["exact", "wilson", "bayes", ""]),
        "--psi-sd": _number(0, 10),
        "--seed": _count(0, 2**32),
        "--folds": _count(-1, 60),
        "--repeats": _count(-1, 3),
        "--json": st.just(None),
    },
    "plot toss": {
        "--omega": _omega3(),
        **FLIGHT,
        "--times": st.sampled_from(["0.6,0.65", "0.7", "", "a", "-1,2", "1e308", "nan"]),
        **COIN,
        "--dpi": _count(20, 60),
    },
    "plot basin": {
        "--resolution": st.sampled_from(["20", "20x30", "0", "1e9", "x", "99999999999x2", ""]),
        "--flight-time": _dist(0.2, 1.0),
        "--omega-x": _dist(0, 300),
        "--omega-y": _number(-50, 50),
        "--omega-z": _number(-50, 50),
        "--psi": _number(0, 180),
        **COIN,
        **TABLE,
        "--bounces": _count(0, 3),
        "--dpi": _count(20, 60),
    },
    "plot bias": {
        "--monte-carlo": _count(1, 500),
        "--psi-points": st.sampled_from(["45,90", "60", "", "200", "nan", "a"]),
        "--measured": _number(0.4, 0.6),
        "--dpi": _count(20, 60),
    },
    "plot edge": {
        "--max-ratio": _number(0.6, 2),
        "--simulate": _count(1, 300),
        "--ratios": st.sampled_from(["0.1,0.3", "0.577", "", "0", "-1", "nan", "1e308"]),
        "--dpi": _count(20, 60),
    },
}
# Options whose value the command needs to run at all (a plausible one when none was drawn).
REQUIRED = {
    "toss": ["--flight-time", "0.7"],
    "plot toss": ["--flight-time", "0.7"],
    "sweep": ["--flight-time", "0.6:0.9"],
}
FIGURE_COMMANDS = {"plot toss", "plot basin", "plot bias", "plot edge"}


class _TooSlow(Exception):
    pass


class _OverBudget(BaseException):
    """A line whose work the library accepts but a test may not take. A BaseException, so
    that no handler of the library turns it into a refusal or an answer."""


@contextmanager
def _work_budget(seconds: float) -> Iterator[None]:
    """Every work bound of the package (``coinflight._validation.work_bound``, called before
    any work with the estimate and its rate) first refuses as the library does, then raises
    :class:`_OverBudget` for an estimate over ``seconds``: the generated lines respect a work
    budget computed from the package's own rates, whatever the command."""
    from coinflight import _validation

    original = _validation.work_bound

    def bounded(what, amount, limit, unit, way_on, rate=None):
        original(what, amount, limit, unit, way_on, rate)  # the library's refusal first
        if rate:
            estimate = float(amount) / rate
        elif unit.startswith("s of"):  # already seconds (sweeps, the server)
            estimate = float(amount)
        else:  # bytes, pieces without a rate: not time
            return
        if estimate > seconds:
            raise _OverBudget(f"{what}: about {estimate:.3g} s of work, over {seconds:g} s")

    _validation.work_bound = bounded
    try:
        yield
    finally:
        _validation.work_bound = original


def _run(args: list[str]):
    """The command line's result, or :class:`_OverBudget` before its work starts."""
    with _time_limit(SECONDS_PER_RUN), _work_budget(BUDGET_SECONDS):
        return runner.invoke(app, args)


@contextmanager
def _time_limit(seconds: int) -> Iterator[None]:
    def _raise(signum, frame):  # pragma: no cover - only on a hang
        raise _TooSlow(f"no answer within {seconds} s")

    previous = signal.signal(signal.SIGALRM, _raise)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def _command_line(draw, command: str, out: Path) -> list[str]:
    table = OPTIONS[command]
    names = draw(st.lists(st.sampled_from(sorted(table)), max_size=4, unique=True))
    if "--coin" in names and "--radius" in names:
        names.remove("--coin")
    args = command.split()
    for name in names:
        value = draw(table[name])
        args.append(name)
        if isinstance(value, list):
            args.extend(value)
        elif value is not None:
            args.append(value)
    if command in REQUIRED and not {"--flight-time", "--launch-speed", "--times"} & set(names):
        args += REQUIRED[command]
    if command == "sweep":
        if not {"--omega-x", "--omega-x-mean", "--omega-x-sd"} & set(names):
            args += ["--omega-x", "60:90"]
        path = draw(
            st.one_of(
                st.just(str(out / "sweep.csv")), st.sampled_from([*HOSTILE_PATHS, EXISTING_FOLDER])
            )
        )
        args += ["--out", path]
    if (
        command in FIGURE_COMMANDS
        or command == "convergence"
        or (command == "data" and draw(st.booleans()))
    ):
        flag = "--plot" if command == "data" else "--out"
        paths = [*HOSTILE_PATHS, EXISTING_FOLDER]
        path = draw(st.one_of(st.just(str(out / "figure.png")), st.sampled_from(paths)))
        args += [flag, path]
    return args


def _check(args: list[str]) -> None:
    start = time.perf_counter()
    try:
        result = _run(args)
        _judge(args, result)
        outcome = "ok" if result.exit_code == 0 else f"refused: {result.stderr.strip()[:200]}"
    except _OverBudget as exc:
        outcome = f"over the test's work budget: {exc}"
        reject()
    except (AssertionError, _TooSlow) as exc:
        outcome = f"FAILED: {str(exc).splitlines()[-1][:300]}"
        if not SURVEY:
            raise
    finally:
        if LOG:
            entry = {"args": args, "outcome": outcome, "s": time.perf_counter() - start}
            with open(LOG, "a", encoding="utf-8") as log:
                log.write(json.dumps(entry, ensure_ascii=False) + "\n")


def _judge(args: list[str], result) -> None:
    stderr = result.stderr
    context = f"coinflight {' '.join(repr(a) for a in args)}\nstderr: {stderr[-2000:]}"
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise AssertionError(f"{context}\nraised {result.exception!r}") from result.exception
    assert result.exit_code in (0, 2), context
    assert "Traceback" not in stderr and "Traceback" not in result.stdout, context
    # pydantic's words (typer reads options through it) never reach the user.
    assert "Input should be" not in stderr, context
    # Nothing the user typed is silently dropped or altered: an empty value is not "the option
    # left out", an absurd thread count is not a thread pool, an existing folder is not
    # FOLDER.png beside it.
    values = dict(itertools.pairwise(args))
    if any(not a.strip() for a in args):
        assert result.exit_code == 2, f"{context}\nan empty value was accepted"
    if values.get("--threads") in ABSURD_COUNTS:
        assert result.exit_code == 2, f"{context}\nan absurd --threads was accepted"
    if args[:1] != ["convergence"] and any(values.get(f) == EXISTING_FOLDER for f in FILE_OPTIONS):
        assert result.exit_code == 2, f"{context}\nan existing folder taken as an output file"
        assert not Path(EXISTING_FOLDER + ".png").exists(), context
    if result.exit_code == 2:
        lines = [line for line in stderr.splitlines() if line.strip()]
        assert len(lines) == 1 and lines[0].startswith("coinflight: error: "), context
        return
    # A success may print warnings, but only a few lines of them.
    assert len(stderr.splitlines()) <= 4, context
    if "--json" in args:
        payload = json.loads(result.stdout)
        for key, value in _numbers(payload):
            if key.startswith("p_") or key in {"p", "probability", "same_side"}:
                assert 0.0 <= value <= 1.0, f"{context}\n{key} = {value}"
            assert math.isfinite(value) or value is None, f"{context}\n{key} = {value}"


def _numbers(payload, key: str = "") -> Iterator[tuple[str, float]]:
    if isinstance(payload, dict):
        for k, v in payload.items():
            yield from _numbers(v, str(k))
    elif isinstance(payload, list):
        for v in payload:
            yield from _numbers(v, key)
    elif isinstance(payload, float):
        yield key, payload


def test_a_line_over_the_work_budget_is_stopped_before_its_work(tmp_path):
    # A line the sweep's own bound accepts (20,000 landings carried to rest a row, ~290 s at
    # the rigid ending's rate, under the hour); the test's budget stops it at the first
    # estimate over budget, the row's, before any row runs (what would run it fails the test
    # if called; not timed: the machine is shared).
    line = ["sweep", "--surface", "hand,table", "--restitution", "0.3,0.6", "--method",
            "monte-carlo", "--omega-x", "60:90", "--flight-time", "0.6:0.9"]  # fmt: skip
    from coinflight.outcomes.table import RIGID_TOSSES_PER_SECOND

    seconds = f"{20000 / RIGID_TOSSES_PER_SECOND:.3g}"  # the row's estimate, at the rate
    said = rf"^monte-carlo with n = 20000: about {re.escape(seconds)} s of work, over 20 s$"
    with pytest.MonkeyPatch.context() as patch:
        never_run(patch, command_work())
        with pytest.raises(_OverBudget, match=said):
            _run([*line, "--n", "20000", "--out", str(tmp_path / "s.csv")])
    assert not (tmp_path / "s.csv").exists()
    # Within the budget the same line runs (a small n), and beyond the library's own limit it
    # is still the library's one-line refusal (exit 2), not a budget stop.
    assert _run([*line, "--n", "5", "--out", str(tmp_path / "t.csv")]).exit_code == 0
    huge = _run([*line, "--n", "99999999999", "--out", str(tmp_path / "u.csv")])
    assert huge.exit_code == 2 and "more than the limit" in huge.stderr


@pytest.mark.slow
@pytest.mark.parametrize("command", sorted(OPTIONS))
def test_generated_command_lines_end_as_promised(command, tmp_path, monkeypatch):
    out = tmp_path
    monkeypatch.chdir(tmp_path)  # nothing a command writes by default lands in the repository
    (tmp_path / EXISTING_FOLDER).mkdir()

    @settings(
        max_examples=EXAMPLES,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    )
    @given(st.data())
    def run(data):
        _check(_command_line(data.draw, command, out))

    run()

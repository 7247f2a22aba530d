"""``coinflight probability`` and ``coinflight convergence`` through typer's CliRunner."""

from __future__ import annotations

import csv
import json
import re

import pytest
from typer.testing import CliRunner

from coinflight._compiling import notice
from coinflight.cli import app
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import estimate

runner = CliRunner()
FIG2A = ["--omega-x", "60:90", "--flight-time", "0.6:0.9"]  # Stefan & Cheche Fig 2a
TABLE_AIR = ["--surface", "table", "--drag", "1.17", "--restitution", "0"]  # dead: no ending
TABLE = ["--surface", "table"]  # landings carried to rest through the rigid ending
THREE_SPINS = ["--omega-x", "60:90", "--omega-y", "0:20", "--omega-z", "0:5"]


def run(*args: str):
    return runner.invoke(app, list(args))


def test_exact_json_matches_library():
    result = run("probability", *FIG2A, "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    expected = estimate(TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9)))
    assert payload["p_heads"] == pytest.approx(expected.p_heads, abs=1e-15)
    assert payload["p_tails"] == pytest.approx(1 - expected.p_heads, abs=1e-15)
    assert payload["method"] == "exact" and payload["n"] is None
    assert payload["distribution"]["omega_x"] == {"kind": "uniform", "low": 60.0, "high": 90.0}
    assert payload["distribution"]["omega_y"] == {"kind": "fixed", "value": 0.0}
    assert {"stderr", "ci95"} <= set(payload)


def test_json_names_the_coin_and_gives_its_dimensions():
    """``coin`` stays the name (scripts read it); ``coin_dimensions`` adds the size and mass in SI
    (US Mint: the cent 19.05 mm across, 1.52 mm thick, 2.5 g), the numbers of the first line."""
    result = run("probability", *FIG2A, "--coin", "us-cent", "--json")
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["coin"] == "US cent"
    size = payload["coin_dimensions"]
    assert set(size) == {"radius", "thickness", "mass"}
    assert size["radius"] == pytest.approx(19.05e-3 / 2, rel=1e-12)
    assert size["thickness"] == pytest.approx(1.52e-3, rel=1e-12)
    assert size["mass"] == pytest.approx(2.5e-3, rel=1e-12)
    text = run("probability", *FIG2A, "--coin", "us-cent").stdout.splitlines()[0]
    assert text == "US cent (d = 19.05 mm, h = 1.52 mm, m = 2.500 g), started heads up"


@pytest.mark.parametrize(
    ("method", "n", "extra"),
    [
        ("grid", "500", []),
        ("monte-carlo", "200000", ["--seed", "7"]),
        ("monte-carlo", "200000", ["--seed", "7", "--grid-cells", "100"]),
        ("qmc", "16384", ["--seed", "7"]),
    ],
)
def test_methods_json(method, n, extra):
    result = run("probability", *FIG2A, "--method", method, "--n", n, *extra, "--json")
    assert result.exit_code == 0, result.stderr
    p = json.loads(result.stdout)
    assert p["method"] == method and p["n"] == int(n)
    assert p["p_heads"] + p["p_tails"] == pytest.approx(1.0)
    if method == "grid":
        assert p["samples"] == int(n) ** 2 and p["stderr"] is None
    else:
        assert p["stderr"] > 0 and p["ci95"][0] < p["p_heads"] < p["ci95"][1]
        assert p["seed"] == 7
        # Within 4 standard errors of the exact value (or method B's 100-cell grid).
        target = 0.497470690 if "--grid-cells" not in extra else _coarse()
        assert abs(p["p_heads"] - target) < 4 * p["stderr"]
    # no progress bar when stderr is not a terminal (a first compilation's notice aside)
    assert result.stderr.replace(notice("coinflight.core.sampling") + "\n", "") == ""


def _coarse() -> float:
    return estimate(
        TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9)), "grid", n=100
    ).p_heads


def test_same_seed_same_answer_any_threads():
    a = run("probability", *FIG2A, "-m", "monte-carlo", "-n", "100000", "--seed", "3", "--json")
    b = run(
        "probability",
        *FIG2A,
        "-m",
        "monte-carlo",
        "-n",
        "100000",
        "--seed",
        "3",
        "--threads",
        "1",
        "--json",
    )
    assert json.loads(a.stdout)["counts"] == json.loads(b.stdout)["counts"]


def test_plain_output_readable():
    result = run("probability", *FIG2A, "-m", "monte-carlo", "-n", "100000", "--seed", "1")
    assert result.exit_code == 0
    out = result.stdout
    assert "P(heads) = 0.49" in out and "95 % CI" in out
    assert re.search(r"± 0\.0016 s\.e\. \(95 % CI", out)  # sqrt(p(1 − p)/1e5) = 0.00158
    assert "seed 1" in out and "100,000 tosses" in out
    exact = run("probability", *FIG2A)
    assert "P(heads) = 0.497471 (closed form)" in exact.stdout
    quad = ["--omega-x", "60:90", "--omega-y", "0:20", "--flight-time", "0.7"]
    text = run("probability", *quad).stdout
    assert "(quadrature error bound)" in text and "CI" not in text and "s.e." not in text
    payload = json.loads(run("probability", *quad, "--json").stdout)
    assert payload["ci95"] is None and 0 < payload["error_estimate"] < 1e-9


def test_short_flight_time_option(tmp_path):
    # -T is --flight-time, as in coinflight toss.
    short = run("probability", "--omega-x", "60:90", "-T", "0.6:0.9", "--json")
    assert json.loads(short.stdout)["p_heads"] == pytest.approx(0.497470690, abs=1e-8)
    conv = run(
        "convergence", "--omega-x", "60:90", "-T", "0.6:0.9", "--methods", "grid",
        "--grid-sizes", "10", "--out", str(tmp_path / "c"), "--json",
    )  # fmt: skip
    assert conv.exit_code == 0, conv.stderr
    assert json.loads(conv.stdout)["exact"] == pytest.approx(0.497470690, abs=1e-8)


def test_launch_speed_and_normal():
    # T = 2 v0 / g (eq 11): launch speed 2.943:4.4145 m/s with g = 9.81 is T = 0.6:0.9 s.
    a = json.loads(
        run("probability", "--omega-x", "60:90", "--launch-speed", "2.943:4.4145", "--json").stdout
    )
    assert a["p_heads"] == pytest.approx(0.497470690, abs=1e-8)
    # What the user asked for is in the output: the launch speed and g.
    assert a["g"] == 9.81 and a["inputs"]["--launch-speed"] == "2.943:4.4145"
    assert a["inputs"]["--flight-time"] is None and a["inputs"]["--omega-x"] == "60:90"
    plain = run("probability", "--omega-x", "60:90", "--launch-speed", "3:4", "--g", "9.7")
    assert "g = 9.7 m/s²; launch speed v0 = 3–4 m/s (T = 2 v0 / g)" in plain.stdout
    assert "g = 9.81 m/s²\n" in run("probability", *FIG2A).stdout
    b = run("probability", "--omega-x", "normal:75,5", "--flight-time", "0.6:0.9", "--json")
    assert b.exit_code == 0 and 0.45 < json.loads(b.stdout)["p_heads"] < 0.55


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--omega-x", "90:60", "--flight-time", "0.6:0.9"], "reversed"),
        (["--omega-x", "60:60", "--flight-time", "0.6:0.9"], "empty"),
        (["--omega-x", "60:90", "--flight-time", "0.9:0.6"], "--flight-time"),
        (["--omega-x", "normal:75,0", "--flight-time", "0.7"], "standard deviation"),
        ([*FIG2A, "--method", "magic"], "unknown method 'magic'"),
        ([*FIG2A, "--method", "grid", "--n", "0"], "n must be at least 1"),
        ([*FIG2A, "--method", "monte-carlo", "--n", "-3"], "n must be at least 1"),
        ([*FIG2A, "--method", "qmc", "--n", "1000"], "power of two"),
        ([*FIG2A, "--grid-cells", "100"], "--grid-cells applies to --method monte-carlo"),
        # exact integrates every distribution the options take (issue 12), within its budget
        (
            [
                "--omega-x",
                "0:1e5",
                "--omega-y",
                "0:1e5",
                "--omega-z",
                "0:1e5",
                "--flight-time",
                "0.5:1",
            ],
            "use --method grid, monte-carlo or qmc instead",
        ),
        (["--omega-x", "60:90"], "exactly one of --flight-time and --launch-speed"),
        ([*FIG2A, "--launch-speed", "3"], "exactly one of"),
        ([*FIG2A, "--n", "abc"], "--n"),
        # A dead table landing through air (~10,000 tosses/s, AIR_LANDINGS_PER_SECOND) would
        # run the default sizes for minutes: --n must be given (the hand catch through air runs
        # them in about a minute); the sizes suggested run for about a minute at that rate
        # (774² ≤ 6e5 < 775²).
        ([*FIG2A, *TABLE_AIR, "-m", "monte-carlo"], "give --n explicitly, e.g. --n 100000"),
        ([*FIG2A, *TABLE_AIR, "-m", "grid"], "--n 774 (774^2 = 599,076 tosses"),
        ([*FIG2A, *TABLE_AIR, "-m", "qmc"], "about 10,000 tosses per second"),
        # Landings carried to rest (RIGID_TOSSES_PER_SECOND, 70/s), drag-free or through air:
        # the same, at that rate (64² ≤ 4,200 < 65², 2^12 ≤ 4,200 < 2^13).
        ([*FIG2A, *TABLE, "-m", "monte-carlo"], "rigid 3-D ending (about 70 tosses per second)"),
        ([*FIG2A, *TABLE, "-m", "grid"], "--n 64 (64^2 = 4,096 tosses"),
        ([*FIG2A, *TABLE, "--drag", "1.17", "-m", "qmc"], "e.g. --n 4096 (about a minute)"),
        (
            ["--omega-x", "60:90", "--launch-speed", "normal:0.1,1"],
            "--launch-speed normal(0.1, sd 1) m/s reaches speeds ≤ 0 m/s",
        ),
        (
            [*THREE_SPINS, "--flight-time", "0.7", "--method", "grid", "--n", "1000"],
            "1,000,000,000 configurations, each evaluated one by one",
        ),
    ],
)
def test_bad_input_is_one_line_exit_2(args, words):
    result = run("probability", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("coinflight: error:")
    assert words in lines[0]


def test_convergence_writes_all_outputs(tmp_path):
    prefix = tmp_path / "fig2a"
    result = run(
        "convergence",
        *FIG2A,
        "--methods",
        "grid,monte-carlo,qmc",
        "--grid-sizes",
        "10,100,1000",
        "--event-sizes",
        "1000,100000",
        "--qmc-sizes",
        "256,4096",
        "--seed",
        "4",
        "--out",
        str(prefix),
        "--json",
    )
    assert result.exit_code == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["exact"] == pytest.approx(0.497470690, abs=1e-8)
    for suffix in (".csv", ".json", ".png", ".svg"):
        assert (tmp_path / f"fig2a{suffix}").stat().st_size > 0
    with (tmp_path / "fig2a.csv").open() as fh:
        rows = list(csv.DictReader(fh))
    assert [r["method"] for r in rows] == ["grid"] * 3 + ["monte-carlo"] * 2 + ["qmc"] * 2
    assert [int(r["samples"]) for r in rows[:3]] == [100, 10_000, 1_000_000]
    # Method A converges: the finest grid is closest to the exact value.
    errs = [abs(float(r["p_heads"]) - payload["exact"]) for r in rows[:3]]
    assert errs[2] == min(errs) and errs[2] < 1e-4
    saved = json.loads((tmp_path / "fig2a.json").read_text())
    assert saved["points"] == payload["points"] and saved["seed"] == 4
    assert (tmp_path / "fig2a.png").read_bytes()[:4] == b"\x89PNG"


def test_convergence_into_directory_and_errors(tmp_path):
    result = run(
        "convergence",
        *FIG2A,
        "--methods",
        "grid",
        "--grid-sizes",
        "10,20",
        "--out",
        str(tmp_path),
    )
    assert result.exit_code == 0, result.stderr
    assert (tmp_path / "convergence.csv").exists() and (tmp_path / "convergence.svg").exists()
    assert "exact P(heads) = 0.497471" in result.stdout
    assert "seed" not in result.stdout  # no random method ran: no seed to report
    grid_only = ["--methods", "grid", "--grid-sizes", "10"]
    payload = json.loads(
        run("convergence", *FIG2A, *grid_only, "-o", str(tmp_path), "--json").stdout
    )
    assert payload["seed"] is None
    for extra, words in (
        (["--event-sizes", "100"], "--event-sizes applies to --methods monte-carlo"),
        (["--qmc-sizes", "64"], "--qmc-sizes applies to --methods qmc"),
        (["--seed", "3"], "--seed applies to monte-carlo and qmc"),
        (["--grid-cells", "50"], "--grid-cells applies to --methods monte-carlo"),
    ):
        bad = run("convergence", *FIG2A, *grid_only, *extra, "--out", str(tmp_path / "z"))
        assert bad.exit_code == 2 and words in bad.stderr, bad.stderr
    bad = run("convergence", *FIG2A, "--methods", "qmc", "--grid-sizes", "5", "-o", str(tmp_path))
    assert bad.exit_code == 2 and "--grid-sizes applies to --methods grid" in bad.stderr
    bad = run("convergence", *FIG2A, "--methods", "grid,exact", "--out", str(tmp_path / "x"))
    assert bad.exit_code == 2 and "unknown method 'exact'" in bad.stderr
    bad = run("convergence", *FIG2A, "--grid-sizes", "10,x", "--out", str(tmp_path / "y"))
    assert bad.exit_code == 2 and "--grid-sizes" in bad.stderr
    assert not list(tmp_path.glob("x*")) and not list(tmp_path.glob("y*"))
    assert not list(tmp_path.glob("z*"))


def test_convergence_library_refuses_ignored_options():
    from coinflight.probability.convergence import convergence

    dist = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))
    with pytest.raises(TypeError, match="event_sizes given but 'monte-carlo'"):
        convergence(dist, ["grid"], grid_sizes=[5], event_sizes=[100])
    with pytest.raises(TypeError, match="seed given but no random method"):
        convergence(dist, ["grid"], grid_sizes=[5], seed=1)
    assert convergence(dist, ["grid"], grid_sizes=[5]).seed is None
    assert convergence(dist, ["qmc"], qmc_sizes=[64], seed=9).seed == 9


def test_progress_bar_only_on_a_terminal(monkeypatch):
    from coinflight.cli import progress

    monkeypatch.setattr(progress, "DELAY", 0.0)
    with progress.progress_bar(10, "x", quiet=True) as bar:
        assert bar is None

    class Tty:
        def isatty(self):
            return True

        def write(self, s):
            return len(s)

        def flush(self):
            pass

    monkeypatch.setattr(progress.sys, "stderr", Tty())
    with progress.progress_bar(10, "x", quiet=False) as bar:
        assert bar is not None
        bar(4)
        bar(6)
        assert bar.done == 10


def test_unsettled_tosses_are_a_warning():
    from coinflight.probability import ProbabilityResult
    from coinflight.queries.probability import result_warnings as _warnings

    counts = (40, 60, 0)
    details = {"unsettled": 25, "unsettled_fraction": 0.25}
    result = ProbabilityResult(0.6, 0.4, 0.0, 0.6, "monte-carlo", counts=counts, details=details)
    (line,) = _warnings(result)
    assert line.startswith("25 of 100 tosses (25 %) never settled")
    assert _warnings(estimate(TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9)))) == []
    payload = json.loads(run("probability", *FIG2A, "--json").stdout)
    assert payload["warnings"] == []


def test_convergence_refuses_an_over_large_grid_before_starting():
    from coinflight.probability.convergence import convergence

    three = TossDistribution(Uniform(60, 90), Uniform(0, 20), Uniform(0, 5), 0.7)
    done: list[int] = []
    with pytest.raises(ValueError, match=r"1000\^3 = 1,000,000,000 configurations"):
        convergence(three, ["grid"], grid_sizes=[5, 10, 1000], progress=done.append)
    assert done == []  # nothing computed before the refusal

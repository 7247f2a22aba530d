"""The public Python API: what ``import coinflight`` offers, and how its pieces compose.

Reference values: P(heads) = 0.497471 for Stefan & Cheche's Fig 2a ranges (ωx 60-90 rad/s,
T 0.6-0.9 s) and 0.497212 for Fig 3a (ωy = 10 rad/s), by the exact method, as in
tests/test_cli_probability.py and the README.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

import coinflight
from coinflight import (
    Coin,
    Fixed,
    Normal,
    ProbabilityResult,
    ProbabilityResults,
    TossDistribution,
    Uniform,
    estimate,
    estimate_many,
)
from coinflight.core import ballistics

ROOT = Path(__file__).resolve().parents[1]
FIG_2A = {"omega_x": Uniform(60, 90), "flight_time": Uniform(0.6, 0.9)}
FIG_3A = {**FIG_2A, "omega_y": 10}


# --- the top level ------------------------------------------------------------------------


def test_top_level_exports_the_nouns_and_verbs():
    needed = {
        "Coin", "Toss", "Flight", "Outcome", "TossDistribution", "Fixed", "Uniform", "Normal",
        "estimate", "estimate_many", "ProbabilityResult", "convergence",
        "same_side_probability", "Surface", "Landing", "plot_toss", "plot_basin", "plot_bias",
        "plot_edge", "plot_convergence", "plot_forest",
    }  # fmt: skip
    assert needed <= set(coinflight.__all__)
    for name in coinflight.__all__:
        assert getattr(coinflight, name) is not None, name
    assert set(coinflight.__all__) <= set(dir(coinflight))


def test_the_api_page_lists_the_top_level_names():
    """docs/api.rst says everything a user needs is importable from ``coinflight`` and lists
    it, each name at the module that defines it: the list is ``coinflight.__all__``."""
    import importlib

    text = (ROOT / "docs" / "api.rst").read_text(encoding="utf-8")
    after = text.split("\nThe package\n", 1)[1].split(".. autosummary::", 1)[1]
    listed = {}
    for line in after.splitlines()[1:]:
        if line.strip() and not line.startswith("   "):
            break
        if line.strip():
            module, _, name = line.strip().rpartition(".")
            listed[name] = getattr(importlib.import_module(module), name)
    assert set(listed) == set(coinflight.__all__) - {"__version__"}
    for name, value in listed.items():
        assert getattr(coinflight, name) is value, name


def test_top_level_names_are_the_library_objects():
    from coinflight.plotting.bias import plot_bias
    from coinflight.probability.convergence import convergence
    from coinflight.studies.bias import same_side_probability

    assert coinflight.same_side_probability is same_side_probability
    assert coinflight.plot_bias is plot_bias
    assert coinflight.convergence is convergence


def test_unknown_top_level_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'bias_figure'"):
        coinflight.bias_figure  # noqa: B018


@pytest.mark.parametrize(
    ("module", "old"),
    [
        ("bias", "bias_figure"),
        ("edge", "edge_figure"),
        ("convergence", "convergence_figure"),
        ("forest", "forest_figure"),
    ],
)
def test_figure_functions_are_named_one_way(module, old):
    import importlib

    mod = importlib.import_module(f"coinflight.plotting.{module}")
    assert not hasattr(mod, old)
    assert callable(getattr(mod, f"plot_{module}"))


def test_import_coinflight_stays_light():
    # The heavy libraries load when used, not on import (nor for coinflight --help).
    code = (
        "import sys, coinflight\n"
        "print(sorted(m for m in ('scipy', 'numba', 'matplotlib', 'pandas') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# --- TossDistribution ---------------------------------------------------------------------


def test_spins_default_to_zero_as_on_the_command_line():
    explicit = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))
    assert TossDistribution(**FIG_2A) == explicit
    assert TossDistribution(**FIG_2A).omega_y == Fixed(0.0) == explicit.omega_z
    assert round(estimate(TossDistribution(**FIG_2A)).p_heads, 6) == 0.497471


def test_launch_speed_gives_the_flight_time_of_eq_11():
    speed = Normal(2.4, 0.24)
    d = TossDistribution(omega_x=80.0, launch_speed=speed, g=9.7)
    # T = 2 v0 / g: the mean and sd of T are those of v0 times T(1 m/s).
    factor = float(ballistics.flight_time(1.0, 9.7))
    assert d.flight_time == Normal(2.4 * factor, 0.24 * factor)
    assert d.launch_speed == speed
    assert d == TossDistribution.from_launch_speed(80.0, 0, 0, speed, g=9.7)
    assert d == TossDistribution(omega_x=80.0, flight_time=d.flight_time, g=9.7)


def test_launch_speed_number_becomes_fixed():
    d = TossDistribution(omega_x=80.0, launch_speed=3.4335)
    assert d.launch_speed == Fixed(3.4335)
    assert d.flight_time.mean == pytest.approx(0.7, rel=1e-12)


def test_exactly_one_of_flight_time_and_launch_speed():
    with pytest.raises(TypeError, match="give one of flight_time"):
        TossDistribution(omega_x=80.0)
    with pytest.raises(TypeError, match="exactly one of flight_time and launch_speed"):
        TossDistribution(omega_x=80.0, flight_time=0.7, launch_speed=3.0)


def test_replace_keeps_a_launch_speed_distribution_consistent():
    d = TossDistribution(omega_x=80.0, launch_speed=Uniform(2.0, 3.0))
    other = dataclasses.replace(d, coin=Coin.preset("eur-1"))
    assert other.flight_time == d.flight_time and other.coin.name != d.coin.name
    with pytest.raises(TypeError, match="set the other one to None"):
        dataclasses.replace(d, flight_time=0.5)
    assert dataclasses.replace(d, flight_time=0.5, launch_speed=None).flight_time == Fixed(0.5)


@pytest.mark.parametrize(
    ("speed", "error", "words"),
    [
        (Uniform(-1.0, 3.0), ValueError, "launch speed -1–3 m/s reaches speeds ≤ 0 m/s"),
        ("fast", TypeError, "launch_speed: expected a number or a Distribution"),
    ],
)
def test_bad_launch_speed_is_named(speed, error, words):
    with pytest.raises(error, match=re.escape(words)):
        TossDistribution(omega_x=80.0, launch_speed=speed)


# --- results as dicts and tables -----------------------------------------------------------


def test_to_row_flattens_the_dict():
    r = estimate(TossDistribution(**FIG_2A), "monte-carlo", n=20_000, seed=7)
    row = r.to_row()
    assert (row["ci95_low"], row["ci95_high"]) == r.ci95
    assert (row["tails"], row["heads"], row["edge"]) == r.counts
    assert row["details.rng"] == r.details["rng"] == "SFC64"
    assert row["seed"] == 7 and row["p_heads"] == r.p_heads
    assert "ci95" not in row and "counts" not in row


def test_to_frame_without_pandas_says_how_to_install_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now fails
    r = estimate(TossDistribution(**FIG_2A))
    with pytest.raises(ImportError, match="pip install pandas"):
        r.to_frame()
    with pytest.raises(ImportError, match="pip install pandas"):
        estimate_many([TossDistribution(**FIG_2A)]).to_frame()


def test_to_frame_is_one_row_of_to_row():
    pytest.importorskip("pandas")
    r = estimate(TossDistribution(**FIG_3A))
    frame = r.to_frame()
    assert frame.shape[0] == 1
    assert list(frame.columns) == list(r.to_row())
    assert round(frame.loc[0, "p_heads"], 6) == 0.497212


# --- a sweep in one call ------------------------------------------------------------------


def test_estimate_many_equals_one_estimate_each():
    dists = [TossDistribution(**FIG_2A), TossDistribution(**FIG_3A)]
    results = estimate_many(dists, "exact")
    assert isinstance(results, ProbabilityResults) and isinstance(results, list)
    assert all(isinstance(r, ProbabilityResult) for r in results)
    assert [round(r.p_heads, 6) for r in results] == [0.497471, 0.497212]
    assert results.distributions == tuple(dists)


def test_estimate_many_passes_options_and_the_seed_to_each():
    dists = [TossDistribution(**FIG_2A), TossDistribution(**FIG_3A)]
    results = estimate_many(dists, "monte-carlo", n=10_000, seed=3, grid_cells=100)
    for d, r in zip(dists, results, strict=True):
        alone = estimate(d, "monte-carlo", n=10_000, seed=3, grid_cells=100)
        assert (r.counts, r.seed, r.details["grid_cells"]) == (alone.counts, 3, 100)


def test_estimate_many_checks_every_entry_before_any_work(monkeypatch):
    import coinflight.probability as prob

    calls = []
    monkeypatch.setattr(prob, "estimate", lambda *a, **k: calls.append(a))
    with pytest.raises(TypeError, match=r"dists\[1\] must be a TossDistribution, got 'x'"):
        estimate_many([TossDistribution(**FIG_2A), "x"])
    assert calls == []
    with pytest.raises(TypeError, match="for one, use estimate"):
        estimate_many(TossDistribution(**FIG_2A))


def test_estimate_many_errors_as_estimate():
    with pytest.raises(ValueError, match="unknown method 'fast'"):
        estimate_many([TossDistribution(**FIG_2A)], "fast")
    assert estimate_many([], "exact") == []


def test_sweep_table_names_each_distribution():
    pd = pytest.importorskip("pandas")
    launch = TossDistribution(omega_x=Uniform(60, 90), launch_speed=Uniform(3.0, 4.0))
    results = estimate_many([TossDistribution(**FIG_3A), launch], "exact")
    frame = results.to_frame()
    assert frame.shape[0] == 2
    assert list(frame["omega_y"]) == ["10 rad/s", "0 rad/s"]
    assert list(frame["omega_x"]) == ["60–90 rad/s"] * 2
    assert pd.isna(frame.loc[0, "launch_speed"]) and frame.loc[1, "launch_speed"] == "3–4 m/s"
    assert list(frame["p_heads"]) == [r.p_heads for r in results]
    assert results.to_dicts()[0]["coin"] == "US quarter"


def test_to_frame_has_each_parameter_as_numbers_beside_its_text():
    """low, high, mean, sd of each parameter as numbers one can plot: a uniform's sd is
    (high − low)/√12 (its variance (b − a)²/12), a normal's its sd over (−inf, inf), a single
    value's 0; a launch speed not given is empty (NaN)."""
    pytest.importorskip("pandas")
    dists = [
        TossDistribution(omega_x=Uniform(60, 90), omega_y=Normal(10, 2), flight_time=0.7),
        TossDistribution(omega_x=70, launch_speed=Uniform(2.0, 2.8)),
    ]
    frame = estimate_many(dists, "exact").to_frame()
    first, second = frame.iloc[0], frame.iloc[1]
    assert first["omega_x"] == "60–90 rad/s"
    assert (first["omega_x.low"], first["omega_x.high"], first["omega_x.mean"]) == (60, 90, 75)
    assert first["omega_x.sd"] == pytest.approx(30 / math.sqrt(12), rel=1e-15)
    assert (first["omega_y.low"], first["omega_y.high"]) == (-math.inf, math.inf)
    assert (first["omega_y.mean"], first["omega_y.sd"]) == (10, 2)
    assert (first["flight_time.low"], first["flight_time.high"]) == (0.7, 0.7)
    assert (first["flight_time.mean"], first["flight_time.sd"]) == (0.7, 0)
    assert math.isnan(first["launch_speed.mean"])
    assert (second["launch_speed.low"], second["launch_speed.high"]) == (2.0, 2.8)
    assert second["omega_x.sd"] == 0 and second["omega_x.mean"] == 70
    for column in ("omega_x.low", "omega_x.high", "omega_x.mean", "omega_x.sd"):
        assert frame[column].dtype.kind == "f", column  # numbers, not text


# --- the README's Python runs ---------------------------------------------------------------


def _python_blocks() -> list[str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    return re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)


def test_readme_has_python_examples():
    assert len(_python_blocks()) >= 3


@pytest.mark.parametrize("index", range(len(_python_blocks())))
def test_readme_python_block_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # anything a snippet writes stays out of the repository
    exec(compile(_python_blocks()[index], f"README.md python block {index}", "exec"), {})


def _guide_blocks() -> list[str]:
    """The Python code blocks of docs/guide.rst (``.. code-block:: python``), dedented."""
    import textwrap

    text = (ROOT / "docs" / "guide.rst").read_text(encoding="utf-8")
    blocks = re.findall(r"\.\. code-block:: python\n\n((?:(?:   .*)?\n)+)", text)
    return [textwrap.dedent(b) for b in blocks]


def test_readme_and_guide_python_results_are_what_the_lines_print(tmp_path, monkeypatch):
    """A line ``EXPR  # 'TEXT'`` of a README or guide block says EXPR gives the string TEXT:
    checked after the block runs (the claims are what the code prints, e.g. describe()'s
    '± 5e-14', once '± 1e-06')."""
    monkeypatch.chdir(tmp_path)  # anything a block writes stays out of the repository
    claims = []
    for block in [*_python_blocks(), *_guide_blocks()]:
        namespace: dict = {}
        exec(compile(block, "README.md or docs/guide.rst python block", "exec"), namespace)
        for line in block.splitlines():
            found = re.fullmatch(r"(?P<expr>\S.*?)\s{2,}# (?P<text>'.*')", line)
            if found:
                claims.append(found["expr"])
                assert eval(found["expr"], namespace) == eval(found["text"]), line
    assert any("face_name" in c for c in claims) and any("describe()" in c for c in claims)


# --- a citable, installable package ---------------------------------------------------------


def test_package_ships_its_type_hints():
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    assert "py.typed" in pyproject["tool"]["setuptools"]["package-data"]["coinflight"]
    assert (Path(coinflight.__file__).parent / "py.typed").is_file()


def test_citation_and_license_match_the_package():
    cff = (ROOT / "CITATION.cff").read_text(encoding="utf-8")
    assert re.search(r"^cff-version: 1\.2\.0$", cff, flags=re.MULTILINE)
    assert re.search(rf"^version: {re.escape(coinflight.__version__)}$", cff, flags=re.MULTILINE)
    assert "doi: 10.1137/S0036144504446436" in cff  # Diaconis, Holmes & Montgomery 2007
    license_text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert license_text.startswith("MIT License") and "coinflight developers" in license_text
    changelog = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert f"## [{coinflight.__version__}]" in changelog


# --- shell completion -----------------------------------------------------------------------


def _run(args: list[str], **env: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "coinflight", *args],
        capture_output=True,
        text=True,
        env={**os.environ, **env},
        check=False,
    )


@pytest.mark.parametrize(
    ("shell", "marker"),
    [("bash", "complete -o default -F _coinflight_completion coinflight"), ("zsh", "#compdef")],
)
def test_show_completion_prints_a_script(shell, marker):
    # typer detects the shell by default; this switch makes it take the shell named here.
    out = _run(["--show-completion", shell], _TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION="1")
    assert out.returncode == 0, out.stderr
    assert marker in out.stdout


def test_completion_completes_commands_and_options():
    out = _run(
        [], _COINFLIGHT_COMPLETE="complete_bash", COMP_WORDS="coinflight pro", COMP_CWORD="1"
    )
    assert out.stdout.split() == ["probability"]
    words = "coinflight toss --flight"
    out = _run([], _COINFLIGHT_COMPLETE="complete_bash", COMP_WORDS=words, COMP_CWORD="2")
    assert out.stdout.split() == ["--flight-time"]

"""The walkthrough "adding an estimator", followed: a toy antithetic Monte Carlo, written as its
own module would be and registered with one call, runs through estimate, convergence, the
command line and the figures without any other file changing."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import estimate, registry, streams
from coinflight.probability.convergence import convergence
from coinflight.probability.result import ProbabilityResult, from_counts, wilson_interval

FIG2A = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))  # Stefan & Cheche Fig 2a
EXACT_2A = 0.497471  # coinflight's exact method (the module docstring of coinflight.probability)


# --- what the new module would hold -----------------------------------------------------------
def antithetic(
    dist: TossDistribution, n: int, *, seed=None, model: OutcomeModel = HAND_CATCH
) -> ProbabilityResult:
    """n/2 random points u and their mirrors 1 − u (antithetic variates)."""
    root = streams.seed_sequence(seed)
    counts = np.zeros(3 + len(model.tallies), dtype=np.int64)
    for u in streams.unit_cube(root, n // 2, len(dist.ranged)):
        counts += model.count(dist, np.ascontiguousarray(u))
        counts += model.count(dist, np.ascontiguousarray(1.0 - u))
    heads, total = int(counts[1]), 2 * (n // 2)
    p = heads / total
    return from_counts(
        (int(counts[0]), heads, int(counts[2])),
        dist.start_sign,
        "antithetic",
        n=total,
        samples=total,
        stderr=math.sqrt(p * (1 - p) / total),  # as if independent: a toy
        ci95=wilson_interval(heads, total),
        seed=streams.reported_seed(root),
    )


ESTIMATOR = registry.Estimator(
    name="antithetic",
    run=antithetic,
    label="antithetic Monte Carlo (x = tosses)",
    description="N/2 random tosses and their mirror images",
    default_n=lambda k: 10**5,
    size="tosses, even (default 100000)",
    seeded=True,
    parallel=False,
    work=lambda dist, n, model: n / model.rate,
    series=(1000, 10_000),
)
# --- and the one registration line ------------------------------------------------------------


@pytest.fixture
def registered():
    registry.register(ESTIMATOR)
    yield ESTIMATOR
    registry.unregister("antithetic")


def test_estimate_runs_the_new_method(registered):
    r = estimate(FIG2A, "antithetic", n=20_000, seed=7)
    assert r.method == "antithetic" and r.n == 20_000 and r.seed == 7
    assert abs(r.p_heads - EXACT_2A) < 4 * r.stderr
    assert estimate(FIG2A, "antithetic", n=20_000, seed=7) == r  # reproducible
    with pytest.raises(TypeError, match="'antithetic' takes no option threads"):
        estimate(FIG2A, "antithetic", n=100, threads=2)
    assert "antithetic" in registry.names(seeded=True)


def test_unknown_before_registration():
    with pytest.raises(ValueError, match="unknown method 'antithetic'"):
        estimate(FIG2A, "antithetic")


def test_convergence_runs_the_new_method(registered):
    c = convergence(FIG2A, ["grid", "antithetic"], grid_sizes=[10], antithetic_sizes=[500, 4000])
    assert [p.n for p in c.series("antithetic")] == [500, 4000]
    assert isinstance(c.seed, int) and c.exact == pytest.approx(EXACT_2A, abs=1e-6)
    default = convergence(FIG2A, ["antithetic"], seed=3)
    assert [p.n for p in default.series("antithetic")] == [1000, 10_000]


def test_command_line_and_figures_read_the_registry(registered, tmp_path):
    import json

    from typer.testing import CliRunner

    from coinflight.cli import app
    from coinflight.plotting.convergence import plot_convergence
    from coinflight.plotting.style import method_color, method_style

    args = ["probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9"]
    out = CliRunner().invoke(app, [*args, "-m", "antithetic", "--n", "2000", "--seed", "5"])
    assert out.exit_code == 0, out.output
    assert "method antithetic: n = 2,000, seed 5;" in out.stdout  # its size and seed
    out = CliRunner().invoke(app, [*args, "-m", "antithetic", "--seed", "5", "--json"])
    assert json.loads(out.stdout)["n"] == 100_000  # the declared default
    bad = CliRunner().invoke(app, [*args, "-m", "antithetic", "--threads", "2"])
    assert bad.exit_code == 2 and "--threads does not apply to the antithetic method" in bad.stderr
    # A colour and marker of its own, with no edit to plotting: the first colour of the
    # Okabe & Ito palette that the built-in methods leave free (reddish purple).
    assert method_style("antithetic") == ("#CC79A7", "s")
    builtin = ("exact", "grid", "monte-carlo", "qmc")
    assert method_color("antithetic") not in {method_color(m) for m in builtin}
    fig = plot_convergence(convergence(FIG2A, ["antithetic"], antithetic_sizes=[200], seed=1))
    handles, labels = fig.axes[0].get_legend_handles_labels()
    assert labels[0] == ESTIMATOR.label
    assert handles[0].get_color() == "#CC79A7" and handles[0].get_marker() == "s"


def test_each_estimator_from_outside_gets_a_look_of_its_own(registered, monkeypatch):
    from dataclasses import replace

    from coinflight.plotting.style import METHOD_STYLES, MethodStyle, method_style

    registry.register(replace(ESTIMATOR, name="antithetic-2"))
    try:  # the second one registered from outside: the next free colour and marker
        assert method_style("antithetic-2") == ("#56B4E9", "^")
        monkeypatch.setitem(METHOD_STYLES, "antithetic", MethodStyle("#E69F00", "x"))
        assert method_style("antithetic") == ("#E69F00", "x")  # its own entry, where given
    finally:
        registry.unregister("antithetic-2")
    with pytest.raises(ValueError, match="unknown method 'nope'"):
        method_style("nope")

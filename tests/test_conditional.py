"""Monte Carlo and QMC conditional on the spins (issue 12): P(same side | spins) in closed form
over the flight time, averaged over random or scrambled-Sobol spins.

The standard errors are checked against the spread of the estimates over seeds, the estimates
against ``exact`` (within 4 s.e.), the answer against the thread count and chunk size, and the
mode against the registry's declaration.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from coinflight.cli.app import app
from coinflight.model.distributions import Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes import outcome_model
from coinflight.probability import estimate, registry
from coinflight.probability.conditional import MODE
from coinflight.studies.presets import human

FIG2A = TossDistribution(Uniform(60.0, 90.0), 0.0, 0.0, Uniform(0.6, 0.9))  # closed form
PRECESSING = TossDistribution(Uniform(60.0, 90.0), 10.0, Normal(20.0, 5.0), Normal(0.5, 0.05))
FIXED_T = TossDistribution(Uniform(60.0, 90.0), 5.0, 0.0, Fixed(0.7))  # closed form


@pytest.mark.parametrize("method", ["monte-carlo", "qmc"])
@pytest.mark.parametrize(
    "dist", [FIG2A, PRECESSING, FIXED_T, human()], ids=["fig2a", "precessing", "fixed-T", "human"]
)
def test_within_four_standard_errors_of_exact(method, dist):
    exact = estimate(dist, "exact")
    n = 16 << 14 if method == "qmc" else 10**6
    result = estimate(dist, method, n=n, seed=31, variance_reduction=MODE)
    assert result.details["variance_reduction"] == MODE
    assert result.counts is None  # no 0/1 counts: averages of probabilities
    assert abs(result.p_heads - exact.p_heads) <= 4 * result.stderr + exact.error_estimate


@pytest.mark.parametrize("method", ["monte-carlo", "qmc"])
def test_standard_error_matches_the_spread_over_seeds(method):
    # 40 seeds: the sample sd of the estimates is within ±35 % of the mean reported s.e.
    # (the sd of a sample sd over 40 draws is about 11 %; 3 of those, plus the spread of the
    # reported s.e. itself for QMC's 16 scramblings).
    dist = PRECESSING
    n = 16 << 8 if method == "qmc" else 1 << 14
    runs = [estimate(dist, method, n=n, seed=s, variance_reduction=MODE) for s in range(40)]
    spread = float(np.std([r.p_heads for r in runs], ddof=1))
    reported = float(np.mean([r.stderr for r in runs]))
    assert 0.65 <= spread / reported <= 1.35


def test_variance_is_reduced():
    # Conditioning never increases the variance (Rao–Blackwell); here by far: the outcome's
    # s.e. is ~5e-4 at 10⁶ tosses, the conditional one ~3e-5.
    plain = estimate(FIG2A, "monte-carlo", n=10**6, seed=2)
    conditioned = estimate(FIG2A, "monte-carlo", n=10**6, seed=2, variance_reduction=MODE)
    assert conditioned.stderr < plain.stderr / 10


def test_same_answer_for_any_thread_count_and_chunk_size():
    kw = {"n": 2 * (1 << 20) + 17, "seed": 5, "variance_reduction": MODE}
    a = estimate(PRECESSING, "monte-carlo", threads=1, **kw)
    b = estimate(PRECESSING, "monte-carlo", threads=2, chunk_size=1 << 21, **kw)
    assert (a.p_heads, a.stderr) == (b.p_heads, b.stderr)
    assert a.seed == 5


def test_declared_in_the_registry_and_refused_elsewhere():
    assert MODE in registry.VARIANCE_REDUCTIONS
    assert registry.get("monte-carlo").modes == (MODE,)
    assert registry.get("qmc").modes == (MODE,)
    with pytest.raises(ValueError, match="no variance reduction 'antithetic'"):
        estimate(FIG2A, "monte-carlo", n=100, seed=1, variance_reduction="antithetic")
    with pytest.raises(TypeError, match="takes no option variance_reduction"):
        estimate(FIG2A, "exact", variance_reduction=MODE)
    table = outcome_model("table")
    with pytest.raises(ValueError, match="closed-form bands"):
        estimate(FIG2A, "monte-carlo", n=100, seed=1, model=table, variance_reduction=MODE)


def test_tails_start_is_the_complement():
    tails = TossDistribution(Uniform(60.0, 90.0), 0.0, 0.0, Uniform(0.6, 0.9), start="tails")
    a = estimate(FIG2A, "monte-carlo", n=1 << 16, seed=3, variance_reduction=MODE)
    b = estimate(tails, "monte-carlo", n=1 << 16, seed=3, variance_reduction=MODE)
    assert a.p_heads == pytest.approx(b.p_tails, abs=1e-15)
    assert math.isclose(a.stderr, b.stderr)


def test_command_line_option():
    fig2a = ["probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9"]
    runner = CliRunner()
    ok = runner.invoke(
        app,
        [*fig2a, "-m", "monte-carlo", "-n", "65536", "--seed", "4", "--json", "--quiet",
         "--variance-reduction", MODE],
    )  # fmt: skip
    assert ok.exit_code == 0, ok.output
    payload = json.loads(ok.output)
    assert payload["method"] == "monte-carlo"
    assert payload["details"]["variance_reduction"] == MODE
    assert payload["seed"] == 4
    refused = runner.invoke(app, [*fig2a, "--variance-reduction", MODE])
    assert refused.exit_code == 2
    assert "--variance-reduction applies to --method monte-carlo and qmc only" in refused.output

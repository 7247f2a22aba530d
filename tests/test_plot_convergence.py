""":func:`coinflight.plotting.convergence.plot_convergence`: errors on log–log axes, rates."""

from __future__ import annotations

import numpy as np
import pytest

from coinflight.plotting.convergence import error_reference, fitted_slope, plot_convergence
from coinflight.probability.convergence import Convergence, ConvergencePoint

EXACT = 0.5


def _series() -> Convergence:
    # Grid errors 1e-2 · (n/100)^-1 exactly; method B's s.e. 0.5/√n (a binomial at p = 1/2).
    grid = [ConvergencePoint("grid", k, k * k, EXACT + 1e-2 * 100 / (k * k)) for k in (10, 30, 100)]
    mc = []
    for n, p in ((100, 0.53), (1_000, 0.49), (10_000, 0.503)):
        se = 0.5 / np.sqrt(n)
        mc.append(ConvergencePoint("monte-carlo", n, n, p, se, (p - 1.96 * se, p + 1.96 * se)))
    return Convergence(
        points=(*grid, *mc),
        exact=EXACT,
        exact_how="closed form",
        seed=1,
        grid_cells=100,
        coarse_limit=0.501,
    )


def test_errors_on_log_log_axes_with_rates_and_labelled_band():
    fig = plot_convergence(_series())
    ax = fig.axes[0]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    a = lines["method A: grid (x = configurations)"]
    np.testing.assert_allclose(a.get_ydata(), [1e-2, 1e-2 * 100 / 900, 1e-2 * 100 / 10_000])
    b = lines["method B: random events from 100 cells (x = events)"]
    np.testing.assert_allclose(b.get_ydata(), [0.03, 0.01, 0.003])
    # Grid errors fall exactly as n^-1 here: the observed slope printed is −1.00.
    assert "method A: observed slope -1.00 (least-squares fit)" in lines
    # Method B: its expected n^-1/2 line through 1.96 s.e. at n = 100.
    guide = lines["method B: expected slope −1/2 (error ∝ n^-1/2)"]
    np.testing.assert_allclose(
        guide.get_ydata(), 1.96 * 0.05 * np.sqrt(100 / np.array([100, 1e3, 1e4])), rtol=1e-3
    )
    # Method B's floor: its 100-cell grid sits 1e-3 from exact.
    assert any("|100-cell grid − exact| = 1.0e-03" in label for label in lines)
    bands = [c.get_label() for c in ax.collections]
    assert "method B: 95 % interval half-width, 1.96 s.e." in bands
    assert ax.get_ylabel().startswith("|P(heads) − exact|")


def test_fitted_slope_and_reference_without_exact():
    n = np.array([1e2, 1e3, 1e4, 1e5])
    slope, intercept = fitted_slope(n, 3.0 * n**-0.75)
    assert slope == pytest.approx(-0.75, abs=1e-12)
    assert intercept == pytest.approx(np.log10(3.0), abs=1e-12)
    assert fitted_slope(n[:2], n[:2] ** -1.0) is None  # two points: no slope drawn
    no_exact = Convergence(
        points=_series().points, exact=None, exact_how=None, seed=1, grid_cells=100
    )
    ref, name = error_reference(no_exact)
    assert ref == EXACT + 1e-2 * 100 / 10_000 and name == "the largest grid estimate"
    ax = plot_convergence(no_exact).axes[0]
    assert ax.get_ylabel() == "|P(heads) − the largest grid estimate|"


def test_the_papers_form_plots_the_estimates_with_the_exact_line():
    """Stefan & Cheche's Figs 2a-3b: P(heads) itself against n for both methods (method B
    with its 95 % intervals), the exact value as a black line, method B's limit dashed."""
    from matplotlib.colors import to_hex

    from coinflight.plotting.convergence import plot_estimates

    result = _series()
    ax = plot_estimates(result).axes[0]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "linear"
    assert ax.get_ylabel() == "P(heads)"
    lines = {ln.get_label(): ln for ln in ax.get_lines()}
    exact = lines["exact P(heads) = 0.500000"]
    assert list(exact.get_ydata()) == [EXACT, EXACT] and to_hex(exact.get_color()) == "#000000"
    assert list(lines["method B's limit: the 100-cell grid, 0.501000"].get_ydata()) == [0.501] * 2
    grid, mc = ax.containers  # one errorbar container per method, in order
    np.testing.assert_allclose(
        grid.lines[0].get_ydata(), [p.p_heads for p in result.series("grid")]
    )
    assert grid.has_yerr is False  # the grid has no standard error
    np.testing.assert_allclose(mc.lines[0].get_ydata(), [0.53, 0.49, 0.503])
    (bars,) = mc.lines[2]  # method B's error bars span its 95 % intervals
    low, high = bars.get_segments()[0][:, 1]
    assert (low, high) == pytest.approx((0.53 - 1.96 * 0.05, 0.53 + 1.96 * 0.05))


def test_the_default_title_names_the_ranges_and_the_coin():
    """The standalone figure (``coinflight convergence``) says which tosses it is about."""
    from coinflight import Coin, TossDistribution, Uniform
    from coinflight.plotting.convergence import default_title, plot_estimates

    dist = TossDistribution(
        omega_x=Uniform(60, 90),
        omega_y=10,
        flight_time=Uniform(0.6, 0.9),
        coin=Coin.preset("eur-1"),
    )
    result = Convergence(
        points=_series().points, exact=EXACT, exact_how="closed form", seed=1, grid_cells=100,
        description=dist.describe(),
    )  # fmt: skip
    title = default_title(result, "Error of P(heads) as the sample grows")
    assert "ωx0 60–90 rad/s, ωy0 10 rad/s, ωz0 0 rad/s, T 0.6–0.9 s" in title
    assert "€1" in title and "started heads up" in title
    assert plot_convergence(result).axes[0].get_title() == title
    assert "ωy0 10 rad/s" in plot_estimates(result).axes[0].get_title()

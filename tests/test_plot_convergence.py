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

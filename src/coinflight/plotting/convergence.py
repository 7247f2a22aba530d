"""Figures: P(heads) against configurations / events (Stefan & Cheche Figs 2a, 2b, 3a, 3b).

Two forms of the same numbers. :func:`plot_estimates` is the paper's: the estimates themselves
on a linear scale against the number of configurations or events, both methods, the exact
value as a line, to set beside the paper. :func:`plot_convergence` draws the error
|estimate − exact| against the sample size on log–log axes, where a rate n^-k is a straight
line of slope −k, so that the methods' rates can be read and compared.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from coinflight.plotting.style import EXACT_COLOR, method_color, method_style, new_figure
from coinflight.probability import registry

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from coinflight.probability.convergence import Convergence, ConvergencePoint

Z95 = 1.959963984540054
"""Two-sided 95 % normal quantile: the half-width of a 95 % interval in standard errors."""
MIN_FIT_POINTS = 3
"""Fewest non-zero errors a fitted slope is drawn from."""
MC_SLOPE_TOLERANCE = 0.1
"""A method whose interval half-widths fall with a fitted slope within this of −1/2 has a Monte
Carlo rate: its expected n^-1/2 line is drawn; any other gets its observed slope."""


def error_reference(result: Convergence) -> tuple[float, str]:
    """The value errors are measured from and its name in the figure.

    The exact value when there is one; otherwise the largest grid (method A) estimate, or the
    largest estimate of any method, named as such (the errors are then relative to it).
    """
    if result.exact is not None:
        return result.exact, "exact"
    grid = result.series("grid") if "grid" in result.methods else ()
    last = grid[-1] if grid else max(result.points, key=lambda p: p.samples)
    return last.p_heads, f"the largest {last.method} estimate"


def fitted_slope(samples: np.ndarray, errors: np.ndarray) -> tuple[float, float] | None:
    """Least-squares slope and intercept of log10 error against log10 n (zero errors left out).

    None with fewer than :data:`MIN_FIT_POINTS` non-zero errors.
    """
    keep = errors > 0
    if keep.sum() < MIN_FIT_POINTS:
        return None
    slope, intercept = np.polyfit(np.log10(samples[keep]), np.log10(errors[keep]), 1)
    return float(slope), float(intercept)


def _series_label(result: Convergence, method: str) -> str:
    estimator = registry.get(method)
    if "grid_cells" in estimator.options and result.grid_cells:
        return f"method B: random events from {result.grid_cells} cells (x = events)"
    if "grid_cells" in estimator.options:
        return "Monte Carlo (x = events)"
    return estimator.label


def _short_name(result: Convergence, method: str) -> str:
    if method == "grid":
        return "method A"
    if "grid_cells" in registry.get(method).options and result.grid_cells:
        return "method B"
    return method


def _draw_series(ax: Axes, result: Convergence, method: str, ref: float, floor: float) -> None:
    """One method's errors, its 95 % band (methods with a standard error) and its rate line."""
    pts: tuple[ConvergencePoint, ...] = result.series(method)
    color, marker = method_style(method)
    name = _short_name(result, method)
    x = np.array([p.samples for p in pts], dtype=float)
    err = np.array([abs(p.p_heads - ref) for p in pts])
    shown = np.maximum(err, floor)  # an exact hit (error 0) sits on the floor, not off the axis
    ax.plot(
        x,
        shown,
        "-",
        marker=marker,
        color=color,
        label=_series_label(result, method),
        markersize=4,
        linewidth=1.2,
    )
    half = np.array([Z95 * p.stderr if p.stderr else np.nan for p in pts])
    has_band = np.isfinite(half)
    if has_band.any():
        ax.fill_between(
            x,
            floor,
            np.where(has_band, half, floor),
            where=has_band,
            color=color,
            alpha=0.15,
            linewidth=0,
            label=f"{name}: 95 % interval half-width, 1.96 s.e.",
        )
    band_fit = fitted_slope(x[has_band], half[has_band]) if has_band.any() else None
    if band_fit is not None and abs(band_fit[0] + 0.5) < MC_SLOPE_TOLERANCE:
        # A Monte Carlo rate: the expected n^-1/2 line through the first interval.
        first = int(np.argmax(has_band))
        ax.plot(
            x,
            half[first] * np.sqrt(x[first] / x),
            ":",
            color=color,
            linewidth=1.2,
            label=f"{name}: expected slope −1/2 (error ∝ n^-1/2)",
        )
        return
    fit = fitted_slope(x, err)
    if fit is not None:
        slope, intercept = fit
        ax.plot(
            x,
            10.0**intercept * x**slope,
            "--",
            color=color,
            linewidth=1,
            label=f"{name}: observed slope {slope:.2f} (least-squares fit)",
        )


_SYMBOLS = {"omega_x": "ωx0", "omega_y": "ωy0", "omega_z": "ωz0", "flight_time": "T"}


def default_title(result: Convergence, what: str) -> str:
    """``what``, then the tosses: the ranges of ωx0, ωy0, ωz0 and T with units, the coin and
    the face up at launch (from the distribution's description)."""
    first, *rest = result.description.splitlines() or [""]
    ranges = []
    for line in rest:
        name, _, value = line.partition(" = ")
        if name in _SYMBOLS:
            ranges.append(f"{_SYMBOLS[name]} {value}")
    return "\n".join(x for x in (what, ", ".join(ranges), first) if x)


def plot_estimates(result: Convergence, title: str | None = None) -> Figure:
    """P(heads) against the number of configurations or events: the paper's form of its Figs
    2a, 2b, 3a and 3b.

    Each method's estimates are a line with markers (x on a log scale, the sizes span decades);
    a method with a standard error carries its 95 % interval as error bars; the exact value is
    a black line, and method B's limit (its coarse grid's exact count) a dashed one when it
    differs from it. Without an exact value the lines are the estimates alone.
    """
    fig = new_figure(figsize=(6.4, 6.0))
    ax = fig.add_subplot()
    for method in result.methods:
        pts = result.series(method)
        color, marker = method_style(method)
        x = np.array([p.samples for p in pts], dtype=float)
        y = np.array([p.p_heads for p in pts])
        ci = [p.ci95 for p in pts]
        yerr = None
        if all(c is not None for c in ci):
            lo = np.array([c[0] for c in ci if c is not None])
            hi = np.array([c[1] for c in ci if c is not None])
            yerr = np.stack([y - lo, hi - y])
        ax.errorbar(
            x,
            y,
            yerr=yerr,
            fmt="-",
            marker=marker,
            color=color,
            markersize=4,
            linewidth=1.2,
            capsize=2 if yerr is not None else 0,
            label=_series_label(result, method) + (", 95 % interval" if yerr is not None else ""),
        )
    if result.exact is not None:
        ax.axhline(
            result.exact,
            color=EXACT_COLOR,
            linewidth=1.2,
            label=f"exact P(heads) = {result.exact:.6f}",
        )
    if result.coarse_limit is not None and result.coarse_limit != result.exact:
        ax.axhline(
            result.coarse_limit,
            color=method_color("monte-carlo"),
            linestyle="--",
            linewidth=1,
            label=f"method B's limit: the {result.grid_cells}-cell grid, {result.coarse_limit:.6f}",
        )
    ax.set_xscale("log")
    ax.set_xlabel("number of configurations (A) or events (B)")
    ax.set_ylabel("P(heads)")
    ax.set_title(title or default_title(result, "P(heads) as the sample grows"), fontsize=10)
    fig.legend(loc="outside lower center", ncols=1, fontsize="x-small")
    return fig


def plot_convergence(result: Convergence, title: str | None = None) -> Figure:
    """|P(heads) − exact| against the number of configurations or events, log–log axes.

    Each method's error is a line with markers. A method with a standard error carries a shaded
    band from the floor to its 95 % interval's half-width 1.96 s.e. (where 95 % of its errors
    would fall if it were unbiased). A method whose half-widths fall as n^-1/2 (Monte Carlo,
    method B) gets a dotted line of slope −1/2, its expected rate; any other (the grid, method
    A; QMC) a dashed least-squares line through its errors, its observed slope in the legend.
    Method B converges to its coarse grid's exact count, not to the exact value: the distance
    between the two, the error B cannot go below, is a dashed horizontal line.
    Errors of 0 (an exact hit) are drawn at the axis' floor. Without an exact value the errors
    are measured from the largest grid estimate (named on the y axis). The default title
    names the tosses' ranges and coin (:func:`default_title`).
    """
    ref, ref_name = error_reference(result)
    errors = [abs(p.p_heads - ref) for p in result.points]
    halves = [Z95 * p.stderr for p in result.points if p.stderr]
    positive = [e for e in (*errors, *halves) if e > 0]
    floor = min(positive) / 2 if positive else 1e-12
    fig = new_figure(figsize=(6.4, 6.6))
    ax = fig.add_subplot()
    for method in result.methods:
        _draw_series(ax, result, method, ref, floor)
    if result.coarse_limit is not None and abs(result.coarse_limit - ref) > 0:
        ax.axhline(
            abs(result.coarse_limit - ref),
            color=method_color("monte-carlo"),
            linestyle="--",
            linewidth=1,
            label=f"method B's limit: |{result.grid_cells}-cell grid − {ref_name}| = "
            f"{abs(result.coarse_limit - ref):.1e}",
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(bottom=floor)
    ax.set_xlabel("number of configurations (A) or events (B)")
    ax.set_ylabel(f"|P(heads) − {ref_name}|" + (f"  ({ref:.6f})" if ref_name == "exact" else ""))
    ax.set_title(
        title or default_title(result, "Error of P(heads) as the sample grows"), fontsize=10
    )
    fig.legend(loc="outside lower center", ncols=2, fontsize="x-small")
    return fig


__all__ = ["default_title", "error_reference", "fitted_slope", "plot_convergence", "plot_estimates"]

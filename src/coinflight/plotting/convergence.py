"""Figure: estimates of P(heads) against configurations / events (Stefan & Cheche Figs 2-3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from coinflight.plotting.style import EXACT_COLOR, new_figure
from coinflight.probability import registry

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from coinflight.probability.convergence import Convergence


def plot_convergence(result: Convergence, title: str | None = None) -> Figure:
    """P(heads) against the number of configurations or events, log x axis.

    Grid estimates are exact counts (no error bar); Monte Carlo and QMC carry 95 % intervals.
    The exact value is a black line, ½ a dotted grey line, and the value method B converges
    to (its coarse grid's exact count) a dashed line.
    """
    fig = new_figure()
    ax = fig.add_subplot()
    for method in result.methods:
        pts = result.series(method)
        x = [p.samples for p in pts]
        y = [p.p_heads for p in pts]
        estimator = registry.get(method)
        label = estimator.label
        if "grid_cells" in estimator.options and result.grid_cells:
            label = f"method B: random events from {result.grid_cells} cells (x = events)"
        elif "grid_cells" in estimator.options:
            label = "Monte Carlo (x = events)"
        color = estimator.color
        ax.plot(
            x,
            y,
            "-",
            marker=estimator.marker,
            color=color,
            label=label,
            markersize=4,
            linewidth=1.2,
        )
        lows = [p.ci95[0] if p.ci95 else p.p_heads for p in pts]
        highs = [p.ci95[1] if p.ci95 else p.p_heads for p in pts]
        if any(p.ci95 for p in pts):
            ax.fill_between(x, lows, highs, color=color, alpha=0.15, linewidth=0)
    ax.axhline(0.5, color="0.6", linestyle=":", linewidth=1, label="1/2")
    if result.exact is not None:
        ax.axhline(
            result.exact,
            color=EXACT_COLOR,
            linewidth=1,
            label=f"exact {result.exact:.6f}",
        )
    if result.coarse_limit is not None:
        ax.axhline(
            result.coarse_limit,
            color=registry.get("monte-carlo").color,
            linestyle="--",
            linewidth=1,
            label=f"method B's limit: {result.grid_cells}-cell grid {result.coarse_limit:.4f}",
        )
    ax.set_xscale("log")
    ax.set_xlabel("number of configurations (A) or events (B)")
    ax.set_ylabel("P(heads)")
    ax.set_title(title or "Probability of heads as the sample grows")
    ax.legend(fontsize="small")
    return fig


__all__ = ["plot_convergence"]

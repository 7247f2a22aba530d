"""Forest plot of per-person same-side rates (Bartoš et al. style data)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from coinflight.plotting.style import EXACT_COLOR, HEADS_COLOR, TAILS_COLOR, new_figure
from coinflight.studies.data import CountsSummary

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def plot_forest(summary: CountsSummary, p_model: float | None = None) -> Figure:
    """Each person's same-side rate with its 95 % interval, and the pooled rate as a diamond.

    Parameters
    ----------
    summary : CountsSummary
        From :func:`coinflight.studies.data.summarize`; people are drawn in file order, top to
        bottom.
    p_model : float, optional
        A model's same-side probability (e.g. Diaconis et al.'s ≈ 0.51) drawn as a line.

    Returns
    -------
    matplotlib.figure.Figure
    """
    people = summary.people
    n = len(people)
    fig = new_figure(figsize=(6.4, max(4.8, 0.18 * n + 1.8)))
    ax = fig.add_subplot()
    y = np.arange(n, 0, -1, dtype=float)
    est = np.array([p.estimate for _, p in people])
    lo = np.array([p.ci95[0] for _, p in people])
    hi = np.array([p.ci95[1] for _, p in people])
    flips = np.array([p.trials for _, p in people], dtype=float)
    ax.hlines(y, lo, hi, color=HEADS_COLOR, linewidth=1)
    ax.scatter(est, y, s=8 + 40 * flips / flips.max(), color=HEADS_COLOR, marker="s", zorder=3)
    pooled = summary.same_side
    d_lo, d_hi = pooled.ci95
    ax.fill(
        [d_lo, pooled.estimate, d_hi, pooled.estimate],
        [0.0, 0.3, 0.0, -0.3],
        color=EXACT_COLOR,
        zorder=3,
    )
    ax.axvline(0.5, color="0.5", linewidth=0.8, linestyle="--", label="½: no bias")
    ax.axvline(
        pooled.estimate,
        color=EXACT_COLOR,
        linewidth=0.6,
        linestyle=":",
        label=f"pooled {pooled.estimate:.4f} (◆: its interval)",
    )
    if p_model is not None:
        ax.axvline(p_model, color=TAILS_COLOR, linewidth=1, label=f"model p = {p_model:.4f}")
    ax.scatter([], [], color=HEADS_COLOR, marker="s", label="one person (size ∝ flips)")
    fig.legend(loc="outside lower center", ncols=2, fontsize="small", frameon=False)
    method = "Clopper-Pearson" if pooled.method == "exact" else "Wilson"
    ax.set_yticks([*y, 0.0], [*(name for name, _ in people), "pooled"], fontsize="x-small")
    ax.set_ylim(-1.0, n + 1.0)
    ax.set_xlabel(f"P(same side) with 95 % {method} interval")
    ax.set_title(
        f"{pooled.successes:,} same-side of {pooled.trials:,} flips: "
        f"{pooled.estimate:.4f} [{d_lo:.3f}, {d_hi:.3f}]",
        fontsize="medium",
    )
    return fig


__all__ = ["plot_forest"]

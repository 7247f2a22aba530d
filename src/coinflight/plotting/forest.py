"""Forest plots of per-person same-side rates (Bartoš et al. style data): the rates with their
intervals (:func:`plot_forest`), and the rates against two models' predictions with the ψ
population under p(ψ) (:func:`plot_flippers`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from coinflight.plotting.style import (
    EDGE_COLOR,
    EXACT_COLOR,
    HEADS_COLOR,
    LAUNCH_COLOR,
    TAILS_COLOR,
    new_figure,
)
from coinflight.studies.data import CountsSummary

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from coinflight.studies.data import CountsTable
    from coinflight.studies.flippers import FlipperAnalysis


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


def plot_flippers(table: CountsTable, analysis: FlipperAnalysis) -> Figure:
    """How people differ: each person's rate against two models' predictions, and the ψ
    population under p(ψ).

    Top, side by side: each person's observed same-side rate (a dot; a cross when outside) and
    the 95 % predictive interval of the rate of a person with that many flips (a bar), under
    one ψ for everybody (left) and under the fitted ψ population (right); people ordered by
    their number of flips, most at the top. Below: p(ψ) of Diaconis, Holmes & Montgomery
    (2007) on 45°-90°, and under it the fitted population's density of ψ (folded at 90°), the
    log-normal alternative's, the one ψ, and each person's shrunken ψ as a tick.

    Parameters
    ----------
    table : CountsTable
        The counts the analysis was made of.
    analysis : FlipperAnalysis
        From :func:`coinflight.studies.flippers.analyse`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    import math

    from scipy.stats import norm

    from coinflight.core.precession import same_side_probability
    from coinflight.studies.flippers import predictive_interval, predictive_interval_one_psi

    fit = analysis.fit
    pop = fit.population
    flips = table.flips_by_person
    rate = table.same_by_person / flips
    order = np.argsort(-flips, kind="stable")
    n = len(order)
    fig = new_figure(figsize=(10.0, 0.16 * n + 6.0))
    grid = fig.add_gridspec(3, 2, height_ratios=[max(3.0, 0.16 * n), 1.6, 1.4])
    y = np.arange(n, 0, -1, dtype=float)
    panels = (
        (predictive_interval_one_psi(flips, fit.one_psi),
         f"one ψ = {math.degrees(fit.one_psi):.2f}° for all"),
        (predictive_interval(flips, pop),
         f"ψ population: normal {math.degrees(pop.location):.1f}° ± "
         f"{math.degrees(pop.scale):.1f}°, folded"),
    )  # fmt: skip
    first = None
    for col, (interval, title) in enumerate(panels):
        ax = fig.add_subplot(grid[0, col], sharex=first, sharey=first)
        first = first or ax
        lo, hi = interval[order, 0], interval[order, 1]
        r = rate[order]
        inside = (r >= lo) & (r <= hi)
        ax.hlines(y, lo, hi, color=TAILS_COLOR, linewidth=3, alpha=0.6,
                  label="95 % predictive interval for that many flips")  # fmt: skip
        ax.scatter(r[inside], y[inside], s=10, color=HEADS_COLOR, zorder=3, label="observed")
        ax.scatter(r[~inside], y[~inside], s=22, color=LAUNCH_COLOR, marker="x", zorder=3,
                   label="observed, outside")  # fmt: skip
        ax.axvline(0.5, color="0.5", linewidth=0.8, linestyle="--")
        ax.set_title(f"{title}: {int(inside.sum())} of {n} inside", fontsize="medium")
        ax.set_xlabel("P(same side)")
        ax.set_yticks(y, [table.people[i] for i in order], fontsize="xx-small")
        if col == 1:
            ax.tick_params(labelleft=False)
            ax.legend(loc="lower right", fontsize="x-small")
    psi_deg = np.linspace(45.0, 90.0, 901)
    curve = fig.add_subplot(grid[1, :])
    curve.plot(psi_deg, same_side_probability(np.radians(psi_deg)), color=EXACT_COLOR,
               label="p(ψ), Diaconis, Holmes & Montgomery 2007")  # fmt: skip
    one = math.degrees(fit.one_psi)
    curve.axvline(one, color=TAILS_COLOR, linewidth=1, label=f"one ψ = {one:.2f}°")
    curve.set_ylabel("P(same side)")
    curve.legend(loc="upper right", fontsize="x-small")
    curve.tick_params(labelbottom=False)
    dens = fig.add_subplot(grid[2, :], sharex=curve)
    mean, sd = math.degrees(pop.location), math.degrees(pop.scale)
    if sd > 0.0:
        folded = norm.pdf(psi_deg, mean, sd) + norm.pdf(180.0 - psi_deg, mean, sd)
        label = f"fitted ψ population (normal {mean:.1f}° ± {sd:.1f}°, folded)"
        dens.fill_between(psi_deg, folded, color=HEADS_COLOR, alpha=0.35, label=label)
    alt = analysis.alternative.population
    if alt.scale > 0.0:
        d = np.radians(90.0 - psi_deg[:-1])
        med = 0.5 * math.pi - alt.location
        ln = norm.pdf(np.log(d), math.log(med), alt.scale) / d * (math.pi / 180.0)
        dens.plot(psi_deg[:-1], ln, color=EDGE_COLOR, linestyle="--",
                  label="log-normal 90° − ψ (alternative)")  # fmt: skip
    dens.axvline(one, color=TAILS_COLOR, linewidth=1)
    shrunk = [math.degrees(p.psi) for p in analysis.people]
    top = dens.get_ylim()[1]
    dens.vlines(shrunk, 0.0, 0.08 * top, color=EXACT_COLOR, linewidth=0.8,
                label="each person's shrunken ψ")  # fmt: skip
    dens.set_xlim(45.0, 90.0)
    dens.set_ylim(0.0, top)
    dens.set_xlabel("precession angle ψ, degrees (ψ and 180° − ψ: the same coin)")
    dens.set_ylabel("density, 1/degree")
    dens.legend(loc="upper left", fontsize="x-small")
    return fig


__all__ = ["plot_flippers", "plot_forest"]

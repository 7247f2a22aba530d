"""Figure of the same-side probability p(ψ) of a precessing coin."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from coinflight.plotting.style import EXACT_COLOR, TAILS_COLOR, method_color, new_figure
from coinflight.probability.result import BinomialEstimate
from coinflight.studies.bias import same_side_probability

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def plot_bias(
    simulated: Sequence[tuple[float, BinomialEstimate]] = (),
    measured: float | None = None,
    psi_measured: float | None = None,
) -> Figure:
    """p(ψ) against ψ in degrees (Diaconis, Holmes & Montgomery 2007), with optional marks.

    Parameters
    ----------
    simulated : sequence of (ψ in degrees, BinomialEstimate)
        Monte Carlo estimates drawn as points with ±2 standard-error bars.
    measured : float, optional
        A measured same-side rate (e.g. Bartoš et al.'s 0.508) drawn as a horizontal line.
    psi_measured : float, optional
        The ψ (degrees) that explains ``measured``, drawn as a vertical line.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = new_figure()
    ax = fig.add_subplot()
    psi = np.linspace(0.0, 180.0, 1441)
    ax.plot(
        psi,
        same_side_probability(psi, degrees=True),
        color=EXACT_COLOR,
        label=r"closed form $p(\psi) = \frac{1}{2} + \frac{1}{\pi}\arcsin(\cot^2\psi)$",
    )
    if simulated:
        xs = [s[0] for s in simulated]
        ys = [s[1].p for s in simulated]
        errs = [2.0 * s[1].stderr for s in simulated]
        n = simulated[0][1].n
        ax.errorbar(
            xs,
            ys,
            yerr=errs,
            fmt="o",
            color=method_color("monte-carlo"),
            markersize=4,
            label=f"Monte Carlo, full flight ({n:,} tosses each, ±2 s.e.)",
        )
    if measured is not None:
        ax.axhline(
            measured,
            color=TAILS_COLOR,
            linestyle="--",
            linewidth=1,
            label=f"measured {measured:.4f}",
        )
    if psi_measured is not None:
        ax.axvline(
            psi_measured,
            color=TAILS_COLOR,
            linestyle=":",
            linewidth=1,
            label=f"ψ = {psi_measured:.2f}°",
        )
    ax.axhline(0.5, color="0.6", linewidth=0.8)
    ax.set_xlim(0.0, 180.0)
    ax.set_ylim(0.45, 1.02)
    ax.set_xticks(np.arange(0, 181, 15))
    ax.set_xlabel("precession angle ψ between normal and angular momentum (degrees)")
    ax.set_ylabel("P(lands on the side it started)")
    ax.set_title(
        "Same-side bias of a precessing coin (Diaconis, Holmes & Montgomery 2007)",
        fontsize="medium",
    )
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0.9), fontsize="x-small")
    return fig


__all__ = ["plot_bias"]

"""Figure of the same-side probability p(ψ) of a precessing coin."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from coinflight.plotting.style import EXACT_COLOR, TAILS_COLOR, method_color, new_figure
from coinflight.probability.result import BinomialEstimate
from coinflight.studies.bias import same_side_probability

if TYPE_CHECKING:
    from matplotlib.figure import Figure

ZOOM_PSI = (60.0, 120.0)
"""ψ range (degrees) of the zoomed panel: where p(ψ) is within a few % of 1/2."""
ZOOM_P = (0.49, 0.53)
"""P range of the zoomed panel: 1/2 and the measured 0.508 of Bartoš et al. with room."""
ZOOM_MARGIN = 0.005
"""Room kept around a measured rate or ψ that falls outside the default zoom."""
CLOSED_FORM = r"closed form $p(\psi) = \frac{1}{2} + \frac{1}{\pi}\arcsin(\cot^2\psi)$"


def zoom_limits(
    measured: float | None, psi_measured: float | None
) -> tuple[tuple[float, float], tuple[float, float]]:
    """ψ and P limits of the zoomed panel: :data:`ZOOM_PSI` × :data:`ZOOM_P`, widened to show a
    measured rate (and its interval) and its ψ and mirror 180° − ψ."""
    lo_psi, hi_psi = ZOOM_PSI
    lo_p, hi_p = ZOOM_P
    if measured is not None:
        lo_p, hi_p = min(lo_p, measured - ZOOM_MARGIN), max(hi_p, measured + ZOOM_MARGIN)
    if psi_measured is not None:
        near = min(psi_measured, 180.0 - psi_measured)
        lo_psi, hi_psi = min(lo_psi, near - 5.0), max(hi_psi, 180.0 - near + 5.0)
    return (max(lo_psi, 0.0), min(hi_psi, 180.0)), (lo_p, hi_p)


def plot_bias(
    simulated: Sequence[tuple[float, BinomialEstimate]] = (),
    measured: float | None = None,
    psi_measured: float | None = None,
    measured_interval: tuple[float, float] | None = None,
) -> Figure:
    """p(ψ) against ψ in degrees (Diaconis, Holmes & Montgomery 2007), with optional marks.

    Two panels: the whole curve, ψ from 0° to 180°, small, above; and below, large, the region
    that matters (:func:`zoom_limits`: ψ ≈ 60°-120°, P ≈ 0.49-0.53), where a measured rate
    such as Bartoš et al.'s 0.508 lies. p(ψ) = p(180° − ψ) (cot² is the same), so a measured
    rate is explained by ψ and by its mirror 180° − ψ: both are marked.

    Parameters
    ----------
    simulated : sequence of (ψ in degrees, BinomialEstimate)
        Monte Carlo estimates drawn as points with ±2 standard-error bars.
    measured : float, optional
        A measured same-side rate (e.g. Bartoš et al.'s 0.508) drawn as a horizontal line.
    psi_measured : float, optional
        The ψ (degrees) that explains ``measured``, drawn as a vertical line with its mirror.
    measured_interval : (float, float), optional
        An interval of the measured rate (e.g. its 95 % interval), shaded.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = new_figure(figsize=(6.4, 7.4))
    full, zoom = fig.subplots(2, 1, height_ratios=[1, 2.3])
    psi = np.linspace(0.0, 180.0, 2881)
    p = same_side_probability(psi, degrees=True)
    (psi_lim, p_lim) = zoom_limits(measured, psi_measured)
    for ax in (full, zoom):
        ax.plot(psi, p, color=EXACT_COLOR, label=CLOSED_FORM)
        ax.axhline(0.5, color="0.6", linewidth=0.8)
        _draw_marks(ax, simulated, measured, psi_measured, measured_interval)
    full.set_xlim(0.0, 180.0)
    full.set_ylim(0.45, 1.02)
    full.set_xticks(np.arange(0, 181, 30))
    full.add_patch(_zoom_box(psi_lim, p_lim))
    full.set_xlabel("ψ (degrees)", fontsize="small")
    full.set_ylabel("P(same side)", fontsize="small")
    full.set_title(
        "Same-side bias of a precessing coin (Diaconis, Holmes & Montgomery 2007)\n"
        "whole curve (above) and the boxed region that matters (below)",
        fontsize="medium",
    )
    zoom.set_xlim(*psi_lim)
    zoom.set_ylim(*p_lim)
    zoom.set_xticks(np.arange(np.ceil(psi_lim[0] / 10) * 10, psi_lim[1] + 0.1, 10))
    zoom.set_xlabel("precession angle ψ between normal and angular momentum (degrees)")
    zoom.set_ylabel("P(lands on the side it started)")
    # below the panels, where it covers no curve or point
    fig.legend(*zoom.get_legend_handles_labels(), loc="outside lower center", fontsize="x-small")
    return fig


def _draw_marks(
    ax: Any,
    simulated: Sequence[tuple[float, BinomialEstimate]],
    measured: float | None,
    psi_measured: float | None,
    measured_interval: tuple[float, float] | None,
) -> None:
    if simulated:
        n = simulated[0][1].n
        ax.errorbar(
            [s[0] for s in simulated],
            [s[1].p for s in simulated],
            yerr=[2.0 * s[1].stderr for s in simulated],
            fmt="o",
            color=method_color("monte-carlo"),
            markersize=4,
            label=f"Monte Carlo, full flight ({n:,} tosses each, ±2 s.e.)",
        )
    if measured_interval is not None:
        ax.axhspan(
            *measured_interval,
            color=TAILS_COLOR,
            alpha=0.2,
            linewidth=0,
            label=f"measured interval [{measured_interval[0]:.4f}, {measured_interval[1]:.4f}]",
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
        mirror = 180.0 - psi_measured
        ax.axvline(
            psi_measured, color=TAILS_COLOR, linestyle=":", linewidth=1.2,
            label=f"ψ = {psi_measured:.2f}°",
        )  # fmt: skip
        ax.axvline(
            mirror, color=TAILS_COLOR, linestyle="-.", linewidth=1.2,
            label=f"its mirror 180° − ψ = {mirror:.2f}° (same p)",
        )  # fmt: skip


def _zoom_box(psi_lim: tuple[float, float], p_lim: tuple[float, float]) -> Any:
    from matplotlib.patches import Rectangle

    return Rectangle(
        (psi_lim[0], p_lim[0]),
        psi_lim[1] - psi_lim[0],
        p_lim[1] - p_lim[0],
        fill=False,
        edgecolor="0.3",
        linewidth=1,
    )


__all__ = ["plot_bias", "zoom_limits"]

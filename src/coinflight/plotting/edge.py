"""Figure of the probability that a thick coin lands on edge, against thickness / diameter."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from coinflight.plotting.style import EDGE_COLOR, EXACT_COLOR, method_color, new_figure
from coinflight.probability.result import BinomialEstimate
from coinflight.studies.edge import (
    MODELS,
    SIM_DIAMETER,
    SIM_DROP,
    SIM_LAUNCH_SPEED,
    SIM_SPIN,
    EdgeModel,
    edge_probability,
    ratio_for,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

MAX_RATIO = 100.0
"""Right end of the h/d axis at most: a coin 100 times thicker than wide is a rod, and the
geometric model's P(edge) is 0.997 already at h/d = 14."""
MODEL_STYLES = {"geometric": "-", "dynamic": "--"}
MODEL_LABELS = {
    "geometric": "geometric: random orientation at rest, (h/d)/√(1 + (h/d)²)",
    "dynamic": "dynamic: planar spin landing dead, 2 arctan(h/d)/π",
}
EXACT_RATIOS = {
    "geometric": ("1/(2√2)", 1.0 / (2.0 * math.sqrt(2.0))),
    "dynamic": ("1/√3", 1.0 / math.sqrt(3.0)),
}
"""Yong & Mahadevan's printed ratios for P(edge) = 1/3 (REFERENCES §5), for the labels."""


MODEL_MARKERS = {"geometric": "s", "dynamic": "D"}


def simulation_text(simulated: Sequence[tuple[float, BinomialEstimate]]) -> str:
    """What :func:`coinflight.studies.edge.simulate_edge` simulated, in a few lines."""
    from coinflight.model.surface import DEFAULT_FRICTION

    first = simulated[0][1]
    seed = "no seed" if first.seed is None else f"seed {first.seed}"
    return (
        f"simulated: {first.n:,} tosses per point, {seed};\n"
        f"d = {SIM_DIAMETER * 1e3:g} mm steel coin, spin about a diameter\n"
        f"ωx ~ U({SIM_SPIN[0]:g}, {SIM_SPIN[1]:g}) rad/s, v0 ~ U({SIM_LAUNCH_SPEED[0]:g}, "
        f"{SIM_LAUNCH_SPEED[1]:g}) m/s,\n"
        f"table {SIM_DROP:g} m below, landing dead (e = 0), μ = {DEFAULT_FRICTION:g}"
    )


def model_distance(ratio: float, estimate: BinomialEstimate, model: EdgeModel) -> float:
    """(p̂ − P_model(h/d)) / s.e., the s.e. the model's own binomial √(P(1 − P)/n).

    The model's s.e. rather than the estimate's, so that a point with no edge at all (p̂ = 0,
    s.e. 0) still has a finite distance; inf when the model gives 0 or 1 and the point differs.
    """
    expected = float(edge_probability(ratio, model))
    se = math.sqrt(expected * (1.0 - expected) / estimate.n)
    diff = estimate.p - expected
    if se == 0.0:
        return 0.0 if diff == 0.0 else math.copysign(math.inf, diff)
    return diff / se


def plot_edge(
    simulated: Sequence[tuple[float, BinomialEstimate]] = (), max_ratio: float = 1.0
) -> Figure:
    """P(edge) against h/d for Yong & Mahadevan's two models, the ratios for 1/3 marked.

    Parameters
    ----------
    simulated : sequence of (h/d, BinomialEstimate)
        Simulated landings (:func:`coinflight.studies.edge.simulate_edge`), drawn as points with
        ±2 standard-error bars; what was simulated is written on the figure, and a lower panel
        gives each point's distance from each model in standard errors
        (:func:`model_distance`), with the ±2 band.
    max_ratio : float
        Right end of the h/d axis (> 1/√3, so both marks show).

    Returns
    -------
    matplotlib.figure.Figure
        Curves of :func:`coinflight.studies.edge.edge_probability` (Yong & Mahadevan 2011,
        §II and §III), the line P(edge) = 1/3, and a vertical mark at each model's ratio for it
        (:func:`coinflight.studies.edge.ratio_for`: 1/(2√2) ≈ 0.354 and 1/√3 ≈ 0.577).
    """
    if not (math.isfinite(max_ratio) and EXACT_RATIOS["dynamic"][1] < max_ratio <= MAX_RATIO):
        raise ValueError(
            f"max ratio must be above 1/√3 ≈ 0.577 and at most {MAX_RATIO:g}, got {max_ratio!r}"
        )
    fig = new_figure(figsize=(6.4, 6.4) if simulated else (6.4, 4.8))
    if simulated:
        ax, resid = fig.subplots(2, 1, sharex=True, height_ratios=[3, 1.3])
    else:
        ax = fig.add_subplot()
    x = np.linspace(0.0, max_ratio, 801)
    for model in MODELS:
        ax.plot(
            x,
            edge_probability(x, model),
            color=EXACT_COLOR,
            linestyle=MODEL_STYLES[model],
            label=MODEL_LABELS[model],
        )
    ax.axhline(1.0 / 3.0, color="0.6", linewidth=0.8)
    for model in MODELS:
        at = ratio_for(1.0 / 3.0, model)
        name, _ = EXACT_RATIOS[model]
        ax.axvline(at, color=EDGE_COLOR, linestyle=MODEL_STYLES[model], linewidth=1)
        # Along the mark, above both curves, so that it hides no data.
        ax.text(
            at,
            0.42 if model == "geometric" else 0.52,
            f" h/d = {name} ≈ {at:.3f}",
            rotation=90,
            ha="right",
            va="bottom",
            color=EDGE_COLOR,
            fontsize="small",
        )
    if simulated:
        n = simulated[0][1].n
        ax.errorbar(
            [ratio for ratio, _ in simulated],
            [s.p for _, s in simulated],
            yerr=[2.0 * s.stderr for _, s in simulated],
            fmt="o",
            color=method_color("monte-carlo"),
            markersize=4,
            label=f"simulated landings, dead on a table ({n:,} tosses each, ±2 s.e.)",
        )
        _draw_distances(resid, simulated)
    ax.set_xlim(0.0, 1.03 * max_ratio)  # room for a point at max_ratio
    ax.set_ylim(0.0, float(edge_probability(max_ratio, "geometric")) * 1.05)
    (resid if simulated else ax).set_xlabel("thickness / diameter h/d")
    ax.set_ylabel("P(edge)")
    ax.set_title(
        "A thick coin lands on edge (Yong & Mahadevan 2011): P(edge) = 1/3 at the marks",
        fontsize="medium",
    )
    ax.legend(
        loc="lower right",
        fontsize="x-small",
        title=simulation_text(simulated) if simulated else None,
        title_fontsize="xx-small",
        alignment="left",
    )
    return fig


def _draw_distances(ax: Any, simulated: Sequence[tuple[float, BinomialEstimate]]) -> None:
    """Each point's distance from each model, in standard errors, with the ±2 band."""
    ratios = [ratio for ratio, _ in simulated]
    ax.axhspan(-2.0, 2.0, color="0.9", linewidth=0, label="±2 s.e.")
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    worst = 2.0
    for model in MODELS:
        z = np.array([model_distance(r, s, model) for r, s in simulated])
        finite = z[np.isfinite(z)]
        worst = max(worst, float(np.abs(finite).max()) if finite.size else 0.0)
        shown = np.clip(z, -1e3, 1e3)
        ax.plot(
            ratios,
            shown,
            linestyle="none",
            marker=MODEL_MARKERS[model],
            markerfacecolor="none",
            color=EXACT_COLOR,
            label=f"from the {model} model",
        )
        for r, zi in zip(ratios, z, strict=True):
            ax.annotate(
                f"{zi:+.1f}",
                (r, float(np.clip(zi, -1e3, 1e3))),
                textcoords="offset points",
                xytext=(7, 0),
                fontsize=6,
                va="center",
            )
    ax.set_ylim(-1.25 * worst, 1.25 * worst)
    ax.set_ylabel("(p̂ − model) / s.e.", fontsize="small")
    ax.legend(fontsize="xx-small", ncols=3, loc="upper left")


__all__ = ["model_distance", "plot_edge", "simulation_text"]

"""Figures of the landing report (:mod:`coinflight.studies.landing`): the (e, μ) maps, the
nickel's P(edge) band over what is not measured, and coinflight beside MuJoCo. The dead
landings reuse :func:`coinflight.plotting.edge.plot_edge`."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight.plotting.style import (
    EDGE_COLOR,
    EXACT_COLOR,
    HEADS_COLOR,
    TAILS_COLOR,
    method_color,
    new_figure,
)
from coinflight.studies.landing import (
    DROP_HEIGHT,
    EDGE_PATHS,
    MURRAY_TEARE,
    Band,
    BouncingEdges,
    ContactMaps,
    DeadLanding,
    MujocoComparison,
    NickelBand,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def plot_dead_and_bouncing(
    dead: Sequence[DeadLanding], bouncing: BouncingEdges | None = None
) -> Figure:
    """Yong & Mahadevan's models with the simulated dead landings
    (:func:`coinflight.plotting.edge.plot_edge`) and, when given, the same tosses bouncing:
    at each ratio a bar from the lowest to the highest cell of the box of e, μ and the
    resistances, ±2 s.e. at its ends."""
    from coinflight.plotting.edge import plot_edge

    fig = plot_edge([(d.ratio, d.simulated) for d in dead])
    if bouncing is None:
        return fig
    ax = fig.axes[0]
    for k, ratio in enumerate(bouncing.ratios):
        (lo, lo_se), (hi, hi_se) = bouncing.low(k), bouncing.high(k)
        ax.plot(
            [ratio + 0.012] * 2,
            [max(lo - 2 * lo_se, 0.0), hi + 2 * hi_se],
            color=EDGE_COLOR,
            linewidth=3,
            alpha=0.7,
            solid_capstyle="butt",
            label=(
                "bouncing, e {:g}–{:g}, μ {:g}–{:g}, ℓ {:g}–{:g} m (lowest to highest ".format(
                    *bouncing.ranges("restitution"),
                    *bouncing.ranges("friction"),
                    *bouncing.ranges("resistance"),
                )
                + f"cell ±2 s.e., {bouncing.n:,} tosses a cell)"
                if k == 0
                else None
            ),
        )
    legend = ax.get_legend()  # plot_edge's, titled with what was simulated
    title = legend.get_title().get_text() if legend is not None else ""
    ax.set_ylim(0.0, 1.4 * ax.get_ylim()[1])  # room above the curves for the legend
    ax.legend(  # upper left: the bouncing bars reach into plot_edge's lower right corner
        loc="upper left",
        fontsize="xx-small",
        title=title or None,
        title_fontsize="xx-small",
        alignment="left",
    )
    return fig


def plot_contact_maps(maps: ContactMaps, coin_name: str = "US nickel") -> Figure:
    """Two maps over restitution e (x) and friction μ (y): P(same side at rest) (diverging
    about 1/2) and P(edge), each cell annotated with its value; ``maps.n`` tosses per cell."""
    fig = new_figure(figsize=(11.0, 4.8))
    axes = fig.subplots(1, 2)
    # one cell per computed (e, μ), labelled with its values: a table of cells, so the axes show
    # only the values computed (none below 0, none between them)
    worst = float(np.max(np.abs(maps.same - 0.5)))
    panels = (
        (maps.same, "P(same side at rest)", "RdBu_r", 0.5 - worst, 0.5 + worst),
        (maps.edge, "P(edge)", "Greens", 0.0, max(float(maps.edge.max()), 1e-9)),
    )
    for ax, (values, label, cmap, lo, hi) in zip(axes, panels, strict=True):
        im = ax.pcolormesh(values, cmap=cmap, vmin=lo, vmax=hi)
        fig.colorbar(im, ax=ax, label=label)
        if values.size <= 150:
            for i, j in np.ndindex(values.shape):
                ax.text(
                    j + 0.5,
                    i + 0.5,
                    f"{values[i, j]:.3f}",
                    ha="center",
                    va="center",
                    fontsize=6,
                    color=_ink(im.cmap(im.norm(values[i, j]))),
                )
        ax.set_xticks(np.arange(len(maps.restitution)) + 0.5, [f"{e:g}" for e in maps.restitution])
        ax.set_yticks(np.arange(len(maps.friction)) + 0.5, [f"{m:g}" for m in maps.friction])
        ax.set_xlabel("restitution e")
        ax.set_ylabel("friction μ")
        ax.set_title(label, fontsize="medium")
    se = float(maps.stderr(np.full(1, 0.5))[0])
    fig.suptitle(
        f"{coin_name} tossed heads up, landing on a table {DROP_HEIGHT:g} m below launch: "
        f"{maps.n:,} tosses per cell, the same in every cell (s.e. ≤ {se:.3f}), seed "
        f"{maps.seed}",
        fontsize="medium",
    )
    return fig


def _ink(rgba: tuple[float, ...]) -> str:
    """Black or white, whichever contrasts more with a cell of colour ``rgba``: white when the
    colour's relative luminance L (WCAG 2, sRGB) is below 0.179, where the contrast ratios
    (1.05 / (L + 0.05) for white, (L + 0.05) / 0.05 for black) are equal."""

    def linear(x: float) -> float:
        return x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4

    r, g, b = (linear(x) for x in rgba[:3])
    return "white" if 0.2126 * r + 0.7152 * g + 0.0722 * b < 0.179 else "black"


def _band_row(ax: Any, k: int, band: Band, words: tuple[str, str, str]) -> None:
    """Row ``k`` of a nickel band figure: the band's cells (points, ±2 s.e.), the band from
    the lowest to the highest (shaded) and the value integrated over its box (diamond, ±2
    s.e.); ``words``: what the cells are, one cell, the box (the legend's, first row only)."""
    y = float(k)
    cells = band.edge.ravel()
    if not np.isnan(band.centre):
        cells = np.append(cells, band.centre)
    se = np.sqrt(cells * (1 - cells) / band.n)
    ax.errorbar(
        cells,
        y + np.linspace(-0.2, 0.2, cells.size),
        xerr=2 * se,
        fmt="o",
        color=EDGE_COLOR,
        markersize=3,
        alpha=0.7,
        label=f"{words[0]} (±2 s.e.)" if k == 0 else None,
    )
    ax.fill_betweenx(
        [y - 0.3, y + 0.3],
        band.low[0],
        band.high[0],
        color=EDGE_COLOR,
        alpha=0.15,
        label=f"band: lowest to highest {words[1]}" if k == 0 else None,
    )
    p = band.integrated
    ax.errorbar(
        [p.p],
        [y + 0.38],
        xerr=[2 * p.stderr],
        fmt="D",
        color=method_color("monte-carlo"),
        label=f"integrated over {words[2]} (±2 s.e.)" if k == 0 else None,
    )


def _nickel_axes(ax: Any, bands: Sequence[Band]) -> None:
    """Murray & Teare's 1 in 6000 (line) and the presets' rows of a nickel band figure."""
    ax.axvline(
        MURRAY_TEARE,
        color=EXACT_COLOR,
        linestyle="--",
        linewidth=1,
        label="Murray & Teare 1993: 1 in 6000 (extrapolated)",
    )
    ax.set_yticks(range(len(bands)))
    ax.set_yticklabels([b.preset for b in bands])
    ax.set_ylim(-0.6, len(bands) - 0.4 + 0.2)


def plot_nickel_band(r: NickelBand) -> Figure:
    """The nickel's P(edge) per surface preset (left): the 16 corners and the centre of the box
    of e, μ, resistance and corner radius (points, ±2 s.e.), the band from the lowest to the
    highest, the value integrated over the box (diamond, ±2 s.e.), Murray & Teare's 1 in 6000
    (line); and (right) the integrated tosses' edges by how they ended
    (:data:`~coinflight.studies.landing.EDGE_PATHS`, shares of the edges)."""
    bands = r.bands
    fig = new_figure(figsize=(9.0, 2.8 + 1.1 * len(bands)))
    ax, shares = fig.subplots(1, 2, sharey=True, gridspec_kw={"width_ratios": (3, 2)})
    for k, band in enumerate(bands):
        y = float(k)
        _band_row(ax, k, band, ("corners and centre of the box", "cell", "the box"))
        edges = band.integrated_paths
        left = 0.0
        for j, (name, count) in enumerate(zip(EDGE_PATHS, edges, strict=True)):
            width = count / edges.sum() if edges.sum() else 0.0
            shares.barh(
                y,
                width,
                left=left,
                height=0.5,
                color=(EXACT_COLOR, EDGE_COLOR, HEADS_COLOR, TAILS_COLOR)[j],
                label=name if k == 0 else None,
            )
            left += width
    _nickel_axes(ax, bands)
    ax.set_xlabel("P(edge) of a US nickel")
    ax.set_xlim(left=0.0)
    below = {"fontsize": "x-small", "loc": "upper center", "bbox_to_anchor": (0.5, -0.2)}
    ax.legend(ncol=2, **below)
    shares.set_xlim(0.0, 1.0)
    shares.set_xlabel("share of the integrated tosses' edges")
    shares.legend(ncol=2, **below)
    fig.suptitle(
        f"US nickel landing on a table {DROP_HEIGHT:g} m below launch: P(edge) over e, μ, "
        "resistance and corner radius, and how the edges ended",
        fontsize="medium",
    )
    return fig


def plot_mujoco(c: MujocoComparison) -> Figure:
    """P(tails, heads, edge) of the same tosses in coinflight and MuJoCo, at the first contact
    and at rest (bars, ±2 s.e.)."""
    fig = new_figure(figsize=(9.0, 4.2))
    axes = fig.subplots(1, 2, sharey=True)
    names = ("tails", "heads", "edge")
    colours = (TAILS_COLOR, HEADS_COLOR, EDGE_COLOR)
    Series = list[tuple[NDArray[np.int8], str | None, str]]
    at_rest: Series = [
        (c.coinflight.rest, None, "coinflight"),
        (c.mujoco_rest, "//", "MuJoCo"),
    ]
    first: Series = [(c.first, None, "coinflight"), (c.mujoco_first, "//", "MuJoCo")]
    panels: tuple[tuple[str, Series], ...] = (("first contact", first), ("at rest", at_rest))
    for ax, (title, series) in zip(axes, panels, strict=True):
        x = np.arange(3)
        width = 0.8 / len(series)
        for k, (faces, hatch, label) in enumerate(series):
            p = c.fractions(faces)
            ax.bar(
                x + (k - (len(series) - 1) / 2) * width,
                p,
                width=0.95 * width,
                color=colours,
                hatch=hatch,
                edgecolor="0.2",
                yerr=2 * c.stderrs(faces),
                capsize=3,
                label=label,
            )
        ax.set_xticks(x)
        ax.set_xticklabels(names)
        ax.set_title(title, fontsize="medium")
        ax.legend(fontsize="x-small")
    top = max(float(np.max(c.fractions(f))) for _, series in panels for f, _, _ in series)
    axes[0].set_ylim(0.0, 1.3 * top + 0.02)  # shared: room for the legends above the bars
    axes[0].set_ylabel("fraction of tosses (±2 s.e.)")
    fig.suptitle(
        f"{c.n:,} identical tosses (seed {c.seed}), e = {c.restitution:g}, μ = "
        f"{c.friction:g}; bars left to right as in the legends",
        fontsize="small",
    )
    return fig


__all__ = ["plot_contact_maps", "plot_dead_and_bouncing", "plot_mujoco", "plot_nickel_band"]

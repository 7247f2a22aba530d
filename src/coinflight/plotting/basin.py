"""Drawing heads/tails maps (:class:`~coinflight.studies.basin.BasinMap`) in the (T, ω) plane.

The map is computed by :func:`coinflight.studies.basin.basin_map`; here it is only drawn, with
the analytic boundaries of the hand catch (Keller 1986; Diaconis, Holmes & Montgomery 2007).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from coinflight.core import ballistics
from coinflight.core.outcome import EDGE, HEADS, TAILS

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from coinflight.studies.basin import BasinMap


def plot_basin(
    basin: BasinMap,
    *,
    title: str | None = None,
    boundaries: bool = True,
    ending: str = "caught",
) -> Figure:
    """Draw a :class:`BasinMap`: heads and tails cells, analytic boundaries, launch speed on top.

    Parameters
    ----------
    basin : BasinMap
        The map.
    title : str, optional
        Replaces the default title, which names the coin, start face, fixed spins, grid and
        face fractions.
    boundaries : bool
        Draw the analytic heads/tails boundaries (they belong to the hand catch).
    ending : str
        How the toss ends, for the default title ("caught", or a table landing).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.colors import BoundaryNorm, ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from coinflight.plotting.style import EDGE_COLOR, HEADS_COLOR, TAILS_COLOR, new_figure

    curves = basin.boundaries() if boundaries else []  # refused before anything is drawn
    fig = new_figure(figsize=(7.2, 5.6))
    ax = fig.add_subplot()
    cmap = ListedColormap([TAILS_COLOR, HEADS_COLOR, EDGE_COLOR])
    norm = BoundaryNorm([-0.5, 0.5, 1.5, 2.5], cmap.N)
    (t_lo, t_hi), (w_lo, w_hi) = basin.flight_time_range, basin.spin_range
    ax.imshow(
        basin.face,
        origin="lower",
        extent=(t_lo, t_hi, w_lo, w_hi),
        aspect="auto",
        cmap=cmap,
        norm=norm,
        interpolation="nearest",
        resample=False,
    )
    handles: list[Patch | Line2D] = [
        Patch(color=HEADS_COLOR, label=f"heads ({basin.fraction(HEADS):.1%} of the map)"),
        Patch(color=TAILS_COLOR, label=f"tails ({basin.fraction(TAILS):.1%})"),
    ]
    if basin.fraction(EDGE) > 0:
        handles.append(Patch(color=EDGE_COLOR, label=f"edge ({basin.fraction(EDGE):.1%})"))
    if boundaries:
        for t, w in curves:
            ax.plot(t, w, color="black", lw=0.7)
        if curves:
            label = (
                "Keller's hyperbolas Ω T = (2n ± ½)π"
                if basin.planar
                else "boundaries cos²ψ + sin²ψ cos(ωp T) = 0"
            )
            handles.append(Line2D([], [], color="black", lw=0.7, label=label))
    ax.set_xlim(t_lo, t_hi)
    ax.set_ylim(w_lo, w_hi)
    ax.set_xlabel("flight time back to launch height, T = 2 v0 / g (s)")
    if basin.axis == "x":
        ax.set_ylabel("spin about a diameter ωx0 (rad/s)")
    else:
        ax.set_ylabel("precession rate ωp = |S| / I1 (rad/s)")
    g = basin.g
    top = ax.secondary_xaxis(
        "top",
        functions=(
            lambda t: ballistics.launch_speed(np.asarray(t), g),
            lambda u: ballistics.flight_time(np.asarray(u), g),
        ),
    )
    top.set_xlabel("launch speed v0 = g T / 2 (m/s)")
    ax.legend(
        handles=handles,
        loc="upper center",
        bbox_to_anchor=(0.5, -0.12),
        ncols=2,
        fontsize=9,
        frameon=False,
    )
    if basin.axis == "x":
        spin = f"ωy0 = {basin.omega_y:g} rad/s, ωz0 = {basin.omega_z:g} rad/s"
    else:
        assert basin.psi is not None
        spin = f"cone angle ψ = {math.degrees(basin.psi):g}°"
    n_w, n_t = basin.face.shape
    edge = f", P(edge) = {basin.fraction(EDGE):.4f}" if basin.fraction(EDGE) > 0 else ""
    fig.suptitle(
        title
        or f"Which face a {basin.coin.name} shows, tossed {basin.start} up and {ending}\n"
        f"{spin}; {n_t}×{n_w} grid: P(heads) = {basin.heads_fraction:.4f}{edge}",
        fontsize=11,
    )
    return fig


__all__ = ["plot_basin"]

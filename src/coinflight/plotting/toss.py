"""The coin at launch and at catch, drawn as in Stefan & Cheche's Figs 2c-d and 3c-f.

Each panel shows the coin's rim at launch (vermillion) and at catch (blue) about its centre of
mass, the caught coin's heads face blue and tails face orange, with the heads normal n and the
angular momentum S as arrows; a last panel shows the path of n
on the unit sphere, the precession cone about S (Diaconis, Holmes & Montgomery 2007).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core.outcome import FACE_NAMES
from coinflight.plotting.style import (
    CATCH_COLOR,
    HEADS_COLOR,
    LAUNCH_COLOR,
    TAILS_COLOR,
    new_figure,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure
    from scipy.spatial.transform import Rotation

    from coinflight.model.coin import Coin
    from coinflight.model.toss import Toss

FloatArray = NDArray[np.float64]
S_COLOR = "#000000"
ARROW_SCALE = 1.5
"""Unit vectors n and Ŝ are drawn ARROW_SCALE coin radii long."""
SPHERE_AZIM = -60.0
"""Azimuth of the view of the unit sphere, degrees (matplotlib's default)."""
PANEL_ZOOM = 0.85
"""Size of a 3-D box within its panel (matplotlib's ``zoom``); 1 lets labels spill out."""
CURVE_POINTS_PER_TURN = 60
"""Points a turn of the normal's path on the sphere (smooth at the figure's size)."""
MAX_CURVE_POINTS = 200_000
"""Most points of a drawn path (plot_toss's sphere, the animation's n·Z curve): 3,300 turns at
60 a turn (a toss makes 5-50); more than twice as many take over half a minute to draw."""
MAX_PANELS = 100
"""Most tosses (panels) one figure draws."""
VIEW_ELEVATION = 35.0
"""Elevation (degrees) of each coin panel's camera: from above, so that the face up is seen."""
VIEW_TURN = 40.0
"""Degrees the camera is turned away from the up face's own direction, so that the launch and
the catch do not hide each other and the tilt still reads."""
DEFAULT_AZIM = -30.0
TITLE_GAP = 0.12
"""Inches of space constrained layout keeps around each panel (its default 0.04 let the figure's
title touch the top panels' titles)."""
"""Azimuth of a coin panel whose catch lies flat (no horizontal direction to look along)."""


def coin_rim(attitude: Rotation, radius: float, n_points: int = 121) -> FloatArray:
    """Points of the coin's rim about its centre of mass, lab frame, shape (..., n_points, 3).

    Parameters
    ----------
    attitude : scipy.spatial.transform.Rotation
        Body → lab rotation (one or a stack).
    radius : float
        Coin radius R, in the length unit wanted for the points.
    n_points : int
        Points along the rim (the first and last coincide, closing the curve).

    Notes
    -----
    Stefan & Cheche section 3: C(s) = R cos s u + R sin s (n × u), n the heads normal and u a
    unit vector in the coin's plane, here the body x axis in the lab frame.
    """
    u = np.asarray(attitude.apply([1.0, 0.0, 0.0]))
    n = np.asarray(attitude.apply([0.0, 0.0, 1.0]))
    w = np.cross(n, u)
    s = np.linspace(0.0, 2.0 * np.pi, n_points)
    c, sn = np.cos(s)[:, None], np.sin(s)[:, None]
    return radius * (c * u[..., None, :] + sn * w[..., None, :])


def normal_path(coin: Coin, toss: Toss, t: ArrayLike) -> FloatArray:
    """Heads normal n(t) in the lab frame, shape (len(t), 3): the precession cone.

    For a batch, the path of its first toss.
    """
    from coinflight.model.toss import Flight, Toss

    single = Toss(
        omega=toss.omega.reshape(-1, 3)[0], flight_time=np.ones(()), start=toss.start, g=toss.g
    )
    return np.asarray(Flight(coin, single).at(np.asarray(t, dtype=float)).normal)


def plot_toss(coin: Coin, toss: Toss, *, title: str | None = None, ncols: int = 2) -> Figure:
    """Coin at launch (vermillion) and at catch (blue), one panel per toss, and the precession cone.

    Parameters
    ----------
    coin : Coin
        The coin.
    toss : Toss
        One toss, or a one-dimensional batch (for instance one spin and several flight times,
        Stefan & Cheche Figs 3c-f); each toss gets a panel showing its catch at t = T.
    title : str, optional
        Figure title; by default it says which coin, spin and start.
    ncols : int
        Panels per row for the coin drawings.

    Returns
    -------
    matplotlib.figure.Figure
        Coin panels in mm about the centre of mass (arrows n and Ŝ drawn 1.5 R long), and a
        unit-sphere panel with the path of n from launch to the last catch.
    """
    from matplotlib.gridspec import GridSpec
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from coinflight.model.toss import Flight, Toss

    if len(toss.shape) > 1:
        raise ValueError(
            f"plot_toss draws one toss or a one-dimensional batch, got shape {toss.shape}"
        )
    k = int(np.prod(toss.shape)) if toss.shape else 1
    v.count("number of panels (flight times)", k, 1, MAX_PANELS)
    flight = Flight(coin, toss)
    catch = flight.catch
    outcome = flight.outcome
    times = np.atleast_1d(np.broadcast_to(toss.flight_time, toss.shape))
    normals = np.asarray(catch.normal).reshape(k, 3)
    s_lab = np.asarray(catch.angular_momentum).reshape(k, 3)
    faces = np.atleast_1d(outcome.face)
    turns = np.atleast_1d(outcome.rotations)
    omegas = np.broadcast_to(toss.omega, (*toss.shape, 3)).reshape(k, 3)
    spins, which = np.unique(omegas, axis=0, return_inverse=True)
    samples_per_spin = [
        max(400, CURVE_POINTS_PER_TURN * float(turns[np.ravel(which) == j].max()))
        for j in range(len(spins))
    ]
    v.work_bound(
        f"the path of the normal over {float(turns.max()):.3g} turns ({CURVE_POINTS_PER_TURN} "
        "points a turn)",
        sum(samples_per_spin),
        MAX_CURVE_POINTS,
        "points",
        "use a smaller spin or flight time (the sphere cannot show so many turns)",
    )
    psi = np.atleast_1d(outcome.psi)
    launch = Flight(coin, toss).at(0.0 * toss.flight_time)
    r_mm = coin.radius * 1e3
    rim0 = coin_rim(launch.attitude, r_mm).reshape(k, -1, 3)
    rim1 = coin_rim(catch.attitude, r_mm).reshape(k, -1, 3)
    n0 = np.asarray(launch.normal).reshape(k, 3)

    distinct_spins = len(spins)
    ncols = max(1, min(ncols, k))
    nrows = math.ceil(k / ncols)
    fig = new_figure(figsize=(3.6 * ncols + 4.2, max(4.4 * nrows, 4.6)))
    grid = GridSpec(nrows, ncols + 1, figure=fig, width_ratios=[1.0] * ncols + [1.15])
    lim = ARROW_SCALE * r_mm
    azimuth = shared_azimuth(normals)  # one viewpoint: the panels compare like with like
    for i in range(k):
        ax: Any = fig.add_subplot(grid[i // ncols, i % ncols], projection="3d")
        ax.computed_zorder = False  # drawn in order: launch, the caught coin's faces, its rim
        _draw_coin(ax, rim0[i], LAUNCH_COLOR)
        _draw_faces(ax, rim1[i], normals[i], coin.thickness * 1e3)
        _draw_coin(ax, rim1[i], CATCH_COLOR, fill=False)  # its faces are drawn
        _arrow(ax, n0[i] * lim, LAUNCH_COLOR, label="n(0)")
        _arrow(ax, normals[i] * lim, CATCH_COLOR, label="n(T)")
        s_norm = float(np.linalg.norm(s_lab[i]))
        if s_norm > 0:
            _arrow(ax, s_lab[i] / s_norm * lim, S_COLOR, style="--", label="S")
        ax.set_xlim(-lim, lim)
        ax.set_ylim(-lim, lim)
        ax.set_zlim(-lim, lim)
        # zoom < 1 keeps the axis labels inside the panel, clear of the next row and the legend.
        ax.set_box_aspect((1, 1, 1), zoom=PANEL_ZOOM)
        ax.view_init(elev=VIEW_ELEVATION, azim=azimuth)
        ticks = [-round(r_mm), 0, round(r_mm)]
        ax.set_xticks(ticks)
        ax.set_yticks(ticks)
        ax.set_zticks(ticks)
        ax.set_xlabel("X (mm)")
        ax.set_ylabel("Y (mm)")
        ax.set_zlabel("Z, up (mm)")
        spin = "" if distinct_spins == 1 else "ω0 = ({:g}, {:g}, {:g}) rad/s, ".format(*omegas[i])
        ax.set_title(
            f"{spin}T = {times[i]:g} s: {turns[i]:.4g} turns,\n"
            f"lands {FACE_NAMES[int(faces[i])].upper()} up",
            fontsize=10,
        )

    sphere: Any = fig.add_subplot(grid[:, ncols], projection="3d")
    _draw_sphere(sphere)
    # One path per distinct spin (a batch of flight times shares one cone), up to its last catch.
    for j, w in enumerate(spins):
        mine = np.ravel(which) == j
        one = Toss(omega=w, flight_time=np.ones(()), start=toss.start, g=toss.g)
        samples = int(samples_per_spin[j])
        path = normal_path(coin, one, np.linspace(0.0, float(times[mine].max()), samples))
        sphere.plot(*path.T, color="#555555", lw=0.8)
        s_hat = s_lab[mine][0] / max(float(np.linalg.norm(s_lab[mine][0])), 1e-300)
        _arrow(sphere, 1.3 * s_hat, S_COLOR, style="--", label="S" if j == 0 else "")
    for start_n in np.unique(n0, axis=0):
        sphere.scatter(*start_n, color=LAUNCH_COLOR, s=40, depthshade=False)
    sphere.scatter(*normals.T, color=CATCH_COLOR, s=40, depthshade=False)
    if k > 1:  # which catch is which: the label beside its point, on the outer side on screen
        azim = math.radians(SPHERE_AZIM)
        right = np.array([-math.sin(azim), math.cos(azim), 0.0])  # screen-right, in the lab
        for i in range(k):
            side = 1.0 if normals[i] @ right >= 0 else -1.0
            sphere.text(
                *(normals[i] + 0.12 * side * right),
                f"T = {times[i]:g} s",
                color=CATCH_COLOR,
                fontsize=8,
                ha="left" if side > 0 else "right",
                va="center",
                bbox={"facecolor": "white", "alpha": 0.8, "edgecolor": "none", "pad": 0.5},
            )
    for end in (n0[0], *normals):
        sphere.plot(*np.stack([np.zeros(3), end]).T, color="#999999", lw=0.6, ls=":")
    psi_deg = np.degrees(psi)
    cone = (
        f"ψ = {psi_deg.min():.1f}°"
        if np.ptp(psi_deg) < 0.05
        else f"ψ = {psi_deg.min():.1f}° to {psi_deg.max():.1f}°"
    )
    sphere.set_title(
        f"path of n on the unit sphere\n(cone of half-angle {cone} about S)", fontsize=10
    )
    for setter in (sphere.set_xlim, sphere.set_ylim, sphere.set_zlim):
        setter(-1.1, 1.1)
    sphere.set_box_aspect((1, 1, 1), zoom=PANEL_ZOOM)
    sphere.view_init(elev=30, azim=SPHERE_AZIM)
    for set_ticks in (sphere.set_xticks, sphere.set_yticks, sphere.set_zticks):
        set_ticks([-1.0, 0.0, 1.0])
    sphere.set_xlabel("nX")
    sphere.set_ylabel("nY")
    sphere.set_zlabel("nZ")

    handles = [
        Line2D([], [], color=LAUNCH_COLOR, lw=2, marker="o", label="coin and n at launch, t = 0"),
        Line2D([], [], color=CATCH_COLOR, lw=2, marker="o", label="coin and n at catch, t = T"),
        Patch(facecolor=HEADS_COLOR, alpha=0.6, label="heads face of the caught coin (H)"),
        Patch(facecolor=TAILS_COLOR, alpha=0.6, label="tails face of the caught coin (T)"),
        Line2D([], [], color="#555555", lw=1, label="path of the heads normal n(t)"),
        Line2D([], [], color=S_COLOR, lw=1.5, ls="--", label="angular momentum S (direction)"),
    ]
    fig.legend(handles=handles, loc="outside lower center", ncols=2, fontsize=9)
    spin_text = (
        "ω0 = ({:g}, {:g}, {:g}) rad/s".format(*spins[0])
        if len(spins) == 1
        else f"{len(spins)} different spins"
    )
    fig.suptitle(
        title or f"{coin.name} tossed {toss.start} up with {spin_text}, caught at launch height",
        fontsize=11,
    )
    # constrained layout packs the suptitle against the 3-D panels' titles: room between them
    fig.get_layout_engine().set(h_pad=TITLE_GAP)  # type: ignore[union-attr, call-arg]
    return fig


def shared_azimuth(normals: FloatArray) -> float:
    """Azimuth (degrees) of the one camera of every coin panel (heads normals ``normals``,
    shape (k, 3)): :func:`catch_azimuth` for one toss; for several, of the azimuths at whole
    degrees (and each toss's own), the one whose view of the worst-seen face up is best (the
    largest least cosine between the camera and a face up, from :data:`VIEW_ELEVATION`), so
    that no panel shows its coin edge-on when another view would not."""
    normals = np.asarray(normals, dtype=float).reshape(-1, 3)
    if len(normals) == 1:
        return catch_azimuth(normals[0])
    up = np.where(normals[:, 2:3] >= 0, normals, -normals)
    candidates = np.concatenate(
        [[catch_azimuth(n) for n in normals], np.arange(-180.0, 180.0, 1.0)]
    )
    el, az = math.radians(VIEW_ELEVATION), np.radians(candidates)
    view = np.stack(
        [math.cos(el) * np.cos(az), math.cos(el) * np.sin(az), np.full_like(az, math.sin(el))],
        axis=-1,
    )
    worst = (view @ up.T).min(axis=1)
    return float(candidates[int(np.argmax(worst))])


def catch_azimuth(normal: FloatArray) -> float:
    """Azimuth (degrees) of a camera that sees the face up of a coin whose heads normal is n.

    The camera looks along the horizontal part of the up face's normal (n if n·Z ≥ 0, else
    −n), turned by :data:`VIEW_TURN`, from :data:`VIEW_ELEVATION` above, so the face up is
    seen obliquely from its own side rather than edge-on; :data:`DEFAULT_AZIM` for a coin
    lying flat.
    """
    up = normal if normal[2] >= 0 else -normal
    if math.hypot(up[0], up[1]) < 1e-6:
        return DEFAULT_AZIM
    return math.degrees(math.atan2(up[1], up[0])) - VIEW_TURN


def _draw_faces(ax: Any, rim: FloatArray, normal: FloatArray, thickness: float) -> None:
    """The two faces of a coin, heads and tails coloured, half a thickness either side, and
    its face up marked with a letter (H or T) above its centre."""
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    half = 0.5 * thickness * normal
    up = 1.0 if normal[2] >= 0 else -1.0
    # The face down first and faint, the face up over it (the camera is above: it sees the face
    # up); the panel draws in this order (computed_zorder off).
    faces = ((1.0, HEADS_COLOR), (-1.0, TAILS_COLOR))
    for sign, color in sorted(faces, key=lambda f: f[0] * up):
        alpha = 0.75 if sign == up else 0.08
        face = Poly3DCollection([rim + sign * half], facecolor=color, alpha=alpha, edgecolor="none")
        ax.add_collection3d(face)
    radius = float(np.linalg.norm(rim[0]))
    ax.text(
        *(up * normal * 0.35 * radius),
        "H" if up > 0 else "T",
        color="white",
        fontsize=13,
        fontweight="bold",
        ha="center",
        va="center",
        bbox={
            "facecolor": HEADS_COLOR if up > 0 else TAILS_COLOR,
            "edgecolor": "none",
            "boxstyle": "circle,pad=0.2",
        },
    )


def _draw_coin(ax: Any, rim: FloatArray, color: str, fill: bool = True) -> None:
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    if fill:
        ax.add_collection3d(Poly3DCollection([rim], facecolor=color, alpha=0.25, edgecolor="none"))
    ax.plot(*rim.T, color=color, lw=2)


def _arrow(ax: Any, vec: FloatArray, color: str, style: str = "-", label: str = "") -> None:
    ax.quiver(0, 0, 0, *vec, color=color, arrow_length_ratio=0.15, linestyle=style, lw=1.5)
    if label:
        ax.text(*(1.12 * vec), label, color=color, fontsize=9, ha="center", va="center")


def _draw_sphere(ax: Any) -> None:
    u = np.linspace(0.0, 2.0 * np.pi, 37)
    v = np.linspace(0.0, np.pi, 19)
    x = np.outer(np.cos(u), np.sin(v))
    y = np.outer(np.sin(u), np.sin(v))
    z = np.outer(np.ones_like(u), np.cos(v))
    ax.plot_wireframe(x, y, z, color="#cccccc", lw=0.4, rstride=3, cstride=3)


__all__ = ["catch_azimuth", "coin_rim", "normal_path", "plot_toss"]

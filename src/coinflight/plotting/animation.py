"""An animated toss: the coin rising, turning and falling, the face up and a clock.

GIF through Pillow (always available with matplotlib); MP4 through ffmpeg, only where an
``ffmpeg`` executable is installed.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from coinflight import _validation as v
from coinflight._files import replacing
from coinflight.core.outcome import FACE_NAMES, HEADS, face_from_alignment
from coinflight.plotting.style import HEADS_COLOR, TAILS_COLOR, new_figure
from coinflight.plotting.toss import MAX_CURVE_POINTS, coin_rim

if TYPE_CHECKING:
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    from coinflight.model.coin import Coin
    from coinflight.model.toss import Toss

FACE_COLORS = {HEADS: HEADS_COLOR, 0: TAILS_COLOR}
MAX_FRAMES = 2000
"""Most frames a movie may have (each is drawn and held in memory as an image: ~1 MB)."""
CURVE_POINTS_PER_TURN = 40
"""Points a turn of the n·Z curve beside the coin (at most :data:`MAX_CURVE_POINTS`)."""

_TAG: dict[str, Any] = {
    "fontsize": 10,
    "weight": "bold",
    "bbox": {"facecolor": "white", "alpha": 0.85, "edgecolor": "none", "pad": 1.5},
}
"""The n·Z panel's "heads up" / "tails up": bold on white, readable over the curve."""

MOVIE_DPI = 120
"""Default resolution of a movie: its 8 × 6.4 inch figure becomes 960 × 768 pixels, the labels
readable on a projector (80 gave 640 × 512 and text a few pixels high)."""


@dataclass(frozen=True, eq=False)
class TossAnimation:
    """A built animation: the figure, the matplotlib animation and its timing.

    Attributes
    ----------
    figure : matplotlib.figure.Figure
    times : ndarray, shape (frames,)
        Flight time shown by each frame, s.
    faces : ndarray of int8, shape (frames,)
        Face up (the one whose normal points up) in each frame.
    fps : int
        Frames per second when saved.
    draw_frame : callable
        ``draw_frame(i)`` sets the figure to frame i and returns the artists it changed.
    """

    figure: Figure
    times: np.ndarray
    faces: np.ndarray
    fps: int
    draw_frame: Callable[[int], tuple[Any, ...]]

    def to_matplotlib(self) -> FuncAnimation:
        """A :class:`matplotlib.animation.FuncAnimation` (e.g. ``.to_jshtml()`` in a notebook)."""
        from matplotlib.animation import FuncAnimation

        return FuncAnimation(
            self.figure,
            self.draw_frame,
            frames=len(self.times),
            interval=1000 / self.fps,
            blit=False,
        )

    def rgb_frames(self, dpi: int = MOVIE_DPI) -> Iterator[np.ndarray]:
        """Each frame as an (h, w, 3) uint8 array, drawn by blitting over a static background.

        The axes, labels and curves are drawn once; only the coin, its normal, the clock and the
        markers are redrawn per frame, which is several times faster than redrawing the figure.
        """
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        fig = self.figure
        canvas = FigureCanvasAgg(fig)
        old_dpi = fig.dpi
        fig.set_dpi(dpi)
        moving = self.draw_frame(0)
        try:
            for artist in moving:
                artist.set_animated(True)
            # Lay out once at this resolution (text sizes scale with dpi), then freeze it.
            fig.set_layout_engine("constrained")
            canvas.draw()
            fig.set_layout_engine("none")
            background = canvas.copy_from_bbox(fig.bbox)
            for i in range(len(self.times)):
                self.draw_frame(i)
                canvas.restore_region(background)
                for artist in moving:
                    if hasattr(artist, "do_3d_projection"):
                        artist.do_3d_projection()
                    artist.axes.draw_artist(artist)
                yield np.array(canvas.buffer_rgba())[..., :3]
        finally:
            for artist in moving:
                artist.set_animated(False)
            fig.set_dpi(old_dpi)

    def save(self, path: str | os.PathLike[str], dpi: int = MOVIE_DPI) -> Path:
        """Write a .gif (Pillow) or .mp4 (ffmpeg), whole or not at all: :func:`save_animation`."""
        return save_animation(self, path, dpi=dpi)


ENLARGE = v.Quantity("enlarge", "", 1e-3, 1e6)
"""How many times larger than life the coin may be drawn: a thousandth to a million (a drawn
coin of 10⁻³²⁰ cm makes a singular 3-D projection; one of 10³⁰⁸ cm, infinite axis limits)."""


def animate_toss(
    coin: Coin,
    toss: Toss,
    *,
    frames: int | None = None,
    fps: int = 24,
    enlarge: float | None = None,
) -> TossAnimation:
    """Animate one toss from launch to catch, in slow motion.

    Parameters
    ----------
    coin : Coin
    toss : Toss
        A single toss.
    frames : int, optional
        Number of frames from t = 0 to t = T; by default 16 per turn of the normal (at least 60,
        at most 400), so that the turning reads smoothly.
    fps : int
        Frames per second of the saved animation.
    enlarge : float, optional
        How many times larger than life the coin is drawn (a 24 mm coin is invisible against a
        60 cm flight); by default so that its diameter is a sixth of the height reached.

    Returns
    -------
    TossAnimation

    Notes
    -----
    Height z(t) = v0 t − g t²/2 (Stefan & Cheche §2) and attitude from the closed form
    (:func:`coinflight.core.torque_free.attitude`); the face up at each frame is the sign of
    n(t)·Z, the rule of eq 14 applied at every instant.
    """
    from matplotlib.patches import Patch
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    from coinflight.model.toss import Flight

    if toss.shape:
        raise ValueError(f"animate_toss animates a single toss, got a batch of shape {toss.shape}")
    if enlarge is not None:
        enlarge = ENLARGE.check(enlarge)
    flight = Flight(coin, toss)
    t_end = float(toss.flight_time)
    turns = float(flight.outcome.rotations)
    v.work_bound(
        f"the n·Z curve of a toss turning {turns:.3g} times ({CURVE_POINTS_PER_TURN} points a "
        "turn)",
        CURVE_POINTS_PER_TURN * turns,
        MAX_CURVE_POINTS,
        "points",
        "use a smaller spin or flight time (a movie of 400 frames cannot show so many turns)",
    )
    if frames is None:
        frames = int(np.clip(16 * turns, 60, 400))
    v.count("frames", frames, 2, MAX_FRAMES)
    if not isinstance(fps, int | np.integer) or not 1 <= fps <= 120:
        raise ValueError(f"fps must be a whole number between 1 and 120, got {fps!r}")

    times = np.linspace(0.0, t_end, frames)
    states = flight.at(times)
    normal = np.asarray(states.normal)
    height = np.asarray(states.height)
    faces = face_from_alignment(normal[:, 2], 1.0)
    apex = float(toss.apex)
    if enlarge is None:
        enlarge = max(1.0, apex / (12.0 * coin.radius))
    r_draw = coin.radius * enlarge * 100.0  # cm
    rims = (
        coin_rim(states.attitude, r_draw)
        + np.stack([np.zeros_like(height), np.zeros_like(height), 100.0 * height], axis=-1)[
            :, None, :
        ]
    )

    fig = new_figure(figsize=(8.0, 6.4))
    grid = fig.add_gridspec(2, 2, width_ratios=[1.1, 1.0])
    ax3: Any = fig.add_subplot(grid[:, 0], projection="3d")
    half = 1.3 * r_draw
    z_lo, z_hi = -1.3 * r_draw, 100.0 * apex + 1.3 * r_draw
    ax3.set_xlim(-half, half)
    ax3.set_ylim(-half, half)
    ax3.set_zlim(z_lo, z_hi)
    ax3.set_box_aspect((2 * half, 2 * half, z_hi - z_lo), zoom=1.1)
    ax3.set_xlabel("X (cm)")
    ax3.set_ylabel("Y (cm)")
    ax3.set_zlabel("height (cm)", labelpad=18)  # clear of the tick labels
    ax3.set_xticks([-round(r_draw), 0, round(r_draw)])
    ax3.set_yticks([-round(r_draw), 0, round(r_draw)])
    ax3.plot([0, 0], [0, 0], [0, 100 * apex], color="#bbbbbb", lw=0.8, ls=":")
    disc = Poly3DCollection([rims[0]], facecolor=FACE_COLORS[int(faces[0])], edgecolor="black")
    ax3.add_collection3d(disc)
    (n_line,) = ax3.plot([], [], [], color="black", lw=1.5)
    clock = ax3.text2D(0.0, 1.0, "", transform=ax3.transAxes, fontsize=12, va="top")
    face_text = ax3.text2D(0.0, 0.94, "", transform=ax3.transAxes, fontsize=12, va="top")
    ax3.set_title(f"coin drawn {enlarge:.0f}× enlarged", fontsize=9, loc="right")

    ax_n = fig.add_subplot(grid[0, 1])
    ax_n.axhspan(0, 1.05, color=HEADS_COLOR, alpha=0.15, lw=0)
    ax_n.axhspan(-1.05, 0, color=TAILS_COLOR, alpha=0.15, lw=0)
    fine = np.linspace(0.0, t_end, max(400, int(CURVE_POINTS_PER_TURN * turns)))
    ax_n.plot(fine, np.asarray(flight.at(fine).normal)[:, 2], color="black", lw=1)
    (n_dot,) = ax_n.plot([], [], "o", color="black")
    ax_n.set_xlim(0, t_end)
    ax_n.set_ylim(-1.05, 1.05)
    ax_n.set_ylabel("n·Z (heads normal, up)")
    ax_n.text(0.01 * t_end, 0.9, "heads up", color=HEADS_COLOR, va="top", **_TAG)
    ax_n.text(0.01 * t_end, -0.9, "tails up", color=TAILS_COLOR, va="bottom", **_TAG)

    ax_h = fig.add_subplot(grid[1, 1], sharex=ax_n)
    ax_h.plot(times, 100.0 * height, color="black", lw=1)
    (h_dot,) = ax_h.plot([], [], "o", color="black")
    ax_h.set_xlabel("time since launch t (s)")
    ax_h.set_ylabel("height of the centre (cm)")
    ax_h.set_ylim(0, 105.0 * apex + 1e-9)

    fig.legend(
        handles=[
            Patch(color=HEADS_COLOR, label="heads face up"),
            Patch(color=TAILS_COLOR, label="tails face up"),
        ],
        loc="outside lower center",
        ncols=2,
        fontsize=9,
    )
    wx, wy, wz = (float(x) for x in toss.omega)
    final = FACE_NAMES[int(flight.outcome.face)]
    fig.suptitle(
        f"{coin.name} tossed {toss.start} up, ω0 = ({wx:g}, {wy:g}, {wz:g}) rad/s, "
        f"T = {t_end:g} s\n{turns:.3f} turns, caught {final.upper()} up "
        f"(played {frames / fps / t_end:.0f}× slower than life)",
        fontsize=11,
    )

    def draw(i: int) -> tuple[Any, ...]:
        face = int(faces[i])
        disc.set_verts([rims[i]])
        disc.set_facecolor(FACE_COLORS[face])
        centre = np.array([0.0, 0.0, 100.0 * height[i]])
        tip = centre + 1.4 * r_draw * normal[i]
        n_line.set_data_3d(*np.stack([centre, tip]).T)
        clock.set_text(f"t = {times[i]:.3f} s")
        face_text.set_text(f"{FACE_NAMES[face]} up")
        face_text.set_color(FACE_COLORS[face])
        n_dot.set_data([times[i]], [normal[i, 2]])
        h_dot.set_data([times[i]], [100.0 * height[i]])
        return disc, n_line, clock, face_text, n_dot, h_dot

    draw(0)
    # Lay the figure out once: constrained layout would otherwise rerun on every frame.
    fig.canvas.draw()
    fig.set_layout_engine("none")
    return TossAnimation(figure=fig, times=times, faces=faces, fps=int(fps), draw_frame=draw)


def ffmpeg_available() -> bool:
    """True when matplotlib can find an ``ffmpeg`` executable to write MP4."""
    from matplotlib.animation import writers

    return bool(writers.is_available("ffmpeg"))


def save_animation(
    movie: TossAnimation, path: str | os.PathLike[str], dpi: int = MOVIE_DPI
) -> Path:
    """Write the animation to ``path`` (.gif or .mp4), whole or not at all.

    Raises
    ------
    ValueError
        For another suffix, or .mp4 when ffmpeg is not installed.
    """
    target = Path(path)
    suffix = target.suffix.lower()
    if suffix not in (".gif", ".mp4"):
        raise ValueError(f"animation file must end in .gif or .mp4, got {str(target)!r}")
    if suffix == ".mp4" and not ffmpeg_available():
        raise ValueError(
            f"cannot write {str(target)!r}: MP4 needs the ffmpeg program, which is not "
            "installed here (not found on PATH); install ffmpeg or write a .gif"
        )
    with replacing(target) as tmp:
        if suffix == ".gif":
            _write_gif(movie, str(tmp), dpi)
        else:
            from matplotlib.animation import FFMpegWriter

            movie.to_matplotlib().save(str(tmp), writer=FFMpegWriter(fps=movie.fps), dpi=dpi)
    return target


def _write_gif(movie: TossAnimation, path: str, dpi: int) -> None:
    from PIL import Image

    images = [Image.fromarray(rgb) for rgb in movie.rgb_frames(dpi)]
    images[0].save(
        path,
        format="GIF",
        save_all=True,
        append_images=images[1:],
        duration=round(1000 / movie.fps),
        loop=0,
    )


__all__ = ["TossAnimation", "animate_toss", "ffmpeg_available", "save_animation"]

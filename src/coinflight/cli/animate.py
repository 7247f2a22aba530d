"""``coinflight animate``: one toss in slow motion, as a GIF (or MP4 where ffmpeg is present)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions, TossOptions
from coinflight.cli.options import OUTPUT_HELP, OUTPUT_PANEL, number, out_file
from coinflight.queries.values import build_toss

MovieFile = Annotated[
    Path, out_file(f"Animation to write: .gif (always) or .mp4 (needs ffmpeg). {OUTPUT_HELP}")
]
Frames = Annotated[
    int | None,
    typer.Option(
        "--frames",
        min=2,
        max=2000,
        rich_help_panel=OUTPUT_PANEL,
        help="Frames from launch to catch [default: 16 per turn, 60 to 400].",
    ),
]
Fps = Annotated[
    int,
    typer.Option("--fps", min=1, max=120, rich_help_panel=OUTPUT_PANEL, help="Frames per second."),
]
Enlarge = Annotated[
    float | None,
    typer.Option(
        "--enlarge",
        parser=number,
        metavar="X",
        rich_help_panel=OUTPUT_PANEL,
        help="Draw the coin X times larger than life [default: a sixth of the apex height].",
    ),
]
MovieDpi = Annotated[
    int,
    typer.Option(
        "--dpi",
        min=20,
        max=600,
        rich_help_panel=OUTPUT_PANEL,
        help="Resolution, dots per inch of the 8 × 6.4 inch frame (120: 960 × 768 pixels).",
    ),
]


@command
def animate(
    out: MovieFile,
    args: TossOptions,
    coin: CoinOptions,
    frames: Frames = None,
    fps: Fps = 24,
    enlarge: Enlarge = None,
    dpi: MovieDpi = 120,  # coinflight.plotting.animation.MOVIE_DPI
) -> None:
    """Animate one toss: the coin rising, turning and falling, the face up and a clock.

    Example: coinflight animate --omega 80 0 0 --flight-time 0.7 --out toss.gif
    """
    from coinflight._files import check_writable
    from coinflight.plotting.animation import animate_toss, save_animation

    if out.suffix.lower() not in (".gif", ".mp4"):
        raise ValueError(f"--out must end in .gif or .mp4, got {str(out)!r}")
    check_writable(out)  # before the frames are drawn, not after
    movie = animate_toss(
        coin,
        build_toss(args),
        frames=frames,
        fps=fps,
        enlarge=enlarge,
    )
    path = save_animation(movie, out, dpi=dpi)
    typer.echo(f"wrote {path} ({len(movie.times)} frames at {fps} fps)")


__all__ = ["animate"]

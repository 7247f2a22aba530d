"""``coinflight plot toss`` and ``coinflight plot basin``: the coin drawn, and heads/tails maps."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from coinflight.cli.options import (
    OUTPUT_PANEL,
    TOSS_PANEL,
    CoinName,
    Gravity,
    Mass,
    Radius,
    StartFace,
    Thickness,
    resolve_coin,
)
from coinflight.cli.toss import FlightTime, LaunchSpeed, Omega, build_toss

OutFile = Annotated[
    Path,
    typer.Option(
        "--out",
        "-o",
        metavar="FILE",
        rich_help_panel=OUTPUT_PANEL,
        help="Image file to write; the format follows the suffix (.png, .svg, .pdf).",
    ),
]
Dpi = Annotated[
    int,
    typer.Option("--dpi", min=20, max=1200, rich_help_panel=OUTPUT_PANEL, help="PNG resolution."),
]
Times = Annotated[
    str | None,
    typer.Option(
        "--times",
        metavar="T1,T2,...",
        rich_help_panel=TOSS_PANEL,
        help="Several flight times, s, one panel each (as Stefan & Cheche Figs 3c-f); "
        "replaces --flight-time.",
    ),
]


def parse_numbers(text: str, name: str) -> list[float]:
    """Comma-separated numbers, or a ValueError naming the option and the bad text."""
    parts = [p.strip() for p in text.split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"{name} must be comma-separated numbers such as 0.6,0.65,0.7; got {text!r}"
        ) from None
    return values


def _written(paths: list[Path]) -> None:
    for p in paths:
        typer.echo(f"wrote {p}")


def plot_toss(
    out: OutFile,
    omega: Omega = (80.0, 0.0, 0.0),
    flight_time: FlightTime = None,
    launch_speed: LaunchSpeed = None,
    times: Times = None,
    start: StartFace = "heads",
    g: Gravity = 9.81,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
    dpi: Dpi = 150,
) -> None:
    """Draw the coin at launch (red) and at catch (blue), n and S, and the precession cone.

    Example: coinflight plot toss --omega 90 30 0 --times 0.6,0.65,0.7,0.75 --out fig3.png
    """
    import numpy as np

    from coinflight.plotting.style import save_figure
    from coinflight.plotting.toss import plot_toss as draw
    from coinflight.toss import Toss

    the_coin = resolve_coin(coin, radius, thickness, mass)
    if times is not None:
        if flight_time is not None or launch_speed is not None:
            raise ValueError("give --times or one of --flight-time and --launch-speed, not both")
        values = np.asarray(parse_numbers(times, "--times"))
        the_toss = Toss(omega=omega, flight_time=values, start=start, g=g)  # type: ignore[arg-type]
    else:
        the_toss = build_toss(omega, flight_time, launch_speed, start, g)
    _written(save_figure(draw(the_coin, the_toss), out, dpi=dpi))


__all__ = ["parse_numbers", "plot_toss"]

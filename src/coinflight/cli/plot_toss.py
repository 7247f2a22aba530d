"""``coinflight plot toss``: the coin drawn at launch and at catch, with n, S and the cone."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions, TossOptions
from coinflight.cli.options import TOSS_PANEL, Dpi, OutFile
from coinflight.cli.output import echo_written
from coinflight.cli.parsers import parse_numbers
from coinflight.queries.values import build_toss

if TYPE_CHECKING:
    pass

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


@command
def plot_toss(
    *,
    out: OutFile,
    args: TossOptions,
    times: Times = None,
    coin: CoinOptions,
    dpi: Dpi = 150,
) -> None:
    """Draw the coin at launch (vermillion) and at catch (blue), n and S, and the precession cone.

    Example: coinflight plot toss --omega 90 30 0 --times 0.6,0.65,0.7,0.75 --out fig3.png
    """
    import numpy as np

    from coinflight.model.toss import Toss
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.plotting.toss import plot_toss as draw

    figure_paths(out, "--out")
    if times is not None:
        if args.flight_time is not None or args.launch_speed is not None:
            raise ValueError("give --times or one of --flight-time and --launch-speed, not both")
        values = np.asarray(parse_numbers(times, "--times"))
        the_toss = Toss(omega=args.omega, flight_time=values, start=args.start, g=args.g)  # type: ignore[arg-type]
    else:
        the_toss = build_toss(args)
    echo_written(save_figure(draw(coin, the_toss), out, dpi=dpi))


__all__ = ["plot_toss"]

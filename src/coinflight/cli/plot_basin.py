"""``coinflight plot basin``: heads and tails mapped over flight times and spins."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from coinflight.cli.cluster import ClusterOptions
from coinflight.cli.command import Group, command
from coinflight.cli.groups import CoinOptions
from coinflight.cli.landing_groups import TableOptions
from coinflight.cli.options import (
    OUTPUT_PANEL,
    TOSS_PANEL,
    Bounces,
    Dpi,
    Gravity,
    OutFile,
    StartFace,
    number_option,
    option,
)
from coinflight.cli.output import echo_written
from coinflight.cli.surface import table_title


def _range(flag: str, help: str, *aliases: str) -> object:
    """A LO:HI range of the map's toss (read by
    :func:`~coinflight.queries.values.parse_range`)."""
    return option(flag, *aliases, metavar="LO:HI", panel=TOSS_PANEL, help=help)


FlightTimeRange = Annotated[
    str | None,
    _range(
        "--flight-time", "Range of flight times T, s [default: 0.6:0.9, Stefan & Cheche].", "-T"
    ),
]
LaunchSpeedRange = Annotated[
    str | None,
    _range(
        "--launch-speed",
        "Range of upward launch speeds v0, m/s, instead of --flight-time (T = 2 v0 / g).",
    ),
]
OmegaXRange = Annotated[
    str | None,
    _range("--omega-x", "Range of the spin about a diameter ωx0, rad/s [default: 60:90]."),
]
OmegaY = Annotated[
    float,
    number_option("--omega-y", "WY", TOSS_PANEL, "Fixed spin about the other diameter ωy0, rad/s."),
]
OmegaZ = Annotated[
    float,
    number_option(
        "--omega-z", "WZ", TOSS_PANEL, "Fixed spin about the normal ωz0, rad/s (a precessing toss)."
    ),
]
PsiDeg = Annotated[
    float | None,
    number_option(
        "--psi",
        "DEG",
        TOSS_PANEL,
        "Fixed angle between the normal and S, degrees; the vertical axis is then the "
        "precession rate (see --precession-rate).",
    ),
]
PrecessionRange = Annotated[
    str | None,
    _range(
        "--precession-rate",
        "Range of the precession rate ωp = |S|/I1, rad/s, with --psi [default: 60:90].",
    ),
]
Resolution = Annotated[
    str,
    option(
        "--resolution",
        metavar="N|NTxNW",
        panel=OUTPUT_PANEL,
        help="Grid cells (pixels): N×N, or NT along T by NW along the spin.",
    ),
]
Boundaries = Annotated[
    bool,
    typer.Option(
        "--boundaries/--no-boundaries",
        rich_help_panel=OUTPUT_PANEL,
        help="Overlay the analytic heads/tails boundaries (Keller's hyperbolas when planar).",
    ),
]
BOX = Group(
    {
        "flight_time": (FlightTimeRange, None),
        "launch_speed": (LaunchSpeedRange, None),
        "omega_x": (OmegaXRange, None),
        "omega_y": (OmegaY, 0.0),
        "omega_z": (OmegaZ, 0.0),
        "psi": (PsiDeg, None),
        "precession_rate": (PrecessionRange, None),
        "resolution": (Resolution, "500"),
        "start": (StartFace, "heads"),
        "g": (Gravity, 9.81),
    },
    dict,
)
"""The map's box and its toss: the command receives them as keywords of
:func:`~coinflight.queries.basin.basin_query`."""


@command
def plot_basin(
    *,
    out: OutFile,
    box: Annotated[dict[str, Any], BOX],
    coin: CoinOptions,
    boundaries: Boundaries = True,
    dpi: Dpi = 150,
    table: TableOptions,
    bounces: Bounces = None,
    cluster: ClusterOptions,
) -> None:
    """Map heads and tails over a box of flight times and spins, with Keller's hyperbolas.

    Example: coinflight plot basin --omega-x 60:90 --flight-time 0.6:0.9 --out basin.png
    (on a table, after K bounces: --surface table --drop-height 0.3 --bounces K; the
    hyperbolas, which belong to the catch, are then not drawn)
    """
    from coinflight.model.surface import surface_kind
    from coinflight.plotting.basin import plot_basin as draw
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.queries.basin import basin_query, draws_boundaries

    figure_paths(out, "--out")  # before the map is computed, not after
    with cluster.executor() as executor:
        basin = basin_query(
            coin,
            **box,
            table=table,
            bounces=bounces,
            executor=executor,
            # their number bounded before the map (the table's maps are drawn without them)
            boundaries=draws_boundaries(table, boundaries),
        )
    n_w, n_t = basin.face.shape
    typer.echo(f"P(heads) on the {n_t}×{n_w} grid = {basin.heads_fraction:.6f}")
    kind = surface_kind(table.surface)
    if kind.model.can_end_on_edge:
        typer.echo(f"P(edge) on the grid = {basin.fraction(2):.6f}")
    if table.surface == "table":
        ending = table_title(table.drop_height, table.restitution, table.friction, bounces)
        figure = draw(basin, ending=ending, boundaries=False)
    elif table.surface != "hand":  # another registered surface kind: its model names it
        figure = draw(basin, ending=f"ended by the {kind.model.name}", boundaries=False)
    else:
        figure = draw(basin, boundaries=draws_boundaries(table, boundaries))
    echo_written(save_figure(figure, out, dpi=dpi))


__all__ = ["plot_basin"]

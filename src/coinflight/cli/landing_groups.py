"""Option groups of where a toss ends and the air it flies through (see
:mod:`coinflight.cli.command`): --surface and the table's options, --drag and the air's."""

from __future__ import annotations

from typing import Annotated

import typer

from coinflight.cli.command import Group
from coinflight.cli.options import SURFACE_PANEL, number_option, option
from coinflight.queries.values import AirArgs, TableArgs

SurfaceKind = Annotated[
    str,
    typer.Option(
        "--surface",
        metavar="hand|table",
        rich_help_panel=SURFACE_PANEL,
        help="hand: caught at launch height (no bounce); table: falls onto a hard surface, "
        "bounces and settles heads, tails or on edge.",
    ),
]
_TABLE = "table: "
_SPREAD = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal "
    "one truncated to the physical range)."
)
TABLE = Group(
    {
        "surface": (SurfaceKind, "hand"),
        "drop_height": (
            Annotated[
                float | None,
                number_option(
                    "--drop-height",
                    "D",
                    SURFACE_PANEL,
                    _TABLE + "how far the surface lies below the launch height, m (default 0).",
                ),
            ],
            None,
        ),
        "restitution": (
            Annotated[
                str | None,
                option(
                    "--restitution",
                    metavar="E",
                    panel=SURFACE_PANEL,
                    help=_TABLE + "coefficient of restitution in [0, 1] (default 0.5; 0 lands "
                    "dead)." + _SPREAD,
                ),
            ],
            None,
        ),
        "friction": (
            Annotated[
                str | None,
                option(
                    "--friction",
                    metavar="MU",
                    panel=SURFACE_PANEL,
                    help=_TABLE + "Coulomb friction coefficient ≥ 0 (default 0.3)." + _SPREAD,
                ),
            ],
            None,
        ),
        "surface_preset": (
            Annotated[
                str | None,
                option(
                    "--surface-preset",
                    metavar="NAME",
                    panel=SURFACE_PANEL,
                    help="table, probability only: restitution and friction spread uniformly over "
                    "the literature's ranges for coin-on-wood or coin-on-table (ranges and "
                    "sources: coinflight.studies.presets, SURFACE_PRESETS); --restitution and "
                    "--friction given replace the preset's.",
                ),
            ],
            None,
        ),
    },
    TableArgs,
)
TableOptions = Annotated[TableArgs, TABLE]
"""--surface and the table's --drop-height, --restitution, --friction, as typed."""
AIR = Group(
    {
        "drag": (
            Annotated[
                float | None,
                number_option(
                    "--drag",
                    "CD",
                    SURFACE_PANEL,
                    "Air drag coefficient C_d ≥ 0 on the coin's projected area (1.17: a flat "
                    "disc broadside on); compiled integration. Default 0 (no air).",
                ),
            ],
            None,
        ),
        "spin_damping": (
            Annotated[
                float | None,
                number_option(
                    "--spin-damping",
                    "K",
                    SURFACE_PANEL,
                    "Damping torque −K ω on the spin, N m s ≥ 0 (default 0).",
                ),
            ],
            None,
        ),
    },
    AirArgs,
)
AirOptions = Annotated[AirArgs, AIR]
"""--drag and --spin-damping, as typed."""

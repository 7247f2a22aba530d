"""Option groups of where a toss ends and the air it flies through (see
:mod:`coinflight.cli.command`): --surface and the table's options, --drag and the air's."""

from __future__ import annotations

from typing import Annotated

from coinflight.cli.command import Group
from coinflight.cli.landing_help import (
    CORNER_HELP,
    DURATION_HELP,
    ENDING_HELP,
    PIVOTING_HELP,
    ROLLING_HELP,
    SPREAD,
    SPREAD_DURATION,
    SPREAD_RESISTANCE,
    resistance_option,
)
from coinflight.cli.landing_help import (
    TABLE_PREFIX as _TABLE,
)
from coinflight.cli.options import (
    AIR_PANEL,
    CONTACT_PANEL,
    SURFACE_PANEL,
    number_option,
    option,
)
from coinflight.cli.surface import SurfaceOption
from coinflight.queries.values import AirArgs, TableArgs

TABLE = Group(
    {
        "surface": (SurfaceOption, "hand"),
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
                    "dead)." + SPREAD,
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
                    help=_TABLE + "Coulomb friction coefficient, 0 to 3 (default 0.3)." + SPREAD,
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
                    help="table, probability only: restitution, friction and contact duration "
                    "spread uniformly over the literature's ranges for coin-on-wood or "
                    "coin-on-table (ranges and sources: coinflight.studies.presets, "
                    "SURFACE_PRESETS); --restitution, --friction and --contact-duration given "
                    "replace the preset's.",
                ),
            ],
            None,
        ),
        "ending": (
            Annotated[
                str | None,
                option(
                    "--ending",
                    metavar="rocking|rigid",
                    panel=CONTACT_PANEL,
                    help=_TABLE + ENDING_HELP,
                ),
            ],
            None,
        ),
        "rolling_resistance": (
            Annotated[
                str | None,
                resistance_option(
                    "rolling",
                    "L",
                    "table, --ending rigid: " + ROLLING_HELP + SPREAD_RESISTANCE,
                ),
            ],
            None,
        ),
        "pivoting_resistance": (
            Annotated[
                str | None,
                resistance_option(
                    "pivoting",
                    "L",
                    "table, --ending rigid: " + PIVOTING_HELP + SPREAD_RESISTANCE,
                ),
            ],
            None,
        ),
        "corner_radius": (
            Annotated[
                float | None,
                number_option("--corner-radius", "A", CONTACT_PANEL, _TABLE + CORNER_HELP),
            ],
            None,
        ),
        "contact_duration": (
            Annotated[
                str | None,
                option(
                    "--contact-duration",
                    metavar="T",
                    panel=SURFACE_PANEL,
                    help=_TABLE + DURATION_HELP + SPREAD_DURATION,
                ),
            ],
            None,
        ),
    },
    TableArgs,
)
TableOptions = Annotated[TableArgs, TABLE]
"""--surface and the table's --drop-height, --restitution, --friction, --surface-preset,
--ending, --rolling-resistance, --pivoting-resistance, --corner-radius and --contact-duration,
as typed."""
AIR = Group(
    {
        "drag": (
            Annotated[
                float | None,
                number_option(
                    "--drag",
                    "CD",
                    AIR_PANEL,
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
                    AIR_PANEL,
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

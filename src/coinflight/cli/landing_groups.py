"""Option groups of where a toss ends and the air it flies through (see
:mod:`coinflight.cli.command`): --surface and the table's options, --drag and the air's."""

from __future__ import annotations

from typing import Annotated, Any

from coinflight.cli.command import Group
from coinflight.cli.options import (
    AIR_PANEL,
    CONTACT_PANEL,
    SURFACE_PANEL,
    number_option,
    option,
)
from coinflight.cli.surface import SurfaceOption
from coinflight.queries.values import AirArgs, TableArgs

_TABLE = "table: "
_SPREAD = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal "
    "one truncated to the physical range)."
)
ENDING_HELP = (
    "how a landing ends once its bounces die out. rocking (default): a planar rocking hand-off, "
    "fast, but it discards the spin and precession. contact: the coin in persistent 3-D contact "
    "(rolling, sliding, pivoting) until it cannot leave its well; experimental, about 30 "
    "times slower than rocking, and its edge rates depend on the unmeasured resistances and "
    "corner radius. rigid: the rigid, event-driven 3-D ending (rolling without slip, exact "
    "Coulomb sliding, hops flown in closed form, rim impacts, rest on the edge band); about "
    "200 times slower than rocking."
)
"""--ending's help (command line and sweep)."""


def _resistance_tail(ell: str, against: str) -> str:
    return (
        f"m, 0 to 0.01 (torque {ell} F_n against {against}; default 1e-4). Not measured for "
        "coins: quote a band over 1e-5 to 1e-3, not a value."
    )


ROLLING_TAIL = _resistance_tail("ℓ_r", "the coin's rolling")
"""--rolling-resistance's help after the name of the length: unit, range, default, unmeasured."""
PIVOTING_TAIL = _resistance_tail("ℓ_p", "the coin's spin about the vertical")
"""--pivoting-resistance's help after the name of the length, as :data:`ROLLING_TAIL`."""
ROLLING_HELP = "rolling resistance length ℓ_r, " + ROLLING_TAIL
"""--rolling-resistance's help."""
PIVOTING_HELP = "pivoting (drilling) resistance length ℓ_p, " + PIVOTING_TAIL
"""--pivoting-resistance's help."""


def resistance_option(which: str, metavar: str, help: str) -> Any:
    """The --rolling-resistance or --pivoting-resistance option (``which``: rolling or
    pivoting), read as text (a number, a distribution or a list: the command parses it); the
    one definition of the table group's and the sweep's."""
    return option(f"--{which}-resistance", metavar=metavar, panel=CONTACT_PANEL, help=help)


CORNER_HELP = (
    "radius of the coin's rounded rim corners, m, 0 to half the thickness (or the radius if "
    "smaller; default 0: sharp). "
    "Used by the flight's contacts, the impacts, both endings (the rocking section rolls on "
    "its round corners) and every ending's face/edge wells. Not measured for coins (worn coins "
    "are rounder): quote a band, not a value."
)
"""--corner-radius's help."""
_SPREAD_RESISTANCE = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal one"
    " truncated to 0 to 0.01 m), drawn toss by toss."
)
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
                    help=_TABLE + "Coulomb friction coefficient, 0 to 3 (default 0.3)." + _SPREAD,
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
        "ending": (
            Annotated[
                str | None,
                option(
                    "--ending",
                    metavar="rocking|contact|rigid",
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
                    "table, --ending contact or rigid: " + ROLLING_HELP + _SPREAD_RESISTANCE,
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
                    "table, --ending contact or rigid: " + PIVOTING_HELP + _SPREAD_RESISTANCE,
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
    },
    TableArgs,
)
TableOptions = Annotated[TableArgs, TABLE]
"""--surface and the table's --drop-height, --restitution, --friction, --surface-preset,
--ending, --rolling-resistance, --pivoting-resistance and --corner-radius, as typed."""
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

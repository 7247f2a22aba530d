"""Option groups: several options a command receives as one value (see
:mod:`coinflight.cli.command`). Each group is defined here once, with the options it shows;
the landing and the air are in :mod:`coinflight.cli.landing_groups`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.command import Group
from coinflight.cli.options import (
    CUSTOM_PANEL,
    TOSS_PANEL,
    CoinName,
    Gravity,
    StartFace,
    number_option,
)
from coinflight.queries.values import DistArgs, TossArgs, resolve_coin

if TYPE_CHECKING:
    from coinflight.model.coin import Coin


def _dist(flag: str, what: str, unit: str, *aliases: str) -> Any:
    """A toss condition given as a distribution (a number, a range or a normal)."""
    help = f"{what}, {unit}: a number, LOW:HIGH (uniform) or normal:MEAN,SD."
    return typer.Option(flag, *aliases, metavar="DIST", rich_help_panel=TOSS_PANEL, help=help)


COIN = Group(
    {
        "coin": (CoinName, None),
        "radius": (
            Annotated[
                float | None, number_option("--radius", "R", CUSTOM_PANEL, "Custom coin radius, m.")
            ],
            None,
        ),
        "thickness": (
            Annotated[
                float | None,
                number_option("--thickness", "H", CUSTOM_PANEL, "Custom coin thickness, m."),
            ],
            None,
        ),
        "mass": (
            Annotated[
                float | None, number_option("--mass", "M", CUSTOM_PANEL, "Custom coin mass, kg.")
            ],
            None,
        ),
    },
    resolve_coin,
)
CoinOptions = Annotated["Coin", COIN]
"""--coin, or --radius, --thickness and --mass: the command receives the Coin."""

# --- one toss, and a range of tosses --------------------------------------------------------
Omega = Annotated[
    tuple[float, float, float],
    number_option(
        "--omega",
        "WX WY WZ",
        TOSS_PANEL,
        "Body-frame angular velocity at launch, rad/s: x and y about diameters, "
        "z about the normal.",
    ),
]
FlightTime = Annotated[
    float | None,
    number_option(
        "--flight-time", "T", TOSS_PANEL, "Flight time to catch at launch height, s.", "-T"
    ),
]
LaunchSpeed = Annotated[
    float | None,
    number_option("--launch-speed", "V0", TOSS_PANEL, "Upward launch speed, m/s (T = 2 V0 / g)."),
]
TOSS = Group(
    {
        "omega": (Omega, (80.0, 0.0, 0.0)),
        "flight_time": (FlightTime, None),
        "launch_speed": (LaunchSpeed, None),
        "start": (StartFace, "heads"),
        "g": (Gravity, 9.81),
    },
    TossArgs,
)
TossOptions = Annotated[TossArgs, TOSS]
"""--omega, --flight-time or --launch-speed, --start, --g: one toss, as typed."""


def _tosses(omega_x: str) -> Group:
    """The options of a range of tosses (``omega_x``: the default of --omega-x)."""
    return Group(
        {
            "omega_x": (
                Annotated[str, _dist("--omega-x", "Spin about the x diameter", "rad/s")],
                omega_x,
            ),
            "omega_y": (
                Annotated[str, _dist("--omega-y", "Spin about the y diameter", "rad/s")],
                "0",
            ),
            "omega_z": (Annotated[str, _dist("--omega-z", "Spin about the normal", "rad/s")], "0"),
            "flight_time": (
                Annotated[
                    str | None,
                    _dist("--flight-time", "Flight time T (catch at launch height)", "s", "-T"),
                ],
                None,
            ),
            "launch_speed": (
                Annotated[
                    str | None,
                    _dist("--launch-speed", "Upward launch speed v0 (T = 2 v0 / g)", "m/s"),
                ],
                None,
            ),
            "start": (StartFace, "heads"),
            "g": (Gravity, 9.81),
        },
        DistArgs,
    )


TossesOptions = Annotated[DistArgs, _tosses("80")]
"""--omega-x/-y/-z, --flight-time or --launch-speed as distributions, --start, --g."""
ConvergenceTossesOptions = Annotated[DistArgs, _tosses("60:90")]
"""As :data:`TossesOptions`, with the paper's Fig 2a spin range as the default."""

"""The option groups of ``coinflight sweep`` (see :mod:`coinflight.cli.command`): the lists
of each toss parameter, and the landings (--surface and the table's lists)."""

from __future__ import annotations

from typing import Annotated, Any

from coinflight.cli.command import Group
from coinflight.cli.landing_help import (
    CORNER_HELP,
    DURATION_LIST_HELP,
    PIVOTING_TAIL,
    ROLLING_TAIL,
    resistance_option,
)
from coinflight.cli.options import CONTACT_PANEL, SURFACE_PANEL, TOSS_PANEL, option
from coinflight.model.surface import surface_kinds
from coinflight.queries.probability import PRESET_OPTIONS
from coinflight.queries.sweep import TOSS_PARAMETERS, SweepLandings
from coinflight.queries.values import flag

_WHAT = {
    "omega_x": "Spin about the x diameter",
    "omega_y": "Spin about the y diameter",
    "omega_z": "Spin about the normal",
    "flight_time": "Flight time",
    "launch_speed": "Launch speed v0 (T = 2 v0 / g), instead of --flight-time",
}
_DEFAULTS = {"omega_y": "0", "omega_z": "0"}


def _toss_options(name: str) -> dict[str, tuple[Any, None]]:
    """--P (a list of distributions), --P-mean and --P-sd (lists of numbers) of parameter P."""
    unit = PRESET_OPTIONS[name][1]
    default = f" Default {_DEFAULTS[name]}." if name in _DEFAULTS else ""
    dists = option(
        flag(name),
        metavar="DISTS",
        panel=TOSS_PANEL,
        help=f"{_WHAT[name]}, {unit}: comma-separated values, each a number or LOW:HIGH "
        f"(uniform), or one normal:MEAN,SD; repeat the option for more.{default}",
    )
    out: dict[str, tuple[Any, None]] = {name: (Annotated[list[str] | None, dists], None)}
    for stat, other, what in (
        ("mean", "sd", "means"),
        ("sd", "mean", "standard deviations (0: fixed at the mean)"),
    ):
        numbers = option(
            f"{flag(name)}-{stat}",
            metavar="LIST",
            panel=TOSS_PANEL,
            help=f"Normal {flag(name)[2:]}: {what}, {unit}; numbers and FROM:TO:COUNT, "
            f"comma-separated (with {flag(name)}-{other}).",
        )
        out[f"{name}_{stat}"] = (Annotated[str | None, numbers], None)
    return out


TOSSES = Group(
    {key: value for name in TOSS_PARAMETERS for key, value in _toss_options(name).items()},
    lambda **typed: {
        name: tuple(typed[name + s] for s in ("", "_mean", "_sd")) for name in TOSS_PARAMETERS
    },
)
"""--P, --P-mean and --P-sd of each toss parameter P: the command receives, by parameter, its
distributions and its -mean and -sd texts."""


def _surface_option(
    flag: str, metavar: str, help: str, kind: Any = str | None, panel: str = SURFACE_PANEL
) -> Any:
    return (Annotated[kind, option(flag, metavar=metavar, panel=panel, help=help)], None)


LANDINGS = Group(
    {
        "surface": (
            _surface_option(
                "--surface",
                ",".join(surface_kinds()),
                "Comma-separated registered surface kinds (coinflight probability --help lists "
                "them): hand (caught, P(edge) empty) and/or table (lands, bounces; "
                "P(edge)). A table's result depends on its unmeasured restitution and friction: "
                "sweep them over their plausible range (e.g. --restitution 0.3,0.5,0.7 "
                "--friction 0.1,0.3,0.5) and quote the band.",
                str,
            )[0],
            "hand",
        ),
        "drop_height": _surface_option("--drop-height", "LIST", "table: m (default 0)."),
        "restitution": _surface_option(
            "--restitution", "LIST", "table: coefficients of restitution in [0, 1] (default 0.5)."
        ),
        "friction": _surface_option(
            "--friction", "LIST", "table: Coulomb friction coefficients, 0 to 3 (default 0.3)."
        ),
        "bounces": _surface_option(
            "--bounces",
            "K",
            "table: the face at the contact after K bounces (default: at rest).",
            int | None,
        ),
        "rolling_resistance": (
            Annotated[
                str | None,
                resistance_option(
                    "rolling", "LIST", "table: rolling resistance lengths ℓ_r, " + ROLLING_TAIL
                ),
            ],
            None,
        ),
        "pivoting_resistance": (
            Annotated[
                str | None,
                resistance_option(
                    "pivoting", "LIST", "table: pivoting resistance lengths ℓ_p, " + PIVOTING_TAIL
                ),
            ],
            None,
        ),
        "contact_duration": _surface_option(
            "--contact-duration",
            "LIST",
            "table: contact durations t_c of an impact, s: " + DURATION_LIST_HELP,
        ),
        "corner_radius": _surface_option(
            "--corner-radius",
            "LIST",
            "--surface table only, swept over every coin: " + CORNER_HELP,
            panel=CONTACT_PANEL,
        ),
    },
    SweepLandings,
)
"""--surface and the table's lists: the command receives their
:class:`~coinflight.queries.sweep.SweepLandings`."""

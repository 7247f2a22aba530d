"""The options of ``coinflight edge`` (the command: :mod:`.edge`): the ratios, the simulated
landings' setting, --target and --json."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from coinflight.cli.command import Group
from coinflight.cli.groups import _dist
from coinflight.cli.landing_help import CORNER_HELP, PIVOTING_HELP, ROLLING_HELP
from coinflight.cli.options import (
    CONTACT_PANEL,
    OUTPUT_PANEL,
    SURFACE_PANEL,
    Gravity,
    number_option,
)
from coinflight.queries.values import flag

SIM_PANEL = "Simulation"
RATIOS = "0.1,0.2,0.3,0.4,0.5,0.6,0.8,1"
_SETTING = "vigorous planar spins, landing dead on a table; coinflight.studies.edge.simulate_edge"


def _simulate(what: str) -> Any:
    """--simulate N: tosses per ratio (``what``: what the command does with them)."""
    return typer.Option(
        "--simulate",
        min=1,
        max=10**7,
        metavar="N",
        rich_help_panel=SIM_PANEL,
        help=f"Also land N simulated tosses per ratio ({_SETTING}) and {what}.",
    )


_ONLY = "with --simulate or --target: "
_BAND = " With --target, not given: a band over "
EdgeRatios = Annotated[
    str | None,
    typer.Option(
        "--ratios",
        metavar="R,R,...",
        show_default=False,
        help="Thickness / diameter ratios h/d, each between 0.001 and 100 [default: "
        "0.1,0.3,0.577,1].",
    ),
]
EdgeSimulate = Annotated[
    int | None,
    _simulate(
        "report their edge fraction with its standard error. With --target: the tosses per "
        "ratio tried (default 2,000)"
    ),
]
TargetOption = Annotated[
    str | None,
    typer.Option(
        "--target",
        metavar="P",
        rich_help_panel=SIM_PANEL,
        help="Find the ratio h/d at which simulated tosses land on edge with probability P "
        "(1/3 or 0.333: the three-sided coin), with its band over the table's unmeasured "
        "restitution, friction and rolling and pivoting resistances, beside Yong & Mahadevan's "
        "closed forms and the measured rows (coinflight.studies.edge_target).",
    ),
]
_BOUNCING = (
    " It acts on every landing that bounces (--restitution above 0), which the rigid ending "
    "carries to rest; dead landings (restitution 0, the default of --simulate) never reach "
    "that ending, and refuse the option."
)
_RESISTANCE = _BOUNCING + _BAND + "1e-5–1e-3 m, both resistances alike."
_TABLE_NUMBERS = {
    "restitution": (
        "E",
        SURFACE_PANEL,
        "the table's coefficient of restitution in [0, 1] (default 0: lands dead, as in the "
        "dynamic model)." + _BAND + "0.3–0.6 (the surface presets').",
    ),
    "friction": (
        "MU",
        SURFACE_PANEL,
        "the table's Coulomb friction coefficient, 0 to 3 (default 0.3)."
        + _BAND
        + "0.05–0.6 (the surface presets').",
    ),
    "drop_height": (
        "D",
        SURFACE_PANEL,
        "how far the table lies below the launch height, m (default 0.5).",
    ),
    "rolling_resistance": ("L", CONTACT_PANEL, "the table's " + ROLLING_HELP + _RESISTANCE),
    "pivoting_resistance": ("L", CONTACT_PANEL, "the table's " + PIVOTING_HELP + _RESISTANCE),
    "corner_radius": (
        "A",
        CONTACT_PANEL,
        CORNER_HELP + " Every ratio's coin takes it: at most half the thinnest one's thickness "
        "(h/d × 24 mm / 2).",
    ),
}
"""The simulated table's numbers: parameter name → (metavar, panel, help after
"with --simulate or --target: ")."""


def _table_number(name: str) -> Any:
    """The option of one of :data:`_TABLE_NUMBERS`, named after it (None: not given)."""
    metavar, panel, help = _TABLE_NUMBERS[name]
    return Annotated[float | None, number_option(flag(name), metavar, panel, _ONLY + help)]


_BOTH = "With --simulate or --target: "
SpinX = Annotated[str | None, _dist("--omega-x", _BOTH + "spin about the x diameter", "rad/s")]
LaunchSpeed = Annotated[
    str | None, _dist("--launch-speed", _BOTH + "upward launch speed v0", "m/s")
]
Psi = Annotated[
    str | None,
    typer.Option(
        "--psi",
        metavar="DEG|human",
        rich_help_panel="Toss",
        help="With --target: a wobble as well, the precession cone angle ψ in degrees "
        "(0 < ψ ≤ 90; 90: none), or human (the human toss preset's spread about 82°); the same "
        "ψ at every ratio. Default: planar tosses.",
    ),
]
EdgeGravity = Annotated[float | None, *Gravity.__metadata__]
_TOSS = {"omega_x": SpinX, "launch_speed": LaunchSpeed, "psi": Psi, "g": EdgeGravity}
SETTING = Group(
    {name: (_table_number(name), None) for name in _TABLE_NUMBERS}
    | {name: (kind, None) for name, kind in _TOSS.items()},
    dict,
)
"""The simulated landings' options: the command receives them as keywords of
:func:`~coinflight.queries.edge.edge_query` (None: not given)."""
EdgeJson = Annotated[
    bool,
    typer.Option(
        "--json",
        rich_help_panel=OUTPUT_PANEL,
        help="Print a JSON list on stdout, one object per ratio, instead of text (with "
        "--target: one object).",
    ),
]

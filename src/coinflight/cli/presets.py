"""``--preset NAME``: a named distribution of tosses for commands that take one.

A preset supplies every initial condition; toss options given explicitly on the command line
(``--omega-x``, ``--omega-y``, ``--omega-z``, ``--flight-time``, ``--launch-speed``) replace
the preset's value for that condition only, and the coin, ``--start`` and ``--g`` apply as
usual. Whether an option was given is read from the parameter source, so an option left
at its default never overrides the preset.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import typer

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution

# Command-line parameter name → (option flag, unit) of the toss options a preset supplies.
TOSS_OPTIONS = {
    "omega_x": ("--omega-x", "rad/s"),
    "omega_y": ("--omega-y", "rad/s"),
    "omega_z": ("--omega-z", "rad/s"),
    "flight_time": ("--flight-time", "s"),
    "launch_speed": ("--launch-speed", "m/s"),
}


def given_on_command_line(ctx: typer.Context, name: str) -> bool:
    """True if the option ``name`` was typed by the user (not a default or environment)."""
    # Compared by name: typer ships its own copy of click, whose ParameterSource enum is not
    # click's.
    source = ctx.get_parameter_source(name)
    return source is not None and source.name == "COMMANDLINE"


def preset_distribution(
    ctx: typer.Context, name: str, coin: Coin, start: str, g: float
) -> TossDistribution:
    """The preset ``name`` with the toss options the user typed laid over it."""
    from coinflight.model.distributions import parse_distribution
    from coinflight.studies.presets import preset

    overrides = {
        param: parse_distribution(str(ctx.params[param]), flag, unit)
        for param, (flag, unit) in TOSS_OPTIONS.items()
        if param in ctx.params and given_on_command_line(ctx, param)
    }
    if "flight_time" in overrides and "launch_speed" in overrides:
        raise ValueError("give at most one of --flight-time and --launch-speed")
    return preset(name, coin=coin, start=start, g=g, **overrides)  # type: ignore[arg-type]

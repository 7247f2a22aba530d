"""``--preset NAME``: a named distribution of tosses for commands that take one.

A preset supplies every initial condition; toss options given explicitly on the command line
(``--omega-x``, ``--omega-y``, ``--omega-z``, ``--flight-time``, ``--launch-speed``) replace
the preset's value for that condition only, and the coin, ``--start`` and ``--g`` apply as
usual. Whether an option was given is read from the parameter source, so an option left
at its default never overrides the preset.
"""

from __future__ import annotations

import typer


def given_on_command_line(ctx: typer.Context, name: str) -> bool:
    """True if the option ``name`` was typed by the user (not a default or environment)."""
    # Compared by name: typer ships its own copy of click, whose ParameterSource enum is not
    # click's.
    source = ctx.get_parameter_source(name)
    return source is not None and source.name == "COMMANDLINE"


def given_toss_options(ctx: typer.Context) -> dict[str, str]:
    """The toss options the user typed, parameter name → text: what replaces a preset's value
    (:func:`coinflight.queries.probability.preset_tosses`)."""
    from coinflight.queries.probability import PRESET_OPTIONS

    return {
        param: str(ctx.params[param])
        for param in PRESET_OPTIONS
        if param in ctx.params and given_on_command_line(ctx, param)
    }

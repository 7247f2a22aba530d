"""Every option used by more than one command, defined once.

A command imports its shared options from here, and its option groups (coin, toss, tosses,
table, air: several options received as one value) from :mod:`coinflight.cli.groups`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import typer

from coinflight.cli.output import print_json
from coinflight.cli.parsers import gravity, number, output_file, output_folder
from coinflight.probability import registry
from coinflight.queries.values import COIN_NAMES, resolve_coin

__all__ = ["number", "print_json", "resolve_coin"]  # also used from here (cli/surface.py)

OUTPUT_HELP = "Missing folders are created; files are replaced only when the run succeeds."
"""What every output option does with its path (stated once, in each option's help)."""

COIN_PANEL = "Coin"
TOSS_PANEL = "Toss"
OUTPUT_PANEL = "Output"
METHOD_PANEL = "Method"
SURFACE_PANEL = "Landing"
PSI_PANEL = "Precession angle"
SIM_PANEL = "Monte Carlo check"
SPLITS_PANEL = "Held-out people"
CUSTOM_PANEL = "Custom coin and gravity"
METHOD_DETAIL_PANEL = "Method details"
CONTACT_PANEL = "Contact ending and rim"
AIR_PANEL = "Air"
PARALLEL_PANEL = "Parallel"
LATER_PANELS = (METHOD_DETAIL_PANEL, CUSTOM_PANEL, CONTACT_PANEL, AIR_PANEL, PARALLEL_PANEL)
"""Panels of rarely used options, shown after the others (in this order) so that the common
options fit a screen (:func:`coinflight.cli.helptext.tidy_help`)."""


def option(
    flag: str, *aliases: str, metavar: str | None, panel: str | None, help: str, **extra: Any
) -> Any:
    """An option with its value's name, its help panel and its help (``extra``: typer's
    other settings, e.g. ``parser``, ``min``)."""
    return typer.Option(flag, *aliases, metavar=metavar, rich_help_panel=panel, help=help, **extra)


def number_option(flag: str, metavar: str, panel: str | None, help: str, *aliases: str) -> Any:
    """A numeric option (parsed by :func:`~coinflight.cli.parsers.number`)."""
    return option(flag, *aliases, metavar=metavar, panel=panel, help=help, parser=number)


def _seed(
    help: str, panel: str | None = None, minimum: int | None = 0, metavar: str | None = "S"
) -> Any:
    """--seed: the one definition; each command says what it seeds and its default."""
    return typer.Option("--seed", min=minimum, metavar=metavar, rich_help_panel=panel, help=help)


def _preset(panel: str, help: str) -> Any:
    """--preset NAME: the one definition (names and values: coinflight.studies.presets)."""
    return typer.Option("--preset", metavar="NAME", rich_help_panel=panel, help=help)


# --- the coin and the toss ---------------------------------------------------------------


def coin_option(metavar: str, help: str) -> Any:
    """--coin: one coin by name, or (a sweep's) several."""
    return option("--coin", metavar=metavar, panel=COIN_PANEL, help=help)


CoinName = Annotated[
    str | None, coin_option("NAME", f"A real coin: {COIN_NAMES}. Default us-quarter.")
]
StartFace = Annotated[
    str, option("--start", metavar="heads|tails", panel=TOSS_PANEL, help="Face up at launch.")
]
Gravity = Annotated[
    float,
    option(
        "--g",
        metavar="G",
        panel=CUSTOM_PANEL,
        help="Gravitational acceleration, m/s².",
        parser=gravity,
    ),
]
TossPreset = Annotated[
    str | None,
    _preset(
        TOSS_PANEL,
        "Start from a named distribution of tosses: human (a person's natural toss, "
        "v0 ≈ 2.4 m/s, 38 rev/s, ψ near but below 90°; coinflight.studies.presets). Toss options "
        "given explicitly replace the preset's value.",
    ),
]
PsiPreset = Annotated[
    str | None,
    _preset(
        PSI_PANEL,
        "A named distribution of tosses: human (a person's natural toss: v0 ≈ 2.4 m/s, "
        "38 rev/s, ψ near but below 90°; DHM 2007 via Keller). See coinflight.studies.presets.",
    ),
]

Bounces = Annotated[
    int | None,
    option(
        "--bounces",
        metavar="K",
        panel=SURFACE_PANEL,
        help="table: stop at the contact after K bounces (0: the first contact) and report "
        "the well the coin is in; default: bounce until it settles.",
    ),
]

# --- how: method, seeds, threads, simulations -----------------------------------------------
Seed = Annotated[
    int | None,
    _seed(
        f"Seed for {' and '.join(registry.names(seeded=True))} (reported; drawn at random if "
        "not given).",
        METHOD_PANEL,
        minimum=None,
    ),
]
SimulationSeed = Annotated[
    int | None,
    _seed(
        "Seed of the --monte-carlo simulation (reported; drawn at random if not given).",
        SIM_PANEL,
    ),
]
SimulateSeed = Annotated[
    int | None,
    _seed("Seed of the --simulate tosses (reported; drawn at random if not given).", "Simulation"),
]
SplitSeed = Annotated[
    int | None,
    _seed(
        "Seed of the random splits of the people in the held-out check (reported; drawn at "
        "random if not given).",
        SPLITS_PANEL,
    ),
]
PaperSeed = Annotated[int, _seed("Seed of method B's random events (reported).", metavar=None)]
Threads = Annotated[
    int | None,
    option(
        "--threads",
        metavar="K",
        panel=PARALLEL_PANEL,
        help="Worker threads (default: all CPUs). The result does not depend on it.",
    ),
]
MonteCarlo = Annotated[
    int | None,
    option(
        "--monte-carlo",
        metavar="N",
        panel=SIM_PANEL,
        help="Also simulate N ≥ 100 tosses of the full torque-free flight (random flight time and "
        "spin at the given ψ) and report their same-side fraction with its standard error.",
        min=1,
    ),
]

# --- output ---------------------------------------------------------------------------------
JsonFlag = Annotated[
    bool,
    typer.Option(
        "--json",
        rich_help_panel=OUTPUT_PANEL,
        help="Print one JSON object on stdout instead of text.",
    ),
]
Quiet = Annotated[
    bool,
    typer.Option("--quiet", "-q", rich_help_panel=OUTPUT_PANEL, help="No progress bar on stderr."),
]


def out_file(help: str) -> Any:
    """--out/-o FILE: the file a command writes, checked as an output path."""
    return option("--out", "-o", metavar="FILE", panel=OUTPUT_PANEL, help=help, parser=output_file)


def out_folder(contents: str) -> Any:
    """--out/-o DIR: the folder of a report (``contents``: what goes in it), all written
    together at the end."""
    return option(
        "--out",
        "-o",
        metavar="DIR",
        panel=OUTPUT_PANEL,
        help=f"Folder for {contents}, all written together at the end. {OUTPUT_HELP}",
        parser=output_folder,
    )


OutFile = Annotated[
    Path,
    out_file(
        "Image file to write; the format follows the suffix (.png, .svg, .pdf, …); "
        f"without a suffix, FILE.png and FILE.svg (written together). {OUTPUT_HELP}"
    ),
]
Dpi = Annotated[
    int,
    typer.Option("--dpi", min=20, max=1200, rich_help_panel=OUTPUT_PANEL, help="PNG resolution."),
]

"""Options shared by several commands, and turning them into library objects."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

if TYPE_CHECKING:
    from coinflight.model.coin import Coin


def number(text: str) -> float:
    """Parse a command-line number, or a usage error that names the text."""
    try:
        return float(text)
    except ValueError:
        raise typer.BadParameter(f"{text!r} is not a number") from None


def gravity(text: str) -> float:
    """Parse --g and check it against the library's range (coinflight.model.toss.GRAVITY) before any
    command divides by it."""
    from coinflight.model.toss import GRAVITY

    value = number(text)
    try:
        return GRAVITY.check(value)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None


def output_file(text: str) -> Path:
    """Parse an output file (--out FILE, --plot FILE): an empty text or a folder's name
    (``.``, ``out/``) is a usage error, not the current folder or a file ``out`` (what
    ``Path`` would silently make of them)."""
    from coinflight._files import check_name

    try:
        check_name(text)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None
    return Path(text)


def output_folder(text: str) -> Path:
    """Parse an output folder (--out DIR): an empty text is a usage error."""
    from coinflight._files import check_name

    try:
        check_name(text, folder=True)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None
    return Path(text)


OUTPUT_HELP = "Missing folders are created; files are replaced only when the run succeeds."
"""What every output option does with its path (stated once, in each option's help)."""

COIN_PANEL = "Coin"
TOSS_PANEL = "Toss"
OUTPUT_PANEL = "Output"

CoinName = Annotated[
    str | None,
    typer.Option(
        "--coin",
        metavar="NAME",
        rich_help_panel=COIN_PANEL,
        help="A real coin: us-cent, us-nickel, us-dime, us-quarter, us-half-dollar, "
        "eur-1, eur-2, eur-50c, gbp-1. Default us-quarter.",
    ),
]
Radius = Annotated[
    float | None,
    typer.Option(
        "--radius",
        parser=number,
        metavar="R",
        rich_help_panel=COIN_PANEL,
        help="Custom coin radius, m.",
    ),
]
Thickness = Annotated[
    float | None,
    typer.Option(
        "--thickness",
        parser=number,
        metavar="H",
        rich_help_panel=COIN_PANEL,
        help="Custom coin thickness, m.",
    ),
]
Mass = Annotated[
    float | None,
    typer.Option(
        "--mass",
        parser=number,
        metavar="M",
        rich_help_panel=COIN_PANEL,
        help="Custom coin mass, kg.",
    ),
]
StartFace = Annotated[
    str,
    typer.Option(
        "--start", metavar="heads|tails", rich_help_panel=TOSS_PANEL, help="Face up at launch."
    ),
]
Gravity = Annotated[
    float,
    typer.Option(
        "--g",
        parser=gravity,
        metavar="G",
        rich_help_panel=TOSS_PANEL,
        help="Gravitational acceleration, m/s².",
    ),
]
JsonFlag = Annotated[
    bool,
    typer.Option(
        "--json",
        rich_help_panel=OUTPUT_PANEL,
        help="Print one JSON object on stdout instead of text.",
    ),
]


def resolve_coin(
    name: str | None, radius: float | None, thickness: float | None, mass: float | None
) -> Coin:
    """The coin the user asked for: a preset by name, or custom dimensions (all three)."""
    from coinflight.model.coin import DEFAULT_COIN, Coin

    custom = {"--radius": radius, "--thickness": thickness, "--mass": mass}
    given = [k for k, val in custom.items() if val is not None]
    if given and name is not None:
        raise ValueError(f"give either --coin or custom dimensions ({', '.join(given)}), not both")
    if given:
        missing = [k for k, val in custom.items() if val is None]
        if missing:
            raise ValueError(
                "a custom coin needs --radius, --thickness and --mass; "
                f"missing {', '.join(missing)}"
            )
        assert radius is not None and thickness is not None and mass is not None
        return Coin(radius=radius, thickness=thickness, mass=mass)
    return Coin.preset(name if name is not None else DEFAULT_COIN)


def print_json(payload: dict[str, Any]) -> None:
    """One JSON object on stdout (NumPy scalars and arrays become numbers and lists)."""
    text = json.dumps(payload, default=_jsonable, allow_nan=False)  # whole, or an error
    sys.stdout.write(text + "\n")


def _jsonable(obj: Any) -> Any:
    import numpy as np

    if isinstance(obj, np.ndarray):
        return obj.tolist()
    if isinstance(obj, np.generic):
        return obj.item()
    raise TypeError(f"cannot write {type(obj).__name__} as JSON")

"""Parsers of command-line texts: numbers, lists, ranges and output paths.

Each turns a bad text into a usage error (typer.BadParameter) or a ValueError that names the
option and what it takes; the library's own range checks do the rest.
"""

from __future__ import annotations

from pathlib import Path

import typer

from coinflight.queries.values import parse_range, parse_resolution

__all__ = ["parse_range", "parse_resolution"]  # the one reading of ranges and resolutions


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


def _checked_name(text: str, folder: bool) -> Path:
    from coinflight._files import check_name

    try:
        check_name(text, folder=folder)
    except ValueError as exc:
        raise typer.BadParameter(str(exc)) from None
    return Path(text)


def output_file(text: str) -> Path:
    """Parse an output file (--out FILE, --plot FILE): an empty text, a folder's name
    (``.``, ``out/``) or an existing folder is a usage error, not the current folder, a file
    ``out`` or ``out.png`` beside the folder ``out`` (what ``Path`` and the suffixes would
    silently make of them)."""
    path = _checked_name(text, folder=False)
    if path.is_dir():
        raise typer.BadParameter(
            f"{text!r} is an existing folder; give a file's name, such as "
            f"{str(path / 'figure.png')!r} for a file inside it"
        )
    return path


def output_folder(text: str) -> Path:
    """Parse an output folder (--out DIR): an empty text is a usage error."""
    return _checked_name(text, folder=True)


def output_prefix(text: str) -> Path:
    """Parse --out PREFIX: a folder's name (existing, or ending in /) means DIR/convergence."""
    from coinflight._files import names_folder

    path = _checked_name(text, folder=True)
    return path / "convergence" if names_folder(text) or path.is_dir() else path


def parse_numbers(text: str, name: str, example: str = "0.6,0.65,0.7") -> list[float]:
    """Comma-separated numbers, or a ValueError naming the option, an ``example`` of what it
    takes and the bad text."""
    parts = [p.strip() for p in text.split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"{name} must be comma-separated numbers such as {example}; got {text!r}"
        ) from None
    return values


def parse_sizes(text: str, option: str) -> list[int]:
    """Comma-separated whole numbers (at least one), or a ValueError naming the option."""
    try:
        values = [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise ValueError(f"{option} {text!r}: give comma-separated whole numbers") from None
    if not values:
        raise ValueError(f"{option} {text!r}: give at least one size")
    return values

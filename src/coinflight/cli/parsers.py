"""Parsers of command-line texts: numbers, lists, ranges and output paths.

Each turns a bad text into a usage error (typer.BadParameter) or a ValueError that names the
option and what it takes; the library's own range checks do the rest.
"""

from __future__ import annotations

from pathlib import Path

import typer

from coinflight.queries.values import parse_numbers, parse_range, parse_resolution, parse_sizes

# the one reading of lists, ranges and resolutions
__all__ = ["parse_numbers", "parse_range", "parse_resolution", "parse_sizes"]


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

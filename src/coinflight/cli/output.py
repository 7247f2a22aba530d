"""What commands print: one JSON object, or the files they wrote."""

from __future__ import annotations

import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import typer


def print_json(payload: dict[str, Any]) -> None:
    """One JSON object on stdout (NumPy scalars and arrays become numbers and lists), the
    plausibility warnings heard so far in its ``"warnings"``, as the web's answers carry them."""
    from coinflight.queries import plausibility
    from coinflight.queries.encoding import json_text

    payload = plausibility.with_warnings(payload, plausibility.so_far())
    sys.stdout.write(json_text(payload) + "\n")  # whole, or an error


def echo_written(paths: Iterable[Path]) -> None:
    """``wrote PATH``, one line per file."""
    for path in paths:
        typer.echo(f"wrote {path}")


def help_when_bare(ctx: typer.Context) -> None:
    """A command group called without a subcommand shows its help."""
    if ctx.invoked_subcommand is None:
        typer.echo(ctx.get_help())

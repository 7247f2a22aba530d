"""``coinflight plot …``: figures. Each subcommand is registered on :data:`plot_app`."""

from __future__ import annotations

import typer

plot_app = typer.Typer(
    help="Draw figures (PNG, SVG, PDF by the --out suffix).",
    no_args_is_help=True,
)

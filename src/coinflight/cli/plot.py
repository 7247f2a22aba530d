"""``coinflight plot …``: figures. Each subcommand is registered on :data:`plot_app`."""

from __future__ import annotations

from collections.abc import Callable

import typer

from coinflight.cli.output import help_when_bare
from coinflight.cli.plot_basin import plot_basin
from coinflight.cli.plot_bias import plot_bias
from coinflight.cli.plot_edge import plot_edge
from coinflight.cli.plot_toss import plot_toss

plot_app = typer.Typer(
    help="Draw figures (PNG, SVG, PDF, …, by the suffix of --out; PNG and SVG without one).",
    invoke_without_command=True,
)


@plot_app.callback()
def _plot(ctx: typer.Context) -> None:
    """Draw figures (PNG, SVG, PDF, …, by the suffix of --out; PNG and SVG without one)."""
    help_when_bare(ctx)


_COMMANDS: dict[str, Callable[..., None]] = {
    "toss": plot_toss,
    "basin": plot_basin,
    "bias": plot_bias,
    "edge": plot_edge,
}
for _name, _command in _COMMANDS.items():
    plot_app.command(_name)(_command)

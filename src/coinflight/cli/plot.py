"""``coinflight plot …``: figures. Each subcommand is registered on :data:`plot_app`."""

from __future__ import annotations

import typer

from coinflight.cli import bias as _bias
from coinflight.cli import edge as _edge
from coinflight.cli import figures as _figures

plot_app = typer.Typer(
    help="Draw figures (PNG, SVG, PDF, …, by the suffix of --out; PNG and SVG without one).",
    invoke_without_command=True,
)


@plot_app.callback()
def _plot(ctx: typer.Context) -> None:
    """Draw figures (PNG, SVG, PDF, …, by the suffix of --out; PNG and SVG without one)."""
    if ctx.invoked_subcommand is None:
        typer.echo(ctx.get_help())


plot_app.command("toss")(_figures.plot_toss)
plot_app.command("basin")(_figures.plot_basin)
plot_app.command("bias")(_bias.plot_bias)
plot_app.command("edge")(_edge.plot_edge)

"""The ``coinflight`` application: commands are registered here, defined in their own modules."""

from __future__ import annotations

from collections.abc import Callable
from typing import Annotated

import typer

from coinflight import __version__
from coinflight.cli import animate as _animate
from coinflight.cli import bias as _bias
from coinflight.cli import convergence as _convergence
from coinflight.cli import data as _data
from coinflight.cli import edge as _edge
from coinflight.cli import landing_report as _landing_report
from coinflight.cli import paper as _paper
from coinflight.cli import probability as _probability
from coinflight.cli import serve as _serve
from coinflight.cli import sweep as _sweep
from coinflight.cli import toss as _toss
from coinflight.cli.errors import OneLineErrors
from coinflight.cli.exits import INTERRUPTED, exit_now, interrupted
from coinflight.cli.output import help_when_bare
from coinflight.cli.plot import plot_app
from coinflight.cli.stdout import guard_stdout

app = typer.Typer(
    cls=OneLineErrors,
    name="coinflight",
    help="The physics of coin tossing: torque-free flight, probabilities, bias, bounces.",
    epilog="Exit codes: 0 done; 2 bad input, or an output (a file, standard output) that cannot "
    "be written; 130 interrupted (Ctrl-C), nothing written; 141 standard output closed by its "
    "reader (| head). Outputs are written whole at the end, all files of a run or none.",
    invoke_without_command=True,
    add_completion=True,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def _version(value: bool) -> None:
    if value:
        typer.echo(f"coinflight {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    ctx: typer.Context,
    version: Annotated[
        bool,
        typer.Option(
            "--version", callback=_version, is_eager=True, help="Show the version and exit."
        ),
    ] = False,
) -> None:
    """The physics of coin tossing: torque-free flight, probabilities, bias, bounces."""
    help_when_bare(ctx)


_COMMANDS: dict[str, Callable[..., None] | typer.Typer] = {
    "toss": _toss.toss,
    "bias": _bias.bias,
    "data": _data.data,
    "probability": _probability.probability,
    "convergence": _convergence.convergence,
    "sweep": _sweep.sweep,
    "edge": _edge.edge,
    "plot": plot_app,
    "animate": _animate.animate,
    "paper": _paper.paper,
    "serve": _serve.serve,
    "landing-report": _landing_report.landing_report,
}
for _name, _command in _COMMANDS.items():
    if isinstance(_command, typer.Typer):
        app.add_typer(_command, name=_name)
    else:
        app.command(_name)(_command)


def main() -> None:
    """Console-script entry point (``coinflight`` and ``python -m coinflight``).

    Standard output is guarded first (:func:`coinflight.cli.stdout.guard_stdout`): a closed
    pipe ends quietly (exit 141), a full disk or closed stdout is one line and exit 2, Ctrl-C
    is ``coinflight: interrupted`` and exit 130.
    """
    try:
        try:
            guard_stdout()
            app(prog_name="coinflight")  # also under python -m: completion keys on this name
        except KeyboardInterrupt:  # before a command starts; inside one, OneLineErrors says it
            interrupted()
    except SystemExit as exc:
        if exc.code == INTERRUPTED:
            exit_now(INTERRUPTED)
        raise

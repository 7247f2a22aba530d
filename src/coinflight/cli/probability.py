"""``coinflight probability``: the chance of heads for a range of tosses."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.cluster import ParallelOptions
from coinflight.cli.command import Group, command
from coinflight.cli.groups import CoinOptions, TossesOptions
from coinflight.cli.landing_groups import AirOptions, TableOptions
from coinflight.cli.options import (
    METHOD_DETAIL_PANEL,
    METHOD_PANEL,
    JsonFlag,
    Quiet,
    Seed,
    TossPreset,
    print_json,
)
from coinflight.cli.presets import given_toss_options
from coinflight.cli.progress import progress_bar
from coinflight.probability import registry
from coinflight.queries.landing import describe_for
from coinflight.queries.probability import result_warnings

if TYPE_CHECKING:
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import ProbabilityResult
    from coinflight.queries.landing import LandingChoice

Method = Annotated[
    str,
    typer.Option(
        "--method",
        "-m",
        metavar="|".join(registry.names()),
        rich_help_panel=METHOD_PANEL,
        help="; ".join(f"{e.name}: {e.description}" for e in registry.estimators()) + ".",
    ),
]
Size = Annotated[
    int | None,
    typer.Option(
        "--n",
        "-n",
        metavar="N",
        rich_help_panel=METHOD_PANEL,
        help="; ".join(f"{e.name}: {e.size}" for e in registry.estimators() if e.size)
        + ". Sizes beyond about a minute's work (grid) or an hour's (monte-carlo, qmc) are "
        "refused with the estimate.",
    ),
]
GridCells = Annotated[
    int | None,
    typer.Option(
        "--grid-cells",
        metavar="C",
        rich_help_panel=METHOD_DETAIL_PANEL,
        help="monte-carlo only: draw from the midpoints of C cells per parameter "
        "(the paper's method B uses 100).",
    ),
]

VarianceReduction = Annotated[
    str | None,
    typer.Option(
        "--variance-reduction",
        metavar="|".join(registry.VARIANCE_REDUCTIONS),
        rich_help_panel=METHOD_DETAIL_PANEL,
        help="; ".join(f"{k}: {text}" for k, text in registry.VARIANCE_REDUCTIONS.items())
        + ". For --method "
        + " and ".join(e.name for e in registry.estimators() if e.modes)
        + ".",
    ),
]
HOW = Group(
    {
        "method": (Method, "exact"),
        "n": (Size, None),
        "seed": (Seed, None),
        "grid_cells": (GridCells, None),
        "variance_reduction": (VarianceReduction, None),
    },
    dict,
)
"""--method and its options: the command receives them as keywords of
:func:`~coinflight.queries.probability.probability_query`."""


@command
def probability(
    ctx: typer.Context,
    *,
    tosses: TossesOptions,
    preset: TossPreset = None,
    coin: CoinOptions,
    table: TableOptions,
    air: AirOptions,
    how: Annotated[dict[str, Any], HOW],
    cluster: ParallelOptions,
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """Chance of heads for tosses spread over ranges of spin and flight time.

    Example (the paper's Fig 2a): coinflight probability --omega-x 60:90 --flight-time 0.6:0.9
    --method grid --n 5000
    """
    from coinflight.queries import probability as q

    query = q.probability_query(
        tosses,
        coin,
        table,
        air,
        **how,
        threads=cluster.threads,
        preset=preset,
        overrides=given_toss_options(ctx) if preset is not None else None,
        inputs={name: ctx.params.get(name) for name in q.INPUT_NAMES},
    )
    if cluster.scheduler is not None and not query.estimator.parallel:
        raise ValueError(f"--scheduler does not apply to the {query.method} method (one task)")
    with (
        cluster.executor() as executor,
        progress_bar(query.work_units(), query.method, quiet) as bar,
    ):
        result = q.run(query, bar, executor=executor)
    if json_output:
        print_json(q.probability_payload(query, result))
        return
    _report(result, query.dist, tosses.launch_speed, query.landing)
    if table.surface_preset is not None:
        from coinflight.studies.presets import surface_preset

        typer.echo(f"surface preset {surface_preset(table.surface_preset).describe()}")


def _report(
    result: ProbabilityResult,
    dist: TossDistribution,
    launch_speed: str | None,
    landing: LandingChoice | None,
) -> None:
    """The text output of ``coinflight probability``."""
    typer.echo(dist.describe())
    typer.echo(_gravity_line(dist.g, launch_speed))
    if landing is not None:
        typer.echo(describe_for(landing.model, dist))
    typer.echo(result.describe())
    line = f"P(tails) = {result.p_tails:.6f}, P(same side) = {result.p_same_side:.6f}"
    if landing is not None and landing.model.can_end_on_edge:
        line += f", P(edge) = {result.p_edge:.6g}"
    typer.echo(line)
    for warning in result_warnings(result):
        typer.echo(f"warning: {warning}")
    typer.echo(_method_line(result))


def _gravity_line(g: float, launch_speed: str | None) -> str:
    """``g = 9.81 m/s²`` and, when given, the launch speed the flight time came from."""
    line = f"g = {g:g} m/s²"
    if launch_speed is not None:
        from coinflight.model.distributions import parse_distribution

        v0 = parse_distribution(launch_speed, "--launch-speed", "m/s")
        line += f"; launch speed v0 = {v0.describe('m/s')} (T = 2 v0 / g)"
    return line


def _method_line(result: ProbabilityResult) -> str:
    return f"method {result.method}: {result.describe_run()}; {result.elapsed:.3g} s"

"""``coinflight probability``: the chance of heads for a range of tosses."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions, TossesOptions
from coinflight.cli.landing import contact_spread
from coinflight.cli.landing_groups import AirOptions, TableOptions
from coinflight.cli.options import (
    METHOD_PANEL,
    JsonFlag,
    Quiet,
    Seed,
    Threads,
    TossPreset,
    print_json,
)
from coinflight.cli.presets import preset_distribution
from coinflight.cli.progress import progress_bar
from coinflight.cli.surface import outcome_model
from coinflight.outcomes.table import DRAG_TOSSES_PER_SECOND
from coinflight.probability import registry

if TYPE_CHECKING:
    from coinflight.cli.surface import LandingChoice
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import ProbabilityResult

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
        rich_help_panel=METHOD_PANEL,
        help="monte-carlo only: draw from the midpoints of C cells per parameter "
        "(the paper's method B uses 100).",
    ),
]


def work_total(method: str, n: int | None, k: int) -> int:
    """Units of work the library reports through ``progress`` for this request."""
    estimator = registry.get(method)
    return estimator.work_units(k, estimator.size_for(k, n) or 1)


@command
def probability(
    ctx: typer.Context,
    *,
    tosses: TossesOptions,
    preset: TossPreset = None,
    coin: CoinOptions,
    table: TableOptions,
    air: AirOptions,
    method: Method = "exact",
    n: Size = None,
    seed: Seed = None,
    grid_cells: GridCells = None,
    threads: Threads = None,
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """Chance of heads for tosses spread over ranges of spin and flight time.

    Example (the paper's Fig 2a): coinflight probability --omega-x 60:90 --flight-time 0.6:0.9
    --method grid --n 5000
    """
    from coinflight.probability import estimate
    from coinflight.studies.presets import surface_preset

    estimator = registry.get(method)
    if preset is not None:
        dist = preset_distribution(ctx, preset, coin, tosses.start, tosses.g)
    else:
        dist = tosses.build(coin)
    options: dict[str, Any] = {}
    if grid_cells is not None:
        if "grid_cells" not in estimator.options:
            takers = [e.name for e in registry.estimators() if "grid_cells" in e.options]
            raise ValueError(f"--grid-cells applies to --method {' and '.join(takers)} only")
        options["grid_cells"] = grid_cells
    if seed is not None and not estimator.seeded:
        seeded = " and ".join(registry.names(seeded=True))
        raise ValueError(f"--seed applies to {seeded}, not {method}")
    if threads is not None and not estimator.parallel:
        raise ValueError(f"--threads does not apply to the {method} method")
    landing = outcome_model(*table, *air, ranged=True)
    # Distributions of e and μ (build_surface refused them for the hand; single values are in
    # the surface) go with the tosses, drawn toss by toss.
    given = contact_spread(table.restitution, table.friction, table.surface_preset)
    spread = {name: d for name, d in given.items() if not d.is_fixed}
    if spread:
        dist = dist.with_contact(**spread)
    if landing is not None and landing.drag is not None and estimator.default_n and n is None:
        raise ValueError(_DRAG_NEEDS_N.format(method=method, example=_drag_example(method, dist)))
    if landing is not None:
        options["model"] = landing.model
    total = work_total(method, n, len(dist.ranged))
    with progress_bar(total, f"{method}", quiet) as bar:
        if estimator.parallel:
            options.update(threads=threads, progress=bar)
        result = estimate(dist, method, n=n, seed=seed, **options)
    if json_output:
        payload = result.to_dict()
        payload["distribution"] = {name: d.to_dict() for name, d in dist.parameters.items()}
        payload.update(coin=coin.name, start=tosses.start, g=dist.g, inputs=_inputs(ctx))
        payload["distribution"].update({name: d.to_dict() for name, d in dist.contact.items()})
        if landing is not None:
            payload.update(landing.model.settings_for(dist))
        if table.surface_preset is not None:
            payload["surface_preset"] = surface_preset(table.surface_preset).to_dict()
        payload["warnings"] = _warnings(result)
        print_json(payload)
        return
    _report(result, dist, tosses.launch_speed, landing)
    if table.surface_preset is not None:
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
        typer.echo(landing.model.describe_for(dist))
    typer.echo(result.describe())
    line = f"P(tails) = {result.p_tails:.6f}, P(same side) = {result.p_same_side:.6f}"
    if landing is not None and landing.surface.bounces:
        line += f", P(edge) = {result.p_edge:.6g}"
    typer.echo(line)
    for warning in _warnings(result):
        typer.echo(f"warning: {warning}")
    typer.echo(_method_line(result))


_DRAG_NEEDS_N = (
    f"with --drag each toss is a numerical integration (about {DRAG_TOSSES_PER_SECOND} tosses "
    "per second per thread), so the default size of --method {method} would run for hours or "
    "days; give --n explicitly, e.g. {example}"
)


def _drag_example(method: str, dist: TossDistribution) -> str:
    """An --n that takes about a minute with drag, and what it means."""
    k = len(dist.ranged)
    if method == "grid":
        cells = max(1, int((60 * DRAG_TOSSES_PER_SECOND) ** (1 / max(k, 1))))
        return f"--n {cells} ({cells}^{k} = {cells**k:,} tosses, about a minute)"
    if method == "qmc":
        return "--n 1024 (about a minute)"
    return "--n 1000 (about a minute; standard error about 0.016)"


def _warnings(result: Any) -> list[str]:
    """What the user must know about the result: tosses that never settled (table landing)."""
    unsettled = int(result.details.get("unsettled", 0))
    if not unsettled:
        return []
    n = sum(result.counts) if result.counts is not None else result.samples
    return [
        f"{unsettled:,} of {n:,} tosses ({100 * result.details['unsettled_fraction']:.3g} %) "
        "never settled (status 'unsettled'); they are counted by the face they showed when the "
        "simulation stopped"
    ]


def _gravity_line(g: float, launch_speed: str | None) -> str:
    """``g = 9.81 m/s²`` and, when given, the launch speed the flight time came from."""
    line = f"g = {g:g} m/s²"
    if launch_speed is not None:
        from coinflight.model.distributions import parse_distribution

        v0 = parse_distribution(launch_speed, "--launch-speed", "m/s")
        line += f"; launch speed v0 = {v0.describe('m/s')} (T = 2 v0 / g)"
    return line


def _inputs(ctx: typer.Context) -> dict[str, Any]:
    """The toss options as the user typed them (or their defaults), by option name."""
    names = ("omega_x", "omega_y", "omega_z", "flight_time", "launch_speed", "g", "preset")
    return {f"--{name.replace('_', '-')}": ctx.params.get(name) for name in names}


def _method_line(result: object) -> str:
    from coinflight.probability import ProbabilityResult

    assert isinstance(result, ProbabilityResult)
    extra = registry.get(result.method).summary(result)
    return f"method {result.method}: {extra}; {result.elapsed:.3g} s"

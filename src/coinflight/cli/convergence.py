"""``coinflight convergence``: estimates against configurations / events (the paper's Figs 2-3)."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.cluster import ParallelOptions
from coinflight.cli.command import Group, command
from coinflight.cli.groups import CoinOptions, ConvergenceTossesOptions
from coinflight.cli.options import (
    METHOD_PANEL,
    OUTPUT_HELP,
    JsonFlag,
    Quiet,
    Seed,
    print_json,
)
from coinflight.cli.parsers import output_prefix
from coinflight.cli.progress import progress_bar
from coinflight.probability import registry

if TYPE_CHECKING:
    from coinflight.probability.convergence import Convergence


def _sizes_option(flag: str, help: str) -> Any:
    return typer.Option(flag, metavar="N1,N2,…", rich_help_panel=METHOD_PANEL, help=help)


GridSizes = Annotated[
    str | None,
    _sizes_option("--grid-sizes", "Cells per parameter for method A (default 5,10,…,5000)."),
]
EventSizes = Annotated[
    str | None,
    _sizes_option("--event-sizes", "Events for method B / Monte Carlo (default 100,…,10000000)."),
]
QmcSizes = Annotated[
    str | None,
    _sizes_option("--qmc-sizes", "QMC points, each 16 × a power of two (default 64,…,1048576)."),
]
SIZES = Group(
    {
        "grid_sizes": (GridSizes, None),
        "event_sizes": (EventSizes, None),
        "qmc_sizes": (QmcSizes, None),
    },
    dict,
)
"""The sizes of each method's series, as typed (read by
:func:`~coinflight.queries.convergence.convergence_plan`)."""
Methods = Annotated[
    str,
    typer.Option(
        "--methods",
        metavar="LIST",
        rich_help_panel=METHOD_PANEL,
        help="Comma-separated, of "
        + ", ".join(registry.names(series=True))
        + " (grid: method A; monte-carlo: method B with --grid-cells 100, the default).",
    ),
]
Cells = Annotated[
    int | None,
    typer.Option(
        "--grid-cells",
        metavar="C",
        rich_help_panel=METHOD_PANEL,
        help="Cells per parameter for method B (default 100, as the paper); 0 for plain Monte "
        "Carlo.",
    ),
]
Out = Annotated[
    Path,
    typer.Option(
        "--out",
        "-o",
        metavar="PREFIX",
        parser=output_prefix,
        rich_help_panel="Output",
        help="Write PREFIX.csv, PREFIX.json, PREFIX.png and PREFIX.svg, all together at the end "
        f"(a folder, existing or written as DIR/: DIR/convergence.*). {OUTPUT_HELP}",
    ),
]


@command
def convergence(
    *,
    tosses: ConvergenceTossesOptions,
    coin: CoinOptions,
    methods: Methods = "grid,monte-carlo",
    sizes: Annotated[dict[str, str | None], SIZES],
    grid_cells: Cells = None,
    seed: Seed = None,
    cluster: ParallelOptions,
    out: Out = Path("convergence"),
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """Estimates of P(heads) as configurations / events grow, with the exact value.

    Example (the paper's Fig 2a): coinflight convergence --omega-x 60:90 --flight-time 0.6:0.9
    --seed 1 --out fig2a
    """
    from coinflight._files import check_all_writable, replacing_all
    from coinflight.plotting.convergence import plot_convergence
    from coinflight.plotting.style import save_figure
    from coinflight.probability.convergence import convergence as run
    from coinflight.probability.convergence import work_total
    from coinflight.queries.convergence import convergence_plan

    dist = tosses.build(coin)
    plan = convergence_plan(methods, sizes, grid_cells, seed)
    prefix = out  # already DIR/convergence for a folder (output_prefix)
    targets = [prefix.with_name(f"{prefix.name}.{ext}") for ext in ("csv", "json", "png", "svg")]
    check_all_writable(targets)  # before computing, not after
    total = work_total(dist, plan.methods, **plan.sizes)
    with cluster.executor() as executor, progress_bar(total, "convergence", quiet) as bar:
        result = run(
            dist,
            plan.methods,
            seed=plan.seed,
            grid_cells=plan.grid_cells or None,
            executor=executor,
            threads=cluster.threads,
            progress=bar,
            **plan.sizes,
        )
    fig = plot_convergence(result)
    with replacing_all(targets) as (csv, _, png, svg):  # the four files together, or none
        result.write(csv.with_name(prefix.name))  # PREFIX.csv and PREFIX.json
        save_figure(fig, png)
        save_figure(fig, svg)
    if json_output:
        print_json({**result.to_dict(), "files": [str(p) for p in targets]})
        return
    _report(result, targets)


def _report(result: Convergence, written: list[Path]) -> None:
    """The text output of ``coinflight convergence``."""
    exact = "not available" if result.exact is None else f"{result.exact:.6f} ({result.exact_how})"
    typer.echo(f"exact P(heads) = {exact}")
    for m in result.methods:
        last = result.series(m)[-1]
        typer.echo(f"{m}: P(heads) = {last.p_heads:.6f} at {last.samples:,} (largest size)")
    files = ", ".join(str(p) for p in written)
    typer.echo(f"wrote {files}" if result.seed is None else f"seed {result.seed}; wrote {files}")

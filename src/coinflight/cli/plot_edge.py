"""``coinflight plot edge``: P(edge) against thickness / diameter, as a figure."""

from __future__ import annotations

from typing import Annotated

import typer

from coinflight.cli.edge_groups import RATIOS, SIM_PANEL, _simulate
from coinflight.cli.options import Dpi, OutFile, SimulateSeed, number
from coinflight.cli.output import echo_written
from coinflight.cli.parsers import parse_numbers
from coinflight.queries.values import simulation_seed

Simulate = Annotated[int | None, _simulate("plot their edge fraction")]
Ratios = Annotated[
    str | None,
    typer.Option(
        "--ratios",
        metavar="R,R,...",
        rich_help_panel=SIM_PANEL,
        help=f"Ratios h/d to simulate with --simulate [default: {RATIOS}].",
    ),
]
MaxRatio = Annotated[
    float,
    typer.Option(
        "--max-ratio",
        parser=number,
        metavar="X",
        help="Right end of the h/d axis (above 1/√3 ≈ 0.577).",
    ),
]


def plot_edge(
    out: OutFile,
    simulate: Simulate = None,
    seed: SimulateSeed = None,
    ratios: Ratios = None,
    max_ratio: MaxRatio = 1.0,
    dpi: Dpi = 150,
) -> None:
    """Plot P(edge) against h/d (Yong & Mahadevan 2011), the ratios for P(edge) = 1/3 marked.

    Example: coinflight plot edge --out edge.png --simulate 4000 --seed 1
    """
    from coinflight.plotting.edge import plot_edge
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.studies.edge import MODELS, ratio_for, simulate_edge

    figure_paths(out, "--out")  # before the simulation, not after
    the_seed = simulation_seed(simulate, seed, ("--ratios", ratios), run_flag="--simulate")
    simulated = []
    if simulate is not None:
        points = parse_numbers(RATIOS if ratios is None else ratios, "--ratios", "0.2,0.5,1")
        simulated = simulate_edge(points, simulate, the_seed)
    figure = plot_edge(simulated, max_ratio)
    echo_written(save_figure(figure, out, dpi=dpi))
    for model in MODELS:
        typer.echo(f"P(edge) = 1/3 at h/d = {ratio_for(1 / 3, model):.4f} ({model} model)")
    if simulated:
        typer.echo(f"simulated, {simulate:,} tosses per ratio, seed {simulated[0][1].seed}:")
        for ratio, s in simulated:
            typer.echo(
                f"  h/d = {ratio:g}: P(edge) = {s.p:.4f} ± {s.stderr:.4f} (s.e.), "
                f"{s.successes:,} of {s.n:,}"
            )


# --- coinflight edge: the numbers --------------------------------------------------------------


__all__ = ["plot_edge"]

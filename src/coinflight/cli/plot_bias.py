"""``coinflight plot bias``: p(ψ), the same-side probability against the precession angle."""

from __future__ import annotations

from typing import Annotated

import typer

from coinflight.cli.options import (
    PSI_PANEL,
    SIM_PANEL,
    Dpi,
    MonteCarlo,
    OutFile,
    SimulationSeed,
    number_option,
    option,
)
from coinflight.cli.output import echo_written
from coinflight.cli.parsers import parse_numbers
from coinflight.queries.values import simulation_seed

PSI_POINTS = "45,50,55,60,70,80,90,100,110,120,130,135"
Measured = Annotated[
    float | None,
    number_option(
        "--measured",
        "P",
        PSI_PANEL,
        "Mark a measured same-side rate (e.g. 0.5077, Bartoš et al.) and the ψ that gives it.",
    ),
]
PsiPoints = Annotated[
    str | None,
    option(
        "--psi-points",
        metavar="DEG,DEG,...",
        panel=SIM_PANEL,
        help=f"Angles (degrees) at which to simulate with --monte-carlo [default: {PSI_POINTS}].",
    ),
]


def plot_bias(
    out: OutFile,
    monte_carlo: MonteCarlo = None,
    seed: SimulationSeed = None,
    psi_points: PsiPoints = None,
    measured: Measured = None,
    dpi: Dpi = 150,
) -> None:
    """Plot p(ψ), optionally with Monte Carlo points of the full flight.

    Example: coinflight plot bias --out bias.png --monte-carlo 20000 --measured 0.5077
    """
    from coinflight.plotting.bias import plot_bias
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.studies import bias as b

    figure_paths(out, "--out")  # before the simulation, not after
    seed = simulation_seed(monte_carlo, seed, ("--psi-points", psi_points))
    simulated = []
    if monte_carlo is not None:
        angles = parse_numbers(
            PSI_POINTS if psi_points is None else psi_points, "--psi-points", "60,80,100"
        )
        simulated = b.simulate_same_side_at(angles, monte_carlo, seed, degrees=True)
    psi_measured = None
    if measured is not None:
        psi_measured = float(b.psi_for_probability(measured, degrees=True))
    echo_written(save_figure(plot_bias(simulated, measured, psi_measured), out, dpi=dpi))
    if measured is not None and psi_measured is not None:
        typer.echo(f"measured P(same side) = {measured:g} needs a fixed ψ = {psi_measured:.2f}°")
    if simulated:
        typer.echo(f"Monte Carlo: {monte_carlo:,} tosses per point, seed {simulated[0][1].seed}")


__all__ = ["plot_bias"]

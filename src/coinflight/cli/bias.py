"""``coinflight bias`` and ``coinflight plot bias``: same-side bias from precession."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions
from coinflight.cli.options import (
    PSI_PANEL,
    JsonFlag,
    MonteCarlo,
    PsiPreset,
    Quiet,
    SimulationSeed,
    number,
    print_json,
)

if TYPE_CHECKING:
    from coinflight.queries.bias import PresetBias

Psi = Annotated[
    float | None,
    typer.Option(
        "--psi",
        parser=number,
        metavar="DEG",
        rich_help_panel=PSI_PANEL,
        help="Fixed angle ψ between the coin's normal and its angular momentum, degrees, "
        "0-180 (90 = spin about a diameter, no bias).",
    ),
]
PsiDist = Annotated[
    str | None,
    typer.Option(
        "--psi-dist",
        metavar="SPEC",
        rich_help_panel=PSI_PANEL,
        help="A distribution of ψ in degrees: normal:MEAN,SD (or LOW:HIGH, uniform; or a "
        "number, fixed), or the people's ψ population fitted to a dataset by name "
        "(bartos2023: see coinflight data). p(ψ) is averaged over it.",
    ),
]


@command
def bias(
    *,
    psi: Psi = None,
    psi_dist: PsiDist = None,
    preset: PsiPreset = None,
    monte_carlo: MonteCarlo = None,
    seed: SimulationSeed = None,
    coin: CoinOptions,
    json_output: JsonFlag = False,
    quiet: Quiet = False,
) -> None:
    """Probability that a precessing coin lands on the side it started (Diaconis et al. 2007).

    Example: coinflight bias --psi 80 --monte-carlo 200000
    """
    from coinflight.cli.progress import progress_bar
    from coinflight.queries.bias import SOURCE, PresetBias, bias_query
    from coinflight.studies import bias as b

    with progress_bar(monte_carlo or 0, "bias Monte Carlo", quiet) as bar:
        answer = bias_query(psi, psi_dist, preset, monte_carlo, seed, coin, bar)
    if json_output:
        print_json(answer.payload())
        return
    if isinstance(answer, PresetBias):
        _report_preset(answer)
        return
    sim = answer.simulation
    typer.echo(f"{answer.what}: P(same side) = {answer.p:.6f}  (closed form, {SOURCE})")
    if sim is not None:
        t_lo, t_hi = b.DEFAULT_FLIGHT_TIME
        w_lo, w_hi = b.DEFAULT_PRECESSION_RATE
        typer.echo(
            f"Monte Carlo: {sim.successes:,} of {sim.n:,} tosses on the same side = "
            f"{sim.p:.6f} ± {sim.stderr:.6f} (s.e.), {sim.z(answer.p):+.2f} s.e. from the "
            f"closed form; seed {sim.seed}"
        )
        typer.echo(
            f"  full torque-free flight of a {coin.name}: T ~ uniform {t_lo:g}-{t_hi:g} s, "
            f"ωp ~ uniform {w_lo:g}-{w_hi:g} rad/s, random spin azimuth"
        )


def _report_preset(answer: PresetBias) -> None:
    """The text of ``coinflight bias --preset NAME``."""
    from coinflight.queries.bias import SOURCE

    p, psi_q, result = answer.p, answer.psi_q, answer.result
    typer.echo(f"preset {answer.name}: {answer.dist.describe()}".replace("\n", "; "))
    typer.echo(
        f"ψ median {psi_q[1]:.1f}° (95 % of spins {psi_q[0]:.1f}°-{psi_q[2]:.1f}° at the mean "
        f"ωx): P(same side) = {p:.6f}  (closed form averaged over the spins, {SOURCE})"
    )
    if result is not None and result.stderr is not None:
        typer.echo(
            f"Monte Carlo (coinflight.probability, full flight): {result.p_same_side:.6f} ± "
            f"{result.stderr:.6f} (s.e.) over {result.n:,} tosses, "
            f"{(result.p_same_side - p) / result.stderr:+.2f} s.e. from the closed form; "
            f"seed {result.seed}"
        )

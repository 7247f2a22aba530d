"""``coinflight bias`` and ``coinflight plot bias``: same-side bias from precession."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.command import command
from coinflight.cli.groups import CoinOptions
from coinflight.cli.options import (
    PSI_PANEL,
    JsonFlag,
    MonteCarlo,
    PsiPreset,
    SimulationSeed,
    number,
    print_json,
)
from coinflight.queries.values import simulation_seed

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.studies.bias import QuantileDistribution

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
        "number, fixed). p(ψ) is averaged over it.",
    ),
]


def resolve_psi(psi: float | None, psi_dist: str | None) -> float | QuantileDistribution:
    """The fixed ψ (degrees) or the ψ distribution the options ask for (exactly one)."""
    if (psi is None) == (psi_dist is None):
        raise ValueError("give exactly one of --psi DEG, --psi-dist SPEC and --preset NAME")
    if psi is not None:
        return psi
    from coinflight.model.distributions import parse_distribution

    assert psi_dist is not None
    return parse_distribution(psi_dist, "--psi-dist", "degrees")


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
) -> None:
    """Probability that a precessing coin lands on the side it started (Diaconis et al. 2007).

    Example: coinflight bias --psi 80 --monte-carlo 200000
    """
    from coinflight.studies import bias as b

    seed = simulation_seed(monte_carlo, seed)
    if preset is not None:
        if psi is not None or psi_dist is not None:
            raise ValueError("give exactly one of --psi DEG, --psi-dist SPEC and --preset NAME")
        _bias_preset(preset, monte_carlo, seed, coin, json_output)
        return
    spec = resolve_psi(psi, psi_dist)
    if isinstance(spec, float):
        p = float(b.same_side_probability(spec, degrees=True))
        what = f"ψ = {spec:g}° (fixed)"
        psi_payload: dict[str, Any] = {"psi_deg": spec, "psi_model": "fixed"}
    else:
        p = b.mean_same_side_probability(spec, degrees=True)
        what = f"ψ ~ {spec.describe('degrees')}"  # type: ignore[attr-defined]
        psi_payload = {"psi_dist": psi_dist, "psi_model": "distribution"}
        mean = getattr(spec, "mean", None)
        if mean is not None:
            psi_payload["psi_deg"] = float(mean)
    sim = None
    the_coin = coin  # enters only the simulation (through I1/I3), but is checked in any case
    if monte_carlo is not None:
        sim = b.simulate_same_side(spec, monte_carlo, seed, coin=the_coin, degrees=True)
    if json_output:
        payload: dict[str, Any] = {"p_same_side": p, **psi_payload, "source": SOURCE}
        if sim is not None:
            payload["monte_carlo"] = {
                **_monte_carlo(sim.p, sim.stderr, sim.n, sim.seed, p),
                "same": sim.successes,
                "flight_time": list(b.DEFAULT_FLIGHT_TIME),
                "precession_rate": list(b.DEFAULT_PRECESSION_RATE),
                "coin": the_coin.name,
            }
        print_json(payload)
        return
    typer.echo(f"{what}: P(same side) = {p:.6f}  (closed form, {SOURCE})")
    if sim is not None:
        t_lo, t_hi = b.DEFAULT_FLIGHT_TIME
        w_lo, w_hi = b.DEFAULT_PRECESSION_RATE
        typer.echo(
            f"Monte Carlo: {sim.successes:,} of {sim.n:,} tosses on the same side = "
            f"{sim.p:.6f} ± {sim.stderr:.6f} (s.e.), {sim.z(p):+.2f} s.e. from the "
            f"closed form; seed {sim.seed}"
        )
        typer.echo(
            f"  full torque-free flight of a {the_coin.name}: T ~ uniform {t_lo:g}-{t_hi:g} s, "
            f"ωp ~ uniform {w_lo:g}-{w_hi:g} rad/s, random spin azimuth"
        )


SOURCE = "Diaconis, Holmes & Montgomery 2007"


def _bias_preset(
    name: str, monte_carlo: int | None, seed: int | None, coin: Coin, json_output: bool
) -> None:
    """``coinflight bias --preset NAME``: the closed-form average over the preset's spins, and
    optionally a Monte Carlo run of the full flight through :func:`coinflight.probability.
    estimate` (started heads up, so P(heads) is the same-side probability)."""
    from coinflight.studies import bias as b
    from coinflight.studies.presets import preset, psi_range

    dist = preset(name, coin=coin)
    p = b.expected_same_side(dist)
    psi_q = psi_range(dist)  # median and 95 % range of ψ over the spins, for the report
    result = None
    if monte_carlo is not None:
        from coinflight.probability import estimate

        result = estimate(dist, "monte-carlo", b.check_tosses(monte_carlo), seed)
    if json_output:
        payload: dict[str, Any] = {
            "p_same_side": p,
            "preset": name,
            "psi_model": "preset",
            "psi_deg": float(psi_q[1]),
            "psi_range95_deg": [float(psi_q[0]), float(psi_q[2])],
            "distribution": {k: d.to_dict() for k, d in dist.parameters.items()},
            "coin": dist.coin.name,
            "source": SOURCE,
        }
        if result is not None:
            payload["monte_carlo"] = _monte_carlo(
                result.p_same_side, result.stderr, result.n, result.seed, p
            )
        print_json(payload)
        return
    typer.echo(f"preset {name}: {dist.describe()}".replace("\n", "; "))
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


def _monte_carlo(
    p_sim: float, stderr: float | None, n: int | None, seed: int | None, p: float
) -> dict[str, Any]:
    """The JSON of a Monte Carlo check against the closed form p: estimate, s.e., n, seed, z."""
    z = (p_sim - p) / stderr if stderr else 0.0
    return {"p_same_side": p_sim, "stderr": stderr, "n": n, "seed": seed, "z": z}

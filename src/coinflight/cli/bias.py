"""``coinflight bias`` and ``coinflight plot bias``: same-side bias from precession."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight.cli.figures import Dpi, OutFile
from coinflight.cli.options import (
    CoinName,
    JsonFlag,
    Mass,
    Radius,
    Thickness,
    number,
    print_json,
    resolve_coin,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.studies.bias import QuantileDistribution

PSI_PANEL = "Precession angle"
SIM_PANEL = "Monte Carlo check"

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
MonteCarlo = Annotated[
    int | None,
    typer.Option(
        "--monte-carlo",
        min=1,
        metavar="N",
        rich_help_panel=SIM_PANEL,
        help="Also simulate N ≥ 100 tosses of the full torque-free flight (random flight time and "
        "spin at the given ψ) and report their same-side fraction with its standard error.",
    ),
]
Seed = Annotated[
    int | None,
    typer.Option(
        "--seed",
        min=0,
        metavar="S",
        rich_help_panel=SIM_PANEL,
        help="Seed of the --monte-carlo simulation (reported; drawn at random if not given).",
    ),
]


def simulation_seed(
    monte_carlo: int | None,
    seed: int | None,
    *others: tuple[str, object],
    run_flag: str = "--monte-carlo",
) -> int | None:
    """--seed, passed through (None: the library draws one and reports it); ValueError if --seed
    or another simulation option is given without ``run_flag``, which alone runs the simulation
    they set."""
    if monte_carlo is None:
        for flag, value in (("--seed", seed), *others):
            if value is not None:
                raise ValueError(f"{flag} needs {run_flag} N (it sets the simulation)")
    return seed


PresetName = Annotated[
    str | None,
    typer.Option(
        "--preset",
        metavar="NAME",
        rich_help_panel=PSI_PANEL,
        help="A named distribution of tosses: human (a person's natural toss: v0 ≈ 2.4 m/s, "
        "38 rev/s, ψ near but below 90°; DHM 2007 via Keller). See coinflight.studies.presets.",
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


def bias(
    psi: Psi = None,
    psi_dist: PsiDist = None,
    preset: PresetName = None,
    monte_carlo: MonteCarlo = None,
    seed: Seed = None,
    coin: CoinName = None,
    radius: Radius = None,
    thickness: Thickness = None,
    mass: Mass = None,
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
        _bias_preset(
            preset, monte_carlo, seed, resolve_coin(coin, radius, thickness, mass), json_output
        )
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
    # The coin enters only the simulation (through I1/I3), but is checked in any case.
    the_coin = resolve_coin(coin, radius, thickness, mass)
    if monte_carlo is not None:
        sim = b.simulate_same_side(spec, monte_carlo, seed, coin=the_coin, degrees=True)
    if json_output:
        payload: dict[str, Any] = {"p_same_side": p, **psi_payload, "source": SOURCE}
        if sim is not None:
            payload["monte_carlo"] = {
                "p_same_side": sim.p,
                "stderr": sim.stderr,
                "same": sim.successes,
                "n": sim.n,
                "seed": sim.seed,
                "z": sim.z(p),
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
    import numpy as np

    from coinflight.core.torque_free import cone_angle
    from coinflight.studies import bias as b
    from coinflight.studies.presets import preset

    dist = preset(name, coin=coin)
    p = b.expected_same_side(dist)
    # Median and 95 % range of ψ over the spins, for the report.
    u = np.array([0.025, 0.5, 0.975])
    omega = np.stack([dist.omega_x.ppf(0.5 + 0 * u), 0 * u, dist.omega_z.ppf(u)], axis=-1)
    psi_q = np.degrees(cone_angle(omega, *dist.moments))[::-1]
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
            payload["monte_carlo"] = {
                "p_same_side": result.p_same_side,
                "stderr": result.stderr,
                "n": result.n,
                "seed": result.seed,
                "z": (result.p_same_side - p) / result.stderr if result.stderr else 0.0,
            }
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


PSI_POINTS = "45,50,55,60,70,80,90,100,110,120,130,135"
Measured = Annotated[
    float | None,
    typer.Option(
        "--measured",
        parser=number,
        metavar="P",
        rich_help_panel=PSI_PANEL,
        help="Mark a measured same-side rate (e.g. 0.5077, Bartoš et al.) and the ψ that gives it.",
    ),
]
PsiPoints = Annotated[
    str | None,
    typer.Option(
        "--psi-points",
        metavar="DEG,DEG,...",
        rich_help_panel=SIM_PANEL,
        help=f"Angles (degrees) at which to simulate with --monte-carlo \\[default: {PSI_POINTS}].",
    ),
]


def plot_bias(
    out: OutFile,
    monte_carlo: MonteCarlo = None,
    seed: Seed = None,
    psi_points: PsiPoints = None,
    measured: Measured = None,
    dpi: Dpi = 150,
) -> None:
    """Plot p(ψ), optionally with Monte Carlo points of the full flight.

    Example: coinflight plot bias --out bias.png --monte-carlo 20000 --measured 0.5077
    """
    from coinflight.cli.figures import parse_numbers
    from coinflight.plotting.bias import plot_bias
    from coinflight.plotting.style import figure_paths, save_figure
    from coinflight.studies import bias as b

    figure_paths(out, "--out")  # before the simulation, not after
    seed = simulation_seed(monte_carlo, seed, ("--psi-points", psi_points))
    simulated = []
    if monte_carlo is not None:
        angles = parse_numbers(psi_points or PSI_POINTS, "--psi-points", "60,80,100")
        simulated = b.simulate_same_side_at(angles, monte_carlo, seed, degrees=True)
    psi_measured = None
    if measured is not None:
        psi_measured = float(b.psi_for_probability(measured, degrees=True))
    for p in save_figure(plot_bias(simulated, measured, psi_measured), out, dpi=dpi):
        typer.echo(f"wrote {p}")
    if measured is not None and psi_measured is not None:
        typer.echo(f"measured P(same side) = {measured:g} needs a fixed ψ = {psi_measured:.2f}°")
    if simulated:
        typer.echo(f"Monte Carlo: {monte_carlo:,} tosses per point, seed {simulated[0][1].seed}")

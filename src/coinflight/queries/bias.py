"""The same-side bias of a precessing coin (``coinflight bias --json``, ``GET /api/bias``):
p(ψ) in closed form for a fixed ψ, a ψ distribution or a preset, optionally checked by a Monte
Carlo run of the full flight."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from coinflight.queries.values import simulation_seed

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import ProbabilityResult
    from coinflight.probability.result import BinomialEstimate
    from coinflight.studies.bias import QuantileDistribution

SOURCE = "Diaconis, Holmes & Montgomery 2007"


def resolve_psi(psi: float | None, psi_dist: str | None) -> float | QuantileDistribution:
    """The fixed ψ (degrees) or the ψ distribution the options ask for (exactly one)."""
    if (psi is None) == (psi_dist is None):
        raise ValueError("give exactly one of --psi DEG, --psi-dist SPEC and --preset NAME")
    if psi is not None:
        return psi
    from coinflight.model.distributions import parse_distribution

    assert psi_dist is not None
    fitted = fitted_psi_dist(psi_dist)
    if fitted is not None:
        return fitted
    try:
        return parse_distribution(psi_dist, "--psi-dist", "degrees")
    except ValueError as exc:
        from coinflight.datasets import DATASETS

        raise ValueError(f"{exc}; or a dataset's name: {', '.join(DATASETS)}") from None


def fitted_psi_dist(name: str) -> QuantileDistribution | None:
    """The ψ population fitted to the shipped dataset ``name`` (``--psi-dist bartos2023``), as a
    normal distribution of ψ in degrees (:func:`coinflight.studies.flippers.fitted_population`;
    unfolded, p(ψ) being the same at ψ and 180° − ψ), or None if ``name`` is not a dataset."""
    from coinflight.datasets import DATASETS

    if name.strip() not in DATASETS:
        return None
    from coinflight.studies.flippers import fitted_population

    return fitted_population(name.strip()).distribution()


@dataclass(frozen=True)
class AngleBias:
    """p(ψ) at a fixed ψ or averaged over a ψ distribution, and the Monte Carlo check."""

    p: float
    what: str
    psi: dict[str, Any]
    coin: Coin
    simulation: BinomialEstimate | None

    def payload(self) -> dict[str, Any]:
        """The JSON object of ``coinflight bias --json``."""
        from coinflight.studies import bias as b

        payload: dict[str, Any] = {"p_same_side": self.p, **self.psi, "source": SOURCE}
        sim = self.simulation
        if sim is not None:
            payload["monte_carlo"] = {
                **monte_carlo_payload(sim.p, sim.stderr, sim.n, sim.seed, self.p),
                "same": sim.successes,
                "flight_time": list(b.DEFAULT_FLIGHT_TIME),
                "precession_rate": list(b.DEFAULT_PRECESSION_RATE),
                "coin": self.coin.name,
            }
        return payload


@dataclass(frozen=True)
class PresetBias:
    """p(ψ) averaged over a preset's spins, ψ's median and 95 % range, the Monte Carlo check."""

    name: str
    p: float
    psi_q: tuple[float, float, float]
    dist: TossDistribution
    result: ProbabilityResult | None

    def payload(self) -> dict[str, Any]:
        """The JSON object of ``coinflight bias --preset NAME --json``."""
        psi_q = self.psi_q
        payload: dict[str, Any] = {
            "p_same_side": self.p,
            "preset": self.name,
            "psi_model": "preset",
            "psi_deg": float(psi_q[1]),
            "psi_range95_deg": [float(psi_q[0]), float(psi_q[2])],
            "distribution": {k: d.to_dict() for k, d in self.dist.parameters.items()},
            "coin": self.dist.coin.name,
            "source": SOURCE,
        }
        r = self.result
        if r is not None:
            payload["monte_carlo"] = monte_carlo_payload(
                r.p_same_side, r.stderr, r.n, r.seed, self.p
            )
        return payload


def bias_query(
    psi: float | None,
    psi_dist: str | None,
    preset: str | None,
    monte_carlo: int | None,
    seed: int | None,
    coin: Coin,
    progress: Callable[[int], object] | None = None,
) -> AngleBias | PresetBias:
    """The answer of ``coinflight bias`` (options checked in its order); ``progress`` is
    called with the tosses done as the Monte Carlo run goes (a progress bar)."""
    from coinflight.datasets import DATASETS
    from coinflight.studies import bias as b

    seed = simulation_seed(monte_carlo, seed)
    if preset is not None:
        if psi is not None or psi_dist is not None:
            raise ValueError("give exactly one of --psi DEG, --psi-dist SPEC and --preset NAME")
        return _preset_bias(preset, monte_carlo, seed, coin, progress)
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
        assert psi_dist is not None
        if psi_dist.strip() in DATASETS:
            what = f"{what}, fitted to the people of {psi_dist.strip()} (coinflight data)"
            psi_payload["psi_sd_deg"] = float(spec.sd)  # type: ignore[attr-defined]
            psi_payload["fitted_to"] = psi_dist.strip()
    sim = None
    if monte_carlo is not None:
        sim = b.simulate_same_side(
            spec, monte_carlo, seed, coin=coin, degrees=True, progress=progress
        )
    return AngleBias(p, what, psi_payload, coin, sim)


MAX_CURVE_POINTS = 2000
"""Most values of ψ in one request for a curve (the page draws p(ψ) from about 50)."""


def bias_curve(psis: Sequence[float], coin: Coin) -> list[dict[str, Any]]:
    """p(ψ) at several fixed ψ (degrees) at once: the object of ``coinflight bias --psi X
    --json`` for each, in the order given (``GET /api/bias?psis=…``, one request for a curve)."""
    from coinflight import _validation as v

    v.work_bound(
        f"a curve of {len(psis)} values of ψ",
        len(psis),
        MAX_CURVE_POINTS,
        "values",
        "ask for fewer values of ψ, or in several requests",
    )
    return [bias_query(float(psi), None, None, None, None, coin).payload() for psi in psis]


def _preset_bias(
    name: str,
    monte_carlo: int | None,
    seed: int | None,
    coin: Coin,
    progress: Callable[[int], object] | None = None,
) -> PresetBias:
    """The closed-form average over the preset's spins, and optionally a Monte Carlo run of the
    full flight through :func:`coinflight.probability.estimate` (started heads up, so P(heads)
    is the same-side probability)."""
    from coinflight.studies import bias as b
    from coinflight.studies.presets import preset, psi_range

    dist = preset(name, coin=coin)
    p = b.expected_same_side(dist)
    lo, mid, hi = (float(x) for x in psi_range(dist))
    result = None
    if monte_carlo is not None:
        from coinflight.probability import estimate

        result = estimate(dist, "monte-carlo", b.check_tosses(monte_carlo), seed, progress=progress)
    return PresetBias(name, p, (lo, mid, hi), dist, result)


def monte_carlo_payload(
    p_sim: float, stderr: float | None, n: int | None, seed: int | None, p: float
) -> dict[str, Any]:
    """The JSON of a Monte Carlo check against the closed form p: estimate, s.e., n, seed, z."""
    z = (p_sim - p) / stderr if stderr else 0.0
    return {"p_same_side": p_sim, "stderr": stderr, "n": n, "seed": seed, "z": z}


__all__ = [
    "SOURCE",
    "AngleBias",
    "PresetBias",
    "bias_curve",
    "bias_query",
    "fitted_psi_dist",
    "monte_carlo_payload",
    "resolve_psi",
]

"""The chance of heads for a range of tosses (``coinflight probability --json``,
``GET /api/probability``): the options checked in one order, the estimate, the JSON object."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from coinflight.model.ensemble import UNITS
from coinflight.queries.landing import (
    LandingChoice,
    landing_coin,
    outcome_model,
    settings_for,
    table_spread,
)
from coinflight.queries.values import AirArgs, DistArgs, TableArgs, flag

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import ProbabilityResult
    from coinflight.probability.registry import Estimator

INPUT_NAMES = ("omega_x", "omega_y", "omega_z", "flight_time", "launch_speed", "g", "preset")
"""The toss options whose typed values the JSON repeats under ``inputs`` (by option name)."""

PRESET_OPTIONS = {name: (flag(name), unit) for name, unit in UNITS.items()}
"""Parameter name → (option, unit) of the toss options a preset supplies and a typed option
replaces."""


@dataclass(frozen=True)
class ProbabilityQuery:
    """A checked request for P(heads): the estimator, the tosses, the landing and the size."""

    method: str
    estimator: Estimator
    dist: TossDistribution
    coin: Coin
    start: str
    landing: LandingChoice | None
    n: int | None
    seed: int | None
    threads: int | None
    options: dict[str, Any] = field(default_factory=dict)
    inputs: dict[str, Any] = field(default_factory=dict)
    surface_preset: str | None = None

    def seconds(self) -> float | None:
        """The estimator's estimate of the run's time on the reference machine, s (a
        ValueError, the library's refusal, beyond what one run may ask); None when the method
        bounds its own work (exact)."""
        if self.estimator.work is None:
            return None
        from coinflight.outcomes.hand import HAND_CATCH

        size = self.estimator.size_for(len(self.dist.ranged), self.n) or 1
        model = self.landing.model if self.landing is not None else HAND_CATCH
        return self.estimator.work(self.dist, size, model)

    def work_units(self) -> int:
        """Units of work the library reports through ``progress`` for this request."""
        e = self.estimator
        return e.work_units(len(self.dist.ranged), e.size_for(len(self.dist.ranged), self.n) or 1)


def preset_tosses(
    name: str, coin: Coin, start: str, g: float, overrides: Mapping[str, str]
) -> TossDistribution:
    """The preset ``name`` with the toss options the user typed (``overrides``, parameter name
    → text) laid over it."""
    from coinflight.model.distributions import parse_distribution
    from coinflight.studies.presets import preset

    laid = {
        param: parse_distribution(str(overrides[param]), flag, unit)
        for param, (flag, unit) in PRESET_OPTIONS.items()
        if param in overrides
    }
    if "flight_time" in laid and "launch_speed" in laid:
        raise ValueError("give at most one of --flight-time and --launch-speed")
    return preset(name, coin=coin, start=start, g=g, **laid)  # type: ignore[arg-type]


def check_method_options(
    estimator: Estimator,
    *,
    seed: int | None = None,
    n: int | None = None,
    threads: int | None = None,
) -> None:
    """ValueError naming the option when ``estimator``'s method does not take --seed, --n or
    --threads (None: not given)."""
    from coinflight.probability import registry

    method = estimator.name
    if seed is not None and not estimator.seeded:
        seeded = " and ".join(registry.names(seeded=True))
        raise ValueError(f"--seed applies to {seeded}, not {method}")
    if n is not None and estimator.default_n is None:
        raise ValueError(f"--n does not apply to the {method} method")
    if threads is not None and not estimator.parallel:
        raise ValueError(f"--threads does not apply to the {method} method")


def probability_query(
    tosses: DistArgs,
    coin: Coin,
    table: TableArgs,
    air: AirArgs,
    *,
    method: str = "exact",
    n: int | None = None,
    seed: int | None = None,
    grid_cells: int | None = None,
    variance_reduction: str | None = None,
    threads: int | None = None,
    preset: str | None = None,
    overrides: Mapping[str, str] | None = None,
    inputs: Mapping[str, Any] | None = None,
) -> ProbabilityQuery:
    """The options of ``coinflight probability`` checked in its order: the method, the tosses
    (``preset`` with ``overrides`` laid over it, or ``tosses``), the method's options, the
    landing. ``inputs``: the toss options as typed, repeated in the JSON."""
    from coinflight.probability import registry

    estimator = registry.get(method)
    coin = landing_coin(coin, table)
    if preset is not None:
        dist = preset_tosses(preset, coin, tosses.start, tosses.g, overrides or {})
    else:
        dist = tosses.build(coin)
    options: dict[str, Any] = {}
    if grid_cells is not None:
        if "grid_cells" not in estimator.options:
            takers = [e.name for e in registry.estimators() if "grid_cells" in e.options]
            raise ValueError(f"--grid-cells applies to --method {' and '.join(takers)} only")
        options["grid_cells"] = grid_cells
    if variance_reduction is not None:
        if not estimator.modes:
            takers = [e.name for e in registry.estimators() if e.modes]
            raise ValueError(
                f"--variance-reduction applies to --method {' and '.join(takers)} only"
            )
        options["variance_reduction"] = variance_reduction
    check_method_options(estimator, seed=seed, threads=threads)
    landing = outcome_model(table, air, ranged=True)
    # Distributions of the contact parameters (build_surface refused them for the hand; single
    # values are in the surface) go with the tosses, drawn toss by toss.
    spread = table_spread(table)
    if spread:
        dist = dist.with_contact(**spread)
    if landing is not None and estimator.default_n and n is None:
        slow = _slow_landing(landing)
        rate = landing.model.rate_for(dist)
        if slow and _default_seconds(estimator, dist, landing.model) > _DRAG_DEFAULT_SECONDS:
            raise ValueError(
                _SLOW_NEEDS_N.format(
                    why=slow,
                    method=method,
                    rate=f"{rate:,.0f}",
                    example=_drag_example(method, dist, rate),
                )
            )
    if landing is not None:
        options["model"] = landing.model
    return ProbabilityQuery(
        method, estimator, dist, coin, tosses.start, landing, n, seed, threads, options,
        dict(inputs or {}), table.surface_preset,
    )  # fmt: skip


def run(
    query: ProbabilityQuery,
    progress: Callable[[int], None] | None = None,
    *,
    executor: Any = None,
) -> ProbabilityResult:
    """The estimate the query asks for (``progress``: called with units of work done;
    ``executor``: where the tasks run, as :func:`coinflight.probability.estimate` takes it)."""
    from coinflight.probability import estimate

    options = dict(query.options)
    if query.estimator.parallel:
        options.update(threads=query.threads, progress=progress, executor=executor)
    return estimate(query.dist, query.method, n=query.n, seed=query.seed, **options)


def probability_payload(query: ProbabilityQuery, result: ProbabilityResult) -> dict[str, Any]:
    """The JSON object of ``coinflight probability --json``."""
    payload = result.to_dict()
    payload["distribution"] = {name: d.to_dict() for name, d in query.dist.parameters.items()}
    dimensions = {k: value for k, value in query.coin.to_dict().items() if k != "name"}
    payload.update(
        coin=query.coin.name,
        coin_dimensions=dimensions,  # radius, thickness (m), mass (kg): as Coin.to_dict
        start=query.start,
        g=query.dist.g,
        inputs={f"--{name.replace('_', '-')}": query.inputs.get(name) for name in INPUT_NAMES},
    )
    payload["distribution"].update({name: d.to_dict() for name, d in query.dist.contact.items()})
    if query.landing is not None:
        payload.update(settings_for(query.landing.model, query.dist))
    if query.surface_preset is not None:
        from coinflight.studies.presets import surface_preset

        payload["surface_preset"] = surface_preset(query.surface_preset).to_dict()
    payload["warnings"] = result_warnings(result)
    return payload


def _share(result: Any, status: str) -> str:
    """``"12 of 1,000 tosses (1.2 %)"``: the tosses ``result.details`` counts under ``status``
    (its count and ``status + "_fraction"``), of all; empty when there are none."""
    count = int(result.details.get(status, 0))
    if not count:
        return ""
    n = sum(result.counts) if result.counts is not None else result.samples
    return f"{count:,} of {n:,} tosses ({100 * result.details[status + '_fraction']:.3g} %)"


def result_warnings(result: Any) -> list[str]:
    """What the user must know about the result: tosses that never settled (table landing)."""
    unsettled = _share(result, "unsettled")
    if not unsettled:
        return []
    return [
        f"{unsettled} never settled (status 'unsettled'); they are counted by the face they "
        "showed when the simulation stopped"
    ]


_DRAG_DEFAULT_SECONDS = 60.0
"""With air or landings carried to rest on a table, the default size must run within this many
seconds, else --n must be given."""
_SLOW_NEEDS_N = (
    "with {why} (about {rate} tosses per second), so the default size of --method {method} "
    "would run for minutes; give --n explicitly, e.g. {example}"
)


def _slow_landing(landing: LandingChoice) -> str:
    """Why each toss of ``landing`` is slow (air, a landing carried to rest through the rigid
    ending), or "" if not."""
    from coinflight.outcomes.table import RIGID_TOSSES_PER_SECOND

    if landing.surface.kind == "table" and landing.model.rate <= RIGID_TOSSES_PER_SECOND:
        return "a table each landing is carried to rest through the rigid 3-D ending"
    if landing.drag is not None:
        return "--drag each toss is integrated through air"
    return ""


def _default_seconds(estimator: Estimator, dist: TossDistribution, model: Any) -> float:
    """Seconds of work of the method's default size with this model (inf beyond its bound)."""
    if estimator.work is None:
        return 0.0
    try:
        size = estimator.size_for(len(dist.ranged), None) or 1
        return float(estimator.work(dist, size, model))
    except ValueError:
        return math.inf


def _drag_example(method: str, dist: TossDistribution, rate: float) -> str:
    """An --n that takes about a minute with drag, and what it means."""
    k = len(dist.ranged)
    if method == "grid":
        cells = max(1, int((60 * rate) ** (1 / max(k, 1))))
        return f"--n {cells} ({cells}^{k} = {cells**k:,} tosses, about a minute)"
    if method == "qmc":
        size = 1 << max(4, int(math.log2(60 * rate)))
        return f"--n {size} (about a minute)"
    size = int(10 ** math.floor(math.log10(60 * rate)))
    return f"--n {size} (about a minute or less; standard error about {0.5 / math.sqrt(size):.2g})"


__all__ = [
    "INPUT_NAMES",
    "PRESET_OPTIONS",
    "ProbabilityQuery",
    "check_method_options",
    "preset_tosses",
    "probability_payload",
    "probability_query",
    "result_warnings",
    "run",
]

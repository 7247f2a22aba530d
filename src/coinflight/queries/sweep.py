"""The rows of a sweep (``coinflight sweep``): its options read, checked and built into
:class:`~coinflight.probability.sweep.Case` rows, and the JSON summary of the run.

The grammar (also in the command's help and the sweeps guide):

- a toss parameter (``--omega-x``, ``--omega-y``, ``--omega-z``, ``--flight-time``,
  ``--launch-speed``) takes a list of distributions: comma-separated items, each a number
  (fixed) or LOW:HIGH (uniform), as in ``coinflight probability``; ``normal:MEAN,SD`` is one
  normal distribution (its comma is its own). Repeat the option to add more values:
  ``--omega-x 60:90 --omega-x normal:240,24``;
- ``--P-mean`` and ``--P-sd`` (P one of the parameters) sweep normal distributions over the
  product of their lists of numbers (:func:`~coinflight.queries.values.parse_numbers_list`);
  an sd of 0 is a fixed value;
- ``--coin``, ``--start``, ``--surface`` take comma-separated names; ``--drop-height``,
  ``--restitution``, ``--friction``, ``--rolling-resistance``, ``--pivoting-resistance`` and
  ``--contact-duration`` lists of numbers, swept for the table rows only;
  ``--corner-radius`` a list of numbers (m) swept over the coins (--surface table only).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, NamedTuple

from coinflight import _validation as v
from coinflight.queries.probability import PRESET_OPTIONS, check_method_options
from coinflight.queries.values import flag, names, parse_numbers_list

if TYPE_CHECKING:
    from pathlib import Path

    from coinflight.model.coin import Coin
    from coinflight.model.distributions import Distribution
    from coinflight.outcomes.base import OutcomeModel
    from coinflight.probability.sweep import Case, SweepResults

TOSS_PARAMETERS = tuple(PRESET_OPTIONS)
"""The swept toss parameters, in the order of the table's columns."""

NOT_INPUTS = ("quiet", "json_output", "out", "fresh", "scheduler", "workers")
"""Options that say where and how a sweep runs, not what it computes: left out of the inputs
its table records (and of what a resumed run must match)."""


def parse_dists(texts: Sequence[str], option_name: str, unit: str) -> list[Distribution]:
    """The distributions of a repeated option: each text a comma-separated list of numbers and
    LOW:HIGH ranges, or one normal:MEAN,SD."""
    from coinflight.model.distributions import parse_distribution

    out = []
    for text in texts:
        raw = str(text).strip()
        if raw.lower().startswith("normal:"):
            if raw.count(",") != 1:
                raise ValueError(
                    f"{option_name} {raw!r}: a normal is normal:MEAN,SD; for several, repeat "
                    f"the option or use {option_name}-mean and {option_name}-sd"
                )
            out.append(parse_distribution(raw, option_name, unit))
            continue
        for item in raw.split(","):
            out.append(parse_distribution(item, option_name, unit))
    return out


def _normals(means: str, sds: str, name: str) -> list[Distribution]:
    from coinflight.model.distributions import Fixed, Normal
    from coinflight.probability.sweep import MAX_ROWS

    option = flag(name)
    mean_list = parse_numbers_list(means, f"{option}-mean")
    sd_list = parse_numbers_list(sds, f"{option}-sd")
    rows = len(mean_list) * len(sd_list)
    if rows > MAX_ROWS:  # before building them
        shown, most = v.over_limit(rows, MAX_ROWS)
        raise ValueError(
            f"{option}-mean × {option}-sd is {v.quantity(len(mean_list))} × "
            f"{v.quantity(len(sd_list))} = {shown} distributions, more than the {most} rows a "
            "sweep accepts; use fewer"
        )
    out: list[Distribution] = []
    for mean in mean_list:
        for sd in sd_list:
            if sd < 0:
                raise ValueError(f"{option}-sd {sds!r}: a standard deviation must be ≥ 0")
            out.append(Fixed(mean) if sd == 0 else Normal(mean, sd))
    return out


def parameter_values(
    name: str, dists: Sequence[str] | None, means: str | None, sds: str | None
) -> list[Distribution] | None:
    """The values of one toss parameter from its options (None when none is given)."""
    option = flag(name)
    if (means is None) != (sds is None):
        given, missing = (f"{option}-mean", f"{option}-sd")[:: 1 if sds is None else -1]
        raise ValueError(f"{given} needs {missing} (normal distributions: both lists)")
    if dists and means is not None:
        raise ValueError(f"give either {option} or {option}-mean/{option}-sd, not both")
    if dists:
        return parse_dists(dists, option, PRESET_OPTIONS[name][1])
    if means is not None and sds is not None:
        return _normals(means, sds, name)
    return None


def _kinds(surfaces: str) -> list[str]:
    from coinflight.outcomes import SURFACE_KINDS

    kinds = names(surfaces, "--surface")
    for kind in kinds:
        v.choice("--surface", kind, SURFACE_KINDS)
    return kinds


class SweepLandings(NamedTuple):
    """--surface and the table's lists, as typed (None: not given)."""

    surface: str = "hand"
    drop_height: str | None = None
    restitution: str | None = None
    friction: str | None = None
    bounces: int | None = None
    rolling_resistance: str | None = None
    pivoting_resistance: str | None = None
    corner_radius: str | None = None
    contact_duration: str | None = None


def outcome_models(landings: SweepLandings) -> list[OutcomeModel]:
    """The outcome models of --surface and the table's lists (swept for the table only)."""
    from coinflight.outcomes import outcome_model as build_model
    from coinflight.queries.landing import build_surface, check_bounces

    kinds = _kinds(landings.surface)
    bounces = landings.bounces
    table = {
        flag(k): getattr(landings, k)
        for k in (
            "drop_height",
            "restitution",
            "friction",
            "contact_duration",
            "rolling_resistance",
            "pivoting_resistance",
        )
    }
    given = [option for option, text in table.items() if text is not None]
    if given and "table" not in kinds:
        from coinflight.model.surface import TABLE_ONLY

        raise ValueError(f"{', '.join(given)} {TABLE_ONLY}")
    models: list[OutcomeModel] = []
    for kind in dict.fromkeys(kinds):
        if kind != "table":
            check_bounces(build_surface(kind, None, None, None), bounces)
            models.append(build_model(kind))
            continue
        lists = [[None] if text is None else parse_numbers_list(text, option)
                 for option, text in table.items()]  # fmt: skip
        for d, e, mu, t_c, rolling, pivoting in itertools.product(*lists):
            surface = build_surface(
                "table", d, e, mu,
                rolling_resistance=rolling, pivoting_resistance=pivoting, contact_duration=t_c,
            )  # fmt: skip
            check_bounces(surface, bounces)
            models.append(build_model(surface, None, bounces))
    return models


def corner_coins(coins: list[Coin], corner_radius: str | None, surfaces: str) -> list[Coin]:
    """Each coin with each --corner-radius of the list (m; --surface table only), or the coins
    as they are."""
    if corner_radius is None:
        return coins
    if names(surfaces, "--surface") != ["table"]:
        raise ValueError(
            "--corner-radius applies to --surface table only (a catch in the hand does not read "
            "it: sweep the table alone)"
        )
    radii = parse_numbers_list(corner_radius, "--corner-radius")
    out = []
    for coin in coins:
        for a in dict.fromkeys(radii):
            try:
                out.append(coin.with_corner_radius(a))
            except ValueError as exc:
                raise ValueError(f"--corner-radius: {coin.name}: {exc}") from None
    return out


def _check_slow(models: list[OutcomeModel], method: str, n: int | None) -> None:
    """--n must be given when a row's landings are carried to rest through the rigid ending (a
    dead or bounce-limited row's never are) and the method has a default size; exact handles
    the hand only."""
    from coinflight.outcomes.table import RIGID_TOSSES_PER_SECOND
    from coinflight.probability import registry

    estimator = registry.get(method)
    slow = [m for m in models if m.rate <= RIGID_TOSSES_PER_SECOND]
    if slow and n is None and estimator.default_n is not None:
        raise ValueError(
            f"on a table each landing is carried to rest through the rigid 3-D ending "
            f"(about {min(m.rate for m in slow):,.0f} tosses per second), so the default size of "
            f"--method {method} would run for about an hour a row; give --n explicitly "
            "(e.g. --n 1000)"
        )
    if method == "exact" and any(not m.closed_form_bands for m in models):
        others = " or ".join(registry.names(seeded=True)) + " or grid"
        raise ValueError(f"--method exact handles --surface hand only; for a table use {others}")


@dataclass(frozen=True)
class SweepQuery:
    """A checked sweep: its rows, the method, its size and seed, and the options as typed
    (``inputs``, recorded with the table)."""

    cases: list[Case]
    method: str
    n: int | None
    seed: int | None
    inputs: dict[str, Any]


def sweep_query(
    tosses: Mapping[str, tuple[Sequence[str] | None, str | None, str | None]],
    landings: SweepLandings | None = None,
    *,
    coin: str = "us-quarter",
    start: str = "heads",
    g: float,
    method: str = "exact",
    n: int | None = None,
    seed: int | None = None,
    out: Path,
    inputs: Mapping[str, Any] | None = None,
) -> SweepQuery:
    """The options of ``coinflight sweep`` checked in its order: the table's format, the method
    and its options, the toss parameters (``tosses``: parameter name → its distributions, its
    ``-mean`` and its ``-sd`` texts), the coins, the start faces, the landings (``landings``:
    --surface and the table's lists), then the rows (counted before they are built).
    ``inputs``: every option as typed, by parameter name."""
    from coinflight.probability import registry
    from coinflight.probability.sweep import product_cases, table_files
    from coinflight.queries.values import resolve_coin

    estimator = registry.get(method)
    landings = landings or SweepLandings()
    table_files(out)  # the suffix, before any work
    check_method_options(estimator, seed=seed, n=n)
    values = {name: parameter_values(name, *tosses.get(name, (None, None, None)))
              for name in TOSS_PARAMETERS}  # fmt: skip
    if values["omega_x"] is None:
        raise ValueError("give --omega-x (or --omega-x-mean and --omega-x-sd)")
    if (values["flight_time"] is None) == (values["launch_speed"] is None):
        raise ValueError(
            "give one of --flight-time and --launch-speed (or their -mean and -sd lists)"
        )
    coins = [resolve_coin(name, None, None, None) for name in names(coin, "--coin")]
    coins = corner_coins(coins, landings.corner_radius, landings.surface)
    starts = names(start, "--start")
    for face in starts:
        v.choice("--start", face, ("heads", "tails"))
    models = outcome_models(landings)
    _check_slow(models, method, n)
    cases = product_cases(
        omega_x=values["omega_x"],
        omega_y=values["omega_y"] or [0.0],
        omega_z=values["omega_z"] or [0.0],
        flight_time=values["flight_time"],
        launch_speed=values["launch_speed"],
        coins=coins,
        starts=starts,
        models=models,
        g=g,
    )
    recorded = {flag(k): x for k, x in (inputs or {}).items()
                if x not in (None, []) and k not in NOT_INPUTS}  # fmt: skip
    return SweepQuery(cases, method, n, seed, recorded)


def sweep_summary(
    query: SweepQuery, results: SweepResults, files: Sequence[Path], elapsed: float
) -> dict[str, Any]:
    """The JSON object of ``coinflight sweep --json``."""
    return {
        "rows": len(results),
        "reused": results.reused,
        "computed": len(results) - results.reused,
        "method": query.method,
        "n": results.n,
        "seed": results.seed,
        "files": [str(f) for f in files],
        "elapsed": elapsed,
    }


__all__ = [
    "SweepLandings",
    "SweepQuery",
    "outcome_models",
    "parameter_values",
    "parse_dists",
    "sweep_query",
    "sweep_summary",
]

"""What each endpoint computes, in a worker process: the options read as the command line reads
them (:mod:`coinflight.queries`), the work bounded for this server, the library called, the
JSON-ready object returned.

Every size is checked twice before work starts: by the library's own refusal
(:func:`coinflight._validation.work_bound`, the words the command line prints), then against this
server's budget (a fraction of its time limit, and at most :data:`MAX_MAP_CELLS` cells of a map).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from typing import Any

from coinflight import _validation as v
from coinflight.queries import toss as toss_queries
from coinflight.queries.values import AirArgs, CoinArgs, DistArgs, TableArgs, TossArgs

MAX_MAP_CELLS = 640_000
"""Most cells of a map the server sends (800 × 800: a phone's or a projector's width; about
2 MB of JSON)."""

BUDGET_SHARE = 0.5
"""Share of the time limit the estimated work of a request may take on the reference machine
(each request runs on one thread; the machine may be busier than the reference)."""


SHORT_SECONDS = 0.5
"""Estimated seconds of work (reference machine) up to which a probability, a map or a Monte
Carlo check is computed among the short requests (:mod:`coinflight.web.runner`); beyond it,
or with no estimate, among the long ones."""


class LongWork(Exception):
    """Raised, in the short lane, by a request whose work is beyond :data:`SHORT_SECONDS`
    (after its refusals were decided there): the server runs it in the long lane instead."""


def triage(seconds: float | None, short_only: bool) -> None:
    """:class:`LongWork` when ``short_only`` and the work is unknown or beyond
    :data:`SHORT_SECONDS`."""
    if short_only and (seconds is None or seconds > SHORT_SECONDS):
        raise LongWork


def budget(what: str, seconds: float, time_limit: float, way_on: str) -> None:
    """Refuse (ValueError, the library's wording) work estimated beyond the server's budget."""
    v.work_bound(
        what,
        seconds,
        BUDGET_SHARE * time_limit,
        "s of estimated work",
        f"{way_on} (this server answers within {time_limit:g} s)",
    )


def toss(
    coin: CoinArgs,
    args: TossArgs,
    table: TableArgs,
    air: AirArgs,
    bounces: int | None,
    trajectory: int | None,
) -> dict[str, Any]:
    """``GET /api/toss``: ``coinflight toss --json``, and the flight sampled at ``trajectory``
    times (the catch in the hand only: the closed form)."""
    the_coin = coin.resolve()
    query = toss_queries.toss_query(the_coin, args, table, air, bounces)
    if trajectory is not None and not query.caught:
        raise ValueError(
            "trajectory draws the catch in the hand (the closed form); leave out --surface "
            "table, --drag and --spin-damping, or trajectory"
        )
    payload = toss_queries.toss_payload(query)
    if trajectory is not None:
        from coinflight.model.toss import Flight

        payload["trajectory"] = toss_queries.trajectory(Flight(the_coin, query.toss), trajectory)
    return payload


def probability(
    coin: CoinArgs,
    tosses: DistArgs,
    table: TableArgs,
    air: AirArgs,
    options: Mapping[str, Any],
    time_limit: float,
    short_only: bool = False,
) -> dict[str, Any]:
    """``GET /api/probability``: ``coinflight probability --json``, on one thread
    (``short_only``: :func:`triage`)."""
    from coinflight.queries import probability as q

    query = q.probability_query(tosses, coin.resolve(), table, air, **options)
    seconds = query.seconds()
    if seconds is not None:
        size = query.estimator.size_for(len(query.dist.ranged), query.n)
        budget(f"{query.method} with n = {size}", seconds, time_limit, "use a smaller n")
    elif short_only and query.estimator.name == "exact":
        from coinflight.outcomes.hand import HAND_CATCH
        from coinflight.probability import exact

        model = query.landing.model if query.landing is not None else HAND_CATCH
        seconds = exact.estimated_seconds(query.dist, model)
    triage(seconds, short_only)
    if query.estimator.parallel:
        query = dataclasses.replace(query, threads=1)  # the answer does not depend on it
    return q.probability_payload(query, q.run(query))


def basin(
    coin: CoinArgs,
    options: Mapping[str, Any],
    table: TableArgs,
    bounces: int | None,
    boundaries: bool,
    time_limit: float,
    short_only: bool = False,
) -> dict[str, Any]:
    """``GET /api/basin``: the map of ``coinflight plot basin`` as JSON
    (:mod:`coinflight.queries.basin`; ``short_only``: :func:`triage`)."""
    from coinflight.queries.basin import basin_payload, basin_query
    from coinflight.queries.landing import table_outcome
    from coinflight.queries.values import parse_resolution

    n_t, n_w = parse_resolution(options.get("resolution", "500"))
    cells = n_t * n_w
    v.work_bound(
        f"a map of {v.quantity(n_t)}×{v.quantity(n_w)} cells",
        cells,
        MAX_MAP_CELLS,
        "cells",
        "use a coarser resolution (e.g. 400 or 600x300)",
    )
    from coinflight.outcomes.hand import HAND_CATCH

    model = table_outcome(table, bounces).get("outcome")
    if model is not None:
        budget(f"a map of {cells:,} table landings", cells / model.rate, time_limit,
               "use a coarser resolution")  # fmt: skip
    triage(cells / (model or HAND_CATCH).rate, short_only)
    the_map = basin_query(
        coin.resolve(), table=table, bounces=bounces, boundaries=boundaries, **options
    )
    return basin_payload(the_map, table, bounces, boundaries)


def bias(
    coin: CoinArgs,
    psi: float | None,
    psi_dist: str | None,
    preset: str | None,
    monte_carlo: int | None,
    seed: int | None,
    time_limit: float,
    short_only: bool = False,
) -> dict[str, Any]:
    """``GET /api/bias``: ``coinflight bias --json`` (``short_only``: :func:`triage`)."""
    from coinflight.queries.bias import bias_query

    if monte_carlo is not None:
        from coinflight.studies.bias import check_tosses

        check_tosses(monte_carlo)  # the library's refusal first, in its words
        if preset is None:
            from coinflight.studies.bias import TOSSES_PER_SECOND as rate
        else:
            from coinflight.outcomes.hand import HAND_CATCH

            rate = HAND_CATCH.rate
        budget(f"a Monte Carlo check of {monte_carlo} tosses", monte_carlo / rate, time_limit,
               "use fewer tosses")  # fmt: skip
        triage(monte_carlo / rate, short_only)
    return bias_query(psi, psi_dist, preset, monte_carlo, seed, coin.resolve()).payload()


def bias_curve(coin: CoinArgs, psis: tuple[float, ...]) -> list[dict[str, Any]]:
    """``GET /api/bias?psis=…``: ``coinflight bias --psi X --json`` for each ψ."""
    from coinflight.queries.bias import bias_curve as curve

    return curve(psis, coin.resolve())


def data(
    dataset: str | None,
    interval: str,
    psi_sd: float,
    seed: int | None,
    folds: int | None,
    repeats: int | None,
    time_limit: float,
) -> dict[str, Any]:
    """``GET /api/data``: ``coinflight data --json`` for a shipped dataset; the held-out check's
    estimated work within the server's budget."""
    from coinflight.queries.data import dataset_payload

    def bound(what: str, seconds: float) -> None:
        budget(what, seconds, time_limit, "use fewer folds or repeats")

    return dataset_payload(dataset, interval, psi_sd, seed, folds, repeats, bound)

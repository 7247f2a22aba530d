"""What each endpoint computes, in a worker thread: the options read as the command line reads
them (:mod:`coinflight.queries`), the library called, the JSON-ready object returned."""

from __future__ import annotations

from typing import Any

from coinflight.queries import toss as toss_queries
from coinflight.queries.values import AirArgs, TableArgs, TossArgs, resolve_coin


def toss(
    coin: tuple[str | None, float | None, float | None, float | None],
    args: TossArgs,
    table: TableArgs,
    air: AirArgs,
    bounces: int | None,
    trajectory: int | None,
) -> dict[str, Any]:
    """``GET /api/toss``: ``coinflight toss --json``, and the flight sampled at ``trajectory``
    times (the catch in the hand only: the closed form)."""
    the_coin = resolve_coin(*coin)
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

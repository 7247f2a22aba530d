"""Imported once by the worker pool's fork server (:mod:`coinflight.web.runner`): the library is
imported and each endpoint's kernels compiled here, so that every worker process forked from
the server starts warm, and a worker ended after its time limit is replaced in milliseconds
rather than the seconds an import and numba's compilation take."""

from __future__ import annotations

from contextlib import suppress

from coinflight.queries.values import AirArgs, CoinArgs, DistArgs, TableArgs, TossArgs
from coinflight.web import endpoints


def warm() -> None:
    """One small request to each endpoint (the answers are thrown away)."""
    hand, air, coin = TableArgs("hand", None, None, None, None), AirArgs(None, None), CoinArgs()
    endpoints.toss(coin, TossArgs((80.0, 0.0, 0.0), 0.7, None, "heads", 9.81), hand, air, None, 3)
    tosses = DistArgs("60:90", "0", "0", "0.6:0.9", None, "heads", 9.81)
    endpoints.probability(coin, tosses, hand, air, {"method": "exact"}, 30.0)
    endpoints.basin(coin, {"resolution": "4"}, hand, None, False, 30.0)
    endpoints.bias(coin, 80.0, None, None, None, None, 30.0)


with suppress(Exception):  # warming only saves time: a failure here shows in the first request
    warm()

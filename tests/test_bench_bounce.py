"""benchmarks/bench_bounce.py --old-src: the statuses of the same tosses from two trees are
compared with both mapped alike (a decided-upright toss counted as settled in contact in each),
so a tree that already has ``Status.DECIDED_UPRIGHT`` shows no difference where the two decide
alike, and a tree before it (which stored the decided coins as settled in contact) none
either; the tosses decided in one tree only are counted apart, so the mapping hides none."""

from __future__ import annotations

import numpy as np

from _bench import load_bench
from coinflight.core.outcome import Status


def _bench():  # type: ignore[no-untyped-def]
    return load_bench("bench_bounce")


S = Status
HERE = np.array(
    [S.DECIDED_UPRIGHT, S.DECIDED_UPRIGHT, S.SETTLED_CONTACT, S.SETTLED_ENERGY, S.UNSETTLED],
    dtype=np.int8,
)


def test_a_tree_with_the_decided_status_differs_only_where_the_statuses_do():
    bench = _bench()
    # The same statuses in both trees: no difference (it counted 2, the decided ones, before).
    assert bench.status_differences(HERE, HERE.copy()) == (0, 2, 2, 0)
    # Decided here, settled in contact there (or the other way): the same status mapped, but
    # decided in one tree only (a real difference when both trees have the status).
    there = HERE.copy()
    there[0] = S.SETTLED_CONTACT
    there[2] = S.DECIDED_UPRIGHT
    assert bench.status_differences(HERE, there) == (0, 2, 2, 2)
    one = np.array([S.DECIDED_UPRIGHT], dtype=np.int8)
    assert bench.status_differences(one, np.array([S.SETTLED_CONTACT], dtype=np.int8)) == (
        0,
        1,
        0,
        1,
    )
    # A real difference counts, once a toss, whichever tree decided.
    there[1] = S.SETTLED_ENERGY
    there[4] = S.SETTLED_CONTACT
    assert bench.status_differences(HERE, there) == (2, 2, 1, 3)


def test_a_tree_before_the_decided_status_differs_only_where_the_statuses_do():
    bench = _bench()
    older = bench.as_undecided(HERE)  # such a tree stored its decided coins so
    assert not np.any(older == S.DECIDED_UPRIGHT)
    assert list(older[:3]) == [S.SETTLED_CONTACT] * 3
    assert bench.status_differences(HERE, older) == (0, 2, 0, 2)  # all the decided ones
    older[3] = S.UNSETTLED
    assert bench.status_differences(HERE, older) == (1, 2, 0, 2)
    assert older.dtype == HERE.dtype and bench.as_undecided(HERE).dtype == np.int8

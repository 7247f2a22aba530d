"""benchmarks/bench_bounce.py --old-src: the statuses of the same tosses from two trees are
compared with both mapped alike (a decided-upright toss counted as settled in contact in each),
so a tree that already has ``Status.DECIDED_UPRIGHT`` shows no difference where the two decide
alike, and a tree before it (which stored the decided coins as settled in contact) none
either."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np

from coinflight.core.outcome import Status

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_bounce.py"


def _bench():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("bench_bounce", SCRIPT)
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    return bench


S = Status
HERE = np.array(
    [S.DECIDED_UPRIGHT, S.DECIDED_UPRIGHT, S.SETTLED_CONTACT, S.SETTLED_ENERGY, S.UNSETTLED],
    dtype=np.int8,
)


def test_a_tree_with_the_decided_status_differs_only_where_the_statuses_do():
    bench = _bench()
    # The same statuses in both trees: no difference (it counted 2, the decided ones, before).
    assert bench.status_differences(HERE, HERE.copy()) == (0, 2, 2)
    # Decided here, settled in contact there (or the other way): the same status mapped.
    there = HERE.copy()
    there[0] = S.SETTLED_CONTACT
    there[2] = S.DECIDED_UPRIGHT
    assert bench.status_differences(HERE, there) == (0, 2, 2)
    # A real difference counts, once a toss, whichever tree decided.
    there[1] = S.SETTLED_ENERGY
    there[4] = S.SETTLED_CONTACT
    assert bench.status_differences(HERE, there) == (2, 2, 1)


def test_a_tree_before_the_decided_status_differs_only_where_the_statuses_do():
    bench = _bench()
    older = bench.as_undecided(HERE)  # such a tree stored its decided coins so
    assert not np.any(older == S.DECIDED_UPRIGHT)
    assert list(older[:3]) == [S.SETTLED_CONTACT] * 3
    assert bench.status_differences(HERE, older) == (0, 2, 0)
    older[3] = S.UNSETTLED
    assert bench.status_differences(HERE, older) == (1, 2, 0)
    assert older.dtype == HERE.dtype and bench.as_undecided(HERE).dtype == np.int8

"""The thread pool every estimator runs its tasks on (``coinflight.probability._runner``)."""

from __future__ import annotations

import threading
import time

import pytest

from coinflight.probability._runner import executor_or_threads


class _Stop(Exception):
    pass


def test_an_interrupted_run_drops_the_tasks_not_yet_started():
    # Ctrl-C, an error or a time limit inside a run must not wait for every task the pool was
    # given (a sweep hands it all its rows at once): only those already running finish.
    # Without the cancellation all 200 tasks would run (~10 s); with it, at most the two
    # running ones and the few a worker picked up before the interruption.
    started = 0
    lock = threading.Lock()

    def task(_: int) -> int:
        nonlocal started
        with lock:
            started += 1
        time.sleep(0.05)
        return 0

    with pytest.raises(_Stop), executor_or_threads(None, 2) as pool:
        results = pool.map(task, range(200))
        next(iter(results))
        raise _Stop
    assert started <= 6, started


def test_a_finished_run_returns_every_result():
    with executor_or_threads(None, 2) as pool:
        assert list(pool.map(lambda i: i * i, range(50))) == [i * i for i in range(50)]

"""Every request's work bounded in time: computed in pools of worker processes, answered within
the time limit or refused with one line, while the server keeps serving.

Two lanes, each its own pool and its own bounded slots: *long* requests (a probability, a map,
a Monte Carlo check whose estimated work is beyond
:data:`coinflight.web.endpoints.SHORT_SECONDS`) and *short* ones (one toss, a closed form, a
dataset, and the small probabilities and maps). A short request never waits behind long ones,
so the page keeps answering while every worker of the long lane computes for its full time
limit.

A request over its time limit has its worker process ended (and replaced), so abandoned work
never goes on taking the machine from the requests after it; a thread could not be stopped.
The pool is :mod:`pebble`'s (a process pool with a timeout per task). Its workers are forked
from multiprocessing's fork server, a clean single-threaded interpreter that has imported the
library and compiled its kernels once (:mod:`coinflight.web.warm`): never a fork of the
server's threads, and a replaced worker starts warm at once. Work waiting for a
worker is bounded too: in each lane at most its workers + ``backlog`` requests are running or
waiting, beyond that a request is refused at once ("busy", HTTP 503) instead of queueing
without end. A request still waiting for a worker when its time is up is answered "busy" (it
never ran); one that ran is answered "over the time limit" and its worker process ended.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import threading
from collections.abc import Callable
from typing import Any, TypeVar

T = TypeVar("T")

DEFAULT_TIME_LIMIT = 30.0
"""Seconds a request may take, waiting for a worker included, before it is answered 503."""

START_TIMEOUT = 300.0
"""Seconds the workers may take to start (the fork server imports the library and compiles its
kernels: a few seconds, longer on a busy machine) before the server gives up starting."""


def default_workers() -> int:
    """Worker processes by default: the CPU count, 1 to 4 (each holds its own NumPy, SciPy and
    numba, about 200 MB)."""
    return max(1, min(4, os.cpu_count() or 1))


def check_runner(workers: int | None, time_limit: float, backlog: int) -> None:
    """ValueError unless workers ≥ 1 (or None: the default), backlog ≥ 0, time limit > 0 s."""
    if (workers is not None and workers < 1) or backlog < 0 or not time_limit > 0:
        raise ValueError(
            f"a runner needs workers ≥ 1, backlog ≥ 0 and a time limit > 0 s; got "
            f"{workers}, {backlog}, {time_limit}"
        )


class Overloaded(Exception):
    """The request was not answered in time, or every worker is taken (HTTP 503)."""


def short_workers(workers: int) -> int:
    """Worker processes of the short lane beside ``workers`` of the long one: 1, or 2 from 2
    long workers on (a short request takes milliseconds)."""
    return 1 if workers < 2 else 2


class _Lane:
    """One pool of worker processes and its slots (running or waiting requests)."""

    def __init__(self, workers: int, backlog: int, busy: str) -> None:
        from pebble import ProcessPool

        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(["coinflight.web.warm"])
        self.workers = workers
        self.pool = ProcessPool(max_workers=workers, context=context)
        self.slots = threading.BoundedSemaphore(workers + backlog)
        self.busy = busy


class Runner:
    """Two lanes of worker processes (:func:`short_workers` and ``workers`` for the long
    requests), each with ``backlog`` waiting slots beyond its workers; each request given
    ``time_limit`` seconds, waiting for a worker included."""

    def __init__(
        self,
        workers: int | None = None,
        time_limit: float = DEFAULT_TIME_LIMIT,
        backlog: int = 64,
    ) -> None:
        check_runner(workers, time_limit, backlog)
        workers = default_workers() if workers is None else workers
        self.workers = workers
        self.time_limit = float(time_limit)
        self._short = _Lane(
            short_workers(workers),
            backlog,
            "the server is busy (every worker is taken); try again in a few seconds",
        )
        self._long = _Lane(
            workers,
            backlog,
            "the server is busy with other long requests (every worker for them is taken); "
            "try again in a few seconds",
        )

    async def run(self, fn: Callable[..., T], *args: Any, long: bool = False) -> T:
        """``fn(*args)`` in a worker process of the short lane (``long``: of the long lane;
        ``fn`` and ``args`` picklable), or :class:`Overloaded` (busy, over time, or the worker
        lost)."""
        from concurrent.futures.process import BrokenProcessPool

        from pebble import ProcessExpired

        lane = self._long if long else self._short
        if not lane.slots.acquire(blocking=False):
            raise Overloaded(lane.busy)
        try:
            future = lane.pool.schedule(fn, args=args, timeout=self.time_limit)
        except BaseException:
            lane.slots.release()
            raise
        future.add_done_callback(lambda _: lane.slots.release())
        waiting = asyncio.wrap_future(future)
        over = Overloaded(
            f"the request ran over the server's time limit of {self.time_limit:g} s; "
            "ask for less work (a smaller n, a coarser resolution)"
        )
        try:
            done, _ = await asyncio.wait({waiting}, timeout=self.time_limit)
            if not done:
                if not future.running():
                    raise Overloaded(
                        f"the server is busy: the request waited {self.time_limit:g} s for a "
                        "worker and did not start; try again in a few seconds"
                    )
                raise over
            return waiting.result()
        except TimeoutError:  # pebble's own limit, counted from the start, reached first
            raise over from None
        except ProcessExpired as exc:
            raise Overloaded(
                f"the worker computing the request ended unexpectedly (exit code "
                f"{exc.exitcode}); try again"
            ) from None
        except BrokenProcessPool:
            raise Overloaded("the server's workers cannot start; restart the server") from None
        finally:
            if not waiting.done():  # over time, or the request itself cancelled:
                waiting.cancel()  # pebble ends the worker computing it, or drops it unstarted

    async def start(self) -> None:
        """Start the workers and wait until each has answered once (:data:`START_TIMEOUT`)."""
        futures = [
            lane.pool.schedule(os.getpid)
            for lane in (self._short, self._long)
            for _ in range(lane.workers)
        ]
        await asyncio.wait_for(
            asyncio.gather(*(asyncio.wrap_future(f) for f in futures)), START_TIMEOUT
        )

    def close(self) -> None:
        """End the workers (running work is abandoned)."""
        for lane in (self._short, self._long):
            lane.pool.stop()
        for lane in (self._short, self._long):
            lane.pool.join(timeout=10)


__all__ = [
    "DEFAULT_TIME_LIMIT",
    "Overloaded",
    "Runner",
    "check_runner",
    "default_workers",
    "short_workers",
]

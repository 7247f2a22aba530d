"""Every request's work bounded in time: computed in a pool of worker processes, answered within
the time limit or refused with one line, while the server keeps serving.

A request over its time limit has its worker process ended (and replaced), so abandoned work
never goes on taking the machine from the requests after it; a thread could not be stopped.
The pool is :mod:`pebble`'s (a process pool with a timeout per task). Its workers are forked
from multiprocessing's fork server, a clean single-threaded interpreter that has imported the
library and compiled its kernels once (:mod:`coinflight.web.warm`): never a fork of the
server's threads, and a replaced worker starts warm at once. Work waiting for a
worker is bounded too: at most ``workers + backlog`` requests are running or waiting, beyond
that a request is refused at once ("busy", HTTP 503) instead of queueing without end.
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


class Runner:
    """A pool of ``workers`` processes and ``workers + backlog`` slots (running or waiting
    requests), each request given ``time_limit`` seconds."""

    def __init__(
        self,
        workers: int | None = None,
        time_limit: float = DEFAULT_TIME_LIMIT,
        backlog: int = 64,
    ) -> None:
        from pebble import ProcessPool

        check_runner(workers, time_limit, backlog)
        workers = default_workers() if workers is None else workers
        self.workers = workers
        self.time_limit = float(time_limit)
        context = multiprocessing.get_context("forkserver")
        context.set_forkserver_preload(["coinflight.web.warm"])
        self._pool = ProcessPool(max_workers=workers, context=context)
        self._slots = threading.BoundedSemaphore(workers + backlog)

    async def run(self, fn: Callable[..., T], *args: Any) -> T:
        """``fn(*args)`` in a worker process (``fn`` and ``args`` picklable), or
        :class:`Overloaded` (busy, over time, or the worker lost)."""
        from concurrent.futures.process import BrokenProcessPool

        from pebble import ProcessExpired

        if not self._slots.acquire(blocking=False):
            raise Overloaded(
                "the server is busy (every worker is taken); try again in a few seconds"
            )
        try:
            future = self._pool.schedule(fn, args=args, timeout=self.time_limit)
        except BaseException:
            self._slots.release()
            raise
        future.add_done_callback(lambda _: self._slots.release())
        try:
            # on time out, the future is cancelled: pebble ends its worker process
            return await asyncio.wait_for(asyncio.wrap_future(future), self.time_limit)
        except TimeoutError:
            raise Overloaded(
                f"the request ran over the server's time limit of {self.time_limit:g} s; "
                "ask for less work (a smaller n, a coarser resolution)"
            ) from None
        except ProcessExpired as exc:
            raise Overloaded(
                f"the worker computing the request ended unexpectedly (exit code "
                f"{exc.exitcode}); try again"
            ) from None
        except BrokenProcessPool:
            raise Overloaded("the server's workers cannot start; restart the server") from None

    async def start(self) -> None:
        """Start the workers and wait until each has answered once (:data:`START_TIMEOUT`)."""
        futures = [self._pool.schedule(os.getpid) for _ in range(self.workers)]
        await asyncio.wait_for(
            asyncio.gather(*(asyncio.wrap_future(f) for f in futures)), START_TIMEOUT
        )

    def close(self) -> None:
        """End the workers (running work is abandoned)."""
        self._pool.stop()
        self._pool.join(timeout=10)


__all__ = ["DEFAULT_TIME_LIMIT", "Overloaded", "Runner", "check_runner", "default_workers"]

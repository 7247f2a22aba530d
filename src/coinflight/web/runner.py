"""Every request's work bounded in time: computed in a pool of worker threads, answered within
the time budget or refused with one line, while the server keeps serving.

A thread cannot be stopped from outside, so work that runs over its budget keeps its worker
until it ends (its size was bounded before it started, :func:`coinflight._validation.work_bound`).
Until then it holds one of the server's slots: when every slot is taken, a new request is
refused at once ("busy", HTTP 503) instead of queueing without end.
"""

from __future__ import annotations

import asyncio
import os
import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from typing import Any, TypeVar

T = TypeVar("T")

DEFAULT_TIME_LIMIT = 30.0
"""Seconds a request may compute before it is answered 503 (a first request also compiles the
numba kernels it needs, a few seconds)."""


class Overloaded(Exception):
    """The request was not answered in time, or every worker is taken (HTTP 503)."""


class Runner:
    """A pool of ``workers`` threads and ``workers + backlog`` slots (running or waiting work,
    including work abandoned after its budget), each call given ``time_limit`` seconds."""

    def __init__(
        self,
        workers: int | None = None,
        time_limit: float = DEFAULT_TIME_LIMIT,
        backlog: int = 64,
    ) -> None:
        if workers is None:
            workers = max(2, min(8, os.cpu_count() or 2))
        if workers < 1 or backlog < 0 or not time_limit > 0:
            raise ValueError(
                f"a runner needs workers ≥ 1, backlog ≥ 0 and a time limit > 0 s; got "
                f"{workers}, {backlog}, {time_limit}"
            )
        self.workers = workers
        self.time_limit = float(time_limit)
        self._pool = ThreadPoolExecutor(workers, thread_name_prefix="coinflight-web")
        self._slots = threading.BoundedSemaphore(workers + backlog)

    async def run(self, fn: Callable[..., T], *args: Any) -> T:
        """``fn(*args)`` in a worker thread, or :class:`Overloaded` (busy, or over time)."""
        if not self._slots.acquire(blocking=False):
            raise Overloaded(
                "the server is busy (every worker is taken); try again in a few seconds"
            )
        try:
            future = self._pool.submit(fn, *args)
        except BaseException:
            self._slots.release()
            raise
        future.add_done_callback(lambda _: self._slots.release())
        try:
            return await asyncio.wait_for(asyncio.wrap_future(future), self.time_limit)
        except TimeoutError:
            raise Overloaded(
                f"the request ran over the server's time limit of {self.time_limit:g} s; "
                "ask for less work (a smaller n, a coarser resolution)"
            ) from None

    def close(self) -> None:
        """Stop taking work; running work is not waited for."""
        self._pool.shutdown(wait=False, cancel_futures=True)


__all__ = ["DEFAULT_TIME_LIMIT", "Overloaded", "Runner"]

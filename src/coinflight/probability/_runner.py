"""Running tasks through an executor, with progress: shared by the estimators."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from typing import Any, Protocol, TypeVar

from coinflight import _validation as v

T = TypeVar("T")
R = TypeVar("R")

Progress = Callable[[int], None]
"""Called with the number of tosses (configurations, points) just completed."""


class Executor(Protocol):
    """Anything with a ``map(fn, iterable)`` method: ``concurrent.futures`` executors, an object
    whose ``map`` is the built-in ``map`` (serial), a ``distributed.Client`` (wrapped by
    :class:`coinflight.probability.distributed.DaskExecutor`). An executor may also have
    ``completed(fn, tasks, sizes)`` yielding ``(index, result)`` pairs as tasks finish, in any
    order (:func:`completed` then uses it)."""

    def map(self, fn: Callable[[Any], Any], *iterables: Iterable[Any]) -> Iterator[Any]: ...


MAX_THREADS = 1024
"""Most worker threads of the default pool: more than the tasks or cores only costs memory
(each thread a stack), and a count beyond any machine (``--threads 99999999999999999999``)
is a typing slip, refused rather than quietly capped."""


def check_runner(executor: object, threads: object, progress: object) -> None:
    """TypeError or ValueError naming the argument unless ``executor`` is None or has a callable
    ``map``, ``threads`` None or a whole number from 1 to :data:`MAX_THREADS`, ``progress``
    None or callable."""
    if executor is not None and not callable(getattr(executor, "map", None)):
        raise TypeError(
            "executor must be None (a thread pool) or an object with a map(fn, tasks) method, "
            f"such as a concurrent.futures executor; got {type(executor).__name__}"
        )
    if threads is not None:
        v.count("threads", threads, 1, MAX_THREADS)
    v.callable_or_none("progress", progress, "a callable taking the amount of work done")


@contextmanager
def executor_or_threads(executor: Executor | None, threads: int | None) -> Iterator[Executor]:
    """The user's executor, or a thread pool (``threads`` workers, default all CPUs)."""
    check_runner(executor, threads, None)
    if executor is not None:
        from coinflight.probability.distributed import DaskExecutor, is_dask_client

        yield DaskExecutor(executor) if is_dask_client(executor) else executor
        return
    workers = threads if threads is not None else (os.cpu_count() or 1)
    if workers == 1:
        yield _SerialExecutor()
        return
    pool = ThreadPoolExecutor(max_workers=workers)
    try:
        yield pool
    except BaseException:
        # Interrupted (Ctrl-C, an error, a time limit): the tasks not yet started are dropped,
        # so that only those running are waited for, not every task the pool was given.
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)


class _SerialExecutor:
    def map(self, fn: Callable[[Any], Any], *iterables: Iterable[Any]) -> Iterator[Any]:
        return map(fn, *iterables)


def completed(
    executor: Executor, fn: Callable[[T], R], tasks: list[T], sizes: list[int]
) -> Iterator[tuple[int, R]]:
    """``(i, fn(tasks[i]))`` as tasks finish: in any order through an executor's own
    ``completed`` (a Dask cluster's), else in task order through its ``map``."""
    own = getattr(executor, "completed", None)
    if callable(own):
        yield from own(fn, tasks, sizes)
        return
    yield from enumerate(executor.map(fn, tasks))


def run_tasks(
    executor: Executor,
    fn: Callable[[T], R],
    tasks: list[T],
    sizes: list[int],
    progress: Progress | None,
) -> list[R]:
    """``[fn(t) for t in tasks]`` through ``executor``, reporting ``sizes[i]`` as each ends.

    The results are in task order whatever the order in which the tasks finish, so sums over
    them are the same, bit for bit, on every executor."""
    v.callable_or_none("progress", progress, "a callable taking the amount of work done")
    if len(sizes) != len(tasks):
        raise ValueError(f"{len(sizes)} sizes for {len(tasks)} tasks; they must pair up")
    out: list[Any] = [None] * len(tasks)
    for i, result in completed(executor, fn, tasks, sizes):
        out[i] = result
        if progress is not None:
            progress(sizes[i])
    return out


def check_count(name: str, value: object, minimum: int = 1) -> int:
    """A whole number ≥ ``minimum`` (not a bool, not 2.5), or TypeError/ValueError naming it."""
    return v.count(name, value, minimum)


def check_tosses(method: str, n: int, rate: float, way_on: str = "") -> None:
    """ValueError (:func:`coinflight._validation.work_bound`) unless ``n`` tosses at ``rate``
    a second take at most :data:`coinflight._validation.MAX_RUN_SECONDS`."""
    v.work_bound(
        f"{method} with n = {n}",
        n,
        rate * v.MAX_RUN_SECONDS,
        "tosses",
        way_on or "use a smaller n (the standard error is at most 0.5/√n)",
        rate,
    )

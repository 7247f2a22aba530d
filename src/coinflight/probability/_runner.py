"""Running tasks through an executor, with progress: shared by the estimators."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import ThreadPoolExecutor
from contextlib import contextmanager
from typing import Any, Protocol, TypeVar

T = TypeVar("T")
R = TypeVar("R")

Progress = Callable[[int], None]
"""Called with the number of tosses (configurations, points) just completed."""


class Executor(Protocol):
    """Anything with ``map(fn, iterable)``: ``concurrent.futures`` executors, a Dask or Ray
    client wrapper, the built-in ``map`` itself."""

    def map(self, fn: Callable[[Any], Any], *iterables: Iterable[Any]) -> Iterator[Any]: ...


@contextmanager
def executor_or_threads(executor: Executor | None, threads: int | None) -> Iterator[Executor]:
    """The user's executor, or a thread pool (``threads`` workers, default all CPUs)."""
    if executor is not None:
        yield executor
        return
    workers = threads if threads is not None else (os.cpu_count() or 1)
    if workers < 1:
        raise ValueError(f"threads must be at least 1, got {workers}")
    if workers == 1:
        yield _SerialExecutor()
        return
    with ThreadPoolExecutor(max_workers=workers) as pool:
        yield pool


class _SerialExecutor:
    def map(self, fn: Callable[[Any], Any], *iterables: Iterable[Any]) -> Iterator[Any]:
        return map(fn, *iterables)


def run_tasks(
    executor: Executor,
    fn: Callable[[T], R],
    tasks: list[T],
    sizes: list[int],
    progress: Progress | None,
) -> list[R]:
    """``[fn(t) for t in tasks]`` through ``executor``, reporting ``sizes[i]`` as each ends."""
    out: list[R] = []
    for size, result in zip(sizes, executor.map(fn, tasks), strict=True):
        out.append(result)
        if progress is not None:
            progress(size)
    return out


def check_count(name: str, value: object, minimum: int = 1) -> int:
    """A positive integer option, or ValueError naming it."""
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            import numpy as np

            if isinstance(value, np.integer):
                value = int(value)
            else:
                raise TypeError
        except TypeError:
            raise TypeError(f"{name} must be an integer, got {value!r}") from None
    assert isinstance(value, int)
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return value

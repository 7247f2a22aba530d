"""The estimators' tasks on a Dask cluster (``dask.distributed``): the one wrapper of a client.

Every estimator cuts its work into independent tasks and runs them through an executor
(:mod:`coinflight.probability._runner`). A ``distributed.Client`` is accepted wherever an
executor is (``estimate(..., executor=client)``); it is wrapped here, once, in
:class:`DaskExecutor`:

* **Results in task order.** ``Client.map`` returns futures; the wrapper gathers the results and
  puts each at its task's index, so the estimators add them up in the same order as on threads,
  and the same seed gives the same answer bit for bit (the random streams belong to blocks, not
  to workers: :mod:`coinflight.probability.streams`).
* **Progress from the futures** as they complete (``distributed.as_completed``), in any order.
* **Tasks sized from the measured overhead.** A task sent to a cluster costs a fixed time
  (scheduling, pickling, the round trip) and CPU outside the task: the client's, the
  scheduler's and the nannies' (all in the client's process on a ``LocalCluster``) and the
  workers' own messaging. On a machine whose cores the client shares with the workers that
  CPU is taken from the workers, so it counts as overhead as much as the round trip:
  :func:`measure_overhead` times no-op tasks once per client and takes the larger of the two,
  and during a run the client process's CPU per batch, observed, raises it when real tasks
  cost more to send and receive than no-ops. Consecutive tasks are then grouped into batches,
  each expected to compute for at least ``overhead / TARGET_OVERHEAD`` seconds, so that the
  overhead stays under :data:`TARGET_OVERHEAD` (5 %) of the work; the compute time per unit of
  work comes from the batches already done. The batches never get so large that a worker
  would stay idle at the end.

:func:`dask_client` opens a client on a new ``LocalCluster`` (``"local"``) or on a running
scheduler (``"tcp://HOST:PORT"``, started with ``dask scheduler`` and ``dask worker``), and
closes it afterwards. The package needs ``dask[distributed]`` only here:
``pip install "coinflight[dask]"``.
"""

from __future__ import annotations

import math
import os
import re
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, TypeVar

from coinflight import _validation as v

T = TypeVar("T")
R = TypeVar("R")

TARGET_OVERHEAD = 0.05
"""Largest share of a batch's time spent on per-task overhead (scheduling, transfer)."""
CONNECT_TIMEOUT = 5.0
"""Seconds to wait for a ``tcp://`` scheduler before giving up."""
INSTALL = 'pip install "coinflight[dask]"'
"""How to install the optional Dask dependency (said in the error when it is missing)."""
IN_FLIGHT_PER_SLOT = 2
"""Batches queued per worker thread: one computing, one waiting, so no worker idles."""

LOCAL_CONFIG = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.admin.tick.interval": "1s",
}
"""Dask settings of the clusters :func:`dask_client` starts: no statistical profiler in the
workers (a thread sampling the computing thread every 10 ms, for a dashboard coinflight does not
serve), the system monitors and the event loops' tick less often. An idle 2-worker cluster then
takes about 0.02 of a core instead of 0.12 (the client's process 0.01 instead of 0.05, the
workers 0.01 instead of 0.07), CPU that on a small machine is the workers'."""

IDLE_SECONDS = 0.25
"""Seconds the client's process is watched idle, once per client: the CPU its event loop (on a
``LocalCluster`` also the scheduler's and the nannies') takes with no task, a rate that is not
charged to the batches."""

_OVERHEADS: dict[str, tuple[float, float, float | None]] = {}
"""Measured per-task overhead by client id (:func:`_measure`): a client passed to several
estimates is timed once."""
_ADDRESS = re.compile(r"^tcp://(?P<host>\[[0-9a-fA-F:]+\]|[A-Za-z0-9_.\-]+):(?P<port>\d{1,5})$")


def require_distributed() -> Any:
    """The ``distributed`` module, or ModuleNotFoundError saying how to install it."""
    try:
        import distributed
    except ModuleNotFoundError:
        raise ModuleNotFoundError(
            f"running on a Dask cluster needs dask.distributed; install it with {INSTALL}"
        ) from None
    return distributed


def is_dask_client(executor: object) -> bool:
    """True when ``executor`` is a ``distributed.Client`` (without importing Dask: a client
    exists only if ``distributed`` was imported)."""
    distributed = sys.modules.get("distributed")
    return distributed is not None and isinstance(executor, distributed.Client)


def _noop(x: int) -> int:
    return x


def worker_slots(client: Any) -> int:
    """Worker threads of the cluster (at least 1)."""
    return max(1, sum(client.nthreads().values()))


def _process_cpu() -> float:
    return time.process_time()


def measure_overhead(client: Any, tasks_per_slot: int = 8, repeats: int = 3) -> float:
    """Seconds of per-task overhead on ``client``'s cluster, from no-op tasks,
    ``tasks_per_slot`` per worker thread, in ``repeats`` rounds after a warm-up round: the
    larger of the wall time per task (times the worker threads; the best round) and the CPU
    per task outside the task, of the client's process (on a ``LocalCluster`` also the
    scheduler's and the nannies') and of the workers' processes, over all rounds."""
    return max(_measure(client, tasks_per_slot, repeats)[:2])


def _measure(
    client: Any, tasks_per_slot: int = 8, repeats: int = 3
) -> tuple[float, float, float | None]:
    """The parts of :func:`measure_overhead`: the wall time per task, the CPU per task, and the
    CPU the client's process uses a second when idle (CPU 0 and None when a worker runs in
    the client's own process: its CPU then includes the workers' computing)."""
    slots = worker_slots(client)
    m = tasks_per_slot * slots
    in_process = os.getpid() in client.run(os.getpid).values()
    best = math.inf
    cpu = client_cpu = workers_cpu = 0.0
    for round_ in range(repeats + 1):
        if round_ == 1:  # the first round warms the connections up
            client_cpu = time.process_time()
            workers_cpu = sum(client.run(_process_cpu).values())
        t0 = time.perf_counter()
        client.gather(client.map(_noop, range(m), pure=False))
        wall = time.perf_counter() - t0
        if round_:
            best = min(best, wall * slots / m)
    if in_process:
        return best, 0.0, None
    used = time.process_time() - client_cpu
    used += sum(client.run(_process_cpu).values()) - workers_cpu
    cpu = used / (m * max(1, repeats))
    c0, t0 = time.process_time(), time.perf_counter()
    time.sleep(IDLE_SECONDS)
    idle = (time.process_time() - c0) / (time.perf_counter() - t0)
    return best, cpu, idle


def _run_batch(fn: Callable[[Any], Any], batch: list[Any]) -> tuple[list[Any], float, float]:
    """Run one batch on a worker: its results, the seconds it computed and their CPU seconds
    (of the worker's thread: one more worker on a busy machine stretches the first, not the
    second)."""
    t0, c0 = time.perf_counter(), time.thread_time()
    out = [fn(task) for task in batch]
    return out, time.perf_counter() - t0, time.thread_time() - c0


@dataclass
class RunStats:
    """How the last run went: tasks, batches, compute and wall seconds, the overhead
    measured, the overhead per batch its last batches were sized by (``cost``: the measured
    one or the client's CPU per batch observed, the larger), the client process's CPU
    seconds during the run; per finished batch (in the order they finished) its compute
    seconds (``durations``), its units of work (``units``) and the compute seconds it was
    sized for (``planned``: its units at the rate measured when it was sent, 0 for the first,
    timed batches)."""

    tasks: int = 0
    batches: int = 0
    compute: float = 0.0
    wall: float = 0.0
    slots: int = 1
    overhead: float = 0.0
    cost: float = 0.0
    durations: list[float] = field(default_factory=list)
    units: list[int] = field(default_factory=list)
    planned: list[float] = field(default_factory=list)
    client_cpu: float = 0.0

    @property
    def overhead_share(self) -> float:
        """Measured share of the workers' time not spent computing: 1 − compute / (wall ×
        worker threads); includes idle workers (a run of fewer tasks than workers)."""
        if self.wall <= 0:
            return 0.0
        return max(0.0, 1.0 - self.compute / (self.wall * self.slots))


class DaskExecutor:
    """A ``distributed.Client`` as an executor of the estimators (see the module notes).

    Parameters
    ----------
    client : distributed.Client
        A connected client.
    overhead : float, optional
        Per-task overhead, s; measured on first use (:func:`measure_overhead`) when None.
    """

    def __init__(self, client: Any, overhead: float | None = None) -> None:
        if not is_dask_client(client):
            raise TypeError(f"client must be a distributed.Client, got {type(client).__name__}")
        if overhead is not None:
            v.in_range("overhead", overhead, 0.0, math.inf, "s")
        self.client = client
        self._overhead = overhead
        self._given = overhead is not None
        self.last = RunStats()

    @property
    def overhead(self) -> float:
        """Per-task overhead of this cluster, s (measured once per client: the larger of the
        wall time and the CPU per task, :func:`measure_overhead`)."""
        if self._overhead is None:
            self._overhead = max(self._facts()[:2])
        return self._overhead

    def _costs(self) -> tuple[float, float, float | None]:
        """Wall and CPU seconds per task, the client's idle CPU rate: measured, or the overhead
        given (in wall seconds; then no CPU is counted)."""
        if self._given:
            return self.overhead, 0.0, None
        return self._facts()

    def _facts(self) -> tuple[float, float, float | None]:
        key = str(self.client.id)
        if key not in _OVERHEADS:
            _OVERHEADS[key] = _measure(self.client)
        return _OVERHEADS[key]

    @property
    def slots(self) -> int:
        """Worker threads of the cluster."""
        return worker_slots(self.client)

    def map(self, fn: Callable[[Any], R], *iterables: Iterable[Any]) -> Iterator[R]:
        """``fn`` over the tasks, results in task order (as the built-in ``map``)."""
        tasks = list(zip(*iterables, strict=True)) if len(iterables) > 1 else list(iterables[0])
        call: Callable[[Any], R] = fn if len(iterables) == 1 else _Star(fn)
        results: list[Any] = [None] * len(tasks)
        for i, result in self.completed(call, tasks, [1] * len(tasks)):
            results[i] = result
        return iter(results)

    def completed(
        self, fn: Callable[[T], R], tasks: Sequence[T], sizes: Sequence[int]
    ) -> Iterator[tuple[int, R]]:
        """``(index, fn(tasks[index]))`` pairs as the batches finish, in any order.

        ``sizes`` are the tasks' amounts of work (tosses), used to size the batches.
        """
        distributed = require_distributed()
        n = len(tasks)
        stats = RunStats(tasks=n, slots=self.slots)
        self.last = stats
        if n == 0:
            return
        overhead = self.overhead
        # the client process's CPU per batch, observed, its idle rate taken off: what sending,
        # receiving and handing over a real batch costs, more than a no-op (not when a worker
        # computes in this process)
        wall_cost, cpu_cost, idle = self._costs()
        cpu0 = time.process_time()
        t0 = time.perf_counter()
        units = [max(1, int(s)) for s in sizes]
        remaining = sum(units)
        next_task = 0
        finished = 0
        done_units = 0.0
        done_seconds = 0.0
        done_cpu = 0.0
        pending = distributed.as_completed()
        owner: dict[str, list[int]] = {}
        planned: dict[str, float] = {}

        def submit() -> None:
            nonlocal next_task, remaining
            if done_seconds > 0:  # units a second, from the batches done
                # the round trip against the batches' wall time, the CPU outside the tasks
                # against their CPU time (on a busy machine a batch's wall time stretches, its
                # CPU time and the CPU it costs to send it do not)
                target = done_units / done_seconds * wall_cost / TARGET_OVERHEAD
                cost = cpu_cost
                if idle is not None and finished >= stats.slots:
                    busy = time.process_time() - cpu0 - idle * (time.perf_counter() - t0)
                    cost = max(cost, busy / stats.batches)  # sent, most of them back
                stats.cost = max(wall_cost, cost)
                if cost > 0 and done_cpu > 0:
                    target = max(target, done_units / done_cpu * cost / TARGET_OVERHEAD)
                # near the end, smaller batches so that no worker idles while another
                # finishes a long one (at most a quarter of the target: a short tail)
                per_batch = min(target, max(remaining / stats.slots, target / 4))
            else:  # not known yet: one task a batch, to measure
                per_batch = 0
            first = next_task
            total = 0
            while next_task < n and (next_task == first or total < per_batch):
                total += units[next_task]
                next_task += 1
            remaining -= total
            batch = [tasks[i] for i in range(first, next_task)]
            future = self.client.submit(_run_batch, fn, batch, pure=False)
            owner[future.key] = list(range(first, next_task))
            planned[future.key] = total * done_seconds / done_units if done_seconds > 0 else 0.0
            pending.add(future)
            stats.batches += 1

        def fill() -> None:
            # one task per worker until a batch has been timed, then batches sized from it
            limit = stats.slots if done_seconds == 0 else IN_FLIGHT_PER_SLOT * stats.slots
            while next_task < n and pending.count() < limit:
                submit()

        try:
            fill()
            for future in pending:
                results, seconds, cpu_seconds = future.result()
                finished += 1
                stats.compute += seconds
                stats.durations.append(seconds)
                indices = owner.pop(future.key)
                stats.units.append(sum(units[i] for i in indices))
                stats.planned.append(planned.pop(future.key))
                # every batch counts, a first one that compiled kernels too: a slow batch only
                # makes the next ones smaller (more overhead), never a worker idle
                done_seconds += seconds
                done_cpu += cpu_seconds
                done_units += sum(units[i] for i in indices)
                yield from zip(indices, results, strict=True)
                fill()
        finally:
            if next_task < n or pending.count():
                for future in list(pending.futures):
                    future.cancel()
            stats.wall = time.perf_counter() - t0
            stats.overhead = overhead
            stats.client_cpu = time.process_time() - cpu0


class _Star:
    """``fn(*args)`` as a one-argument callable (for :meth:`DaskExecutor.map` over several
    iterables); a class, not a lambda, so that it pickles."""

    def __init__(self, fn: Callable[..., Any]) -> None:
        self.fn = fn

    def __call__(self, args: tuple[Any, ...]) -> Any:
        return self.fn(*args)


MAX_LOCAL_WORKERS = 256
"""Most worker processes of a local cluster (each a Python process of ~100 MB): a count
beyond any machine is a typing slip, refused before a process starts."""


def check_scheduler(scheduler: object, workers: object = None) -> str:
    """``scheduler`` if it is ``"local"`` or ``"tcp://HOST:PORT"``, else ValueError/TypeError
    naming it; ``workers`` must be None or a whole number from 1 to :data:`MAX_LOCAL_WORKERS`
    and only with ``"local"``."""
    v.instance("scheduler", scheduler, str, 'a string: "local" or "tcp://HOST:PORT"')
    assert isinstance(scheduler, str)
    if workers is not None:
        v.count("workers", workers, 1, MAX_LOCAL_WORKERS)
    if scheduler == "local":
        return scheduler
    match = _ADDRESS.match(scheduler)
    if match is None or not 1 <= int(match["port"]) <= 65535:
        raise ValueError(
            f"scheduler {scheduler!r} is neither local nor an address tcp://HOST:PORT "
            "(port 1–65535), e.g. tcp://127.0.0.1:8786"
        )
    if workers is not None:
        raise ValueError(
            "workers applies to the local scheduler only; the workers of "
            f"{scheduler} are those its `dask worker` commands started"
        )
    return scheduler


@contextmanager
def dask_client(
    scheduler: str = "local",
    workers: int | None = None,
    *,
    timeout: float = CONNECT_TIMEOUT,
) -> Iterator[DaskExecutor]:
    """A :class:`DaskExecutor` on a new local cluster or a running scheduler, closed on exit.

    Parameters
    ----------
    scheduler : str
        ``"local"``: a ``distributed.LocalCluster`` of ``workers`` processes (default: one per
        CPU), one thread each, no dashboard, with :data:`LOCAL_CONFIG`. ``"tcp://HOST:PORT"``:
        the scheduler of a cluster started elsewhere (``dask scheduler`` and ``dask worker
        tcp://HOST:PORT``); its workers must be able to import coinflight.
    workers : int, optional
        Worker processes of the local cluster.
    timeout : float
        Seconds to wait for a ``tcp://`` scheduler.

    Raises
    ------
    ValueError
        A malformed scheduler, or one that cannot be reached within ``timeout``.
    ModuleNotFoundError
        dask.distributed is not installed (the message says how to install it).
    """
    check_scheduler(scheduler, workers)
    v.in_range("timeout", timeout, 0.0, math.inf, "s")
    distributed = require_distributed()
    import logging

    if scheduler == "local":
        import dask

        n = workers if workers is not None else (os.cpu_count() or 1)
        with dask.config.set(LOCAL_CONFIG):  # read as the scheduler and the workers start
            cluster = distributed.LocalCluster(
                n_workers=n,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                # the scheduler's HTTP server on a free local port, not 8787 (maybe taken)
                scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
                silence_logs=logging.ERROR,
            )
        try:
            with distributed.Client(cluster) as client:
                yield DaskExecutor(client)
        finally:
            cluster.close()
        return
    try:
        client = distributed.Client(scheduler, timeout=timeout)
    except Exception as exc:  # refused, timed out, or not a Dask scheduler answering
        raise ValueError(
            f"cannot reach a Dask scheduler at {scheduler} within {timeout:g} s "
            f"({type(exc).__name__}); start one with `dask scheduler` or check the address"
        ) from None
    with client:
        yield DaskExecutor(client)


__all__ = [
    "CONNECT_TIMEOUT",
    "INSTALL",
    "LOCAL_CONFIG",
    "TARGET_OVERHEAD",
    "DaskExecutor",
    "RunStats",
    "check_scheduler",
    "dask_client",
    "is_dask_client",
    "measure_overhead",
    "require_distributed",
]

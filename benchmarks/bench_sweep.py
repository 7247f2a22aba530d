"""Scaling of a sweep on a Dask LocalCluster from 1 to 2 workers, in one run.

    python benchmarks/bench_sweep.py            # 1000 rows, 3 repeats (a few minutes)
    python benchmarks/bench_sweep.py --quick    # 200 rows, 1 repeat
    python benchmarks/bench_sweep.py --json     # the record as JSON (the text on stderr)
    python benchmarks/bench_sweep.py --json F   # the record written to the file F instead

A sweep of 10 mean spins × 10 spreads × 10 flight-time ranges = 1000 rows, each a Monte Carlo
estimate of 50,000 tosses (:func:`coinflight.probability.sweep.sweep`). Two LocalClusters, one
of 1 worker process and one of 2 (one thread each), started anew for each repeat and one at a
time (an idle cluster would take CPU from the other), the repeats alternating between them so
that both see the same load of a shared machine; the result is the median time of each and
their ratio (the target: 2.0, perfect scaling on 2 cores). Also: the per-task overhead each cluster
measured, the batches it formed, the share of the workers' time not spent computing, and where
the CPU went (psutil, per process and, in the client's process, per thread): the worker
processes; the client process's event loop (on a LocalCluster it runs the client's messaging,
the scheduler and the nannies); its main thread (the sweep's own Python: rows, keys,
submitting, results). On a 2-core machine the client's CPU is taken from the 2 workers, not
from the 1. The answers on 1 and 2 workers are checked equal, bit for bit.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import threading
import time
from pathlib import Path

import psutil  # a dependency of dask.distributed

from _record import Recorder, summary
from coinflight.model.distributions import Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.distributed import dask_client
from coinflight.probability.sweep import Case, sweep

N = 50_000


def _cpu_seconds() -> float:
    return time.process_time()


def worker_cpu(ex: object) -> float:
    """CPU seconds used so far by all the cluster's worker processes."""
    return sum(ex.client.run(_cpu_seconds).values())  # type: ignore[attr-defined]


def cpu_split(ex: object) -> dict[str, float]:
    """CPU seconds so far: this cluster's worker processes, and this process's threads (the
    main thread; the event loops and every other thread)."""
    pids = ex.client.run(os.getpid).values()  # type: ignore[attr-defined]
    workers = sum(sum(psutil.Process(pid).cpu_times()[:2]) for pid in pids)
    main_id = threading.main_thread().native_id
    main = loops = 0.0
    for thread in psutil.Process().threads():
        seconds = thread.user_time + thread.system_time
        if thread.id == main_id:
            main += seconds
        else:
            loops += seconds
    return {"workers": workers, "client_main_thread": main, "client_event_loops": loops}


def cases(k: int) -> list[Case]:
    """k³ rows: ωx ~ normal(mean, sd) × T ~ uniform ranges."""
    means = [60.0 + 20.0 * i for i in range(k)]
    sds = [1.0 + 2.0 * i for i in range(k)]
    times = [(0.4 + 0.05 * i, 0.6 + 0.05 * i) for i in range(k)]
    return [
        Case(TossDistribution(omega_x=Normal(m, s), flight_time=Uniform(*t)))
        for m in means
        for s in sds
        for t in times
    ]


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="200 rows, one repeat")
    parser.add_argument(
        "--json",
        nargs="?",
        const="-",
        type=str,
        metavar="FILE",
        help="print the record as JSON (the text to stderr), or write it to FILE",
    )
    args = parser.parse_args(argv)
    recorder = Recorder("bench_sweep", argv)
    to_stdout = args.json == "-"
    with recorder.text_to_stderr(to_stdout):
        figures = run(args.quick)
    if figures is None:
        return 1
    if to_stdout:
        print(recorder.json(figures))
    elif args.json is not None:
        Path(args.json).write_text(recorder.json(figures) + "\n")
    return 0


def run(quick: bool) -> dict[str, object] | None:
    """Times the sweep on 1 and 2 workers and prints the comparison; the figures of the record,
    None when the answers on 1 and 2 workers differ."""
    k, repeats = (6, 1) if quick else (10, 3)
    rows = cases(k)
    if quick:
        rows = rows[:200]
    print(f"machine: {summary()}; shared with other jobs, timings are noisy: compare the ratio")
    print(f"sweep of {len(rows)} rows, monte-carlo n = {N:,} each, seed 1")
    times: dict[int, list[float]] = {1: [], 2: []}
    stats: dict[int, dict[str, float]] = {}
    answers: dict[int, list[tuple[int, int, int] | None]] = {}
    for _ in range(repeats):
        for workers in (1, 2):
            with dask_client("local", workers) as ex:
                # warm-up (not timed): imports, compiled kernels, the measured overhead
                sweep(rows[:8], "monte-carlo", n=N, seed=1, executor=ex)
                c0 = worker_cpu(ex)
                split0 = cpu_split(ex)
                t0 = time.perf_counter()
                result = sweep(rows, "monte-carlo", n=N, seed=1, executor=ex)
                times[workers].append(time.perf_counter() - t0)
                cpu = worker_cpu(ex) - c0
                split = {k: x - split0[k] for k, x in cpu_split(ex).items()}
                answers[workers] = [r.counts for r in result]
                last = ex.last
                stats[workers] = {
                    "overhead_ms": 1e3 * ex.overhead,
                    "batches": last.batches,
                    "compute_s": last.compute,
                    "wall_s": last.wall,
                    "not_computing": last.overhead_share,
                    # CPU the workers got, in cores: 1.0 per worker on an idle machine
                    "cores_used": cpu / times[workers][-1],
                    "cost_ms": 1e3 * last.cost,
                    "load": os.getloadavg()[0],
                    **{f"cpu_{k}_s": x for k, x in split.items()},
                }
    if answers[1] != answers[2]:
        print("ERROR: the answers on 1 and 2 workers differ")
        return None
    median = {w: statistics.median(t) for w, t in times.items()}
    ratio = median[1] / median[2]
    for w in (1, 2):
        s = stats[w]
        print(
            f"{w} worker(s): median {median[w]:.2f} s over {repeats} run(s) "
            f"({', '.join(f'{t:.2f}' for t in times[w])}); {s['batches']} batches, "
            f"{100 * s['not_computing']:.1f} % of the workers' time not computing, "
            f"{s['cores_used']:.2f} cores of CPU used (last run)"
        )
        print(
            f"  CPU of the last run: workers {s['cpu_workers_s']:.2f} s, client process "
            f"{s['cpu_client_event_loops_s']:.2f} s in its event loops (scheduler, nannies, "
            f"messaging) + {s['cpu_client_main_thread_s']:.2f} s in its main thread (the sweep); "
            f"batches sized for {s['cost_ms']:.1f} ms of overhead each; load average "
            f"{s['load']:.1f}"
        )
    print(f"speed-up 1 → 2 workers: {ratio:.2f}× (2.00 = linear); answers equal bit for bit")
    cores = stats[2]["cores_used"] / stats[1]["cores_used"]
    print(
        f"CPU the machine gave: {cores:.2f}× as much to 2 workers as to 1; speed-up per core "
        f"obtained {ratio / cores:.2f} (1.00: the cluster adds no loss of its own)"
    )
    return {
        "rows": len(rows),
        "tosses_per_row": N,
        "repeats": repeats,
        "times_s": {f"{w}_workers": t for w, t in times.items()},
        "median_s": {f"{w}_workers": t for w, t in median.items()},
        "speed_up": ratio,
        "speed_up_target": 2.0,
        "stats": {f"{w}_workers": s for w, s in stats.items()},
    }


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

"""Speed and memory of the probability methods, ratios measured in one run.

    python benchmarks/bench_probability.py            # everything (about a minute)
    python benchmarks/bench_probability.py --quick    # skip the billion-toss memory run
    python benchmarks/bench_probability.py --accuracy # time to a given accuracy only
    python benchmarks/bench_probability.py --json     # the record as JSON (the text on stderr)

Monte Carlo of fully general tosses (ωx, ωy, ωz and T all random, precession included), side
by side with a plain NumPy vectorised baseline (Generator draws + the NumPy closed form) and
per-toss numerical integration (``coinflight.core.numerical.integrate``, SciPy DOP853); the
grid method at 5000² and 100000² configurations; the exact method; the command's cold start;
peak resident memory of a billion Monte Carlo tosses. Medians of repeats. Targets on 2 cores:
Monte Carlo ≥ 50 M tosses/s, grid 5000² < 0.1 s and 100000² < 10 s, exact < 10 ms, a billion
tosses in < 300 MB.

Time to a given accuracy: for five distributions, the seconds each method needs to reach a
standard error (or error) of 1e-4 and 1e-6, as ratios to exact in one run. Sampling methods
are measured at two sizes and extrapolated at their measured rate (Monte Carlo: s.e. ∝
n^-1/2; QMC: the exponent fitted between the sizes), which the table says.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from _record import Recorder, summary
from coinflight.core import sampling
from coinflight.core.numerical import integrate
from coinflight.core.torque_free import normal_alignment
from coinflight.model.distributions import Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import estimate
from coinflight.studies.presets import human

GENERAL = TossDistribution(
    Uniform(60.0, 90.0), Uniform(-10.0, 10.0), Uniform(-20.0, 20.0), Uniform(0.6, 0.9)
)
FIG2A = TossDistribution(Uniform(60.0, 90.0), 0, 0, Uniform(0.6, 0.9))
FIG3B = TossDistribution(Uniform(60.0, 90.0), 60.0, 0, Uniform(0.6, 0.9))


def median_times(fn: Callable[[], object], repeats: int) -> tuple[float, float]:
    """Median wall time and median CPU time (all threads of the process) of ``fn()``, s."""
    walls, cpus = [], []
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        fn()
        walls.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    return statistics.median(walls), statistics.median(cpus)


def median_time(fn: Callable[[], object], repeats: int) -> float:
    """Median wall time of ``fn()``, s."""
    return median_times(fn, repeats)[0]


def numpy_baseline(n: int, seed: int = 0, chunk: int = 1 << 20) -> int:
    """Plain NumPy: Generator draws and the closed form on arrays, chunk by chunk."""
    rng = np.random.default_rng(seed)
    i1, i3 = GENERAL.moments
    same = 0
    for start in range(0, n, chunk):
        m = min(chunk, n - start)
        wx, wy, wz, t = GENERAL.sample(rng, m)
        same += int(np.count_nonzero(normal_alignment(wx, wy, wz, t, i1, i3) > 0.0))
    return same


def per_toss_ivp(n: int, seed: int = 0) -> int:
    """One SciPy integration of Euler's equations per toss (the numerical reference)."""
    rng = np.random.default_rng(seed)
    i1, i3 = GENERAL.moments
    wx, wy, wz, t = GENERAL.sample(rng, n)
    same = 0
    for j in range(n):
        traj = integrate((wx[j], wy[j], wz[j]), (i1, i1, i3), [t[j]], rtol=1e-10, atol=1e-10)
        same += int(traj.normal()[-1, 2] > 0.0)
    return same


NORMAL_SPINS = TossDistribution.from_launch_speed(
    Normal(240.0, 24.0), 0.0, Normal(0.0, 40.0), Normal(2.4, 0.24)
)
"""Normal spins (--omega-x normal:240,24 --omega-z normal:0,40 --launch-speed normal:2.4,0.24)."""

THREE_SPINS_FIXED_T = TossDistribution(
    Uniform(60.0, 90.0), Uniform(-20.0, 20.0), Uniform(-10.0, 10.0), 0.7
)
"""Three uniform spins and a fixed flight time (precession)."""

CONDITIONAL = "conditional-on-spin"


def _seconds_for(
    run: Callable[[int], tuple[float, float]], sizes: tuple[int, int], target: float
) -> tuple[float, str]:
    """Seconds to reach a standard error ``target``: measured at two sizes (median of 3 runs
    each), extrapolated by the fitted power law of s.e. and of time in n."""
    points = []
    for n in sizes:
        results = [run(n) for _ in range(3)]
        points.append((n, statistics.median(r[0] for r in results), statistics.median(
            r[1] for r in results)))  # fmt: skip
    (n1, _t1, e1), (n2, t2, e2) = points
    slope = math.log(e2 / e1) / math.log(n2 / n1) if e1 > 0 and e2 > 0 else -0.5
    n_target = n2 * (target / e2) ** (1.0 / slope)
    t_per = t2 / n2
    how = "within the sizes run" if n_target <= n2 else f"extrapolated, s.e. ∝ n^{slope:.2f}"
    return max(t_per * n_target, 0.0), how


def time_to_accuracy() -> dict[str, dict[str, float]]:
    """Seconds to s.e. (or error) 1e-4 and 1e-6, per method, as ratios to exact; medians.
    Returns the figures: by distribution, exact's ms and p, each method's seconds."""
    figures: dict[str, dict[str, float]] = {}
    print("\nTime to a given accuracy (seconds; ratio to exact; medians of 3):")
    cases = (("Fig 2a (uniform ωx, T)", FIG2A), ("human preset", human()),
             ("normal spins", NORMAL_SPINS),
             ("four uniform: ωx, ωy, ωz, T", GENERAL),
             ("three uniform spins, fixed T", THREE_SPINS_FIXED_T))  # fmt: skip
    for label, dist in cases:
        estimate(dist, "exact")
        t_exact = median_time(lambda d=dist: estimate(d, "exact"), 5)
        exact = estimate(dist, "exact")
        print(f"  {label}: exact {t_exact * 1e3:.1f} ms, p = {exact.p_heads:.10f} "
              f"± {exact.error_estimate:.1g}")  # fmt: skip
        row = figures[label] = {"exact_ms": t_exact * 1e3, "exact_p_heads": exact.p_heads}

        def sampled(method: str, mode: str | None, d: TossDistribution = dist) -> Callable[
            [int], tuple[float, float]]:  # fmt: skip
            def run(n: int) -> tuple[float, float]:
                kw = {"variance_reduction": mode} if mode else {}
                r = estimate(d, method, n=n, seed=n, **kw)
                return r.elapsed, float(r.stderr or 0.0)

            return run

        rows = (
            ("monte-carlo", None, (1 << 20, 1 << 22)),
            ("monte-carlo", CONDITIONAL, (1 << 16, 1 << 18)),
            ("qmc", None, (16 << 14, 16 << 16)),
            ("qmc", CONDITIONAL, (16 << 8, 16 << 12)),
        )
        for method, mode, sizes in rows:
            name = method + (f" ({mode})" if mode else "")
            cells = []
            for target in (1e-4, 1e-6):
                secs, how = _seconds_for(sampled(method, mode), sizes, target)
                row[f"{method}{'_' + mode if mode else ''}_to_{target:.0e}_s"] = secs
                cells.append(f"{target:.0e}: {secs:10.3g} s ({secs / t_exact:9.3g}x, {how})")
            print(f"    {name:34s} " + "; ".join(cells))
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="skip the billion-toss run")
    parser.add_argument("--accuracy", action="store_true", help="time to accuracy only")
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    recorder = Recorder("bench_probability")
    with recorder.text_to_stderr(args.json):
        figures = run(args.quick, args.accuracy)
    if args.json:
        print(recorder.json(figures))


def run(quick: bool, accuracy_only: bool) -> dict[str, object]:
    """Times and prints each part; the figures of the record."""
    print(f"machine: {summary()}")
    t0 = time.perf_counter()
    sampling.warm_up()
    warm = time.perf_counter() - t0
    print(f"numba kernels ready (loaded from the on-disk cache): {warm:.2f} s")
    figures: dict[str, object] = {"warm_up_s": warm, "time_to_accuracy": time_to_accuracy()}
    if accuracy_only:
        return figures

    print("\nMonte Carlo, fully general tosses (ωx, ωy, ωz, T all uniform; precession):")
    n_fast = 1 << 27
    estimate(GENERAL, "monte-carlo", n=1 << 20, seed=1)
    numpy_baseline(1 << 16)
    runs: dict[str, tuple[int, Callable[[], object]]] = {
        "coinflight kernel, 1 thread": (
            n_fast,
            lambda: estimate(GENERAL, "monte-carlo", n=n_fast, seed=1, threads=1),
        ),
        "coinflight kernel, 2 threads": (
            n_fast,
            lambda: estimate(GENERAL, "monte-carlo", n=n_fast, seed=1, threads=2),
        ),
        "plain NumPy vectorised (1 thread)": (1 << 23, lambda: numpy_baseline(1 << 23)),
        "per-toss solve_ivp (1 thread)": (30, lambda: per_toss_ivp(30)),
    }
    wall: dict[str, float] = {}
    cpu: dict[str, float] = {}
    for name, (n, fn) in runs.items():
        dt, dcpu = median_times(fn, 3)
        wall[name], cpu[name] = n / dt, n / dcpu
    best = wall["coinflight kernel, 2 threads"]
    best_cpu = cpu["coinflight kernel, 2 threads"]
    print(f"  {'':38s} {'wall: tosses/s':>16s} {'per CPU-second':>16s}  kernel is … faster (CPU)")
    for name in runs:
        print(f"  {name:38s} {wall[name]:16,.0f} {cpu[name]:16,.0f}  {best_cpu / cpu[name]:,.3g}x")
    print(
        f"  target ≥ 50 M tosses/s on 2 cores: wall {best / 1e6:.1f} M/s "
        f"({'met' if best >= 50e6 else 'NOT met'} at this load); "
        f"2 cores × {best_cpu / 1e6:.1f} M per CPU-second = {2 * best_cpu / 1e6:.0f} M/s idle"
    )
    figures["monte_carlo_target_tosses_per_s"] = 50e6
    figures["monte_carlo_tosses_per_s"] = wall
    figures["monte_carlo_tosses_per_cpu_s"] = cpu

    print("\nGrid (method A), Fig 2a box (ωx 60-90 rad/s, T 0.6-0.9 s), exact counts:")
    for n, target in ((5000, 0.1), (100_000, 10.0)):
        estimate(FIG2A, "grid", n=n)
        dt = median_time(lambda n=n: estimate(FIG2A, "grid", n=n), 5)
        p = estimate(FIG2A, "grid", n=n).p_heads
        print(f"  {n}² = {n * n:.3g} configurations: {dt * 1e3:9.2f} ms (target < {target:g} s)")
        figures[f"grid_{n}_squared_ms"] = dt * 1e3
        figures[f"grid_{n}_squared_target_ms"] = target * 1e3
        print(f"    p = {p:.9f}")

    print("\nExact (closed form band integral):")
    for name, d in (("Fig 2a", FIG2A), ("Fig 3b", FIG3B)):
        estimate(d, "exact")
        dt = median_time(lambda d=d: estimate(d, "exact"), 50)
        figures[f"exact_{name.replace(' ', '').lower()}_ms"] = dt * 1e3
        print(
            f"  {name}: {dt * 1e3:.3f} ms (target < 10 ms) p = {estimate(d, 'exact').p_heads:.12f}"
        )

    print("\nCold start of the command (fresh process; numba code loaded from its cache):")
    figures["exact_target_ms"] = 10.0
    cold: dict[str, float] = {}
    figures["cold_start_s"] = cold
    cli = [str(Path(sys.executable).with_name("coinflight"))]
    fig2a = ["--omega-x", "60:90", "--flight-time", "0.6:0.9"]
    for label, extra in (
        ("coinflight --help", ["--help"]),
        ("probability (exact)", ["probability", *fig2a]),
        ("probability --method grid --n 5000", ["probability", *fig2a, "-m", "grid"]),
        ("probability -m monte-carlo -n 1000", ["probability", *fig2a, "-m", "monte-carlo"]),
    ):
        if "monte-carlo" in extra:
            extra = [*extra, "-n", "1000"]
        dt = median_time(
            lambda e=extra: subprocess.run([*cli, *e], check=True, capture_output=True), 3
        )
        cold[label] = dt
        print(f"  {label:38s} {dt:6.2f} s")

    if not quick:
        n = 10**9
        print(f"\nMemory: {n:.0e} Monte Carlo tosses by the command (peak resident set):")
        general = [
            "--omega-x", "60:90", "--omega-y=-10:10", "--omega-z=-20:20",
            "--flight-time", "0.6:0.9",
        ]  # fmt: skip
        # A small wrapper process starts the command and reports its peak RSS: measured from
        # this (large) process, a forked child's RSS before exec would count as well.
        wrapper = (
            "import resource, subprocess, sys; subprocess.run(sys.argv[1:], check=True); "
            "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr)"
        )
        proc = subprocess.run(
            [sys.executable, "-c", wrapper, *cli, "probability", *general, "-m", "monte-carlo",
             "-n", str(n), "--seed", "1", "--json", "--quiet"],
            capture_output=True, text=True, check=True,
        )  # fmt: skip
        result = json.loads(proc.stdout)
        peak = int(proc.stderr.split()[-1]) / 1024  # ru_maxrss is in KiB on Linux
        dt = result["elapsed"]
        print(
            f"  {dt:.1f} s ({n / dt / 1e6:.1f} M tosses/s), peak RSS of the command {peak:.0f} MB "
            f"(target < 300 MB), p = {result['p_heads']:.6f} ± {result['stderr']:.1g}"
        )
        figures["billion_tosses_s"] = dt
        figures["billion_tosses_peak_rss_mb"] = peak
        figures["billion_tosses_target_mb"] = 300.0
    return figures


if __name__ == "__main__":
    main()

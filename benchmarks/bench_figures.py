"""Speed of the pictures (issue 4): the paper reproduction, toss drawing, basin map, animation.

    python benchmarks/bench_figures.py            # 3 repeats of each, medians
    python benchmarks/bench_figures.py --quick    # 1 repeat

Each step is timed in-process (imports already paid), so the numbers are the library's own
work; the target is ``coinflight paper`` under a minute on a 2-core machine. The basin map's
outcome evaluation (one vectorised closed-form call) is timed apart from its drawing.
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from coinflight import Coin, Toss
from coinflight.plotting.animation import animate_toss, save_animation
from coinflight.plotting.basin import plot_basin
from coinflight.plotting.style import save_figure
from coinflight.plotting.toss import plot_toss
from coinflight.report.reproduce import reproduce_paper
from coinflight.studies.basin import basin_map

QUARTER = Coin.preset("us-quarter")


def median_time(fn: Callable[[], object], repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="one repeat instead of three")
    repeats = 1 if parser.parse_args().quick else 3
    print(f"cores: {os.cpu_count()}, repeats: {repeats} (medians)")
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        reproduce_paper(out / "warm", events=10_000)  # JIT compilation and imports
        rows = [
            (
                "coinflight paper (7 figures PNG+SVG, report)",
                lambda: reproduce_paper(out / "paper"),
            ),
            (
                "plot toss, 4 panels + sphere, PNG",
                lambda: save_figure(
                    plot_toss(
                        QUARTER,
                        Toss(omega=(90.0, 30.0, 0.0), flight_time=np.array([0.6, 0.65, 0.7, 0.75])),
                    ),
                    out / "toss.png",
                ),
            ),
            (
                "basin map 1000x1000 outcomes only",
                lambda: basin_map(QUARTER, omega_y=10.0, resolution=(1000, 1000)),
            ),
            (
                "plot basin 500x500, PNG",
                lambda: save_figure(plot_basin(basin_map(QUARTER)), out / "basin.png"),
            ),
            (
                "animate 80 rad/s, 0.7 s (142 frames), GIF",
                lambda: save_animation(
                    animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7)),
                    out / "toss.gif",
                ),
            ),
        ]
        for name, fn in rows:
            print(f"{name:<48} {median_time(fn, repeats):7.2f} s")


if __name__ == "__main__":
    main()

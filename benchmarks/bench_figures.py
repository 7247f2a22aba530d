"""Speed of the pictures: the paper reproduction, toss drawing, basin map, animation.

    python benchmarks/bench_figures.py            # 3 repeats of each, medians
    python benchmarks/bench_figures.py --quick    # 1 repeat
    python benchmarks/bench_figures.py --json     # the record as JSON (the text on stderr)

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

from _record import Recorder
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
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    recorder = Recorder("bench_figures")
    with recorder.text_to_stderr(args.json):
        figures = run(1 if args.quick else 3)
    if args.json:
        print(recorder.json(figures))


def run(repeats: int) -> dict[str, float | int]:
    """Times each step (median of ``repeats``), prints them; the figures of the record."""
    print(f"cores: {os.cpu_count()}, repeats: {repeats} (medians)")
    figures: dict[str, float | int] = {"repeats": repeats, "paper_target_s": 60.0}
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        reproduce_paper(out / "warm", events=10_000)  # JIT compilation and imports
        rows = [
            (
                "paper_s",
                "coinflight paper (7 figures PNG+SVG, report)",
                lambda: reproduce_paper(out / "paper"),
            ),
            (
                "plot_toss_s",
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
                "basin_map_1000x1000_s",
                "basin map 1000x1000 outcomes only",
                lambda: basin_map(QUARTER, omega_y=10.0, resolution=(1000, 1000)),
            ),
            (
                "plot_basin_500x500_s",
                "plot basin 500x500, PNG",
                lambda: save_figure(plot_basin(basin_map(QUARTER)), out / "basin.png"),
            ),
            (
                "animate_gif_s",
                "animate 80 rad/s, 0.7 s (142 frames), GIF",
                lambda: save_animation(
                    animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7)),
                    out / "toss.gif",
                ),
            ),
        ]
        for key, name, fn in rows:
            figures[key] = median_time(fn, repeats)
            print(f"{name:<48} {figures[key]:7.2f} s", flush=True)
    return figures


if __name__ == "__main__":
    main()

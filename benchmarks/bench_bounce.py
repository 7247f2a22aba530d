"""Speed of the table landing: tosses carried to rest, the first contact, and MuJoCo beside it.

    python benchmarks/bench_bounce.py                  # 2,000 tosses a set, 3 rounds
    python benchmarks/bench_bounce.py --quick          # 200 tosses a set
    python benchmarks/bench_bounce.py --n 500 --rounds 5
    python benchmarks/bench_bounce.py --quick --json   # the record as JSON (the text on stderr)

Times :func:`coinflight.outcomes.table.land` (all of numba's threads, the median of the rounds,
one of each case in turn) on two sets of US nickel tosses onto a table 0.8 m below launch
(e 0.5, μ 0.3, the default rolling and pivoting resistances): vigorous tosses (:func:`tosses`)
and human ones (the ``human`` preset of :mod:`coinflight.studies.presets`), seed 2026. For
each set: the landings carried to rest (the bounces, then the rigid 3-D ending) on ``--n``
tosses, and how they ended; the first contact alone (``max_bounces=0``) on 1,000,000 tosses
(``--quick`` 200,000); MuJoCo (optional: ``pip install coinflight[mujoco]``, skipped when not
installed; :func:`coinflight.studies.mujoco_compare.run`, its settings with the RK4
integrator, which these precessing tosses need, the surface's resistances as its rolling and
torsional friction) on the first 100 of the ``--n`` tosses (``--quick`` 16): its tosses a
second, coinflight's speed ratio to it and the agreement of the faces at the first contact and
at rest (the first contact compares the two models' flights and impacts; the roll after the
bounces is chaotic, so the faces at rest agree less often, and that agreement is no check of
either engine).

Targets on 2 cores: ≥ 20,000 human or vigorous tosses carried to rest a second, first contact
≥ 2 M a second, and the speed ratio against MuJoCo on the same tosses (no target).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from _record import Recorder, summary
from coinflight import Coin
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land

COIN_PRESET = "us-nickel"
COIN = Coin.preset(COIN_PRESET)
G = 9.81
DROP = 0.8
SURFACE = Surface("table", drop_height=DROP, restitution=0.5, friction=0.3)
"""The table of every case (default rolling and pivoting resistances and contact duration)."""

SEED = 2026
TO_REST_TARGET = 20_000.0
FIRST_CONTACT_TARGET = 2e6
"""The targets, tosses a second on 2 cores."""


def tosses(n: int, seed: int = SEED) -> tuple[np.ndarray, np.ndarray]:
    """Vigorous tosses: ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30) rad/s, v0 ~ U(1.5, 3) m/s."""
    rng = np.random.default_rng(seed)
    omega = np.column_stack(
        [
            rng.uniform(150.0, 300.0, n),
            rng.uniform(-30.0, 30.0, n),
            rng.uniform(-30.0, 30.0, n),
        ]
    )
    return omega, rng.uniform(1.5, 3.0, n)


def human_tosses(n: int, seed: int = SEED) -> tuple[np.ndarray, np.ndarray]:
    """Human tosses: the ``human`` preset of :mod:`coinflight.studies.presets` for the nickel
    (ω body frame, rad/s; v0 = g × flight time / 2, m/s)."""
    from coinflight.studies.presets import preset

    wx, wy, wz, flight = preset("human", coin=COIN).sample(np.random.default_rng(seed), n)
    return np.column_stack([wx, wy, wz]), 0.5 * G * flight


SETS = {"vigorous": tosses, "human": human_tosses}
"""The sets of tosses, by name (each a function of the number of tosses)."""

OWN_RATES_SEED = 7
"""The seed of :func:`own_rates` (reported by ``bench_targets.py``)."""


def own_rates(n: int) -> dict[str, np.ndarray]:
    """Each of ``n`` tosses' own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6) (seed :data:`OWN_RATES_SEED`),
    in ``land``'s ``contact`` form (``bench_targets.py``'s own-e, μ cases)."""
    rng = np.random.default_rng(OWN_RATES_SEED)
    return {"restitution": rng.uniform(0.2, 0.8, n), "friction": rng.uniform(0.1, 0.6, n)}


def face_fractions(face: np.ndarray) -> str:
    """'P(heads, tails, edge) = (…)' of an array of face codes (TAILS=0, HEADS=1, EDGE=2)."""
    share = np.bincount(face, minlength=3) / len(face)
    return f"P(heads, tails, edge) = ({share[HEADS]:.4f}, {share[TAILS]:.4f}, {share[EDGE]:.2e})"


def interleaved(
    cases: dict[str, tuple[int, Callable[[], Any]]], rounds: int
) -> tuple[dict[str, float], dict[str, Any]]:
    """Tosses a second of each case ({name: (tosses, call)}), the median of ``rounds`` rounds
    with one of each case in turn (so that the machine's other load falls on all alike), and
    what each call returned in the last round."""
    times: dict[str, list[float]] = {name: [] for name in cases}
    last: dict[str, Any] = {}
    for _ in range(rounds):
        for name, (_, fn) in cases.items():
            t0 = time.perf_counter()
            last[name] = fn()
            times[name].append(time.perf_counter() - t0)
    return {name: n / statistics.median(times[name]) for name, (n, _) in cases.items()}, last


def mujoco(
    name: str, w: np.ndarray, s: np.ndarray, m: int, rate: float, rest: np.ndarray
) -> dict[str, Any]:
    """MuJoCo on the first ``m`` tosses (ω, v0) of the set ``name``, with :data:`SURFACE`'s
    resistances as its torsional and rolling friction (the mapping of
    :mod:`coinflight.studies.mujoco_compare`): its tosses a second, coinflight's speed ratio to
    it (``rate``, coinflight's tosses a second carried to rest, over MuJoCo's) and the agreement
    of the faces at the first contact and at rest (``rest``: coinflight's faces at rest of the
    tosses)."""
    from coinflight.studies import mujoco_compare as mc

    if not mc.available():
        print("  MuJoCo: not installed (pip install 'coinflight[mujoco]'), skipped")
        return {}
    w, s = w[:m], s[:m]
    # RK4: these tosses precess (axial spin, wobble), and MuJoCo's default Euler integrator
    # drifts in the precession over the fall (mujoco_compare's notes).
    engine = mc.Engine(
        torsional=SURFACE.pivoting_resistance,
        rolling=SURFACE.rolling_resistance,
        integrator="RK4",
    )
    e, mu = SURFACE.restitution, SURFACE.friction
    run = mc.run(COIN, w, s, DROP, e, mu, G, engine=engine)
    theirs = m / float(run.elapsed)
    first = np.mean(land(COIN, w, s, 1.0, G, SURFACE, max_bounces=0).face == run.first)
    rest = np.mean(rest[:m] == run.rest)
    print(
        f"  MuJoCo {run.version} on {m} of the same tosses: {theirs:,.1f}/s ({run.unsettled} "
        f"still moving at {engine.limit:g} s); coinflight is {rate / theirs:,.0f} times as "
        f"fast; the faces agree at the first contact {first:.0%}, at rest {rest:.0%}"
    )
    return {
        f"{name}_mujoco_tosses": m,
        f"{name}_mujoco_tosses_per_s": theirs,
        f"{name}_speed_ratio": rate / theirs,
        f"{name}_agreement_first_contact": float(first),
        f"{name}_agreement_at_rest": float(rest),
    }


def timed(n: int, first_n: int, m: int, rounds: int) -> dict[str, Any]:
    """The run: for each of :data:`SETS`, ``n`` tosses carried to rest and ``first_n`` to
    the first contact (medians of ``rounds``), how the landings ended, and MuJoCo on the first
    ``m`` of the ``n`` tosses; prints them and returns the figures of the record."""
    import numba

    from coinflight.studies import mujoco_compare as mc

    print(summary())
    figures: dict[str, Any] = {
        "tosses": n,
        "first_contact_tosses": first_n,
        "rounds": rounds,
        "threads": numba.get_num_threads(),
        "to_rest_target_tosses_per_s": TO_REST_TARGET,
        "first_contact_target_tosses_per_s": FIRST_CONTACT_TARGET,
    }
    if mc.available():
        import mujoco as mj

        figures["mujoco_version"] = str(mj.__version__)
    for name, draw in SETS.items():
        w, s = draw(n)
        wf, sf = draw(first_n)
        land(COIN, w[:20], s[:20], 1.0, G, SURFACE)  # compile (or load the cache)
        cases = {
            "to rest": (n, lambda w=w, s=s: land(COIN, w, s, 1.0, G, SURFACE)),
            "first contact": (
                first_n,
                lambda w=wf, s=sf: land(COIN, w, s, 1.0, G, SURFACE, max_bounces=0),
            ),
        }
        load = os.getloadavg()[0]
        rates, last = interleaved(cases, rounds)
        figures[f"{name}_to_rest_tosses_per_s"] = rates["to rest"]
        figures[f"{name}_first_contact_tosses_per_s"] = rates["first contact"]
        out = last["to rest"]
        statuses = {st.label: int(np.count_nonzero(out.status == st)) for st in Status}
        print(
            f"{name} tosses, {numba.get_num_threads()} threads, median of {rounds}, load "
            f"{load:.1f}: {rates['to rest']:,.0f}/s carried to rest ({n:,} tosses), "
            f"{rates['first contact']:,.0f}/s to the first contact ({first_n:,})"
        )
        print(
            f"  at rest: {face_fractions(out.face)}; "
            + ", ".join(f"{k} {v}" for k, v in statuses.items() if v)
            + f"; settle time median {np.median(out.settle_time):.2f} s, "
            f"max {out.settle_time.max():.1f} s"
        )
        figures.update(mujoco(name, w, s, min(m, n), rates["to rest"], out.face))
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer tosses")
    parser.add_argument("--n", type=int, default=None, help="tosses a set carried to rest")
    parser.add_argument("--rounds", type=int, default=3, help="rounds (the median is taken)")
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    for option, value in (("--n", args.n), ("--rounds", args.rounds)):
        if value is not None and value < 1:  # one line, exit code 2
            parser.exit(2, f"bench_bounce.py: {option} must be a positive integer, got {value}\n")
    n = args.n or (200 if args.quick else 2_000)
    first_n, m = (200_000, 16) if args.quick else (1_000_000, 100)
    recorder = Recorder("bench_bounce")
    with recorder.text_to_stderr(args.json):
        figures = timed(n, first_n, m, args.rounds)
    if args.json:
        print(recorder.json(figures))


if __name__ == "__main__":
    sys.exit(main())

"""Speed of the bouncing model, and a general rigid-body engine beside it.

    python benchmarks/bench_bounce.py              # coinflight speed + MuJoCo on 200 tosses
    python benchmarks/bench_bounce.py --quick      # fewer tosses
    python benchmarks/bench_bounce.py --nickel     # also the US nickel's P(edge) band
    python benchmarks/bench_bounce.py --rigid-rates N [--rounds R]  # the rigid ending's speed,
                                                    # and MuJoCo's on the same tosses
    python benchmarks/bench_bounce.py --quick --json  # the record as JSON (the text on stderr)

coinflight: the event-driven numba kernel (``coinflight.outcomes.table.land``; exact flights between
impacts, contacts found by root finding, parallel over tosses), on tosses of a US nickel
dropped onto a table 0.8 m below launch (e = 0.5, μ = 0.3): tosses per second, median of
repeats, all threads of the machine. Targets on 2 cores: ≥ 20,000 human or vigorous tosses
carried to rest a second (``--rigid-rates``: the rigid ending), first contact ≥ 2 M a second.

MuJoCo (optional: ``pip install coinflight[mujoco]``; skipped cleanly when not installed): the
same tosses in coinflight and MuJoCo, with the settings of
:mod:`coinflight.studies.mujoco_compare` (the comparison lives in the library; the landing
report, ``coinflight landing-report``, runs it on 10,000 tosses): tosses per second of each and
the agreement of outcomes, (a) at the first contact (geometry and free flight only) and (b) at
rest (depends on each engine's contact model).

``--json`` prints the record (the rates and the provenance) of the default run or
``--rigid-rates``.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from typing import Any

import numpy as np

from _record import Recorder, key, summary
from coinflight import Coin
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land

COIN_PRESET = "us-nickel"
COIN = Coin.preset(COIN_PRESET)
G = 9.81
DROP = 0.8
SURFACE = Surface("table", drop_height=DROP, restitution=0.5, friction=0.3)


def tosses(n: int, seed: int = 2026) -> tuple[np.ndarray, np.ndarray]:
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


def median_rate(fn, n: int, repeats: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return n / statistics.median(times)


def bench_coinflight(n: int, repeats: int) -> dict[str, Any]:
    import numba

    omega, v0 = tosses(n)
    land(COIN, omega[:100], v0[:100], 1.0, G, SURFACE)  # compile (or load the cache)
    rate = median_rate(lambda: land(COIN, omega, v0, 1.0, G, SURFACE), n, repeats)
    first = median_rate(lambda: land(COIN, omega, v0, 1.0, G, SURFACE, max_bounces=0), n, repeats)
    out = land(COIN, omega, v0, 1.0, G, SURFACE)
    print(
        f"coinflight bouncing (default rocking ending), {n:,} tosses, {numba.get_num_threads()} "
        f"threads: {rate:,.0f} tosses/s carried to rest (median of {repeats}); first contact "
        f"only: {first:,.0f} tosses/s"
    )
    rocking = np.mean(out.status == Status.SETTLED_ROCKING)
    print(
        f"  mean bounces {out.bounces.mean():.2f}, max {out.bounces.max()}; decided by the "
        f"rocking hand-off {rocking:.1%}; unsettled {np.mean(out.status == Status.UNSETTLED):.2%}; "
        f"{face_fractions(out.face)}"
    )
    return {
        "tosses": n,
        "repeats": repeats,
        "threads": numba.get_num_threads(),
        "rocking_to_rest_tosses_per_s": rate,
        "first_contact_tosses_per_s": first,
        "first_contact_target_tosses_per_s": 2e6,
    }


def bench_mujoco(m: int) -> dict[str, Any]:
    """The same tosses in MuJoCo (coinflight.studies.landing.mujoco_comparison: settings and
    the comparison live in the library, coinflight.studies.mujoco_compare)."""
    from coinflight.studies import mujoco_compare
    from coinflight.studies.landing import mujoco_comparison

    if not mujoco_compare.available():
        print("MuJoCo: not installed (pip install 'coinflight[mujoco]'), skipped")
        return {"mujoco_skipped": "not installed"}
    c = mujoco_comparison(m, seed=2026)
    s = c.settings
    print(
        f"MuJoCo {s['mujoco']} ({s['integrator']}, dt = {s['timestep']:g} s, {s['threads']} "
        f"threads), {m} tosses: {m / c.mujoco_seconds:,.1f} tosses/s; coinflight "
        f"{m / c.rocking.seconds:,.0f} tosses/s on the same tosses: ratio "
        f"{c.ratio(c.rocking):,.0f}"
    )
    print(
        f"  agreement with coinflight: first contact {c.first_agreement:.1%}, at rest "
        f"{c.agreement(c.rocking):.1%}; MuJoCo at rest: {face_fractions(c.mujoco_rest)} "
        f"({c.mujoco_unsettled} still moving at {c.mujoco.limit:g} s), coinflight: "
        f"{face_fractions(c.rocking.rest)}"
    )
    return {
        "mujoco_tosses": m,
        "mujoco_version": s["mujoco"],
        "mujoco_tosses_per_s": m / c.mujoco_seconds,
        "coinflight_same_tosses_per_s": m / c.rocking.seconds,
        "speed_ratio": c.ratio(c.rocking),
        "agreement_first_contact": c.first_agreement,
        "agreement_at_rest": c.agreement(c.rocking),
    }


def nickel_edge(n: int) -> None:
    """P(edge) of a US nickel as a band over the literature's (e, μ) (the surface presets),
    beside Murray & Teare's extrapolated 1 in 6000 (coinflight.studies.landing.nickel_band)."""
    from coinflight.studies.landing import nickel_band

    print(f"US nickel, {n:,} tosses per cell, table 0.8 m below launch (Murray & Teare: 1/6000)")
    for band in nickel_band(n, seed=6000):
        (lo, lo_se), (hi, hi_se) = band.low, band.high
        p = band.integrated
        print(
            f"  {band.preset}: P(edge) from {lo:.2e} ± {lo_se:.1e} to {hi:.2e} ± {hi_se:.1e}; "
            f"integrated over the ranges {p.p:.2e} ± {p.stderr:.1e}"
        )


RIGID = Surface("table", DROP, 0.5, 0.3, ending="rigid")
"""The rigid ending's surface of :func:`rigid_rates` (default resistances, 1e-4 m)."""


def mujoco_rigid(name: str, w: np.ndarray, s: np.ndarray, rigid_rate: float) -> dict[str, Any]:
    """MuJoCo on the first tosses of one set of :func:`rigid_rates`, with the rigid ending's
    resistances as its torsional and rolling friction (the mapping of
    :mod:`coinflight.studies.mujoco_compare`): its tosses a second and the rigid ending's speed
    ratio to it (``rigid_rate``, measured on the whole set, over MuJoCo's)."""
    from coinflight.studies import mujoco_compare as mc

    if not mc.available():
        print("  MuJoCo: not installed (pip install 'coinflight[mujoco]'), skipped")
        return {}
    m = min(len(s), 100)
    r = RIGID.rolling_resistance
    engine = mc.Engine(torsional=RIGID.pivoting_resistance, rolling=r)
    e, mu = RIGID.restitution, RIGID.friction
    run = mc.run(COIN, w[:m], s[:m], DROP, e, mu, G, engine=engine)
    rate = m / float(run.elapsed)
    print(
        f"  MuJoCo on {m} of the same {name} tosses: {rate:,.1f}/s "
        f"({int(np.count_nonzero(run.moving))} still moving at {engine.limit:g} s); the rigid "
        f"ending is {rigid_rate / rate:,.0f} times as fast"
    )
    return {
        f"{name}_mujoco_tosses": m,
        f"{name}_mujoco_tosses_per_s": rate,
        f"{name}_rigid_over_mujoco_speed": rigid_rate / rate,
    }


def rigid_rates(n: int, repeats: int = 3) -> dict[str, Any]:
    """Tosses a second carried to rest with the rigid ending against the rocking ending and
    first contact, in one run (medians of ``repeats``, all threads), on the vigorous tosses
    (:func:`tosses`) and on human ones (:data:`coinflight.studies.presets`' ``human``, drawn
    with the same seed), US nickel, e = 0.5, μ = 0.3; with how the rigid landings ended.
    Returns the rates (the figures of the record)."""
    import numba

    from coinflight.studies.presets import preset

    omega, v0 = tosses(n)
    wx, wy, wz, flight = preset("human", coin=COIN).sample(np.random.default_rng(2026), n)
    human = (np.column_stack([wx, wy, wz]), 0.5 * G * flight)
    sets = {"vigorous": (omega, v0), "human": human}
    for w, s in sets.values():
        land(COIN, w[:20], s[:20], 1.0, G, RIGID)  # compile (or load the cache)
    load = os.getloadavg()
    figures: dict[str, Any] = {
        "tosses": n,
        "repeats": repeats,
        "threads": numba.get_num_threads(),
        "to_rest_target_tosses_per_s": 20_000.0,
        "first_contact_target_tosses_per_s": 2e6,
    }
    for name, (w, s) in sets.items():
        cases = {
            "rigid ending": lambda w=w, s=s: land(COIN, w, s, 1.0, G, RIGID),
            "rocking ending": lambda w=w, s=s: land(COIN, w, s, 1.0, G, SURFACE),
            "first contact": lambda w=w, s=s: land(COIN, w, s, 1.0, G, SURFACE, max_bounces=0),
        }
        rates = {case: median_rate(fn, n, repeats) for case, fn in cases.items()}
        for case, rate in rates.items():
            figures[f"{name}_{key(case)}_tosses_per_s"] = rate
        out = land(COIN, w, s, 1.0, G, RIGID)
        statuses = {st.label: int(np.count_nonzero(out.status == st)) for st in Status}
        print(
            f"{n:,} {name} nickel tosses, e 0.5, μ 0.3, {numba.get_num_threads()} threads, "
            f"median of {repeats}, load {load[0]:.1f}: "
            + ", ".join(f"{case} {rate:,.0f}/s" for case, rate in rates.items())
        )
        print(
            f"  rigid ending: {face_fractions(out.face)}; statuses "
            + ", ".join(f"{k} {v}" for k, v in statuses.items() if v)
            + f"; settle time median {np.median(out.settle_time):.2f} s, "
            f"max {out.settle_time.max():.1f} s"
        )
        figures.update(mujoco_rigid(name, w, s, rates["rigid ending"]))
    return figures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--nickel", action="store_true")
    parser.add_argument("--rigid-rates", type=int, default=0, metavar="N")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    recorder = Recorder("bench_bounce")
    with recorder.text_to_stderr(args.json):
        figures = timed(args)
    if args.json:
        print(recorder.json(figures))


def timed(args: argparse.Namespace) -> dict[str, Any]:
    """The run of ``--rigid-rates`` or the default one; the figures of the record."""
    if args.rigid_rates:
        return rigid_rates(args.rigid_rates, args.rounds)
    print(summary())
    figures = bench_coinflight(200_000 if args.quick else 1_000_000, 3 if args.quick else 5)
    figures.update(bench_mujoco(16 if args.quick else 100))
    if args.nickel:
        nickel_edge(200_000)
    return figures


if __name__ == "__main__":
    main()

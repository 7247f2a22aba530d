"""Speed of the bouncing model, and a general rigid-body engine beside it.

    python benchmarks/bench_bounce.py              # coinflight speed + MuJoCo on 200 tosses
    python benchmarks/bench_bounce.py --quick      # fewer tosses
    python benchmarks/bench_bounce.py --nickel     # also the US nickel's P(edge) band
    python benchmarks/bench_bounce.py --contact N  # the opt-in contact phase: same side, edges
    python benchmarks/bench_bounce.py --contact-rates N  # its speed only
    python benchmarks/bench_bounce.py --contact-rates N [--rounds R] --old-src DIR  # + another src
    python benchmarks/bench_bounce.py --upright N [--rounds R]  # its upright decision on/off
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

``--json`` prints the record (the rates and the provenance) of the default run,
``--contact-rates`` or ``--rigid-rates``.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
from typing import Any

import numpy as np

from _record import Recorder, key, summary
from coinflight import Coin
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Surface
from coinflight.outcomes.table import contact_record, land

COIN_PRESET = "us-nickel"
COIN = Coin.preset(COIN_PRESET)
G = 9.81
DROP = 0.8
SURFACE = Surface("table", drop_height=DROP, restitution=0.5, friction=0.3)
CONTACT = Surface("table", DROP, 0.5, 0.3, ending="contact")
"""The contact ending's surface of :func:`contact_rates` (and of :data:`OLD_CONTACT`)."""


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
    in ``land``'s ``contact`` form (:func:`contact_rates`)."""
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


CONTACT_CASES = ("contact ending", "contact ending, each toss its own e, μ")
"""The cases :func:`contact_rates` times against another implementation (``--old-src``)."""

OLD_CONTACT = """
import json, sys, time
import numpy as np
from coinflight import Coin
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land
a = json.loads(sys.argv[1])
given = np.load(a["inputs"])
omega, v0 = given["omega"], given["v0"]
mixture = {"restitution": given["restitution"], "friction": given["friction"]}
n = len(v0)
coin = Coin.preset(a["coin"])
g = a["g"]
contact = Surface("table", a["drop"], a["restitution"], a["friction"], ending="contact")
cases = {
    "contact ending": lambda p: land(coin, omega, v0, 1.0, g, contact, parallel=p),
    "contact ending, each toss its own e, μ": lambda p: land(
        coin, omega, v0, 1.0, g, contact, contact=mixture, parallel=p),
}
for p in (True, False):  # compile or load the cache
    land(coin, omega[:20], v0[:20], 1.0, g, contact, parallel=p)
    land(coin, omega[:20], v0[:20], 1.0, g, contact, parallel=p,
         contact={k: v[:20] for k, v in mixture.items()})
out, arrays = {"wall": {}, "cpu": {}}, {}
for k, f in cases.items():
    t0 = time.perf_counter(); r = f(True); out["wall"][k] = n / (time.perf_counter() - t0)
    t0 = time.process_time(); f(False); out["cpu"][k] = n / (time.process_time() - t0)
    arrays[k + " face"], arrays[k + " status"] = r.face, r.status
if a["save"]:
    np.savez(a["save"], **arrays)
print(json.dumps(out))
"""
"""One round of :data:`CONTACT_CASES` in another implementation (run with ``python -c``, its
``src`` on PYTHONPATH), on the tosses :func:`contact_rates` gives it in an .npz (ω, v0 and each
toss's e, μ) and the surface's values in its JSON argument."""


def _other_contact(old_src: str, inputs: str, cache: str, save: str = "") -> dict:
    """Rates of :data:`OLD_CONTACT` in a subprocess (its numba cache in ``cache``, not in its
    sources) on the tosses in ``inputs`` (.npz: omega, v0, restitution, friction): ``{"wall":
    tosses a second of wall time (all threads), "cpu": per CPU second in one thread
    (parallel=False)}``, each a dict by case; with ``save`` its faces and statuses written
    there (.npz)."""
    import json
    import subprocess
    import sys

    payload = json.dumps(
        {
            "inputs": inputs,
            "save": save,
            "coin": COIN_PRESET,
            "g": G,
            "drop": DROP,
            "restitution": CONTACT.restitution,
            "friction": CONTACT.friction,
        }
    )
    env = dict(os.environ, PYTHONPATH=old_src, NUMBA_CACHE_DIR=cache)
    done = subprocess.run(
        [sys.executable, "-c", OLD_CONTACT, payload],
        env=env,
        capture_output=True,
        text=True,
        check=True,
    )
    return dict(json.loads(done.stdout.strip().splitlines()[-1]))


def cpu_rate(fn, n: int) -> float:  # type: ignore[no-untyped-def]
    """Tosses per CPU second of ``fn`` (one thread: on a shared machine the wall clock also
    counts the time other processes hold the cores)."""
    t0 = time.process_time()
    fn()
    return n / (time.process_time() - t0)


def as_undecided(status: np.ndarray) -> np.ndarray:
    """``status`` with DECIDED_UPRIGHT written as SETTLED_CONTACT: the status of the same toss
    without the upright decision's own status (a tree older than that status stored its decided
    coins as settled in contact; with the decision off they are carried to rest there), so
    that comparing with such a run counts no decided toss as a difference."""
    decided = status == Status.DECIDED_UPRIGHT
    return np.where(decided, np.asarray(Status.SETTLED_CONTACT, dtype=status.dtype), status)


def status_differences(here: np.ndarray, there: np.ndarray) -> tuple[int, int, int, int]:
    """Tosses whose statuses differ between two runs of the same tosses, each mapped by
    :func:`as_undecided` (so a decided toss is no difference whether the other tree has the
    status, stores it as settled in contact, or was run with the decision off), the tosses
    decided upright in each, and those decided in one tree only (the mapping hides them: a
    real difference when both trees have the status, all the decided ones when the other
    has not): (differing, decided here, decided there, decided in one only)."""
    differing = int(np.count_nonzero(as_undecided(here) != as_undecided(there)))
    decided_here = here == Status.DECIDED_UPRIGHT
    decided_there = there == Status.DECIDED_UPRIGHT
    return (
        differing,
        int(np.count_nonzero(decided_here)),
        int(np.count_nonzero(decided_there)),
        int(np.count_nonzero(decided_here != decided_there)),
    )


def contact_rates(n: int, repeats: int = 3, old_src: str | None = None) -> dict[str, Any]:
    """Tosses a second carried to rest with the 3-D contact ending against the rocking ending
    and first contact, in one run (medians), on one surface (e = 0.5, μ = 0.3) and with each
    toss's own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6); and where the contact ending decides them.

    With ``old_src`` (the ``src`` folder of another coinflight, e.g. a checkout of main) the
    contact ending's cases (:data:`CONTACT_CASES`) are timed in that implementation too, in a
    subprocess, one round of it in each round of these (so the ratio is taken over the same
    minutes: medians of the rounds), then once each per CPU second in one thread; and the faces
    and statuses of the same tosses are compared between the two. Returns the rates (the
    figures of the record)."""
    import tempfile

    omega, v0 = tosses(n)
    contact = CONTACT
    mixture = own_rates(n)
    for parallel in (True, False):  # compile (or load the cache)
        land(COIN, omega[:20], v0[:20], 1.0, G, contact, parallel=parallel)
        part = {k: v[:20] for k, v in mixture.items()}
        land(COIN, omega[:20], v0[:20], 1.0, G, contact, contact=part, parallel=parallel)
    cases = {
        "contact ending": lambda: land(COIN, omega, v0, 1.0, G, contact),
        "rocking ending": lambda: land(COIN, omega, v0, 1.0, G, SURFACE),
        "first contact": lambda: land(COIN, omega, v0, 1.0, G, SURFACE, max_bounces=0),
        "contact ending, each toss its own e, μ": lambda: land(
            COIN, omega, v0, 1.0, G, contact, contact=mixture
        ),
        "rocking ending, each toss its own e, μ": lambda: land(
            COIN, omega, v0, 1.0, G, SURFACE, contact=mixture
        ),
    }
    own = {
        "contact ending": lambda p: land(COIN, omega, v0, 1.0, G, contact, parallel=p),
        "contact ending, each toss its own e, μ": lambda p: land(
            COIN, omega, v0, 1.0, G, contact, contact=mixture, parallel=p
        ),
    }
    load_before = os.getloadavg()
    times: dict[str, list[float]] = {name: [] for name in cases}
    cpu: dict[str, list[float]] = {name: [] for name in CONTACT_CASES}
    other: dict[str, dict[str, list[float]]] = {"wall": {}, "cpu": {}}
    with tempfile.TemporaryDirectory() as cache:
        saved = os.path.join(cache, "other.npz")
        inputs = os.path.join(cache, "tosses.npz")
        np.savez(inputs, omega=omega, v0=v0, **mixture)
        for r in range(repeats):
            for name, fn in cases.items():
                t0 = time.perf_counter()
                fn()
                times[name].append(time.perf_counter() - t0)
            if old_src:  # one round of the other implementation in each round of these
                for name in CONTACT_CASES:
                    cpu[name].append(cpu_rate(lambda f=own[name]: f(False), n))
                rates = _other_contact(old_src, inputs, cache, save=saved if r == 0 else "")
                for kind, by_case in rates.items():
                    for name, rate in by_case.items():
                        other[kind].setdefault(name, []).append(rate)
        old_out = dict(np.load(saved)) if old_src else {}
    rates = {name: n / statistics.median(ts) for name, ts in times.items()}
    first = rates["first contact"]
    print(f"{n:,} vigorous tosses, e = 0.5, μ = 0.3, median of {repeats}, load {load_before}")
    figures: dict[str, Any] = {"tosses": n, "repeats": repeats}
    for name, rate in rates.items():
        figures[f"{key(name)}_tosses_per_s"] = rate
        print(f"  {name}: {rate:,.0f} tosses/s ({rate / first:.2e} of first contact)")
    if old_src:
        print(f"  other implementation ({old_src}), same tosses, in the same rounds (medians):")
        for name in CONTACT_CASES:
            that = statistics.median(other["wall"][name])
            here_cpu = statistics.median(cpu[name])
            that_cpu = statistics.median(other["cpu"][name])
            figures[f"other_{key(name)}_tosses_per_s"] = that
            figures[f"{key(name)}_one_thread_tosses_per_cpu_s"] = here_cpu
            figures[f"other_{key(name)}_one_thread_tosses_per_cpu_s"] = that_cpu
            out = own[name](True)
            differ = int(np.count_nonzero(out.face != old_out[name + " face"]))
            status, decided, decided_there, one_only = status_differences(
                out.status, old_out[name + " status"]
            )
            print(
                f"    {name}: {that:,.0f} tosses/s (this one / other = "
                f"{rates[name] / that:.2f}); one thread {here_cpu:,.0f} against "
                f"{that_cpu:,.0f} per CPU second (this one / other = "
                f"{here_cpu / that_cpu:.2f}); faces differing {differ} of {n}, statuses "
                f"{status} (decided upright, {decided} here and {decided_there} there, counted "
                "as settled in contact in both, the status of a tree without it); decided upright "
                f"in one tree only {one_only} (all the decided ones if the other tree has no "
                "such status)"
            )
    print(f"  load average {load_before[0]:.2f} before, {os.getloadavg()[0]:.2f} after")
    for e, mu in ((0.5, 0.3), (0.2, 0.5), (0.8, 0.1)):
        out = land(COIN, omega, v0, 1.0, G, Surface("table", DROP, e, mu, ending="contact"))
        share = np.bincount(out.status, minlength=len(Status)) / n
        print(
            f"  e = {e}, μ = {mu}: decided at an impact (whole energy below the barrier) "
            f"{share[Status.SETTLED_ENERGY]:.1%}, in the contact phase "
            f"{share[Status.SETTLED_CONTACT] + share[Status.DECIDED_UPRIGHT]:.1%} (of which "
            f"decided upright {share[Status.DECIDED_UPRIGHT]:.1%}), unsettled "
            f"{share[Status.UNSETTLED]:.2%}; "
            f"contact phase {np.median(out.settle_time - out.first_contact):.2f} s after the first "
            f"contact (median); {face_fractions(out.face)}"
        )
    for name, surface in (("contact", contact), ("rocking", SURFACE)):
        out = land(COIN, omega, v0, 1.0, G, surface, contact=mixture)
        same = np.mean(out.face == HEADS)
        print(
            f"  {name} ending, each toss its own e, μ: P(same side) {same:.4f} ± "
            f"{math.sqrt(same * (1 - same) / n):.4f}, {face_fractions(out.face)}"
        )
    return figures


UPRIGHT_SURFACES = {"e 0.5, μ 0.3": (0.5, 0.3), "e 0.5, μ 0.6": (0.5, 0.6), "own e, μ": None}
"""The surfaces of :func:`upright_decision` (None: each toss's own e ~ U(0.2, 0.8),
μ ~ U(0.1, 0.6), as :func:`contact_rates`)."""


def _upright_child(n: int, setting: str, out: str) -> None:
    """One round of :func:`upright_decision` in this process: the contact ending with the
    upright decision ``setting`` ("on" or "off"), each surface timed once, the rates printed as
    JSON and the faces and statuses saved to ``out`` (an .npz)."""
    import json

    from coinflight.core import contact_phase

    # Before anything compiles: numba reads the global when it compiles settle (the parent
    # gives the "off" child its own numba cache directory, whose key ignores globals).
    contact_phase.UPRIGHT_DECISION = setting == "on"
    omega, v0 = tosses(n)
    mixture = own_rates(n)
    rates, arrays = {}, {}
    for name, pair in UPRIGHT_SURFACES.items():
        e, mu = pair or (0.5, 0.3)
        surface = Surface("table", DROP, e, mu, ending="contact")
        own = mixture if pair is None else None
        part = None if own is None else {k: v[:20] for k, v in own.items()}
        land(COIN, omega[:20], v0[:20], 1.0, G, surface, contact=part)  # compile or load
        t0 = time.perf_counter()
        out_ = land(COIN, omega, v0, 1.0, G, surface, contact=own)
        rates[name] = n / (time.perf_counter() - t0)
        arrays[f"{name} face"] = out_.face
        arrays[f"{name} status"] = out_.status
    np.savez(out, **arrays)
    print(json.dumps(rates))


def upright_decision(n: int, rounds: int = 3) -> None:
    """Tosses a second carried to rest by the contact ending with
    :func:`coinflight.core.contact_phase.upright_decided` on and off, and the faces they give.

    numba compiles a module's global as a constant and its on-disk cache ignores a changed
    global, so each setting runs in a child process of its own ("off": UPRIGHT_DECISION set to
    False before numba compiles, in its own numba cache directory); the rounds alternate the two
    settings, so that the ratio is taken over the same minutes (medians over the rounds). The
    faces of every toss are compared between the settings (the decision must not change any),
    and the statuses: identical but where the decision ended the coin (DECIDED_UPRIGHT with it,
    SETTLED_CONTACT without)."""
    import json
    import subprocess
    import sys
    import tempfile

    rates: dict[str, dict[str, list[float]]] = {"on": {}, "off": {}}
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ)
        for r in range(rounds):
            for setting in ("on", "off"):
                child_env = dict(env)
                if setting == "off":
                    child_env["NUMBA_CACHE_DIR"] = os.path.join(tmp, "numba-off")
                out = os.path.join(tmp, f"{setting}-{r}.npz")
                done = subprocess.run(
                    [sys.executable, __file__, "--upright-child", setting, str(n), out],
                    env=child_env,
                    capture_output=True,
                    text=True,
                    check=True,
                )
                line = done.stdout.strip().splitlines()[-1]
                for name, rate in json.loads(line).items():
                    rates[setting].setdefault(name, []).append(rate)
        on = np.load(os.path.join(tmp, "on-0.npz"))
        off = np.load(os.path.join(tmp, "off-0.npz"))
        print(
            f"{n:,} vigorous tosses, contact ending carried to rest, upright decision on/off, "
            f"{rounds} rounds alternated, medians; load {os.getloadavg()}"
        )
        for name in UPRIGHT_SURFACES:
            a, b = statistics.median(rates["on"][name]), statistics.median(rates["off"][name])
            faces = on[f"{name} face"], off[f"{name} face"]
            differ = int(np.count_nonzero(faces[0] != faces[1]))
            edges = int(np.count_nonzero(faces[1] == EDGE))
            decided = on[f"{name} status"] == Status.DECIDED_UPRIGHT
            same_status = bool(
                np.array_equal(as_undecided(on[f"{name} status"]), off[f"{name} status"])
            )
            print(
                f"  {name}: on {a:,.0f} tosses/s, off {b:,.0f} tosses/s (ratio {a / b:.2f}); "
                f"faces differing {differ} of {n} ({edges} on edge without the decision); "
                f"{int(decided.sum())} decided upright; statuses identical but those "
                f"{same_status}"
            )


def rounded_edges(n: int) -> None:
    """P(edge) of the contact ending over the rim's corner radius a (the coin's corner_radius)
    and the resistances, e = 0.5, μ = 0.3."""
    from coinflight.core import bounce

    omega, v0 = tosses(n)
    print(f"contact ending, {n:,} vigorous tosses per setting, e = 0.5, μ = 0.3: P(edge)")
    for resist in (1e-5, 1e-4, 1e-3):
        row = []
        surface = Surface("table", DROP, 0.5, 0.3, resist, resist, ending="contact")
        for a in (0.0, 0.3e-3, 0.6e-3, 0.9e-3):
            c = contact_record(COIN.with_corner_radius(a), surface, G)
            face = bounce.land(omega, v0, np.ones(n), c)[0]
            k = int(np.sum(face == EDGE))
            row.append(f"a = {a * 1e3:.1f} mm: {k / n:.4f} ({k})")
        print(f"  rolling = pivoting = {resist:.0e} m: " + ", ".join(row))


def contact_phase(n: int) -> None:
    """What the experimental contact phase (``ending="contact"``) decides, over the parameters
    nobody has measured."""
    contact_rates(n)
    rounded_edges(n)
    rng = np.random.default_rng(11)
    # The axial-spin toss: ωx 150-300, ωz = ±20 rad/s, 0.8 m drop, started heads up.
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), np.zeros(n), rng.choice([-20.0, 20.0], n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    print(f"axial-spin tosses (ωx 150-300, ωz ±20 rad/s, {DROP} m drop), {n:,} per setting:")
    for mu in (0.0, 0.1, 0.3, 1.0):
        for resist in (1e-5, 1e-4, 1e-3):
            surface = Surface("table", DROP, 0.5, mu, resist, resist, ending="contact")
            t0 = time.perf_counter()
            out = land(COIN, omega, v0, 1.0, G, surface)
            rate = n / (time.perf_counter() - t0)
            same = np.mean(out.face == HEADS)
            se = math.sqrt(same * (1 - same) / n)
            print(
                f"  e = 0.5, μ = {mu:.1f}, rolling = pivoting = {resist:.0e} m: P(same side) = "
                f"{same:.3f} ± {se:.3f}, edge {np.mean(out.face == EDGE):.4f}, contact phase "
                f"{np.mean(out.status == Status.SETTLED_CONTACT):.1%}, decided upright "
                f"{np.mean(out.status == Status.DECIDED_UPRIGHT):.1%}, unsettled "
                f"{np.mean(out.status == Status.UNSETTLED):.2%}, {rate:,.0f} tosses/s"
            )
    omega = np.column_stack([rng.uniform(150.0, 300.0, n), np.zeros(n), np.zeros(n)])
    print(f"planar tosses (ωx 150-300 only), {n:,} per setting: P(heads) − P(tails)")
    for e, mu in ((0.2, 0.1), (0.5, 0.3), (0.8, 1.0)):
        out = land(COIN, omega, v0, 1.0, G, Surface("table", DROP, e, mu, ending="contact"))
        h, t = np.mean(out.face == HEADS), np.mean(out.face == TAILS)
        se = math.sqrt((h + t - (h - t) ** 2) / n)
        print(f"  e = {e}, μ = {mu}: {h - t:+.4f} ± {se:.4f} (s.e.)")


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
    parser.add_argument("--contact", type=int, default=0, metavar="N")
    parser.add_argument("--contact-rates", type=int, default=0, metavar="N")
    parser.add_argument("--upright", type=int, default=0, metavar="N")
    parser.add_argument("--rigid-rates", type=int, default=0, metavar="N")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--upright-child", nargs=3, metavar=("SETTING", "N", "OUT"))
    parser.add_argument("--old-src", default=None, help="src folder of another coinflight")
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    if args.upright_child:
        setting, count, out = args.upright_child
        _upright_child(int(count), setting, out)
        return
    contact_only = args.contact and not (args.contact_rates or args.rigid_rates)
    if args.json and (args.upright or contact_only):
        print(
            "bench_bounce.py: --json records the default run, --contact-rates or --rigid-rates, "
            "not --upright or --contact",
            file=sys.stderr,
        )
        sys.exit(2)
    if args.upright:
        upright_decision(args.upright, args.rounds)
        return
    if contact_only:
        contact_phase(args.contact)
        return
    recorder = Recorder("bench_bounce")
    with recorder.text_to_stderr(args.json):
        figures = timed(args)
    if args.json:
        print(recorder.json(figures))


def timed(args: argparse.Namespace) -> dict[str, Any]:
    """The run of ``--contact-rates``, ``--rigid-rates`` or the default one; the figures of
    the record."""
    if args.contact_rates:
        return contact_rates(args.contact_rates, args.rounds, args.old_src)
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

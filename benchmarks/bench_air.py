"""Speed of tosses through air: the compiled integrator against the vacuum models.

    python benchmarks/bench_air.py                          # air vs vacuum + SciPy reference
    python benchmarks/bench_air.py --old-src /path/to/src   # + another implementation
    python benchmarks/bench_air.py --quick                  # about a minute
    python benchmarks/bench_air.py --quick --json           # the record as JSON
    python benchmarks/bench_air.py --accuracy 40 [--old-src DIR]   # times against DOP853
    python benchmarks/bench_air.py --profile 200            # where a landing's time goes
    python benchmarks/bench_air.py --ab 7 --old-src DIR     # one-thread A/B, 7 rounds

The tosses are those of ``bench_bounce.py`` (a US nickel, ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30)
rad/s, v0 ~ U(1.5, 3) m/s) in air: C_d = 1.17, ρ = 1.2 kg/m³, spin damping K (default 0). Rates
are tosses a second, all of numba's threads, the median of the repeats; the repeats of every
case are interleaved (one of each in turn), so that the machine's other load falls on all alike,
and each air case is given as a ratio to its vacuum model timed in the same rounds:

- hand catch (:func:`coinflight.outcomes.air.catch_with_drag`) against the closed-form hand
  catch (:data:`coinflight.outcomes.hand.HAND_CATCH`),
- table landing 0.8 m below launch (e = 0.5, μ = 0.3) to the first contact and carried to rest
  (the bounces, then the rigid 3-D ending; :func:`coinflight.outcomes.table.land` with and
  without drag); the landings carried to rest on the first ``--rest`` tosses (default 1,000,
  ``--quick`` 100: a few ms each), the other cases on ``--n`` (default 100,000, ``--quick``
  20,000),
- the air kernels in one thread, per second of CPU time (the machine's other load excluded),
- the SciPy reference (:func:`coinflight.core.numerical.air_catch`, DOP853 at rtol 1e-12, one
  toss at a time: the previous product path's method and tolerance) on the first tosses,
- with ``--old-src DIR``: another implementation (``coinflight`` imported from DIR in a
  subprocess with its own numba cache folder, after a few tosses of each to compile) on the
  same tosses and cases (with its default ending), one round of it in each round of these;
  e.g. ``--old-src /path/to/main/src`` for the before/after ratios.

The load average is printed before and after: absolute rates on a shared machine vary with it.

With ``--profile N`` only the shares of a landing carried to rest spent in its phases (first
flight, bounce flights, impacts, endings, lifts), timed by the processor's cycle counter around
each phase of a copy of :func:`coinflight.core.drag.land_one` in one thread (:func:`profile`),
``--repeats`` runs (median and range), with the drag of ``--drag`` and ``--spin-damping``; the
copy's impacts and endings are checked toss by toss against ``land_one`` itself. The shares
are of the timed phases (the graze steps, ``lowest_depth`` and ``split`` are not timed); the
cycle counter runs on while the thread is switched out, so on a loaded machine each phase
carries some of other processes' time (the printout gives the timed cycles against the CPU
time); the times a step are the phases' shares of the CPU time.

With ``--accuracy M`` only the times against DOP853 at rtol 1e-12 on the first M tosses are
printed (:func:`accuracy`): the catch, the first contact, a bounce flight from the state after
the reference's first impact, and the second contact; with ``--old-src`` the other
implementation's on the same tosses.

Target: the hand catch and the table's first contact through air ≥ 100,000 a second on 2 cores
(none for the landings carried to rest, which the rigid ending's cost sets: ``bench_bounce.py``).
``--json`` (the default run only) prints the record: the rates, the ratios and the provenance
(the text on stderr).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from typing import Any

import numpy as np

# bench_bounce.py's coin, table and tosses (the script's own folder is on the path)
from _record import Recorder
from bench_bounce import COIN, COIN_PRESET, SURFACE, G, tosses
from coinflight.core import numerical
from coinflight.core.outcome import Status
from coinflight.model.surface import Drag
from coinflight.outcomes.air import catch_with_drag, drag_model
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.outcomes.table import land

OLD = """
import json, sys, time
import numpy as np
from coinflight import Coin
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.air import catch_with_drag
from coinflight.outcomes.table import land
a = json.loads(sys.argv[1])
given = np.load(a["inputs"])
omega, v0 = given["omega"], given["v0"]
n, r = len(v0), a["rest"]
coin, g = Coin.preset(a["coin"]), a["g"]
drag = Drag(coefficient=a["cd"], spin_damping=a["k"])
surface = Surface("table", drop_height=a["drop"], restitution=a["e"], friction=a["mu"])
cases = {
    "hand": lambda p: catch_with_drag(coin, omega, v0, 1.0, g, drag, parallel=p),
    "table first contact": lambda p: land(
        coin, omega, v0, 1.0, g, surface, drag, max_bounces=0, parallel=p
    ),
    "table to rest": lambda p: land(coin, omega[:r], v0[:r], 1.0, g, surface, drag, parallel=p),
}
size = {"hand": n, "table first contact": n, "table to rest": r}
for p in (True, False):  # compile or load the cache
    catch_with_drag(coin, omega[:10], v0[:10], 1.0, g, drag, parallel=p)
    land(coin, omega[:10], v0[:10], 1.0, g, surface, drag, parallel=p)
out = {}
for k, f in cases.items():
    if a["cpu"]:
        t0 = time.process_time(); f(False); out[k] = size[k] / (time.process_time() - t0)
    else:
        t0 = time.perf_counter(); f(True); out[k] = size[k] / (time.perf_counter() - t0)
print(json.dumps(out))
"""


def _other(
    args: argparse.Namespace, n: int, rest: int, cache: str, *, cpu: bool
) -> dict[str, float]:
    """One round of the other implementation's cases (``--old-src``) in a subprocess, its numba
    cache in ``cache`` (not in its sources), on the first ``n`` of :func:`bench_bounce.tosses`
    (seed 2026, written to an .npz in ``cache``: one definition of the tosses; the landings
    carried to rest on the first ``rest`` of them): rates a second of wall time, or with ``cpu``
    of CPU time in one thread."""
    inputs = os.path.join(cache, f"tosses-{n}.npz")
    if not os.path.exists(inputs):
        omega, v0 = tosses(n)
        np.savez(inputs, omega=omega, v0=v0)
    payload = json.dumps(
        {
            "inputs": inputs,
            "coin": COIN_PRESET,
            "g": G,
            "drop": SURFACE.drop_height,
            "e": SURFACE.restitution,
            "mu": SURFACE.friction,
            "cd": args.drag,
            "k": args.spin_damping,
            "cpu": cpu,
            "rest": rest,
        }
    )
    env = dict(os.environ, PYTHONPATH=args.old_src, NUMBA_CACHE_DIR=cache)
    out = subprocess.run(
        [sys.executable, "-c", OLD, payload], env=env, capture_output=True, text=True, check=True
    )
    return dict(json.loads(out.stdout))


OLD_TIMES = """
import json, sys
import numpy as np
from coinflight import Coin
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.air import catch_with_drag
from coinflight.outcomes.table import land
a = json.loads(sys.argv[1])
omega, v0 = np.array(a["omega"]), np.array(a["v0"])
coin = Coin.preset("us-nickel")
drag = Drag(coefficient=a["cd"])
surface = Surface("table", drop_height=0.8, restitution=0.5, friction=0.3)
_, catch = catch_with_drag(coin, omega, v0, 1.0, 9.81, drag)
first = land(coin, omega, v0, 1.0, 9.81, surface, drag, max_bounces=0)
second = land(coin, omega, v0, 1.0, 9.81, surface, drag, max_bounces=1)
out = [list(catch), list(first.first_contact), list(second.settle_time)]
print(json.dumps([*out, [int(x) for x in second.status]]))
"""


def _reference_contact(f, y0, height, rising):  # type: ignore[no-untyped-def]
    """(time, state) of the coin's lowest point reaching the surface ``height`` below the
    centre's start by DOP853 at rtol 1e-12 (``f`` of :func:`coinflight.core.numerical.air_rhs`);
    ``rising``: not before the apex."""
    from scipy.integrate import solve_ivp

    from coinflight.core.impact import lowest_depth

    r, hh = COIN.radius, COIN.thickness / 2

    def gap(t, y):  # type: ignore[no-untyped-def]
        if t == 0.0 or (rising and y[5] > 0.0):
            return 1.0
        nz = float(numerical.quaternion_normal(y[9:13])[2])
        return height + y[2] - lowest_depth(nz, r, hh)

    gap.terminal = True  # type: ignore[attr-defined]
    gap.direction = -1  # type: ignore[attr-defined]
    sol = solve_ivp(f, (0, 60), y0, method="DOP853", rtol=1e-12, atol=1e-13, events=gap)
    return float(sol.t_events[0][0]), np.asarray(sol.y_events[0][0])


def accuracy(args: argparse.Namespace, m: int, drag: Drag) -> None:
    """Times against DOP853 at rtol 1e-12 on the first ``m`` tosses (no spin damping): the
    catch, the first contact with the table, and a bounce flight (from the state after the
    reference's first impact, :func:`coinflight.core.impact.impact`, to the next contact,
    :func:`coinflight.core.drag.bounce_flight`); with ``--old-src`` the other implementation's
    catch and first contact, and for both the second contact (first flight, impact, bounce
    flight) against the reference's. Median and largest absolute differences, s."""
    from scipy.spatial.transform import Rotation

    from coinflight.core import bounce
    from coinflight.core import drag as drag_kernels
    from coinflight.core.contact import Contact
    from coinflight.core.impact import impact, lowest_depth

    omega, v0 = tosses(m)
    air = drag_model(COIN, drag, G)
    i1, i3 = COIN.moments
    contact = Contact.build(
        radius=COIN.radius, thickness=COIN.thickness, mass=COIN.mass, i1=i1, i3=i3,
        restitution=SURFACE.restitution, friction=SURFACE.friction,
        drop_height=SURFACE.drop_height, g=G, rest_speed=bounce.REST_SPEED,
    )  # fmt: skip
    inertia = np.array([i1, i1, i3])
    f = numerical.air_rhs(
        COIN.mass, COIN.radius, COIN.thickness, inertia, G, air.drag_factor, 0.0, True
    )
    ref = {"catch": [], "first contact": [], "bounce flight": [], "second contact": []}
    got = {"catch": [], "first contact": [], "bounce flight": [], "second contact": []}
    _, catch = catch_with_drag(COIN, omega, v0, 1.0, G, drag)
    first = land(COIN, omega, v0, 1.0, G, SURFACE, drag, max_bounces=0)
    second = land(COIN, omega, v0, 1.0, G, SURFACE, drag, max_bounces=1)
    second_ref = np.full(m, np.nan)
    for k in range(m):
        ref["catch"].append(numerical.air_catch(f, omega[k], v0[k])[0])
        got["catch"].append(catch[k])
        y0 = np.concatenate([[0.0, 0.0, 0.0, 0.0, 0.0, v0[k]], omega[k], [0.0, 0.0, 0.0, 1.0]])
        tc, y = _reference_contact(f, y0, SURFACE.drop_height, True)
        ref["first contact"].append(tc)
        got["first contact"].append(first.first_contact[k])
        # The reference's first impact, then its bounce flight and the kernel's from there.
        rot = Rotation.from_quat(y[9:13])
        n = rot.apply([0.0, 0.0, 1.0])
        z = lowest_depth(float(n[2]), COIN.radius, COIN.thickness / 2)
        lm = rot.apply(inertia * y[6:9])
        v1, lm1, rebound = impact(
            tuple(y[3:6]), tuple(lm), tuple(n), COIN.radius, COIN.thickness / 2, COIN.mass,
            i1, i3, SURFACE.restitution, SURFACE.friction,
        )  # fmt: skip
        if drag_kernels.ending(v1, lm1, tuple(n), rebound, contact)[1] >= 0:
            continue  # settled at its first impact
        w1 = rot.inv().apply(np.array(lm1)) / inertia
        y1 = np.concatenate([[0.0, 0.0, 0.0], v1, w1, y[9:13]])
        tb, _ = _reference_contact(f, y1, z, False)
        ref["bounce flight"].append(tb)
        got["bounce flight"].append(
            drag_kernels.bounce_flight(z, v1, tuple(n), lm1, rebound, air, contact)[0]
        )
        if second.status[k] == int(Status.BOUNCE_LIMIT):
            second_ref[k] = tc + tb
            ref["second contact"].append(tc + tb)
            got["second contact"].append(second.settle_time[k])

    def line(name, a, b):  # type: ignore[no-untyped-def]
        d = np.abs(np.asarray(a) - np.asarray(b))
        return f"{name} ({d.size}): median {np.median(d):.2g} s, largest {np.max(d):.2g} s"

    print(f"  against DOP853 (rtol 1e-12), the first {m} tosses:")
    for name in ref:
        print("    " + line(name, got[name], ref[name]))
    if args.old_src:
        payload = json.dumps({"omega": omega.tolist(), "v0": v0.tolist(), "cd": drag.coefficient})
        env = dict(os.environ, PYTHONPATH=args.old_src)
        out = subprocess.run(
            [sys.executable, "-c", OLD_TIMES, payload],
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        old_catch, old_first, old_second, old_status = json.loads(out.stdout)
        keep = [
            k
            for k in range(m)
            if np.isfinite(second_ref[k]) and old_status[k] == int(Status.BOUNCE_LIMIT)
        ]
        print(f"  other implementation ({args.old_src}), same tosses:")
        print("    " + line("catch", old_catch, ref["catch"]))
        print("    " + line("first contact", old_first, ref["first contact"]))
        print("    " + line("second contact", [old_second[k] for k in keep], second_ref[keep]))


def profile(n: int, drag: Drag, runs: int) -> None:
    """Shares of the time of ``n`` landings carried to rest through air (one thread) in their
    phases, and the steps and impacts a toss: a copy of :func:`coinflight.core.drag.land_one`
    (its grazes and impacts as there) with the cycle counter (LLVM's ``readcyclecounter``) read
    around each phase, ``runs`` times (median and range printed). The copy's impacts and endings
    are checked against the real :func:`coinflight.core.drag.land_one` on the same tosses (an
    error if any toss differs). The shares are of the timed phases only (the graze steps,
    ``lowest_depth`` before an impact and ``split`` after it are not timed), and the cycle
    counter keeps running while the thread is switched out: on a loaded machine every phase
    includes some of other processes' time, in proportion to its own length."""
    from llvmlite import ir
    from numba import njit, types
    from numba.core import cgutils
    from numba.extending import intrinsic

    from coinflight.core import drag as d
    from coinflight.core.bounce import GRAZE_SKIP, MAX_IMPACTS
    from coinflight.core.impact import lowest_depth
    from coinflight.outcomes.table import contact_record

    unsettled = int(Status.UNSETTLED)

    @intrinsic
    def cycles(typingctx):  # type: ignore[no-untyped-def]
        def codegen(context, builder, signature, args):  # type: ignore[no-untyped-def]
            fnty = ir.FunctionType(ir.IntType(64), [])
            fn = cgutils.get_or_insert_function(builder.module, fnty, "llvm.readcyclecounter")
            return builder.call(fn, [])

        return types.uint64(), codegen

    @njit
    def now():  # type: ignore[no-untyped-def]
        return cycles()

    @njit
    def one(omega, launch_speed, air, c, acc):  # type: ignore[no-untyped-def]
        # acc: cycles of the first flight, bounce flights, impacts, endings, lifts; impacts,
        # steps of the first flight, of the bounce flights; bounce flights. Returns (impacts,
        # status) as land_one's.
        n, u, a0, b0 = d.launch_state(omega, 1.0, air)
        z, v, tr, tmin = c.drop_height, (0.0, 0.0, launch_speed), 0.0, 0.0
        rising, budget, impacts = True, d.MAX_STEPS, 0
        while impacts < MAX_IMPACTS:
            t0 = cycles()
            dt, z, v, n, u, tr, lm, speed, steps = d.next_contact(
                z, v, n, u, tr, a0, b0, tmin, rising, air, c, budget
            )
            k = 0 if impacts == 0 else 1
            acc[k] += cycles() - t0
            acc[6 + k] += steps
            acc[8] += k
            budget -= steps
            if dt < 0.0:
                return impacts, unsettled
            rising, tmin = False, 0.0
            if speed >= 0.0:
                z, v, n, u = d.step(z, v, n, u, tr, GRAZE_SKIP, a0, b0, air)
                tr += GRAZE_SKIP
                continue
            impacts += 1
            z = lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
            t0 = cycles()
            v, lm, rebound = d.impact(v, lm, n, c)
            t1 = cycles()
            status = d.ending(v, lm, n, rebound, c)[1]
            t2 = cycles()
            acc[2] += t1 - t0
            acc[3] += t2 - t1
            acc[5] += 1
            if status >= 0:
                return impacts, status
            a0, b0, u = d.split(lm, n)
            t0 = cycles()
            tmin, z, v, n, u, tr = d.lift(z, v, n, u, lm, a0, b0, rebound, air, c)
            acc[4] += cycles() - t0
        return impacts, unsettled

    @njit
    def run(omega, v0, air, c, acc, impacts, status):  # type: ignore[no-untyped-def]
        for k in range(omega.shape[0]):
            impacts[k], status[k] = one((omega[k, 0], omega[k, 1], omega[k, 2]), v0[k], air, c, acc)

    @njit
    def real(omega, v0, air, c, impacts, status):  # type: ignore[no-untyped-def]
        for k in range(omega.shape[0]):
            _, b, _, _, st = d.land_one(
                (omega[k, 0], omega[k, 1], omega[k, 2]), 1.0, v0[k], air, c, 1_000_000_000
            )
            impacts[k] = b + (0 if st == unsettled else 1)  # the impact that ended it
            status[k] = st

    omega, v0 = tosses(n)
    air = drag_model(COIN, drag, G)
    c = contact_record(COIN, SURFACE, G)
    acc = np.zeros(9, dtype=np.uint64)
    impacts, status = np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)
    run(omega[:10], v0[:10], air, c, acc, impacts[:10], status[:10])  # compile
    want_impacts, want_status = np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64)
    real(omega, v0, air, c, want_impacts, want_status)
    load = os.getloadavg()[0]
    shares, cpus, rates = [], [], []
    for _ in range(runs):
        acc[:] = 0
        c0, w0, t0 = now(), time.perf_counter(), time.process_time()
        run(omega, v0, air, c, acc, impacts, status)
        cpus.append(time.process_time() - t0)
        rates.append((now() - c0) / (time.perf_counter() - w0))  # cycles a wall second
        shares.append(acc[:5] / float(acc[:5].sum()))
    bad = np.flatnonzero((impacts != want_impacts) | (status != want_status))
    if bad.size:
        k = int(bad[0])
        sys.exit(
            f"profile: the copy of land_one differs from land_one on {bad.size} of {n} tosses "
            f"(toss {k}: {impacts[k]} impacts, status {status[k]}; land_one {want_impacts[k]}, "
            f"{want_status[k]})"
        )
    print(
        f"{n:,} landings carried to rest through air (C_d = {drag.coefficient:g}, K = "
        f"{drag.spin_damping:g} N m s), one thread, {runs} runs: "
        f"{statistics.median(cpus) / n * 1e6:.1f} µs of CPU a toss (median; "
        f"{min(cpus) / n * 1e6:.1f}-{max(cpus) / n * 1e6:.1f}); impacts and endings of every "
        f"toss as land_one's"
    )
    print("  shares of the timed phases (median, range over the runs):")
    for k, name in enumerate(["first flight", "bounce flights", "impacts", "endings", "lifts"]):
        col = [float(s[k]) for s in shares]
        print(f"    {name}: {statistics.median(col):.1%} ({min(col):.1%}-{max(col):.1%})")
    rate = statistics.median(rates)
    first_steps, bounce_steps, flights = (float(x) for x in acc[6:9])
    print(
        f"  a toss (last run): {acc[5] / n:.2f} impacts, {flights / n:.2f} bounce flights, "
        f"{first_steps / n:.1f} steps in the first flight, {bounce_steps / n:.1f} in the bounce "
        f"flights"
    )
    # The cycle counter runs on while the thread is switched out: the timed phases' cycles
    # against the CPU time show how much of them is other processes' time. The times a step are
    # the phase's share of the CPU time, on the assumption that it is spread alike.
    cpu_toss = cpus[-1] / n
    timed_toss = float(acc[:5].sum()) / rate / n
    first, bounce, impact_share = (float(shares[-1][k]) for k in range(3))
    print(
        f"  last run: the timed phases {timed_toss * 1e6:.1f} µs a toss by the cycle counter "
        f"({rate / 1e9:.2f} GHz against the wall clock), {cpu_toss * 1e6:.1f} µs of CPU in all; "
        f"as shares of the CPU time: {first * cpu_toss / first_steps * n * 1e9:.0f} ns a step "
        f"of the first flight, {bounce * cpu_toss / max(bounce_steps, 1.0) * n * 1e9:.0f} ns a "
        f"step of the bounce flights (with their evaluations of the gap's lower bound), "
        f"{impact_share * cpu_toss / max(float(acc[5]), 1.0) * n * 1e9:.0f} ns an impact"
    )
    ends = ", ".join(
        f"{Status(s).label} {np.mean(want_status == s):.1%}" for s in np.unique(want_status)
    )
    print(f"  endings: {ends}")
    print(f"  load average {load:.2f} before, {os.getloadavg()[0]:.2f} after")


def median_rate(fn, n: int, repeats: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return n / statistics.median(times)


def cpu_rate(fn, n: int) -> float:  # type: ignore[no-untyped-def]
    """Tosses per second of this process's CPU time (one call, after a warm-up)."""
    t0 = time.process_time()
    fn()
    return n / (time.process_time() - t0)


def ab(args: argparse.Namespace, n: int, rest: int, drag: Drag, rounds: int) -> None:
    """Interleaved A/B in one thread against ``--old-src``: in each of ``rounds`` rounds this
    implementation's three cases, then the other's (:func:`_other`, a subprocess), as tosses per
    CPU second of one thread (the machine's other load excluded as far as CPU time does), on
    ``n`` tosses (carried to rest: the first ``rest``); prints each case's ratio, this one /
    other, median and range over the rounds."""
    omega, v0 = tosses(n)
    cases = cases_in_air(omega, v0, drag, parallel=False, rest=rest)
    size = {"hand": n, "table first contact": n, "table to rest": min(rest, n)}
    catch_with_drag(COIN, omega[:10], v0[:10], 1.0, G, drag, parallel=False)  # compile
    land(COIN, omega[:10], v0[:10], 1.0, G, SURFACE, drag, parallel=False)
    load = os.getloadavg()[0]
    ratios: dict[str, list[float]] = {name: [] for name in cases}
    with tempfile.TemporaryDirectory() as cache:
        for _ in range(rounds):
            mine = {name: cpu_rate(fn, size[name]) for name, fn in cases.items()}
            other = _other(args, n, size["table to rest"], cache, cpu=True)
            for name in cases:
                ratios[name].append(mine[name] / other[name])
    print(
        f"interleaved A/B, one thread, {rounds} rounds of {n:,} tosses, this one / "
        f"{args.old_src} per CPU second (median, range):"
    )
    for name, r in ratios.items():
        print(f"  {name}: {statistics.median(r):.3f} ({min(r):.3f}-{max(r):.3f})")
    print(f"  load average {load:.2f} before, {os.getloadavg()[0]:.2f} after")


def cases_in_air(
    omega: np.ndarray,
    v0: np.ndarray,
    drag: Drag,
    parallel: bool = True,
    rest: int | None = None,
) -> dict[str, Callable[[], Any]]:
    """The timed cases through air on the tosses (ω, v0), all of numba's threads (one without
    ``parallel``): the hand catch, the table's first contact and the landing carried to rest
    (:data:`SURFACE`; on the first ``rest`` tosses, all when None); each a call of no
    arguments (also ``bench_targets.py``'s)."""
    p = parallel
    wr, sr = omega[:rest], v0[:rest]
    return {
        "hand": lambda: catch_with_drag(COIN, omega, v0, 1.0, G, drag, parallel=p),
        "table first contact": lambda: land(
            COIN, omega, v0, 1.0, G, SURFACE, drag, max_bounces=0, parallel=p
        ),
        "table to rest": lambda: land(COIN, wr, sr, 1.0, G, SURFACE, drag, parallel=p),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="fewer tosses")
    parser.add_argument("--n", type=int, default=None, help="tosses for the compiled kernels")
    parser.add_argument("--rest", type=int, default=None, help="of them carried to rest")
    parser.add_argument("--repeats", type=int, default=5, help="rounds (runs of --profile)")
    parser.add_argument("--reference", type=int, default=None, help="tosses for SciPy")
    parser.add_argument("--spin-damping", type=float, default=0.0, help="K, N m s")
    parser.add_argument("--drag", type=float, default=1.17, help="C_d")
    parser.add_argument("--old-src", default=None, help="src folder of another coinflight")
    parser.add_argument(
        "--accuracy", type=int, default=None, help="only: times against DOP853 on this many tosses"
    )
    parser.add_argument(
        "--profile", type=int, default=None, help="only: shares of the phases of this many landings"
    )
    parser.add_argument(
        "--ab",
        type=int,
        default=None,
        help="only: this many rounds of an interleaved one-thread A/B against --old-src",
    )
    parser.add_argument(
        "--json", action="store_true", help="print the record as JSON (the text to stderr)"
    )
    args = parser.parse_args()
    if args.json and (args.profile is not None or args.ab is not None or args.accuracy):
        print(
            "bench_air.py: --json records the default run only, not --profile, --ab or --accuracy",
            file=sys.stderr,
        )
        sys.exit(2)
    if args.ab is not None and not args.old_src:
        print("bench_air.py: --ab needs --old-src (the implementation to compare)", file=sys.stderr)
        sys.exit(2)
    for name, value in (
        ("--profile", args.profile),
        ("--repeats", args.repeats),
        ("--ab", args.ab),
        ("--n", args.n),
        ("--rest", args.rest),
    ):
        if value is not None and value < 1:  # one line, exit code 2
            print(f"bench_air.py: {name} must be a positive integer, got {value}", file=sys.stderr)
            sys.exit(2)
    n = args.n or (20_000 if args.quick else 100_000)
    rest = min(n, args.rest or (100 if args.quick else 1_000))
    m = args.reference or (10 if args.quick else 40)
    drag = Drag(coefficient=args.drag, spin_damping=args.spin_damping)
    if args.profile is not None:
        profile(args.profile, drag, args.repeats)
        return
    if args.ab is not None:
        ab(args, args.n or 10_000, args.rest or 100, drag, args.ab)
        return
    if args.accuracy:
        accuracy(args, args.accuracy, drag)
        return
    recorder = Recorder("bench_air")
    with recorder.text_to_stderr(args.json):
        figures = rates_in_air(args, n, rest, m, drag)
    if args.json:
        print(recorder.json(figures))


def rates_in_air(args: argparse.Namespace, n: int, rest: int, m: int, drag: Drag) -> dict[str, Any]:
    """The default run on ``n`` tosses (``rest`` of them carried to rest): the air cases against
    their vacuum models, one thread per CPU second, the SciPy reference on ``m``, with
    ``--old-src`` the other implementation; prints them and returns the figures of the
    record."""
    import numba

    omega, v0 = tosses(n)
    load_before = f"{os.getloadavg()[0]:.2f}"
    print(
        f"{n:,} tosses of a US nickel ({rest:,} carried to rest), C_d = {drag.coefficient:g}, "
        f"K = {drag.spin_damping:g} N m s, {numba.get_num_threads()} threads, {os.cpu_count()} "
        f"CPUs, median of {args.repeats}"
    )
    for parallel in (True, False):  # compile or load the cache
        catch_with_drag(COIN, omega[:10], v0[:10], 1.0, G, drag, parallel=parallel)
        land(COIN, omega[:10], v0[:10], 1.0, G, SURFACE, drag, parallel=parallel)
    flight = 2.0 * v0 / G
    air_cases = cases_in_air(omega, v0, drag, rest=rest)
    size = {"hand": n, "table first contact": n, "table to rest": rest}
    vacuum_cases = {
        "hand": lambda: HAND_CATCH.faces(COIN, omega, flight, 1.0, G),
        "table first contact": lambda: land(COIN, omega, v0, 1.0, G, SURFACE, max_bounces=0),
        "table to rest": lambda: land(COIN, omega[:rest], v0[:rest], 1.0, G, SURFACE),
    }
    for fn in [*vacuum_cases.values()]:  # compile or load the cache
        fn()
    cases = {("air", k): f for k, f in air_cases.items()}
    cases.update({("vacuum", k): f for k, f in vacuum_cases.items()})
    times: dict[tuple[str, str], list[float]] = {key: [] for key in cases}
    old_rates: dict[str, list[float]] = {name: [] for name in air_cases}
    with tempfile.TemporaryDirectory() as cache:
        for _ in range(args.repeats):
            for key, fn in cases.items():
                t0 = time.perf_counter()
                fn()
                times[key].append(time.perf_counter() - t0)
            if args.old_src:  # one round of the other implementation in each round of these
                for name, rate in _other(args, n, rest, cache, cpu=False).items():
                    old_rates[name].append(rate)
        old_cpu = _other(args, n, rest, cache, cpu=True) if args.old_src else {}
    rates = {key: size[key[1]] / statistics.median(ts) for key, ts in times.items()}
    figures: dict[str, Any] = {
        "tosses": n,
        "rest_tosses": rest,
        "repeats": args.repeats,
        "threads": numba.get_num_threads(),
        "drag_coefficient": drag.coefficient,
        "spin_damping_n_m_s": drag.spin_damping,
        "target_tosses_per_s": 100_000.0,
    }
    for name in air_cases:
        air_rate, vacuum_rate = rates[("air", name)], rates[("vacuum", name)]
        key = name.replace(" ", "_")
        figures[f"air_{key}_tosses_per_s"] = air_rate
        figures[f"vacuum_{key}_tosses_per_s"] = vacuum_rate
        print(
            f"  {name}: air {air_rate:,.0f} tosses/s, vacuum {vacuum_rate:,.0f} tosses/s, "
            f"air / vacuum = {air_rate / vacuum_rate:.3f}"
        )
    # On a shared machine the wall clock counts the time other processes hold the cores: the
    # serial kernels' CPU time gives the rate of one core (times the cores for a quiet machine).
    serial = cases_in_air(omega, v0, drag, parallel=False, rest=rest)
    cpu = {name: cpu_rate(fn, size[name]) for name, fn in serial.items()}
    for name, rate in cpu.items():
        figures[f"air_{name.replace(' ', '_')}_one_thread_tosses_per_cpu_s"] = rate
        print(f"  air, {name}, one thread: {rate:,.0f} tosses per CPU second")
    air = drag_model(COIN, drag, G)
    i1, i3 = COIN.moments
    f = numerical.air_rhs(
        COIN.mass, COIN.radius, COIN.thickness, (i1, i1, i3), G, air.drag_factor, air.spin_damping
    )
    scipy_rate = median_rate(
        lambda: [numerical.air_catch(f, omega[k], v0[k]) for k in range(m)], m, 1
    )
    figures["scipy_reference_tosses"] = m
    figures["scipy_reference_hand_tosses_per_s"] = scipy_rate
    print(
        f"  SciPy DOP853 reference, hand ({m} tosses): {scipy_rate:,.2f} tosses/s; "
        f"compiled / SciPy = {rates[('air', 'hand')] / scipy_rate:,.0f}"
    )
    if args.old_src:
        print(f"  other implementation ({args.old_src}), same tosses, in the same rounds:")
        for name in air_cases:
            other = statistics.median(old_rates[name])
            key = name.replace(" ", "_")
            figures[f"other_{key}_tosses_per_s"] = other
            figures[f"other_{key}_one_thread_tosses_per_cpu_s"] = old_cpu[name]
            print(
                f"    {name}: {other:,.0f} tosses/s (this one / other = "
                f"{rates[('air', name)] / other:.2f}); one thread {old_cpu[name]:,.0f} per CPU "
                f"second (this one / other = {cpu[name] / old_cpu[name]:.2f})"
            )
    print(f"  load average {load_before} before, {os.getloadavg()[0]:.2f} after")
    return figures


if __name__ == "__main__":
    main()

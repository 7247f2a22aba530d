"""How fast can the contact phase soundly be? Its measured routes combined on the same tosses.

    python benchmarks/bench_ceiling.py [N] [--seed S] [--rounds R] [--rate L] [--chunk DT]
        [--floor-budget STEPS] [--settings 0,1,2]

Issue 11 asks for 50,000 landings a second carried to rest on 2 cores. The routes measured
one at a time before (``bench_predictors.py``, ``bench_tolerance.py``, ``bench_contact.py``,
``bench_rigid.py``) are measured here **together, on the same handed tosses**: the N vigorous
nickel tosses of ``bench_bounce.tosses(N, S)`` (ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30) rad/s,
v0 ~ U(1.5, 3) m/s, 0.8 m drop, heads up) on the surfaces of ``bench_tolerance.SETTINGS`` (e 0.5
μ 0.3; e 0.5 μ 0.6; each toss its own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6) from
``bench_bounce.own_rates``, seed 7 whatever S; ``bench_tolerance.records``), resistances
ℓ_r = ℓ_p = 1e-4 m (the surface's). Each toss's bounces run once
(``bench_contact.handoff``); a toss handed to the contact phase is then carried by
:func:`coinflight.core.contact_phase.advance` (``bench_tolerance.carry``: one thread, CPU time
per toss) as:

1. **shipped**: RTOL 1e-7, the upright decision on (what ``land`` does);
2. **RTOL 1e-5**: the same with the looser step tolerance;
3. **oracle**: stopped at the toss's last well change (or at the upright decision, or by the
   energy test, whichever first), at 1e-7 and at 1e-5. The last well change comes from a
   full run's record (``bench_predictors.carry`` at that tolerance: the toss carried on to
   rest without the upright decision in ``--chunk`` pieces, its well after each;
   ``bench_predictors.last_well_change``), the first chunk end after which the coin is never
   outside the well it ends in: the best any sound "cannot leave its well" rule can do;
4. **hops**: the steps and simulated time spent off the table (:func:`contact_mode`, from
   ``advance``'s ``stats``) in each variant. Hops flown in closed form would remove them; counted
   as removed at zero cost (:func:`hop_factor`), an upper bound of that route's gain;
5. **the steps against the motion itself**, at 1e-7 up to the oracle's stop: the rotation
   ∫|ω| dt (:func:`rotation`, the trapezoid rule on the states after each accepted step), its
   share in hops, and the contact episodes (touchdowns, :func:`episodes`) of each toss; the
   steps an integrator would need at the shipped stepper's own caps, min(:data:`MAX_STEP` = 1
   ms, π/8 / |ω|) a step (the 1 ms cap binds: π/8 only above 392.7 rad/s, which these tosses
   never reach), all and with the hops flown in closed form (:func:`caps`); the steps of **an
   ideal integrator unconstrained by MAX_STEP** turning the coin by π/8 a step
   (:data:`STEP_TURN`), all and with the hops in closed form; and the share of steps held
   (shorter than a tenth of their cap: held by the contact's stiffness or the tolerance, not
   the rotation). **Estimates, not proofs**: they assume that a step's accuracy is set by its
   caps, not by the contact's stiffness, the impacts' few-millisecond pulses or the friction's
   stick-slip. Also printed: the steps at the median step's turn (:func:`weighted_median` of
   |ω| h): ∫|ω| dt over that angle, which equals the shipped phase's steps over the oracle's ×
   median/mean turn, the oracle's factor times a skew of the turn distribution, **not a
   floor** (for long rollers sampled every k > 1 steps, a median of stretch means).

The states after each step are those of the shipped run itself: ``advance`` called from the
handed state with ``max_steps`` k, 2k, 3k, ... (a call reproduces the first k steps of one call
to the bit; no restart), k = 1 while the toss's steps N keep the cost N²/2 within
``--floor-budget`` steps, else k = ceil(N² / (2 budget)) (then a segment's turn is its mean
turn per step, and two hops within one segment count as one touchdown).

Timings: ``--rounds`` rounds, the four carried variants (and the bounces of all N tosses) each
timed once a round, their order rotated between rounds; the medians over the rounds of each
variant's total CPU time over the handed tosses. The factors are ratios of those totals (the
rate of landings is set by the total, not by the median toss). The contact phase's factor F
enters the landings through the bounces it leaves alone: a landing's CPU is B + P (B the
bounces of all tosses, P the phase of the handed ones), so the landings run
(B + P) / (B + P/F) times faster (:func:`landing_factor`, Amdahl's law). The landings a second
on 2 cores: ``--rate`` (default 2,923, e 0.5 μ 0.3, ``python benchmarks/bench_bounce.py
--contact-rates 300``, quiet, 2026-11-24 07:15 UTC, load 0.8), scaled to the other settings by
their one-thread CPU per landing, B + P, measured here (:func:`combined`).

The **combined ceiling**: the oracle at RTOL 1e-5 (measured directly, not a product) times
the hops' bound at equal step price, through the bounces. Beside it, as a stated hypothetical
only, the rigid contact's accepted steps a simulated second (``core/rigid_contact.py``,
"Speed": 1,915 against 3,016 on the one-rim stretches, :data:`RIGID_STEPS`) taken at the
compliant step's price, which they do not have (a rigid step is ~1.7× dearer: 0.73× as fast as
measured).

Measured 2026-11-24, 07:35:56-07:42:55 UTC (416 s wall, load 8.5 before, 5.9 after; the
project machine, 2 CPUs AMD EPYC shared with four other sessions; CPU times in one thread, so
the load enters the ratios little): ``python benchmarks/bench_ceiling.py 600`` (seed 7; 427,
423, 420 of 600 handed at e 0.5 μ 0.3, e 0.5 μ 0.6, own e, μ: the tosses and hand-offs of
``bench_predictors.py 600 --seed 7``). Per handed toss (mean CPU, median in brackets), and the
factor over the shipped phase:

====================  ===================  ===================  ===================
variant               e 0.5, μ 0.3         e 0.5, μ 0.6         own e, μ
====================  ===================  ===================  ===================
shipped (1e-7)        0.922 ms (0.646)     1.196 ms (1.040)     1.044 ms (0.727)
RTOL 1e-5             2.00×                1.57×                1.93×
oracle at 1e-7        1.88×                1.68×                2.04×
oracle at 1e-5        3.71× (product       2.78× (2.64×)        3.83× (3.93×)
                      of the two 3.77×)
hops in it            45.0 % of steps,     31.0 %, 50.5 %       33.0 %, 41.9 %
                      52.8 % of the time
hops at no cost       1.82×                1.45×                1.49×
combined phase        6.74×                4.03×                5.72×
landings (Amdahl)     5.66×                3.73×                4.90×
today, 2 cores        2,923/s              2,291/s              2,618/s
**ceiling**           **16,548/s**         **8,552/s**          **12,816/s**
50,000 missed by      3.0×                 5.8×                 3.9×
rigid steps (hyp.)    23,519/s             12,749/s             18,336/s
====================  ===================  ===================  ===================

A 300-toss run (``bench_ceiling.py 300``, other tosses: the draws depend on N; 07:21-07:27
UTC, load 4.1-8.6) gave 14,177, 7,907, 11,121 a second (3.5×, 6.3×, 4.5× short), the combined
phase 5.54×, 3.79×, 4.98×: the spread of the toss sample.

Cross-checks: the oracle at 1e-7 agrees with ``bench_predictors.py 600 --seed 7``'s, counted
there in steps (1.92×, 1.59×, 2.04×), and RTOL 1e-5 with ``bench_tolerance.py``'s 1.7-1.95×
(medians there, seed 2026). The rate of 2,923 a second was measured on ``bench_bounce``'s
seed-2026 tosses; here a landing costs 0.679 ms of CPU in one thread at e 0.5 μ 0.3 (1,472
a CPU second, against 1,399 measured on those tosses, last session's closing note): the same
within 5 %.

The oracle and the looser tolerance combine as a product (3.71× measured against 3.77×, 2.78×
against 2.64×, 3.83× against 3.93×): their savings are separate (the tolerance makes each
stretch cheaper, the oracle cuts the stretch after the last well change). Hops take a larger
share of what the oracle leaves (31-45 % of the steps at 1e-5; the hop steps left after the
oracle at 1e-5 are 13-19 % of the shipped phase's steps),
so closed-form flight is worth more after it. The bounces, which none of these routes touch,
are 2.6-3.6 % of a landing's CPU: with the contact phase at no cost at all a landing would run
73,000-88,000 a second (the ceiling of every route that leaves the bounces as they are).

The motion (1e-7, up to the oracle's stop): a handed toss turns the coin by a median 3.3,
8.0, 4.5 rad (means 21.7, 20.9, 18.8: a few long rollers) in a median 1 contact episode (means
1.8, 2.0, 1.7), ~235-315 steps an episode; its steps turn the coin a median 23.6, 12.9, 20.3
mrad, a mean 50.0, 33.1, 42.4 mrad (the hops' long steps turn it most). The steps at the
median step's turn, 0.89×, 0.62×, 0.96× the shipped phase's, are the oracle's factor × the
median/mean turn (1.886 × 23.6/50.0, 1.59 × 12.9/33.1, 2.005 × 20.3/42.4): a skew of the turn
distribution, which says nothing of what a step control could gain.

The steps against the stepper's caps (printed since the review; ``python
benchmarks/bench_ceiling.py 300``, seed 7, 2026-11-24 08:02-08:06 UTC, load 2.1 before, 4.5
after; 206, 205, 221 of 300 handed; its ceiling 14,197, 8,075, 11,594 a second, as the earlier
300-toss run): hops carry 67 %, 73 %, 62 % of the rotation to the oracle's stop. At the
stepper's own coarsest step (the 1 ms cap binds) the steps to the stop would be 3.4×, 4.1×,
3.8× fewer than the shipped phase's (9,200, 8,700, 9,100 landings a second at today's step
price: no more than the measured combination), 6.3×, 8.3×, 6.5× with the hops in closed form.
An ideal integrator unconstrained by MAX_STEP, π/8 a step: 13.3×, 19.9×, 16.2× (28,100,
31,100, 28,200 a second); with the hops in closed form 40.4×, 73.2×, 42.2× (**53,300, 60,900,
46,600 a second**: about the target). The shipped steps are mostly not far below the cap:
10 %, 23 %, 11 % of the steps to the stop (13 %, 29 %, 14 % of those in contact) are shorter
than a tenth of it.

**Conclusion**: on these tosses, at ℓ_r = ℓ_p = 1e-4 m, 50,000 landings a second is not
reachable by the measured routes: the best sound rule (the last-well-change oracle, which no
real rule beats) with RTOL 1e-5 and hops flown at no cost gives 8,600-16,500 a second, 3.0-5.8×
short; the rigid contact's fewer steps at the compliant step's price (a hypothetical: it is
1.7× dearer) 12,700-23,500, 2.1-3.9× short. Steps at the stepper's own 1 ms cap, stopped at the
oracle, give no more: ~9,000 a second, ~14,400-16,100 with the hops in closed form (6.3-8.3×
fewer steps; through Amdahl by hand, the 300-toss run's shares).
50,000 would need contact steps turning the coin by ~π/8 (several times longer than the 1 ms
cap, and than the stiffness-limited explicit steps or the rigid contact's measured
accuracy-limited steps at RTOL 1e-7), plus the hops in closed form, plus the oracle, at
today's step price: an integrator held neither by the contact's stiffness nor by the
tolerance at the rotation's scale, none in view. Or a step 3-6× cheaper on top of the measured
routes (none in view: the step is ~1 μs, its derivative six ~126 ns evaluations), or a
predictor naming the final well while the coin can still leave it (``bench_predictors.py``'s
"first in final well", 9-24×: a prediction, not a bound), or a revised target. Caveats: the oracle's
stop comes from a chunked run whose trajectory parts from the timed one's at the rounding level,
so the timed run stopped there is in another well than carried on for 9, 3, 5 tosses at 1e-7
and 18, 20, 16 at 1e-5 (of ~420): those stops are early, the oracle's factors slightly
optimistic; RTOL 1e-5 changes 11, 16, 8 faces of the shipped phase's (1.9-3.8 %, as
``bench_tolerance.py`` found; a team decision); the hops' bound counts a hop's step at the
mean step's price (a flight step is cheaper, so it is an upper bound) and ignores what a
touchdown after a closed-form flight would cost; every landings figure is an upper estimate
in the same way: the Amdahl scaling leaves out ``land``'s own overhead and the batch's and
threads' (outside :func:`bounce_cpu`), whose share grows as the phase gets cheaper; at ℓ 1e-5
m (not run here) the oracle alone was 14.6-61× in steps (``bench_predictors.py``), the upright
rollers' time, and the shipped phase slower.
"""

from __future__ import annotations

import os

os.environ.setdefault("NUMBA_NUM_THREADS", "1")  # before numba is imported: one thread

import argparse
import math
import statistics
import time
from collections.abc import Sequence
from typing import Any

import numpy as np

import bench_predictors
import bench_tolerance
from coinflight.core import bounce
from coinflight.core import contact_phase as cp
from coinflight.core.impact import angular_velocity

FREE = cp.MODES.index("free")
"""The index of a hop (off the table) among :data:`coinflight.core.contact_phase.MODES`."""
RIGID_STEPS = 3_016 / 1_915
"""Compliant over rigid accepted steps a simulated second on the same one-rim stretches
(``python benchmarks/bench_rigid.py 300 --rounds 3``, 2026-11-24 03:39 UTC, load 6.2;
``core/rigid_contact.py``, "Speed"): the rigid contact's gain were its step as cheap as the
compliant one (it is ~1.7× dearer: 0.73× as fast, measured)."""
TARGET = 50_000.0
"""Issue 11's landings a second carried to rest on 2 cores."""
RATE = 2_923.0
"""Landings a second on 2 cores with the contact ending, e 0.5 μ 0.3 (``python
benchmarks/bench_bounce.py --contact-rates 300``, quiet, 2026-11-24 07:15 UTC, load 0.8)."""
STEP_TURN = math.pi / 8.0
"""The turn cap of the shipped stepper, rad: ``advance`` caps a step at min(:data:`MAX_STEP`,
π/8 / |ω|), so π/8 binds only above π/8 / 1 ms = 392.7 rad/s, which these tosses (ωx ≤ 300
rad/s) never reach. Steps turning the coin by π/8 are those of **an ideal integrator
unconstrained by MAX_STEP**, not the stepper's coarsest (that is the 1 ms cap, :func:`caps`)."""
MAX_STEP = cp.MAX_STEP
"""The shipped stepper's longest step, s (:data:`coinflight.core.contact_phase.MAX_STEP`)."""
HELD = 0.1
"""A step is "held" (by the contact's stiffness or the tolerance, not by the rotation) when it is
shorter than this share of its cap min(MAX_STEP, π/8 / |ω|) (:func:`caps`)."""
VARIANTS = ("shipped 1e-7", "rtol 1e-5", "oracle 1e-7", "oracle 1e-5")
"""The carried variants, in their first round's order."""


def rotation(times: np.ndarray, speeds: np.ndarray) -> float:
    """∫|ω| dt, rad, by the trapezoid rule over the samples (``times`` increasing, s; ``speeds``
    |ω| there, rad/s): exact for |ω| linear between samples (constant: |ω| T)."""
    t = np.asarray(times, dtype=float)
    w = np.asarray(speeds, dtype=float)
    if len(t) < 2:
        return 0.0
    return float(np.sum(0.5 * (w[1:] + w[:-1]) * np.diff(t)))


def segment_turns(times: np.ndarray, speeds: np.ndarray) -> np.ndarray:
    """The angle turned in each interval between consecutive samples (trapezoid), rad."""
    t = np.asarray(times, dtype=float)
    w = np.asarray(speeds, dtype=float)
    return 0.5 * (w[1:] + w[:-1]) * np.diff(t)


def episodes(modes: Sequence[int], hopped: Sequence[bool]) -> int:
    """Contact episodes (touchdowns) of a sampled run: ``modes`` the
    :func:`~coinflight.core.contact_phase.contact_mode` at each sample (the first the handed
    state), ``hopped[i]`` whether any step between samples i and i + 1 was a hop (one shorter
    than ``modes``). An episode starts at a first sample in contact, at each sample in contact
    after one off the table, and once for a stretch between two samples in contact with a hop
    inside it (a lower bound when stretches hold more than one step: two hops in one count
    once)."""
    if len(modes) == 0:
        return 0
    count = int(modes[0] != FREE)
    for i in range(1, len(modes)):
        if modes[i] == FREE:
            continue
        if modes[i - 1] == FREE or hopped[i - 1]:
            count += 1
    return count


def weighted_median(values: np.ndarray, weights: np.ndarray) -> float:
    """The median of ``values`` each counted ``weights`` times (the lower median for an even
    total, as the value at the ⌈W/2⌉-th place); NaN when nothing is counted."""
    v = np.asarray(values, dtype=float)
    w = np.asarray(weights, dtype=float)
    keep = w > 0
    if not keep.any():
        return math.nan
    order = np.argsort(v[keep])
    v, cum = v[keep][order], np.cumsum(w[keep][order])
    return float(v[np.searchsorted(cum, 0.5 * cum[-1])])


def caps(dt: np.ndarray, turns: np.ndarray, counts: np.ndarray, free: np.ndarray) -> dict:
    """The steps an ideal integrator would need on a sampled run, from each stretch between
    samples: its simulated time ``dt`` (s), turn ``turns`` (rad), accepted steps ``counts``
    and time off the table ``free`` (s; its share of ``dt`` splits the stretch between hops
    and contact). Returns (sums over the stretches):

    - ``"rot_hop"``, ``"rot_contact"``: the rotation in hops and in contact, rad;
    - ``"cap"``: steps at the shipped stepper's own caps, max(turn / (π/8), dt / MAX_STEP) a
      stretch (the 1 ms cap binds wherever |ω| < 392.7 rad/s), ``"cap_contact"`` the same in
      contact only (hops flown in closed form);
    - ``"turn"``, ``"turn_contact"``: steps turning the coin by π/8 each, unconstrained by
      MAX_STEP (:data:`STEP_TURN`), all and in contact only;
    - ``"held"``, ``"held_contact"``: accepted steps shorter than :data:`HELD` of their cap
      min(MAX_STEP, π/8 / |ω|) (|ω| the stretch's mean, dt / counts its mean step), all and in
      contact.

    A stretch of k > 1 steps counts as one of its mean step (max of sums ≤ sum of maxes: the
    cap counts are then slightly low)."""
    dt = np.asarray(dt, dtype=float)
    turns = np.asarray(turns, dtype=float)
    counts = np.asarray(counts, dtype=float)
    hop = np.clip(np.asarray(free, dtype=float) / np.where(dt > 0, dt, 1.0), 0.0, 1.0)
    need = np.maximum(turns / STEP_TURN, dt / MAX_STEP)
    w = turns / np.where(dt > 0, dt, 1.0)
    cap = np.minimum(MAX_STEP, STEP_TURN / np.maximum(w, 1e-300))
    held = counts * (dt / np.maximum(counts, 1.0) < HELD * cap)
    return {
        "rot_hop": float(np.sum(turns * hop)),
        "rot_contact": float(np.sum(turns * (1.0 - hop))),
        "cap": float(np.sum(need)),
        "cap_contact": float(np.sum(need * (1.0 - hop))),
        "turn": float(np.sum(turns) / STEP_TURN),
        "turn_contact": float(np.sum(turns * (1.0 - hop)) / STEP_TURN),
        "held": float(np.sum(held)),
        "held_contact": float(np.sum(held * (1.0 - hop))),
    }


def hop_factor(stats: np.ndarray) -> float:
    """The contact phase's speed-up if its hops cost nothing: all steps over the steps not off
    the table (``stats`` rows per mode of :data:`~coinflight.core.contact_phase.MODES`, columns
    (time, steps), summed over tosses), at equal step price (an upper bound: a hop's step is the
    cheapest, its derivative has no contact)."""
    steps = float(np.sum(stats[: len(cp.MODES), 1]))
    left = steps - float(stats[FREE, 1])
    return steps / left if left > 0 else math.inf


def landing_factor(bounces: float, phase: float, factor: float) -> float:
    """How many times faster a landing gets when its contact phase's CPU ``phase`` gets
    ``factor`` times cheaper and its bounces' CPU ``bounces`` not (Amdahl's law,
    (B + P) / (B + P/F))."""
    return (bounces + phase) / (bounces + phase / factor)


def combined(
    rate: float, bounces: float, phase: float, factors: Sequence[float]
) -> tuple[float, float]:
    """(the contact phase's factor, the landings a second): ``rate`` landings a second with
    the phase made the product of ``factors`` cheaper, through :func:`landing_factor`."""
    f = float(np.prod(factors))
    return f, rate * landing_factor(bounces, phase, f)


def bounce_cpu(cs: list[Any], omega: np.ndarray, v0: np.ndarray) -> float:
    """CPU s of the bounces of all tosses up to their end or hand-off (what a landing spends
    outside the contact phase, but for ``land``'s own overhead)."""
    t0 = time.process_time()
    for k in range(len(cs)):
        bounce.bounce_loop(
            (omega[k, 0], omega[k, 1], omega[k, 2]), 1.0, v0[k], cs[k], bounce.MAX_IMPACTS
        )
    return time.process_time() - t0


def mode_stats(
    states: np.ndarray, cs: list[Any], handed: np.ndarray, rtol: float, durations: np.ndarray
) -> np.ndarray:
    """Time and steps per mode (``advance``'s ``stats``, summed over the handed tosses) of the
    run :func:`bench_tolerance.carry` times (untimed here: the stats cost a little)."""
    total = np.zeros((len(cp.MODES), 2))
    for k in np.flatnonzero(handed):
        stats = np.zeros((len(cp.MODES), 2))
        cp.advance(
            states[k].copy(),
            float(durations[k]),
            cs[k],
            settle_check=True,
            decide=cp.UPRIGHT_DECISION,
            stats=stats,
            rtol=rtol,
        )
        total += stats
    return total


def trace(y0: np.ndarray, c: Any, duration: float, steps: int, budget: float) -> dict:  # type: ignore[no-untyped-def]
    """The first ``steps`` accepted steps of the shipped run (RTOL) of the handed state ``y0``
    (for at most ``duration`` s), sampled after every k-th step (module notes): its rotation
    ∫|ω| dt, contact episodes, and the turn of each sampled stretch with its steps. The calls
    carry the coin on past the upright decision (``decide=False``; the decision only stops a
    run, and its test depends on the step limit, which the sampling changes), so ``steps``
    (those of the timed run) is where the trace ends."""
    k = max(1, math.ceil(steps * steps / (2.0 * budget)))
    times, speeds, modes, hopped, counts = [0.0], [], [cp.contact_mode(y0, c)], [], []
    free_time = [0.0]  # time off the table up to each sample

    def speed(y: np.ndarray) -> float:
        w = angular_velocity((y[7], y[8], y[9]), (y[4], y[5], y[6]), c.i1, c.i3)
        return math.sqrt(w[0] ** 2 + w[1] ** 2 + w[2] ** 2)

    speeds.append(speed(y0))
    done, free = 0, 0.0
    while done < steps:
        y = y0.copy()
        stats = np.zeros((len(cp.MODES), 2))
        limit = min(done + k, steps)
        t, taken, ended = cp.advance(
            y, duration, c, settle_check=True, max_steps=limit, stats=stats
        )
        short = taken < limit  # stopped before its step limit: settled or out of time
        if taken > done:
            times.append(t)
            speeds.append(speed(y))
            modes.append(cp.contact_mode(y, c))
            hopped.append(stats[FREE, 1] > free)
            counts.append(taken - done)
            free_time.append(float(stats[FREE, 0]))
            done, free = taken, float(stats[FREE, 1])
        if ended or short or t >= duration:
            break
    turns = segment_turns(np.array(times), np.array(speeds))
    count = np.array(counts, dtype=float)
    return {
        "caps": caps(np.diff(times), turns, count, np.diff(free_time)),
        "rotation": rotation(np.array(times), np.array(speeds)),
        "episodes": episodes(modes, hopped),
        "turn": turns / np.maximum(count, 1.0),
        "count": count,
        "steps": done,
        "stride": k,
        "time": times[-1],
    }


def setting_run(args: argparse.Namespace, name: str, setting: Any) -> dict:  # type: ignore[no-untyped-def]
    """All measurements of one setting (module notes); prints them and returns the totals."""
    import bench_bounce

    n, seed = args.n, args.seed
    omega, v0 = bench_bounce.tosses(n, seed)
    cs = bench_tolerance.records(n, setting)
    states, handed, base_face, base_status = bench_tolerance.handoffs(cs, omega, v0)
    idx = np.flatnonzero(handed)
    m = len(idx)
    print(f"\n{name}: {n} tosses (seed {seed}), {m} handed; load {os.getloadavg()[0]:.2f}")
    if m == 0:
        return {}
    first = int(idx[0])
    for r in (1e-7, 1e-5):  # compile or load the caches
        cp.advance(states[first].copy(), 1e-3, cs[first], settle_check=True, rtol=r)
    # The last well change of each handed toss at each tolerance, from a full chunked record.
    w0 = time.perf_counter()
    oracle = {r: np.full(n, math.inf) for r in (1e-7, 1e-5)}
    unsettled = {}
    for r in oracle:
        bad = 0
        for k in idx:
            row = bench_predictors.carry(states[k].copy(), cs[k], args.chunk, rtol=r)
            oracle[r][k] = row["oracle"][0]
            bad += not row["settled"]
        unsettled[r] = bad
    print(
        f"  oracle records ({args.chunk * 1e3:g} ms chunks, no upright decision, carried to "
        f"rest): {time.perf_counter() - w0:.0f} s wall; unsettled {unsettled[1e-7]} at 1e-7, "
        f"{unsettled[1e-5]} at 1e-5"
    )
    inf = np.full(n, math.inf)
    plans = {
        "shipped 1e-7": (1e-7, inf),
        "rtol 1e-5": (1e-5, inf),
        "oracle 1e-7": (1e-7, oracle[1e-7]),
        "oracle 1e-5": (1e-5, oracle[1e-5]),
    }
    cpu: dict[str, list[float]] = {v: [] for v in (*VARIANTS, "bounces")}
    runs: dict[str, Any] = {}
    order = [*VARIANTS, "bounces"]
    for rnd in range(args.rounds):
        for v in order[rnd % len(order) :] + order[: rnd % len(order)]:
            if v == "bounces":
                cpu[v].append(bounce_cpu(cs, omega, v0))
                continue
            r, durations = plans[v]
            run = bench_tolerance.carry(
                states, cs, handed, base_face, base_status, r, durations=durations
            )
            cpu[v].append(float(run.cpu[handed].sum()))
            runs.setdefault(v, run)
    med = {v: statistics.median(ts) for v, ts in cpu.items()}
    stats = {v: mode_stats(states, cs, handed, *plans[v]) for v in VARIANTS}
    shipped = runs["shipped 1e-7"]
    print(
        f"  CPU (one thread, medians of {args.rounds} rounds): bounces of all {n} "
        f"{med['bounces'] * 1e3:.1f} ms; the contact phase per handed toss, mean (median):"
    )
    for v in VARIANTS:
        run, st = runs[v], stats[v]
        steps = st[:, 1].sum()
        differ = int(np.count_nonzero(run.face[handed] != shipped.face[handed]))
        same_rtol = runs["rtol 1e-5" if v.endswith("1e-5") else "shipped 1e-7"]
        own = int(np.count_nonzero(run.face[handed] != same_rtol.face[handed]))
        print(
            f"    {v:13s}: {med[v] / m * 1e3:.3f} ms ({np.median(run.cpu[handed]) * 1e3:.3f}), "
            f"{med['shipped 1e-7'] / med[v]:.2f}× the shipped; steps {steps:,.0f} "
            f"(median {np.median(run.steps[handed]):,.0f}), simulated {st[:, 0].sum():.1f} s; "
            f"hops {st[FREE, 1] / steps:.1%} of the steps, {st[FREE, 0] / st[:, 0].sum():.1%} "
            f"of the time (bound {hop_factor(st):.2f}×); faces differing from the shipped "
            f"{differ} of {m}, from the same tolerance carried on {own}"
        )
    # The floor of the motion itself, at 1e-7 up to the oracle's stop.
    w0 = time.perf_counter()
    oracle_run = runs["oracle 1e-7"]
    traces = [
        trace(states[k], cs[k], float(oracle[1e-7][k]), int(oracle_run.steps[k]), args.budget)
        for k in idx
    ]
    same = all(tr["steps"] == int(oracle_run.steps[k]) for tr, k in zip(traces, idx, strict=True))
    turn = weighted_median(
        np.concatenate([tr["turn"] for tr in traces]),
        np.concatenate([tr["count"] for tr in traces]),
    )
    rot = np.array([tr["rotation"] for tr in traces])
    eps = np.array([tr["episodes"] for tr in traces])
    to_stop = float(sum(tr["steps"] for tr in traces))
    ideal = float(rot.sum() / turn)
    all_steps = float(stats["shipped 1e-7"][:, 1].sum())
    strided = sum(tr["stride"] > 1 for tr in traces)
    cap = {key: sum(tr["caps"][key] for tr in traces) for key in traces[0]["caps"]}
    print(
        f"  floor (1e-7 up to the oracle's stop; {time.perf_counter() - w0:.0f} s wall; "
        f"{strided} of {m} tosses sampled every k > 1 steps; steps equal to the timed run's: "
        f"{same}): rotation ∫|ω| dt median {np.median(rot):.1f} rad (mean {rot.mean():.1f}, "
        f"total {rot.sum():,.0f}; in hops {cap['rot_hop']:,.0f}, "
        f"{cap['rot_hop'] / rot.sum():.1%}), contact episodes median {np.median(eps):.0f} (mean "
        f"{eps.mean():.1f}); steps to the stop {to_stop:,.0f} ({to_stop / max(eps.sum(), 1):.0f} "
        f"an episode; of {all_steps:,.0f} the shipped phase takes), their turn a step median "
        f"{turn * 1e3:.1f} mrad, mean {rot.sum() / to_stop * 1e3:.1f} mrad"
    )
    print(
        f"    steps held (shorter than {HELD:g} of their cap min(1 ms, π/8/|ω|)): "
        f"{cap['held'] / to_stop:.1%} of the steps to the stop, {cap['held_contact']:,.0f} of "
        f"the {to_stop - stats['oracle 1e-7'][FREE, 1]:,.0f} in contact"
    )
    print(
        f"    at the median step's turn {turn * 1e3:.1f} mrad: {ideal:,.0f} steps (the shipped "
        f"phase's over them {all_steps / ideal:.2f}× = the oracle's {all_steps / to_stop:.2f}× "
        f"× median/mean turn {turn * to_stop / rot.sum():.2f}: a skew, not a floor); at the "
        f"stepper's own caps (1 ms binds) {cap['cap']:,.0f} ({all_steps / cap['cap']:.1f}×), "
        f"hops in closed form {cap['cap_contact']:,.0f} ({all_steps / cap['cap_contact']:.1f}×); "
        f"an ideal integrator unconstrained by MAX_STEP, π/8 a step: {cap['turn']:,.0f} "
        f"({all_steps / cap['turn']:.1f}×), hops in closed form {cap['turn_contact']:,.0f} "
        f"({all_steps / cap['turn_contact']:.1f}×)"
    )
    return {
        "handed": m,
        "bounces": med["bounces"],
        "phase": med["shipped 1e-7"],
        "cpu": med,
        "stats": stats,
        "floors": {
            "median turn": ideal,
            "1 ms cap": cap["cap"],
            "π/8": cap["turn"],
            "π/8, hops closed": cap["turn_contact"],
        },
    }


def setting_row(rate: float, ref_cost: float, res: dict) -> dict:  # type: ignore[type-arg]
    """One setting's combined figures (module notes), from its measurements ``res`` (as
    :func:`setting_run` returns them: ``"bounces"`` and ``"phase"`` CPU s, ``"cpu"`` the median
    CPU s of each of :data:`VARIANTS`, ``"stats"`` each variant's mode stats, ``"floors"`` the
    ideal steps of each floor to the oracle's stop), ``rate`` the landings a second of the
    setting whose CPU per landing is ``ref_cost``: today's rate here (scaled by the CPU per
    landing), the factors (RTOL 1e-5, the oracle at 1e-7 and at 1e-5, the hops' bound in the
    oracle at 1e-5 run), the ceiling (oracle at 1e-5 × hops, through the bounces), the rigid
    hypothetical, each floor's factor (the shipped phase's steps over its) and landings, and
    the bounces alone."""
    b, p, cpu = res["bounces"], res["phase"], res["cpu"]
    here = rate * ref_cost / (b + p)  # scaled by the one-thread CPU per landing
    hops = hop_factor(res["stats"]["oracle 1e-5"])
    f_or5 = p / cpu["oracle 1e-5"]
    f, ceiling = combined(here, b, p, (f_or5, hops))
    steps = float(res["stats"]["shipped 1e-7"][:, 1].sum())
    floors = {}
    for name, ideal in res.get("floors", {}).items():
        factor = steps / ideal if ideal > 0 else math.inf
        floors[name] = (factor, combined(here, b, p, (factor,))[1])
    return {
        "here": here,
        "f_rtol": p / cpu["rtol 1e-5"],
        "f_or7": p / cpu["oracle 1e-7"],
        "f_or5": f_or5,
        "hops": hops,
        "f": f,
        "ceiling": ceiling,
        "rigid": combined(here, b, p, (f_or5, hops, RIGID_STEPS))[1],
        "floors": floors,
        "free": here * (b + p) / b,  # the contact phase at no cost: the bounces alone
    }


def report(results: dict[str, dict], rate: float) -> None:
    """The combined ceiling per setting (module notes)."""
    ref = next(iter(results.values()))
    ref_cost = ref["bounces"] + ref["phase"]
    print(
        f"\nCombined ceiling, landings a second on 2 cores (today's rate {rate:,.0f} for the "
        "first setting, the others scaled by their CPU per landing; upper estimates: land's "
        "own and the batch's overhead left out):"
    )
    for name, res in results.items():
        if not res:
            continue
        row = setting_row(rate, ref_cost, res)
        b, p, ceiling = res["bounces"], res["phase"], row["ceiling"]
        verdict = (
            "reaches 50,000"
            if ceiling >= TARGET
            else f"misses 50,000 by {TARGET / ceiling:.1f}× ({TARGET - ceiling:,.0f}/s short)"
        )
        floors = "; ".join(
            f"{key} {factor:.2f}×, {landings:,.0f}/s"
            for key, (factor, landings) in row["floors"].items()
        )
        print(
            f"  {name}: today {row['here']:,.0f}/s (the phase {p / (b + p):.1%} of a landing's "
            f"CPU); RTOL 1e-5 {row['f_rtol']:.2f}×, oracle {row['f_or7']:.2f}× at 1e-7, "
            f"{row['f_or5']:.2f}× with RTOL 1e-5 (the product of the two alone "
            f"{row['f_rtol'] * row['f_or7']:.2f}×), hops at zero cost {row['hops']:.2f}×: the "
            f"phase {row['f']:.2f}×, landings {landing_factor(b, p, row['f']):.2f}× = "
            f"**{ceiling:,.0f}/s**, {verdict}; with the rigid contact's steps at the compliant "
            f"step's price (hypothetical, {RIGID_STEPS:.2f}×) {row['rigid']:,.0f}/s; the "
            f"motion's steps to the oracle's stop at today's step price (estimates): {floors}; "
            f"the phase at no cost (the bounces alone) {row['free']:,.0f}/s"
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=300, help="tosses per setting")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--rate", type=float, default=RATE, help="today's landings/s, 2 cores")
    parser.add_argument("--chunk", type=float, default=2e-3, help="simulated s an oracle chunk")
    parser.add_argument(
        "--floor-budget", dest="budget", type=float, default=2e5, help="steps a toss's floor"
    )
    parser.add_argument("--settings", default="0,1,2", help="indices of bench_tolerance.SETTINGS")
    args = parser.parse_args()
    if args.n < 1:
        parser.error(f"N {args.n}: must be at least 1")
    if args.rounds < 1:
        parser.error(f"--rounds {args.rounds}: must be at least 1")
    for option, value in (
        ("--rate", args.rate),
        ("--chunk", args.chunk),
        ("--floor-budget", args.budget),
    ):
        if not (math.isfinite(value) and value > 0.0):
            parser.error(f"{option} {value:g}: must be a finite number > 0")
    names = list(bench_tolerance.SETTINGS)
    keys = args.settings.split(",")
    if not all(k in {str(i) for i in range(len(names))} for k in keys):
        parser.error(f"--settings {args.settings!r}: must be indices among 0-{len(names) - 1}")
    t0 = time.perf_counter()
    load = os.getloadavg()
    results = {}
    for key in keys:
        name = names[int(key)]
        results[name] = setting_run(args, name, bench_tolerance.SETTINGS[name])
    report(results, args.rate)
    print(
        f"{time.perf_counter() - t0:.0f} s wall; load {load[0]:.2f} before, "
        f"{os.getloadavg()[0]:.2f} after"
    )


if __name__ == "__main__":
    main()

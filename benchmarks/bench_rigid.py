"""The rigid one-rim contact against the compliant phase: steps and CPU per simulated second.

    python benchmarks/bench_rigid.py [N] [--rounds R] [--seed S] [--e E] [--mu MU]
                                     [--resistance L] [--contact-time T] [--duration D]
                                     [--rtol TOL]

The states are those the bounces hand to the contact phase (:func:`bench_contact.handoff` on
the vigorous nickel tosses of ``bench_bounce.py --contact-rates``, :func:`bench_bounce.tosses`),
on one surface (e, μ, ℓ_r = ℓ_p). Each is put on the rigid contact (its lowest rim point
touching, the rebound speed of at most ``rest_speed`` at the contact removed: ``advance_rigid``
with ``approach = rest_speed`` and no time), then run by
:func:`coinflight.core.rigid_contact.advance_rigid` until it stops (lift-off, second rim, face,
Painlevé, the energy below the well's barrier as the contact phase's ending, or
``--duration``): that time T is the toss's stretch in one-rim modes. The compliant
phase (:func:`coinflight.core.contact_phase.advance`, no settle test) runs the same state for
the same T. Both are timed in CPU seconds (one thread: ``NUMBA_NUM_THREADS=1`` is set here),
``--rounds`` times each, alternated; the medians of the rounds are quoted, per simulated second
summed over the tosses, and their ratio.

Measured (2026-11-24, the project machine, 2 CPUs AMD EPYC shared with other sessions):
``python benchmarks/bench_rigid.py 300 --rounds 3`` (03:39 UTC, load 6.2): 213 handed states,
23.1 s of one-rim time; accepted steps a simulated second (the compliant phase's count) rigid
1,915, compliant 3,016 (the rigid run also rejected 270 and spent 393 locating events); CPU
4.28 ms against 3.12 ms a simulated second: **the rigid contact 0.73× as fast** (lift-off
stretches 7,097 against 5,583 accepted steps a second, below-barrier stretches 1,612 against
3,142). Where the rigid steps go: :mod:`coinflight.core.rigid_contact`, "Speed".
"""

from __future__ import annotations

import os

os.environ.setdefault("NUMBA_NUM_THREADS", "1")  # before numba is imported

import argparse
import statistics
import time

import numpy as np


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=300, help="tosses (default 300)")
    parser.add_argument("--rounds", type=int, default=3, help="timed rounds of each engine")
    parser.add_argument("--seed", type=int, default=2026, help="seed of the tosses")
    parser.add_argument("--e", type=float, default=0.5, help="restitution of the bounces")
    parser.add_argument("--mu", type=float, default=0.3, help="friction μ")
    parser.add_argument("--resistance", type=float, default=1e-4, help="ℓ_r = ℓ_p, m")
    parser.add_argument("--contact-time", type=float, default=1e-3, help="t_c of the compliant, s")
    parser.add_argument("--duration", type=float, default=1.0, help="longest rigid run, s")
    parser.add_argument("--rtol", type=float, default=None, help="rigid step tolerance (RTOL)")
    args = parser.parse_args()
    if args.n < 1 or args.rounds < 1:
        parser.error("N and --rounds must be at least 1")
    if not args.duration > 0.0 or not args.contact_time > 0.0:
        parser.error("--duration and --contact-time must be positive")
    if args.rtol is not None and not 0.0 < args.rtol < 1.0:
        parser.error("--rtol must be in (0, 1)")

    import bench_bounce
    import bench_contact
    from coinflight.core import contact_phase as cp
    from coinflight.core import rigid_contact as rc

    rtol = rc.RTOL if args.rtol is None else args.rtol
    c = bench_contact.contact(args.e, args.mu, resistance=args.resistance)._replace(
        contact_time=args.contact_time
    )
    omega, v0 = bench_bounce.tosses(args.n, args.seed)
    states = []
    for k in range(args.n):
        y, handed = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if handed:
            run = rc.advance_rigid(y, c, 0.0, approach=c.rest_speed)  # onto the constraint
            if run.reason == rc.DURATION:
                states.append(y.copy())
    # The one-rim stretch of each state, and the rigid run's counts.
    spans = np.zeros(len(states))
    reasons = np.zeros(len(rc.REASON_NAMES), dtype=int)
    ends = np.zeros(len(states), dtype=int)
    rigid_steps = np.zeros(len(states))
    rigid_rejected = np.zeros(len(states))
    rigid_events = np.zeros(len(states))
    rolling = np.zeros(len(states))
    for k, y0 in enumerate(states):
        y = y0.copy()
        run = rc.advance_rigid(y, c, args.duration, settle=True, rtol=rtol)
        spans[k] = run.time
        reasons[run.reason] += 1
        ends[k] = run.reason
        rigid_steps[k] = run.steps  # accepted, counted as the compliant phase's
        rigid_rejected[k] = run.rejected
        rigid_events[k] = run.event_steps
        rolling[k] = run.rolling_time
    use = spans > 0.0
    states = [s for s, u in zip(states, use, strict=True) if u]
    spans = spans[use]
    ends = ends[use]
    rigid_steps = rigid_steps[use]
    rigid_rejected = rigid_rejected[use]
    rigid_events = rigid_events[use]
    compliant_steps = np.zeros(len(states))
    for k, y0 in enumerate(states):
        y = y0.copy()
        _, compliant_steps[k], _ = cp.advance(y, spans[k], c)
    total = float(spans.sum())

    def rigid() -> None:
        for k, y0 in enumerate(states):
            rc.advance_rigid(y0.copy(), c, spans[k] * (1.0 + 1e-12), settle=True, rtol=rtol)

    def compliant() -> None:
        for k, y0 in enumerate(states):
            cp.advance(y0.copy(), spans[k], c)

    cpu = {"rigid": [], "compliant": []}
    for _ in range(args.rounds):
        for name, fn in (("rigid", rigid), ("compliant", compliant)):
            t0 = time.process_time()
            fn()
            cpu[name].append(time.process_time() - t0)
    rigid_cpu = statistics.median(cpu["rigid"]) / total
    compliant_cpu = statistics.median(cpu["compliant"]) / total
    print(
        f"{args.n} vigorous nickel tosses (seed {args.seed}), e {args.e}, μ {args.mu}, "
        f"ℓ {args.resistance:g} m, compliant t_c {args.contact_time:g} s, rigid rtol {rtol:g}; "
        f"NUMBA_NUM_THREADS={os.environ['NUMBA_NUM_THREADS']}; load {os.getloadavg()}"
    )
    print(
        f"handed and in one-rim contact: {len(states)}; one-rim time per toss median "
        f"{np.median(spans) * 1e3:.1f} ms (total {total:.3f} s), rolling "
        f"{rolling.sum() / total:.0%} of it"
    )
    print(
        "rigid runs stopped by: "
        + ", ".join(
            f"{name} {count}" for name, count in zip(rc.REASON_NAMES, reasons, strict=True) if count
        )
    )
    print(
        f"accepted steps per simulated second: rigid {rigid_steps.sum() / total:,.0f}, "
        f"compliant {compliant_steps.sum() / total:,.0f}; the rigid run also rejected "
        f"{rigid_rejected.sum() / total:,.0f} and spent {rigid_events.sum() / total:,.0f} "
        "locating events (a simulated second)"
    )
    for reason in np.unique(ends):
        mine = ends == reason
        span = float(spans[mine].sum())
        print(
            f"  runs ending by {rc.REASON_NAMES[reason]}: {mine.sum()}, {span:.3f} s; steps a "
            f"simulated second (accepted) rigid {rigid_steps[mine].sum() / span:,.0f}, compliant "
            f"{compliant_steps[mine].sum() / span:,.0f}"
        )
    print(
        f"CPU per simulated second (median of {args.rounds} rounds): rigid "
        f"{rigid_cpu * 1e3:.2f} ms, compliant {compliant_cpu * 1e3:.2f} ms: "
        f"the rigid contact {compliant_cpu / rigid_cpu:.1f}x faster"
    )
    print(f"rounds (CPU s): rigid {cpu['rigid']}, compliant {cpu['compliant']}")


if __name__ == "__main__":
    main()

"""How the contact ending's edges depend on its numerical parameters, from fixed hand-off states.

    python benchmarks/bench_edge_sensitivity.py [N] [--seed S] [--slip-factor F]
        [--contact-time T] [--damping-factor D] [--friction MU] [--resistance L] [--stride K]
        [--exponent 1|1.5] [--no-decision] [--trace K]

The N vigorous tosses of ``bench_mujoco_edges.py --handoff-only`` (seed 2026, a US nickel, e
0.5, μ 0.3, rolling and pivoting resistance 1e-4 m) bounce as the contact ending's landings do
(``bench_contact.handoff``); the states in which the bounces hand them to
:mod:`coinflight.core.contact_phase` (446 of 600) are then carried to rest by that phase alone
with one parameter changed: ``SLIP_SPEED`` times F (the regularisation of Coulomb's friction; F
→ 0 is the Coulomb limit), the contact time t_c, the damping ratio ζ times D, μ, the
resistances, or the exponent p of the rim's normal law (``--exponent 1``: F ∝ d0 as MuJoCo's,
instead of the default d0^(3/2); ``normal_law.py``, a benchmark-only knob, its damping ζ_p set
for the same e). Prints P(edge) among the handed tosses. SLIP_SPEED is a constant compiled into
the numba kernels, and the exponent swaps a kernel (``contact_phase._rim``): either compiles
them afresh into a temporary cache, removed at the end (the package's own cache is not touched).
With ``--exponent 1`` or ``--no-decision`` each toss is carried to rest
(:func:`coinflight.core.contact_phase.advance`, ``decide=False``; the upright decision bounds
the rims' sinking with the 3/2 law). ``--trace K``: every K-th carried toss is also sampled over
its first 0.1 s from the hand-off at 0.1 ms (``bench_edge_trace.ours_trace`` and ``episodes``,
as that benchmark does for 60 tosses): medians of the first contact episode's length and normal
impulse, the share of samples in contact and the number of episodes, for the tosses that end on
edge and the others.

Re-measured with the contact phase's sliding-mass damper (2026-11-24 05:20 UTC, main 4f0dfa5,
``600``, load 9, 5 s): on edge by default 44 of the 446 (0.099 ± 0.014; heads 0.482), against
the 49 (0.110 ± 0.015; heads 0.475) below, measured before the damper; the other rows below
were not re-run.

Measured (446 hand-off states, 2026-11-24 00:39-00:44 UTC, load 2-4, each run 0-32 s; the same
counts as first measured 2026-11-23 23:36-00:05 UTC on the code before the contact phase's
speed-up, but for the 3/2 law at 0.25 ms, then 47): on edge by default 49 (0.110 ± 0.015), with
the upright decision and carried to rest without it (``--no-decision``) alike (heads 0.475 in
both; not compared toss by toss); with a linear rim law (``--exponent 1``, always carried to
rest: K_1 = 2πκ, ζ_p 0.2553 for e 0.5; a nickel dropped upright on both rims at 0.1 and 1 m/s
stays in contact 0.76 and 0.74 ms, as MuJoCo's 0.8 ms, where the 3/2 law holds it 5.7 and 3.0
ms) **47** (0.105 ± 0.015) against those 49; at t_c 0.25 ms 49 (0.110 ± 0.015) with the linear
law against the 3/2 law's 48 (0.108 ± 0.015, with the decision and without alike). ``--trace 1``
(the 3/2 law with ``--no-decision``), medians over all 446 (edge-enders in brackets): the first
contact from the hand-off lasts 29 ms (10 ms) with the 3/2 law and 15 ms (9 ms) with the linear
one, the coin is in contact 90 % (68 %) and 76 % (64 %) of the first 0.1 s. So the long first
contact is not a slow impact of a soft law (a law whose impacts last 0.75 ms keeps it): the coin
stays on its rim, sliding and rolling, as a rigid coin pressed by gravity does. Frictionless
(``--friction 0 --trace 2``) it stays there too (28 ms, 85 %): friction does not press it. What
makes MuJoCo's coins hop is MuJoCo's: its sliding contacts move apart
(``bench_mujoco_edges.py``'s notes). The exponent, the stiffness (t_c) and, in MuJoCo, the
impedance's first touch leave the edge counts where they were; the normal law is not where the
engines part."""

from __future__ import annotations

import argparse
import math
import os
import time


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=600)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--slip-factor", type=float, default=1.0)
    parser.add_argument("--contact-time", type=float, default=1e-3)
    parser.add_argument("--damping-factor", type=float, default=1.0)
    parser.add_argument("--friction", type=float, default=0.3, help="μ of the contact phase")
    parser.add_argument("--resistance", type=float, default=1e-4, help="ℓ_r = ℓ_p, m")
    parser.add_argument("--stride", type=int, default=1, help="every K-th handed toss")
    parser.add_argument(
        "--exponent", type=float, default=1.5, help="p of the rim law F ∝ d0^p (1 or 1.5)"
    )
    parser.add_argument(
        "--no-decision", action="store_true", help="carry every toss to rest (no upright decision)"
    )
    parser.add_argument("--trace", type=int, default=0, help="trace every K-th toss (0: none)")
    args = parser.parse_args()
    import normal_law

    if args.exponent not in normal_law.EXPONENTS:
        parser.error(f"--exponent must be one of {normal_law.EXPONENTS}, got {args.exponent}")
    if args.slip_factor != 1.0 or args.exponent != 1.5:
        normal_law.fresh_cache()
    import numpy as np

    from coinflight.core import contact_phase as cp

    cp.SLIP_SPEED *= args.slip_factor  # before any kernel is compiled
    normal_law.use_exponent(args.exponent)
    import bench_contact
    from coinflight.core.impact import resting_face
    from coinflight.core.outcome import EDGE, HEADS, Status
    from coinflight.studies import landing as study

    e, mu = 0.5, 0.3
    _, omega, v0 = study.edge_draw(args.n, args.seed)
    c = bench_contact.contact(e, mu)
    states = []
    for k in range(args.n):  # the tosses the bounces hand to the contact phase
        y, h = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if h:
            states.append(y.copy())
    if args.exponent == 1.5:
        zeta = cp.damping_of(c) * args.damping_factor
    else:
        zeta = normal_law.damping_ratio(e, args.exponent) * args.damping_factor
    carry = args.no_decision or args.exponent != 1.5
    c = c._replace(
        friction=args.friction,
        rolling_resistance=args.resistance,
        pivoting_resistance=args.resistance,
        contact_time=args.contact_time,
        damping_ratio=zeta,
        damping_restitution=c.restitution,
    )
    t0 = time.perf_counter()
    faces, unsettled, traced = [], 0, []
    for i, y in enumerate(states[:: args.stride]):
        if args.trace and i % args.trace == 0:
            traced.append((i, first_contacts(y, c)))
        if carry:
            _, _, settled = cp.advance(y, math.inf, c, settle_check=True)
            face = resting_face(y[6], c.edge_sine)
        else:
            face, status, _ = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
            settled = status != Status.UNSETTLED
        faces.append(face)
        unsettled += int(not settled)
    f = np.array(faces)
    k = len(f)
    p = float(np.mean(f == EDGE))
    print(
        f"{args.n} tosses (seed {args.seed}), {len(states)} handed, {k} carried: SLIP_SPEED "
        f"{cp.SLIP_SPEED:g} m/s, t_c {args.contact_time:g} s, rim law d0^{args.exponent:g}, ζ "
        f"{zeta:.4g}, {'carried to rest' if carry else 'upright decision'}, μ {args.friction:g}, "
        f"resistances {args.resistance:g} m: edges {np.count_nonzero(f == EDGE)}/{k} = {p:.3f} "
        f"± {np.sqrt(p * (1 - p) / k):.3f}, heads {np.mean(f == HEADS):.3f}, unsettled "
        f"{unsettled} (counted by their well); {time.perf_counter() - t0:.0f} s, load "
        f"{os.getloadavg()[0]:.1f}"
    )
    if traced:
        edge = np.array([f[i] == EDGE for i, _ in traced])
        rows = np.array([row for _, row in traced])
        for name, mask in (("on edge", edge), ("not on edge", ~edge), ("all", edge | ~edge)):
            q = np.nanmedian(rows[mask], axis=0) if mask.any() else np.full(4, np.nan)
            print(
                f"  traced, {name} ({int(mask.sum())}): first episode {q[0] * 1e3:.2f} ms, J_n "
                f"{q[1] * 1e3:.2f} mN s; in contact {q[2]:.0%} of the first 0.1 s, {q[3]:.0f} "
                "episodes (medians)"
            )


def first_contacts(y, c) -> tuple[float, float, float, float]:  # type: ignore[no-untyped-def]
    """The first 0.1 s from the state y sampled at 0.1 ms (``bench_edge_trace``): the first
    contact episode's length (s) and normal impulse (N s), the share of samples in contact, the
    number of episodes."""
    import bench_edge_trace as trace

    tr = trace.ours_trace(y, c, 0.1, 1e-4)
    eps = trace.episodes(tr, c, c.friction)
    if not eps:
        return 0.0, 0.0, float((tr["fn"] > 0).mean()), 0.0
    return eps[0]["length"], eps[0]["jn"], float((tr["fn"] > 0).mean()), float(len(eps))


if __name__ == "__main__":
    main()

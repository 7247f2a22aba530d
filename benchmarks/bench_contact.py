"""Where the 3-D contact ending spends its time (issue 11): a profile of the contact phase.

    python benchmarks/bench_contact.py [N] [--seed S]

For N vigorous tosses of a US nickel (those of ``bench_bounce.py``: ωx ~ U(150, 300),
ωy, ωz ~ U(−30, 30) rad/s, v0 ~ U(1.5, 3) m/s, 0.8 m drop), each with its own e ~ U(0.2, 0.8)
and μ ~ U(0.1, 0.6), the bounces are run by :func:`coinflight.core.bounce.bounce_loop` (those
of :func:`coinflight.core.bounce.land_one`) with the contact ending, up to the hand-off to the
contact phase; the phase is then
integrated to its end with :func:`coinflight.core.contact_phase.advance`, recording per toss
the simulated time and the steps spent in each mode of :data:`~coinflight.core.contact_phase.MODES`
(off the table, on one rim's arc, on both rims, on the face), and the composition of the
energy the coin brings in (horizontal translation, spin about n, tumbling, vertical motion and
height above the face's rest), in barriers m g ρ above the face's rest energy m g h/2. (The
looser candidate endings it once measured are recorded in :mod:`coinflight.core.contact_phase`.)

Each phase is carried to rest without the upright roller's decision
(:func:`coinflight.core.contact_phase.upright_decided`), while the integrator records where it
would have ended the toss; the benchmark then counts the tosses it decides, those among them
that do not end on edge at rest (disagreements; the decision is adopted only at 0), and the
steps and simulated time it saves. ``--pairs 0.5,0.3 0.5,0.6`` runs the same tosses on those
surfaces (e, μ) instead of each toss's own; ``--resistance L`` sets ℓ_r = ℓ_p (default the
surface's, 1e-4 m).

Since 2026-11-23 a decided toss that, carried on, does not settle (stopped by MAX_STEPS)
counts as a disagreement; before, it counted as agreeing. Re-measured that way at ℓ 1e-5 m,
where rollers roll ten times longer (2026-11-23, 23:33-00:07 UTC, load 5-14): ``python
benchmarks/bench_contact.py 600 --pairs 0.5,0.3 0.5,0.6 --resistance 1e-5`` decides 56 of 429
handed tosses (57 end on edge at rest) and 178 of 446 (182; 6 handed tosses unsettled, none of
them decided), 0 disagreements; ``1500 --pairs 0.5,0.3 0.5,0.6 --resistance 1e-5`` 120 of
1,061 (122) and 416 of 1,028 (421), and ``1500 --resistance 1e-5`` (each toss its own e, μ)
191 of 1,030 (195): 0 disagreements in the 727 decisions of the 1,500-toss runs (254, 1,033
and 195 s wall; at μ 0.6 4 of the 1,028 handed tosses unsettled, none of them decided), and 0
in the 234 of the 600-toss runs (961 in all). The "0 in 737" at the default
1e-4 m was counted the old way and is not re-run here; there the rollers stop within ~15 s, far
inside MAX_STEPS. All these counts were measured before the joint damping of two pressed rims
(2026-11-24); with it, ``1500 [--pairs 0.5,0.3 0.5,0.6]`` at 1e-4 m decides 126, 424, 201 with
0 disagreements (the contact_phase notes).
"""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np

from coinflight import Coin
from coinflight.core import bounce
from coinflight.core import contact_phase as cp
from coinflight.core.contact import Contact
from coinflight.core.impact import resting_face
from coinflight.model.surface import (
    DEFAULT_PIVOTING_RESISTANCE,
    DEFAULT_ROLLING_RESISTANCE,
    Surface,
)
from coinflight.outcomes.table import contact_record

COIN = Coin.preset("us-nickel")
G = 9.81
DROP = 0.8


def contact(e: float, mu: float, corner: float = 0.0, resistance: float | None = None) -> Contact:
    """The nickel's contact record (corner radius ``corner``, m) on a table with the contact
    ending and rolling and pivoting resistance ``resistance`` (m; default the surface's
    defaults)."""
    surface = Surface(
        "table",
        DROP,
        e,
        mu,
        DEFAULT_ROLLING_RESISTANCE if resistance is None else resistance,
        DEFAULT_PIVOTING_RESISTANCE if resistance is None else resistance,
        ending="contact",
    )
    return contact_record(COIN.with_corner_radius(corner), surface, G)


def handoff(omega_body, start_sign, launch_speed, c):  # type: ignore[no-untyped-def]
    """The state y = (z, v, n, L) in which :func:`coinflight.core.bounce.land_one` hands the
    toss to the contact phase (:func:`coinflight.core.bounce.bounce_loop`), and whether it does
    (False: it ended at an impact, or did not end)."""
    *_, status, z, v, n, lm = bounce.bounce_loop(
        omega_body, start_sign, launch_speed, c, bounce.MAX_IMPACTS
    )
    return np.array([z, *v, *n, *lm]), status == bounce.DIED_OUT


def composition(y: np.ndarray, c: Contact) -> np.ndarray:
    """Energy at the hand-off in barriers (m g ρ − m g h/2): horizontal translation, spin about
    n, tumbling, vertical motion + height above the face's rest m g h/2."""
    m, i1, i3 = c.mass, c.i1, c.i3
    n, lm = y[4:7], y[7:10]
    ln = float(n @ lm)
    lperp2 = float(lm @ lm) - ln * ln
    scale = c.barrier - m * c.g * c.half_thickness
    return (
        np.array(
            [
                0.5 * m * (y[1] ** 2 + y[2] ** 2),
                0.5 * ln * ln / i3,
                0.5 * lperp2 / i1,
                0.5 * m * y[3] ** 2 + m * c.g * (y[0] - c.half_thickness),
            ]
        )
        / scale
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=400)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--corner", type=float, default=0.0, help="rim corner radius a, m")
    parser.add_argument("--contact-time", type=float, default=cp.CONTACT_TIME, help="t_c, s")
    parser.add_argument(
        "--resistance", type=float, default=None, help="ℓ_r = ℓ_p, m (default the surface's)"
    )
    parser.add_argument(
        "--pairs", nargs="*", default=[], metavar="E,MU", help="surfaces (e, μ) to run instead"
    )
    args = parser.parse_args()
    surfaces = [tuple(float(x) for x in pair.split(",")) for pair in args.pairs] or [None]
    for surface in surfaces:
        profile(args, surface)


def profile(args: argparse.Namespace, surface: tuple[float, ...] | None) -> None:
    """The profile of ``args.n`` tosses on ``surface`` (e, μ), or each with its own e, μ."""
    rng = np.random.default_rng(args.seed)
    n = args.n
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    # e on a grid of 0.01 so that Contact.build's cached damping ratio is computed 61 times.
    e = np.round(rng.uniform(0.2, 0.8, n), 2)
    mu = rng.uniform(0.1, 0.6, n)
    if surface is not None:
        e[:], mu[:] = surface
    modes = len(cp.MODES)
    times = np.zeros((n, modes))
    steps = np.zeros((n, modes))
    energy = np.full((n, 4), np.nan)
    handed = np.zeros(n, dtype=bool)
    settled = np.zeros(n, dtype=bool)
    wall = np.zeros(n)
    final = np.full(n, -1)
    decided = np.full((n, 2), -1.0)  # (time, steps) where upright_decided first held
    t0 = time.perf_counter()
    for k in range(n):
        c = contact(float(e[k]), float(mu[k]), args.corner, args.resistance)._replace(
            contact_time=args.contact_time
        )
        y, handed[k] = handoff((omega[k, 0], omega[k, 1], omega[k, 2]), 1.0, v0[k], c)
        if not handed[k]:
            continue
        energy[k] = composition(y, c)
        stats = np.zeros((modes + 1, 2))
        stats[modes] = -1.0
        w0 = time.perf_counter()
        _, _, settled[k] = cp.advance(y, math.inf, c, settle_check=True, stats=stats)
        wall[k] = time.perf_counter() - w0
        final[k] = resting_face(y[6], c.edge_sine)
        times[k], steps[k] = stats[:modes, 0], stats[:modes, 1]
        decided[k] = stats[modes]
    total = time.perf_counter() - t0
    h = handed
    kind = "e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6)" if surface is None else f"e = {e[0]}, μ = {mu[0]}"
    print(
        f"{n} vigorous nickel tosses, {kind}, resistances "
        f"{c.rolling_resistance:g} m, corner radius {args.corner:g} m, t_c "
        f"{args.contact_time:g} s; {total:.1f} s wall, load {os.getloadavg()}"
    )
    print(
        f"handed to the contact phase: {h.mean():.1%} ({h.sum()}); of those settled "
        f"{settled[h].mean():.1%}; median wall time {np.median(wall[h]) * 1e3:.1f} ms a toss"
    )
    tt, ss = times[h].sum(axis=1), steps[h].sum(axis=1)
    print(
        f"per handed toss: simulated time median {np.median(tt):.3f} s (quartiles "
        f"{np.percentile(tt, 25):.3f}-{np.percentile(tt, 75):.3f}), steps median "
        f"{np.median(ss):,.0f} (quartiles {np.percentile(ss, 25):,.0f}-"
        f"{np.percentile(ss, 75):,.0f}), mean step "
        f"{tt.sum() / ss.sum() * 1e6:.1f} μs"
    )
    for j, name in enumerate(cp.MODES):
        print(
            f"  {name:9s}: time median {np.median(times[h, j]):.3f} s, share of all time "
            f"{times[h, j].sum() / tt.sum():5.1%}; steps median {np.median(steps[h, j]):,.0f}, "
            f"share of all steps {steps[h, j].sum() / ss.sum():5.1%}; mean step "
            f"{times[h, j].sum() / max(steps[h, j].sum(), 1) * 1e6:.1f} μs"
        )
    print(
        f"steps a handed toss: mean {ss.mean():,.0f}; the 10 % longest tosses take "
        f"{np.sort(ss)[-max(1, len(ss) // 10) :].sum() / ss.sum():.0%} of all steps; final wells "
        f"(tails, heads, edge) {np.bincount(final[h], minlength=3)}"
    )
    hit = h & (decided[:, 1] >= 0)
    # A decided toss that, carried on, did not settle (stopped by MAX_STEPS) disagrees too.
    wrong = hit & ((final != 2) | ~settled)
    saved = (ss[hit[h]] - decided[hit, 1]).sum()
    print(
        f"upright decision (margin {cp.UPRIGHT_MARGIN}): would end {hit.sum()} of {h.sum()} "
        f"handed tosses ({np.sum(h & (final == 2) & settled)} end on edge at rest); "
        f"disagreements (not on edge at rest) {wrong.sum()} {np.flatnonzero(wrong).tolist()}; "
        f"steps saved {saved:,.0f} of {ss.sum():,.0f} ({saved / ss.sum():.1%}), "
        f"simulated time saved {(tt[hit[h]] - decided[hit, 0]).sum():,.1f} of {tt.sum():,.1f} s"
    )
    names = ("horizontal translation", "spin about n", "tumbling", "vertical + height")
    en = energy[h]
    print(
        f"energy at the hand-off, in barriers above the face's rest: total median "
        f"{np.median(en.sum(axis=1)):.2f}"
    )
    for j, name in enumerate(names):
        print(
            f"  {name:23s}: median {np.median(en[:, j]):.3f}, mean share "
            f"{np.mean(en[:, j] / en.sum(axis=1)):.1%}"
        )


if __name__ == "__main__":
    main()

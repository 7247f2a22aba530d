"""Edges in two engines: coinflight's 3-D contact ending against MuJoCo, the same tosses.

    python benchmarks/bench_mujoco_edges.py [N] [--pairs 0.5,0.3 0.5,0.6] [--seed S]
        [--tosses vigorous|report] [--limit 20] [--integrator RK4] [--threads T]

N tosses (default 200) of :func:`coinflight.studies.landing.edge_check`: by default the
vigorous tosses of ``bench_contact.py`` (ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30) rad/s, v0 ~
U(1.5, 3) m/s, a US nickel 0.8 m above the table), for each (e, μ) in coinflight with the 3-D
contact ending (sharp corners, rolling and pivoting resistance 1e-4 m) and in MuJoCo (a sharp
cylinder, condim 6, rolling and torsional friction 1e-4 m, damping calibrated to e, RK4, each
toss carried until it settles or ``--limit`` s past its first contact). Prints, per (e, μ),
P(tails, heads, edge) at rest with standard errors (all tosses; among the tosses coinflight
hands to its contact phase; MuJoCo's settled ones only), the tosses still moving in MuJoCo at
the limit, which tosses end on edge in each engine, and how long the edge-enders take to come
to rest in each (simulated seconds after the first contact: MuJoCo to within its 0.1 s window;
coinflight's bounces plus its contact phase, from ``bench_contact.handoff``), and how long
they stood on their rim.

Measured with the contact phase's sliding-mass damper (2026-11-24, main 4f0dfa5, MuJoCo 3.17,
``1500 --pairs 0.5,0.3 0.5,0.6``, seed 2026, load 1.9 at start, 6.0 at end; the figures of
:mod:`coinflight.core.contact_phase`'s notes, "An independent engine", were measured before the
damper, 2026-11-23): P(edge) among the tosses handed to the contact phase, coinflight against
MuJoCo on the same tosses, **0.115 ± 0.010 against 0.012 ± 0.003** at e 0.5, μ 0.3 (1,077
handed; 0.123 before the damper) and **0.435 ± 0.015 against 0.043 ± 0.006** at μ 0.6 (1,067;
0.439 before); of all tosses 0.083 and 0.309 here (0.088, 0.312 before). MuJoCo's runs do not
involve the phase, and the tosses handed to it are the same (the bounces are unchanged): its
figures are those of 2026-11-23 again (of all tosses 0.011 and 0.035; 2 and 11 still moving at
20 s). On edge in both engines 2 and 20 tosses, here only 122 and 444, in MuJoCo only 14 and 33
(2, 23; 130, 445; 14, 30 before); coinflight's edge-enders stand upright a median 7.1 and 7.8 s
(6.7, 7.9 before), MuJoCo's 14.6 and 10.9 s. 2,723 s wall, 1,106 s of CPU (MuJoCo 32,480 and
33,781 RK4 steps a second).

``--from-handoff`` also starts MuJoCo from coinflight's own state at the hand-off to its
contact phase (:func:`coinflight.studies.mujoco_compare.run_from`; the impacts left out, the
contact phases compared alone); ``--handoff-only`` does only that (no MuJoCo flights), with
``--handoff-integrator`` (default ``--integrator``), ``--condim`` (MuJoCo's contact dimension,
default 6; 3: sliding friction only, no rolling or torsional friction sharing its cone) and
``--resistance-factor`` (MuJoCo's rolling and torsional friction times 1e-4 m; coinflight's
stay 1e-4 m), and MuJoCo's friction made harder than its default
(:class:`coinflight.studies.mujoco_compare.FrictionSolver`): ``--cone elliptic``,
``--impratio R`` (friction impedance R times the normal's), ``--noslip K`` (K no-slip
iterations after the main solver); ``--mujoco-restitution E``: MuJoCo's contact damping
calibrated to E instead of the pair's e (coinflight keeps e); ``--solimp D0,DMAX,WIDTH`` and
``--timeconst T``: MuJoCo's impedance ramp and contact time constant (its damping calibrated
again for e).

Is the gap at condim 3 MuJoCo's soft friction? (2026-11-23, 20:36-21:45 UTC, load 7-14; ``600
--handoff-only --condim 3`` with the options below, MuJoCo RK4, limit 20 s; 446 hand-off states,
coinflight 49 on edge, 0.110 ± 0.015, before the sliding-mass damper; 44, 0.099 ± 0.014,
with it: ``bench_edge_sensitivity.py 600``, 2026-11-24.) MuJoCo on edge, among the 446 (still
moving at 20 s, counted by their well):

=============================================  ==========================  ======
MuJoCo friction (condim 3)                     on edge                     moving
=============================================  ==========================  ======
pyramidal cone, impratio 1 (default; earlier)  23, 0.052 ± 0.011           32
elliptic, impratio 10                          22, 0.049 ± 0.010           31
elliptic, impratio 100                         23, 0.052 ± 0.011           31
pyramidal, 20 no-slip iterations               21, 0.047 ± 0.010           28
default friction, calibrated to e 0.45         19, 0.043 ± 0.010           24
=============================================  ==========================  ======

(1,154, 2,493, 2,195 and 1,606 s wall.) Made Coulomb-hard, MuJoCo's friction leaves its edge count
where it was: the factor left between the engines is not MuJoCo's soft friction. Nor is it the
larger rebound MuJoCo's rim impacts have once friction acts (``bench_rim_impacts.py
--release``: the contact point leaves at 0.53 of its approach speed against 0.48 in the rigid
law and coinflight's phase, at e 0.5): with its contact calibrated to e 0.45
(``--mujoco-restitution 0.45``, which by scaling, not measured, brings that rebound to ~0.48)
MuJoCo leaves 19 on edge.
Toss by toss (``bench_edge_trace.py``) the two part within ~30 ms of the hand-off: MuJoCo kicks
the coin off its rim in 0.8 ms where coinflight's compliant rim keeps it pressed for ~9 ms, and
MuJoCo's coins then hop (6 % of the first 0.1 s in contact, against 51 %) where coinflight's
stay on the rim and roll up. The factor left lies in that normal contact; not yet pinned to a
parameter (coinflight's t_c 0.25 ms leaves 47 on edge, ``bench_edge_sensitivity.py``; 48
re-measured since; MuJoCo's
``solimp``, which sets how soft its contact is at first touch, is untried).

MuJoCo's normal contact changed (2026-11-23, 23:39-00:10 UTC, load 8-14; ``600 --handoff-only
--condim 3 --handoff-integrator Euler`` with the options below, limit 20 s; the same 446
hand-off states; Euler, which from these states gives RK4's faces at ~1/4 of its cost):

=============================================  ==========================  ======
MuJoCo normal contact (condim 3, Euler)        on edge                     moving
=============================================  ==========================  ======
default (solimp 0.9 0.95 0.001, τ 1 ms)        22, 0.049 ± 0.010           27
soft first touch, ``--solimp 0.1,0.95,3e-5``   19, 0.043 ± 0.010           25
``--solimp 0.5,0.95,0.001``                    20, 0.045 ± 0.010           24
``--timeconst 4e-3`` (softer, longer contacts) 27, 0.061 ± 0.011           28
=============================================  ==========================  ======

(353, 217, 359, 165 s wall.) The soft first touch makes MuJoCo's slow contacts press as
coinflight's do (a nickel dropped upright on its rim at 0.01 m/s stays 4.6 ms in contact and
does not rebound, against 0.8 ms and 0.34 of its speed by default; at 0.1 m/s 0.9 ms, 0.43;
coinflight's 3/2 law 5.7 ms, 0.18), yet leaves its edge count where it was: MuJoCo's
impedance does not move it toward coinflight's 49 (0.110 ± 0.015; 44 with the damper). Nor
does coinflight's normal law move toward MuJoCo: a linear rim law
(``bench_edge_sensitivity.py --exponent 1``, impacts of 0.75 ms as MuJoCo's) leaves 47
against the 3/2 law's 49 (both carried to rest without the upright decision, which changes
none of the 49), and 49 against 48 at t_c 0.25 ms (these before the damper). The gap is not in
the normal law's shape, stiffness or first-touch softness of either engine (that run's notes).

Where they part is MuJoCo's sliding contact, which moves apart
(:mod:`coinflight.studies.mujoco_compare`'s notes, "Why the engines part"; its documentation:
"the only way to initiate slip is to generate some motion in the normal direction"): a flat
nickel sliding at 0.5 m/s with μ 0.3 is in contact 7 % of 30 ms in MuJoCo, lifted up to 54 μm
(a sphere 6 %), 89 % frictionless, and 100 % in coinflight's phase, both decelerating as
Coulomb's law says; a nickel leaning 60° on its rim and sliding at 0.3 m/s along it, 6 % of
10 ms in MuJoCo (88 % frictionless), 100 % in coinflight's. A coin sliding on its rim from a
hand-off state is so kicked off in MuJoCo (its 0.8 ms first contact, 6 % of the first 0.1 s in
contact, ``bench_edge_trace.py``) where coinflight's stays on the rim until friction turns the
slide into a roll, and rolls up. The lift shrinks with a softer MuJoCo contact (time constant
4 ms: upward speed 12 against 32 mm/s, in contact 29 %), and MuJoCo's edges rise a little (27
against 22, within the noise); no MuJoCo setting tried removes the lift.
"""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np

from coinflight.core import contact_phase as cp
from coinflight.core.outcome import EDGE
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land
from coinflight.studies import landing as study
from coinflight.studies import mujoco_compare

NAMES = ("tails", "heads", "edge")


def pm(p: np.ndarray, se: np.ndarray) -> str:
    return ", ".join(f"{x:.4f} ± {e:.4f}" for x, e in zip(p, se, strict=True))


def spread(t: np.ndarray) -> str:
    t = t[np.isfinite(t)]
    if not len(t):
        return "none"
    q1, q2, q3 = np.percentile(t, (25, 50, 75))
    return f"median {q2:.2f} s (quartiles {q1:.2f}-{q3:.2f}, max {t.max():.2f}; {len(t)} tosses)"


def coinflight_times(
    check: study.EdgeCheck, cell: study.EdgeCell, omega: np.ndarray, v0: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Simulated seconds from the first contact to the end of coinflight's contact ending
    (the bounces, last impact − first contact, plus the contact phase, run again from the
    hand-off, :func:`bench_contact.handoff`, to its end), and of those in the contact phase
    on both rims (upright in the edge band, :data:`coinflight.core.contact_phase.MODES`)."""
    import bench_contact

    assert check.rolling_resistance == bench_contact.DEFAULT_ROLLING_RESISTANCE
    assert check.pivoting_resistance == bench_contact.DEFAULT_PIVOTING_RESISTANCE
    dist = study.EDGE_TOSSES[check.tosses]()
    surface = Surface(
        "table",
        study.DROP_HEIGHT,
        cell.restitution,
        cell.friction,
        rolling_resistance=check.rolling_resistance,
        pivoting_resistance=check.pivoting_resistance,
        ending="contact",
    )
    out = land(dist.coin, omega, v0, 1.0, dist.g, surface)
    times = np.asarray(out.settle_time - out.first_contact, dtype=float)
    upright = np.zeros(len(times))
    c = bench_contact.contact(cell.restitution, cell.friction)
    two_rims = cp.MODES.index("two rims")
    for k in np.flatnonzero(cell.handed):
        y, handed = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if handed:
            stats = np.zeros((len(cp.MODES), 2))
            elapsed, _, _ = cp.advance(y, math.inf, c, settle_check=True, stats=stats)
            times[k] += elapsed
            upright[k] = stats[two_rims, 0]
    return times, upright


def from_handoff(
    e: float,
    mu: float,
    handed_by_land: np.ndarray,
    omega: np.ndarray,
    v0: np.ndarray,
    args: argparse.Namespace,
) -> tuple[np.ndarray, mujoco_compare.MujocoRun]:
    """coinflight's handed tosses started in MuJoCo from coinflight's own hand-off state
    (:func:`bench_contact.handoff`; the contact phase alone, the impacts left out): (indices of
    the tosses, MuJoCo's run)."""
    import bench_contact
    from coinflight.core.impact import angular_velocity

    c = bench_contact.contact(e, mu)
    idx, states = [], []
    for k in np.flatnonzero(handed_by_land):
        y, handed = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if handed:
            idx.append(k)
            states.append(y.copy())
    y = np.array(states).reshape(-1, 10)
    w = np.array([angular_velocity(tuple(s[7:10]), tuple(s[4:7]), c.i1, c.i3) for s in y])
    speed = math.sqrt(float(np.mean(v0)) ** 2 + 2.0 * 9.81 * study.DROP_HEIGHT)
    run = mujoco_compare.run_from(
        study.EDGE_TOSSES[args.tosses]().coin,
        y[:, 0],
        y[:, 1:4],
        y[:, 4:7],
        w.reshape(-1, 3),
        e if args.mujoco_restitution is None else args.mujoco_restitution,
        mu,
        speed,
        threads=args.threads,
        limit=args.limit,
        condim=args.condim,
        torsional=study.EDGE_RESISTANCE * args.resistance_factor,
        rolling=study.EDGE_RESISTANCE * args.resistance_factor,
        integrator=args.handoff_integrator or args.integrator,
        solver=solver_of(args),
    )
    return np.array(idx, dtype=int), run


def solver_of(args: argparse.Namespace) -> mujoco_compare.FrictionSolver:
    """MuJoCo's solver settings from ``--cone``, ``--impratio``, ``--noslip``, ``--solimp``,
    ``--timeconst``."""
    return mujoco_compare.FrictionSolver(
        args.cone, args.impratio, args.noslip, args.solimp, args.timeconst
    )


def handoff_report(
    e: float,
    mu: float,
    handed: np.ndarray,
    ours_all: np.ndarray,
    omega: np.ndarray,
    v0: np.ndarray,
    args: argparse.Namespace,
) -> dict[str, np.ndarray]:
    """Print the hand-off comparison; its per-toss arrays."""
    idx, hr = from_handoff(e, mu, handed, omega, v0, args)
    ours = ours_all[idx]

    def frac(faces: np.ndarray) -> str:
        k = max(len(faces), 1)
        p = np.bincount(faces, minlength=3) / k
        return pm(p, np.sqrt(p * (1 - p) / k))

    print(
        f"  from coinflight's hand-off state ({len(idx)} tosses; MuJoCo {hr.integrator}, "
        f"condim {hr.condim}, {hr.solver}, damping ratio {hr.dampratio:.4f}; "
        f"{hr.elapsed:.0f} s wall, {hr.steps:,} steps)"
    )
    print(f"    coinflight             : {frac(ours)}")
    print(f"    MuJoCo                 : {frac(hr.rest)}")
    ours_e, theirs_e = ours == EDGE, hr.rest == EDGE
    print(
        f"    on edge: both {np.count_nonzero(ours_e & theirs_e)}, coinflight only "
        f"{np.count_nonzero(ours_e & ~theirs_e)}, MuJoCo only "
        f"{np.count_nonzero(~ours_e & theirs_e)}; same face {np.mean(ours == hr.rest):.1%}"
        f"; MuJoCo moving at the limit {hr.unsettled}"
    )
    print(f"    upright time, MuJoCo edges          : {spread(hr.edge_time[theirs_e])}")
    print(f"    upright time, MuJoCo, cf's edges    : {spread(hr.edge_time[ours_e])}")
    print(f"    upright time, MuJoCo, all > 0       : {spread(hr.edge_time[hr.edge_time > 0])}")
    print(f"    time to rest, MuJoCo                : {spread(hr.rest_time)}")
    return {
        "ho_index": idx,
        "ho_rest": hr.rest,
        "ho_moving": hr.moving,
        "ho_time": hr.rest_time,
        "ho_upright": hr.edge_time,
    }


def handoff_only(args: argparse.Namespace, pairs: tuple[tuple[float, ...], ...]) -> None:
    """coinflight's contact ending and MuJoCo from coinflight's hand-off states only."""
    from coinflight.core.outcome import Status

    dist, omega, v0 = study.edge_draw(args.n, args.seed, args.tosses)
    print(
        f"{args.n} {args.tosses} tosses (seed {args.seed}), from coinflight's hand-off states "
        f"only; load {os.getloadavg()[0]:.1f}"
    )
    for e, mu in pairs:
        surface = study.edge_surface(e, mu)
        out = land(dist.coin, omega, v0, 1.0, dist.g, surface)
        handed = out.status != Status.SETTLED_ENERGY
        print(f"\ne = {e:g}, μ = {mu:g}: handed {handed.sum()} ({handed.mean():.1%})")
        extra = handoff_report(e, mu, handed, out.face, omega, v0, args)
        if args.save:
            np.savez(f"{args.save}-handoff-e{e:g}-mu{mu:g}.npz", **extra)


def main() -> None:
    import mujoco_args

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=200)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--pairs", nargs="+", default=["0.5,0.3"], help="e,μ pairs")
    parser.add_argument("--tosses", choices=sorted(study.EDGE_TOSSES), default="vigorous")
    parser.add_argument("--limit", type=float, default=mujoco_compare.SETTLE)
    parser.add_argument("--integrator", default=study.EDGE_INTEGRATOR)
    parser.add_argument("--threads", type=int, default=None)
    parser.add_argument(
        "--from-handoff",
        action="store_true",
        help="also start MuJoCo from coinflight's hand-off state (the contact phase alone)",
    )
    parser.add_argument(
        "--handoff-only",
        action="store_true",
        help="only coinflight and MuJoCo from coinflight's hand-off states (no MuJoCo flights)",
    )
    parser.add_argument("--handoff-integrator", default=None, help="default: --integrator")
    parser.add_argument(
        "--condim",
        type=int,
        default=mujoco_compare.CONDIM,
        help="MuJoCo's contact dimension from the hand-off (3: sliding friction only)",
    )
    parser.add_argument(
        "--resistance-factor",
        type=float,
        default=1.0,
        help="MuJoCo's rolling and torsional friction from the hand-off, times 1e-4 m",
    )
    parser.add_argument(
        "--cone",
        choices=mujoco_compare.CONES,
        default=mujoco_compare.CONE,
        help="MuJoCo's friction cone from the hand-off",
    )
    parser.add_argument(
        "--impratio",
        type=float,
        default=1.0,
        help="MuJoCo's frictional-to-normal impedance ratio from the hand-off (elliptic cone)",
    )
    parser.add_argument(
        "--noslip",
        type=int,
        default=0,
        help="MuJoCo's no-slip iterations from the hand-off (0: none)",
    )
    parser.add_argument(
        "--solimp",
        type=mujoco_args.solimp,
        default=",".join(str(x) for x in mujoco_compare.SOLIMP),
        help="MuJoCo's impedance d0,dmax,width (m) from the hand-off (default MuJoCo's)",
    )
    parser.add_argument(
        "--timeconst",
        type=mujoco_args.timeconst,
        default=mujoco_compare.TIMECONST,
        help="MuJoCo's contact time constant solref[0] from the hand-off, s",
    )
    parser.add_argument(
        "--mujoco-restitution",
        type=float,
        default=None,
        help="MuJoCo's contact calibrated to this e from the hand-off (default: the pair's e)",
    )
    parser.add_argument("--save", default=None, help="write per-toss arrays to SAVE-e…-mu….npz")
    args = parser.parse_args()
    pairs = tuple(tuple(float(x) for x in p.split(",")) for p in args.pairs)
    solver_of(args)  # bad values refused before anything runs
    if args.handoff_only:
        handoff_only(args, pairs)
        return
    load0 = os.getloadavg()
    t0 = time.perf_counter()
    cpu0 = time.process_time()
    check = study.edge_check(
        args.n,
        args.seed,
        pairs,  # type: ignore[arg-type]
        tosses=args.tosses,
        limit=args.limit,
        integrator=args.integrator,
        threads=args.threads,
    )
    wall, cpu = time.perf_counter() - t0, time.process_time() - cpu0
    _, omega, v0 = study.edge_draw(check.n, check.seed, check.tosses)
    print(
        f"{check.n} {check.tosses} tosses (seed {check.seed}), resistances "
        f"{check.rolling_resistance:g} m, MuJoCo {check.integrator}, condim "
        f"{mujoco_compare.CONDIM}, limit {check.limit:g} s past first contact; "
        f"{wall:.0f} s wall, {cpu:.0f} s CPU, load {load0[0]:.1f} -> {os.getloadavg()[0]:.1f}"
    )
    for cell in check.cells:
        r = cell.mujoco
        h = cell.handed
        print(
            f"\ne = {cell.restitution:g}, μ = {cell.friction:g}: MuJoCo {r.elapsed:.0f} s wall "
            f"({r.steps:,} steps, {r.steps / r.elapsed:,.0f}/s; damping ratio "
            f"{r.dampratio:.3f}, flat-drop e {r.restitution:.3f}); coinflight "
            f"{cell.coinflight.seconds:.2f} s; handed to the contact phase {h.sum()} "
            f"({h.mean():.1%})"
        )
        print(f"  P({', '.join(NAMES)}) ± s.e.")
        print(f"  coinflight, all          : {pm(*cell.fractions(cell.coinflight.rest))}")
        print(f"  MuJoCo, all              : {pm(*cell.fractions(r.rest))}")
        print(f"  coinflight, handed       : {pm(*cell.fractions(cell.coinflight.rest, h))}")
        print(f"  MuJoCo, cf's handed      : {pm(*cell.fractions(r.rest, h))}")
        print(f"  MuJoCo, cf's not handed  : {pm(*cell.fractions(r.rest, ~h))}")
        print(f"  MuJoCo, settled only     : {pm(*cell.fractions(r.rest, ~r.moving))}")
        moving_edge = int(np.count_nonzero(r.moving & (r.rest == EDGE)))
        print(
            f"  MuJoCo still moving at {r.limit:g} s: {r.unsettled} ({moving_edge} on edge); "
            f"coinflight unsettled {cell.coinflight.unsettled}"
        )
        both, ours, theirs = cell.edges
        print(
            f"  on edge: both {both}, coinflight only {ours}, MuJoCo only {theirs}; same well at "
            f"first contact {cell.first_agreement:.1%}, same face at the end "
            f"{cell.rest_agreement:.1%}"
        )
        t_ours, up_ours = coinflight_times(check, cell, omega, v0)
        ours_edge = cell.coinflight.rest == EDGE
        print(f"  time to rest, MuJoCo edges     : {spread(r.rest_time[r.rest == EDGE])}")
        print(f"  time to rest, MuJoCo faces     : {spread(r.rest_time[r.rest != EDGE])}")
        print(f"  time to rest, coinflight edges : {spread(t_ours[ours_edge])}")
        print(f"  time to rest, coinflight faces : {spread(t_ours[~ours_edge])}")
        rolled = r.edge_time > 1.0
        print(
            f"  upright on the rim > 1 s: MuJoCo {rolled.sum()} tosses (of which end on edge "
            f"{np.count_nonzero(rolled & (r.rest == EDGE))}), coinflight "
            f"{np.count_nonzero(up_ours > 1.0)} (on edge "
            f"{np.count_nonzero((up_ours > 1.0) & ours_edge)})"
        )
        print(
            f"  upright time, MuJoCo faces > 1 s : {spread(r.edge_time[rolled & (r.rest != EDGE)])}"
        )
        print(f"  upright time, MuJoCo edges       : {spread(r.edge_time[r.rest == EDGE])}")
        print(f"  upright time, coinflight edges   : {spread(up_ours[ours_edge])}")
        print(
            f"  upright time, cf faces > 1 s     : {spread(up_ours[(up_ours > 1.0) & ~ours_edge])}"
        )
        extra: dict[str, np.ndarray] = {}
        if args.from_handoff:
            extra = handoff_report(
                cell.restitution, cell.friction, h, cell.coinflight.rest, omega, v0, args
            )
        if args.save:
            np.savez(
                f"{args.save}-e{cell.restitution:g}-mu{cell.friction:g}.npz",
                omega=omega,
                v0=v0,
                handed=cell.handed,
                cf_rest=cell.coinflight.rest,
                cf_first=cell.first,
                cf_time=t_ours,
                cf_upright=up_ours,
                mj_rest=r.rest,
                mj_first=r.first,
                mj_moving=r.moving,
                mj_time=r.rest_time,
                mj_upright=r.edge_time,
                **extra,
            )


if __name__ == "__main__":
    main()

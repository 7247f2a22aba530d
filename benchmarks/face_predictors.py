"""Predictors of the well a coin in the contact phase ends in, from its state now (numba; a study).

Benchmark code, not part of the package: ``bench_predictors.py`` (beside it) imports it, and
``tests/test_bench_predictors.py`` tests it; nothing in ``src/`` uses it.

Issue 11 asks for 50,000 landings a second carried to rest; the 3-D contact ending
(:mod:`coinflight.core.contact_phase`) runs ~2,000, because a handed coin spins and rolls for
~0.3 s simulated (median) while its mechanical energy is still above its well's barrier m g ρ,
much of it spin about the normal that may never lift the coin over its rim. These kernels ask
whether the well can be named earlier: each returns the face of the well the coin is in now
(:func:`coinflight.core.impact.resting_face`) when its rule fires, else −1. They are
**predictors, not proofs**: with friction none of the quantities they hold fixed is conserved.
Nothing here is wired into the contact ending; ``benchmarks/bench_predictors.py`` measures them
against carrying the coin on to rest (results below).

The state is :mod:`coinflight.core.contact_phase`'s y = (z, v, n, L) (centre height, velocity,
heads normal, angular momentum about the centre, lab frame, SI) and ``c`` its
:class:`coinflight.core.contact.Contact` record.

The family (:func:`corner_barrier`, :func:`lifting_energy`): the least energy of the coin
balanced on a corner of its well, n_z = ±sin(arctan(h/d)) (the top of the barrier, Yong &
Mahadevan 2011, eq. 1), with a share of the energy that the angular momentum it cannot lose
would still hold there,

    B(s_n, s_z) = m g ρ + s_n (L·n)² / (2 I3) + s_z (L_z − (L·n) n_z)² / (2 I1 (1 − n_z²)),

the corner's n_z taken on the side the well's rim lies (for the edge well, the lower of the
two). Balanced on the corner the centre is at rest and ω is split into the spin about n,
L·n / I3, and a part about an axis across n whose vertical angular momentum is what L_z
leaves after the spin's share (L·n) n_z; its least energy is the second term (L − (L·n) n has
the vertical component L_z − (L·n) n_z and is at least 1/sqrt(1 − n_z²) times longer, so
I1 ω_⊥ ≥ (L_z − (L·n) n_z)/sqrt(1 − n_z²)). A rule fires when the mechanical energy
(:func:`coinflight.core.contact_phase.energy`, the springs' with it) less a share s_h of the
horizontal kinetic energy ½ m v_h² is below B(s_n, s_z).

- **(a) the frictionless rule used with friction**, ``(1, 1, 1)``: exact without friction and
  resistances: the normal forces are vertical (the horizontal momentum is kept) with
  horizontal moments (L_z is kept), and each moment is perpendicular to n too (the rim point,
  the centre and n lie in one vertical plane), which is all an axisymmetric body's L·n needs
  to be kept (d(L·n)/dt = τ·n + L·(ω × n), the second term 0 for L = I1 ω + (I3 − I1)(ω·n) n).
  So B(1, 1) equals :func:`coinflight.core.contact_phase._barrier`'s frictionless branch
  (:func:`corner_barrier` calls its ``_corner_energy``)
  and the rule is :func:`coinflight.core.contact_phase.below_barrier`'s there. With friction
  the rim's tangential force has a moment about n (the rim point's lever crossed with a
  horizontal force) and about the vertical, and it turns sliding into rolling: it can trade
  all three for lift (a rolling disc above its critical spin rises towards upright, O'Reilly
  1996; a tippe-top-like rise).
- **(b) the spin locked**, ``(1, 0, 0)``: only (L·n)² / (2 I3) is counted as unable to lift;
  the vertical angular momentum and the sliding are left free. A heuristic, not a bound: the
  pivoting torque −(μ r_t + ℓ_p) F_n ω_z/sqrt(ω_z² + ω_ε²) is about the vertical
  (``contact_phase._derivative``), so its part along n is that torque times n_z: for a nearly
  flat coin it acts on L·n almost fully, and for a coin rolling without slip the spin about n
  is the rolling itself, which friction changes as the coin rolls. No bound of what pivoting
  friction can return to lift was derived (the brief's "spin locked with a bound" is not done);
  what (b) rests on is measured only. B(1, 0) ≤ B(1, 1): (b) fires on a subset of (a).
- **(c) half of (a)**, ``(0.5, 0.5, 0.5)``: half of what (a) sets aside is assumed
  returnable by friction; a hedge between (a) and the proof, with no physical argument for the
  half.
- **(d) spin and sliding locked**, ``(1, 0, 1)``: (b) with ½ m v_h² set aside too (a coin
  sliding flat cannot turn its slide into lift without rolling up its rim): the "tumbling
  energy" ending of the contact phase's notes (disagreeing on 23-30 of ~226 tosses there).
- **the proof**, ``(0, 0, 0)``: B = m g ρ; with friction or resistance the mechanical energy
  only falls (the damping and friction dissipate), so a coin below it stays in its well: the
  contact ending's own rule, no earlier.

All four are one family (shares of the same three energy terms). Not tried: rules on the tilt
(the rolling disc's Chaplygin integrals bounding how far a rolling coin can rise towards
upright, or a tilt-and-energy rule), although the failure measured below (rolling coins
rising to the edge) is what such a rule would address.

Properties tested (``tests/test_bench_predictors.py``): the mirror toss n → −n (the same body
with heads and tails swapped; ω unchanged) gives the other face, edge to edge, B to the bit;
(a) is ``_barrier`` and ``below_barrier`` when frictionless and (0, 0, 0) is
``below_barrier`` with friction; each rule is monotone in the energy (more vertical speed
never makes it fire) and in its shares.

Results at resistances ℓ_r = ℓ_p = 1e-4 m (2026-11-24, 05:07-05:15 UTC, re-run on the final
benchmark by the review, load 6-9 on the shared 2-core machine; counts of
simulated steps, not timings, so the load does not enter them). ``python
benchmarks/bench_predictors.py 600 --seed 2026`` (the design seed: the rules and their shares
were fixed before it and not changed after it) and ``600 --seed 7`` (the report seed, below);
US nickel, vigorous tosses, 0.8 m drop, resistances 1e-4 m, t_c 1 ms, carried on to rest in
2 ms chunks without the upright decision. A decision counts when a rule fires before the toss
settles, and disagrees when its face is not the face at rest. Speed-up: the phase's steps over
the steps left when each decided toss stops at its decision (steps counted on a run without
chunks, ``bench_predictors.segmented``); "shipped": against the phase as it runs, with
:func:`coinflight.core.contact_phase.upright_decided`, the rule added to it. These are ratios
of steps; a step's cost differs a little between modes.

Report seed 7, resistances 1e-4 m (427, 423, 405 handed of 600 at e 0.5 μ 0.3; e 0.5 μ 0.6;
each toss its own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6)); decided early, disagreements (95 %
Clopper-Pearson upper bound of their rate), speed-up against carrying on / against the
shipped phase:

- (a) 409, 393, 389; **49, 127, 93 disagreements (≤ 0.155, 0.372, 0.285)**; 4.14×, 17.6×,
  7.96× / 2.03×, 2.16×, 2.69×. Where it fails: faces that end on edge (22, 85, 44: rolling
  coins rising upright — friction turns rolling and sliding into lift, as a rolling disc
  above its critical spin rises, O'Reilly 1996, where the frictionless rule sets ½ m v_h²
  and the precession aside), face flips (24, 38, 34: a coin decided on one face rolls over
  to the other), and edges that fall (3, 4, 15); its wrong decisions come a median 0.31,
  5.0 and 0.83 s before rest (the rising rollers then roll upright for seconds).
- (b) 245, 319, 245; 0, 0, 0 (≤ 0.015, 0.011, 0.015); 1.01× / 1.01-1.02×: the only rule
  with no disagreement (0 of ~1,650 decisions over both seeds), and useless: the spin about n
  is a small part of a handed coin's energy (median 0.03-0.10 of a barrier m g ρ − m g h/2,
  against 1.4-2.2 above m g ρ), so it fires ~1 % of the contact time before the proof does.
  The brief's premise that the spin holds the energy does not hold for these tosses: the
  energy above the barrier is tumbling, sliding and height.
- (c) 385, 374, 371; 1, 3, 1 (≤ 0.014, 0.023, 0.015); 1.03-1.06× / 1.07-1.12×: near-safe
  (10 disagreements in ~2,300 decisions over both seeds), and the project adopts a predictor
  only at 0.
- (d) 403, 386, 384; 20, 99, 53 (≤ 0.076, 0.303, 0.177); 2.58×, 13.9×, 4.06× / 1.27×,
  1.71×, 1.37×; 15, 66, 34 of them faces that end on edge (the rising rollers).
- the upright decision, for comparison: 46, 175, 65; 0, 0, 0 (≤ 0.077, 0.021, 0.055);
  2.03×, 8.13×, 2.95× against carrying on (what the shipped phase has already).
- **the ceiling, "last well change"**: an oracle naming the final well at the first chunk
  end after which the coin is never seen outside it (166, 98, 152 tosses never leave the
  well they are handed in): 3.90×, 12.9×, 6.03× against carrying on, **1.92×, 1.59×, 2.04×
  against the shipped phase**. This caps rules that fire only once the coin cannot leave its
  well (a sound energy bound is one): none of them, however good, makes the shipped phase
  faster than that at 1e-4 m. A rule that names the well the coin is in but may fire while it
  can still leave it is not capped by it (the next item). At 1e-4 m the steps are spent while
  the coin still changes wells (bouncing, hopping, rolling over); the time after its last
  change (89-95 % of the contact time, median) is cheap once the upright rollers are decided.
- **a lucky rule's ceiling, "first in final well"**: the first chunk end at which the coin is
  in the well it ends in (254, 170, 256 are in it at the hand-off, 88, 72, 104 of them
  leaving it and coming back): 48.7×, 70.4×, 54.8× / **23.9×, 8.67×, 18.5×**. Only there is
  the target's factor: a rule naming the final well while the coin can still leave it, which
  no bound on energy can do (it has to predict the excursions' outcome).
- **the well at the hand-off**, the naive such rule (every toss decided at once): wrong on
  173, 253, 149 (41 %, 60 %, 37 %; three outcomes): the hand-off's well says little.

The design seed 2026 (429, 446, 430 handed) agrees: (a) 55, 145, 73 disagreements of 408,
410, 410 (2.08×, 2.22×, 2.29× shipped); (b) 0, 0, 0 of 252, 322, 263 (1.01-1.02×); (c) 0,
5, 0 of 383, 397, 387 (1.08-1.10×); (d) 23, 122, 48 of 401, 405, 403 (1.26×, 1.87×,
1.31×); the oracle 1.88×, 1.59×, 1.88× shipped. Chunking: faces or settling of the chunked
run and of the run without chunks differ on 0-3 tosses of each ~430 (a restart changes the
trajectory at the rounding level, which a wobble can grow). The chunk (the resolution of
every first firing and of the oracle) hardly matters: seed 2026, e 0.5 μ 0.3, chunks of 1, 2
and 5 ms give (a) 57, 55, 55 disagreements and 2.10×, 2.08×, 2.05× shipped, (c) 1.10×,
1.10×, 1.09×, (d) 1.26×, 1.26×, 1.25×, the oracle 1.87×, 1.88×, 1.86×.

Results at resistances ℓ_r = ℓ_p = 1e-5 m (2026-11-24, 05:53-06:03 UTC, load 4-6; the rolling
resistance ``bench_contact.py`` also studies): ``python benchmarks/bench_predictors.py 300
--seed 7 --resistance 1e-5`` (205-210 handed of 300; e 0.5 μ 0.3 run twice, by the review and
here, to the same numbers: 206 handed, 0 unsettled). Decided early; disagreements; speed-up
against carrying on / against the shipped phase, e 0.5 μ 0.3, e 0.5 μ 0.6, each toss its own e,
μ:

- (a) 198, 194, 200; 37, 83, 47; 24.9×, 118×, 52.0× / 18.8×, 90.4×, 41.6×.
- (b) 119, 142, 129; 0, 0, 0 (≤ 0.031, 0.026, 0.028); 1.01× / 1.00×.
- (c) 184, 181, 186; 1, 1, 1; 1.02-1.03× / 1.00-1.01×.
- (d) 195, 192, 199; 9, 71, 31; 14.2×, 92.9×, 25.5× / 10.8×, 71.3×, 20.4×.
- the upright decision: 28, 78, 35; 0, 0, 0; 1.32×, 1.30×, 1.25× against carrying on; it
  saves a median 30 %, 39 %, 32 % of the contact time of the coins it decides (92-96 % at
  1e-4 m): the long upright rollers (66-160 s simulated) are decided late.
- **"last well change"**: 19.3×, 79.7×, 41.5× / **14.6×, 61.1×, 33.2× against the shipped
  phase**; "first in final well" 212×, 387×, 332× shipped; the well at the hand-off wrong on
  87, 131, 80.

At 1e-5 m the chunked run reaches ``MAX_STEPS`` (counted with its restart steps, after
~160 s simulated) on 7 of 205 (μ 0.6) and 2 of 210 (own) edge rollers, which count as
unsettled, i.e. as disagreements of every rule that decided them (the oracles' only ones); the
run without chunks differs from it on 7 and 1 tosses. So the ceiling of rules that fire
once the coin cannot leave its well is a range over the unmeasured resistance: 1.9-14.6×
(e 0.5 μ 0.3), 1.6-61× (e 0.5 μ 0.6), 2.0-33× (own e, μ) over ℓ in [1e-5, 1e-4] m. At 1e-5 m
the remaining time is not spent changing wells: it is the upright rollers', rolling on their
edge for a minute or more after their last well change, which the shipped upright decision
ends late; there the upright decision's timing, not the well changes, is what an earlier
decision would have to improve.

**Conclusion**: no energy rule of this family is both safe and useful: (b), the only one with
no disagreement, makes the shipped phase ≤ 1.02× faster; (c), near-safe (10 disagreements in
~2,300), ≤ 1.12×; (a), 2.0-2.7× faster at 1e-4 m, names the wrong well on 12-32 % of its
decisions, (d), 1.3-1.7×, on 5-26 %. A rule that fires only once the coin cannot leave its well
makes the shipped phase at most 1.9-14.6× faster at e 0.5 μ 0.3 (1.6-61× at μ 0.6, 2.0-33× with
each toss's own e, μ; the last-well-change oracle, seed 7, over ℓ_r = ℓ_p in [1e-5, 1e-4] m,
the low end at 1e-4 m); past that only a rule naming the final well while the coin can still
leave it (the lucky ceiling, 9-24× at 1e-4 m), a prediction, not a bound. At 1e-4 m the 50,000
landings a second (~25× away) need the motion before the last well change made cheaper, or a
predictor of the outcome of the excursions still to come (a learned or a reduced dynamical one,
not an energy bound; not attempted); at 1e-5 m the time after the last well change is the
upright rollers', so there the upright decision's timing is what to improve. Nothing here is
used by the landings.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from coinflight.core.contact_phase import _corner_energy, energy
from coinflight.core.impact import resting_face

SHARES = np.array([[1.0, 1.0, 1.0], [1.0, 0.0, 0.0], [0.5, 0.5, 0.5], [1.0, 0.0, 1.0]])
"""The (s_n, s_z, s_h) of predictors (a), (b), (c) and (d) of the module notes, one row each."""
NAMES = (
    "(a) frictionless rule",
    "(b) spin locked",
    "(c) half of (a)",
    "(d) spin, sliding locked",
)
"""The predictors of :data:`SHARES`, in its order."""


@njit(cache=True)
def corner_barrier(y, c, spin_share, turn_share):
    """B(s_n, s_z) of the module notes, J: the least energy of the coin balanced on a corner of
    its well at the current L·n and L_z, the spin's and the precession's terms weighted by
    ``spin_share`` s_n and ``turn_share`` s_z. Built on
    :func:`coinflight.core.contact_phase._corner_energy` (the one formula): its full value on
    the corner less (1 − s_n) times its spin term (its value at L_z = n_z = 0, less m g ρ) and
    (1 − s_z) times its precession term (its value at L·n = 0 with L_z − (L·n) n_z, less
    m g ρ). So (1, 1) is :func:`coinflight.core.contact_phase._barrier`'s frictionless branch
    to the bit (the same call, less 0.0) and (0, 0) is m g ρ to rounding (a few ulps)."""
    ln = y[4] * y[7] + y[5] * y[8] + y[6] * y[9]
    lz = y[9]
    nz = y[6]
    corner = c.edge_sine
    spin = _corner_energy(ln, 0.0, 0.0, c) - c.barrier
    up = (
        _corner_energy(ln, lz, corner, c)
        - (1.0 - spin_share) * spin
        - (1.0 - turn_share) * (_corner_energy(0.0, lz - ln * corner, corner, c) - c.barrier)
    )
    down = (
        _corner_energy(ln, lz, -corner, c)
        - (1.0 - spin_share) * spin
        - (1.0 - turn_share) * (_corner_energy(0.0, lz + ln * corner, -corner, c) - c.barrier)
    )
    if abs(nz) < corner:
        return min(up, down)
    return up if nz > 0.0 else down


@njit(cache=True)
def lifting_energy(y, c, stiffness, slide_share):
    """The mechanical energy (:func:`coinflight.core.contact_phase.energy`, the springs' with
    it) less ``slide_share`` s_h of the horizontal kinetic energy ½ m v_h², J. With s_h = 1 it
    is :func:`coinflight.core.contact_phase.free_energy`'s frictionless energy to the bit."""
    e = energy(y, c, stiffness)
    return e - slide_share * (0.5 * c.mass * (y[1] * y[1] + y[2] * y[2]))


@njit(cache=True)
def predict(y, c, stiffness, spin_share, turn_share, slide_share):
    """The face (TAILS 0, HEADS 1, EDGE 2) of the well the coin is in if
    :func:`lifting_energy` (``slide_share``) is below :func:`corner_barrier` (``spin_share``,
    ``turn_share``), else −1. ``stiffness``: the contact's κ
    (:func:`coinflight.core.contact_phase.stiffness_of`), for the springs' energy."""
    free = lifting_energy(y, c, stiffness, slide_share)
    if free < corner_barrier(y, c, spin_share, turn_share):
        return resting_face(y[6], c.edge_sine)
    return -1


@njit(cache=True)
def predict_all(y, c, stiffness, shares, out):
    """:func:`predict` for each row (s_n, s_z, s_h) of ``shares`` (shape (k, 3)), into ``out``
    (shape (k,), int)."""
    for i in range(shares.shape[0]):
        out[i] = predict(y, c, stiffness, shares[i, 0], shares[i, 1], shares[i, 2])

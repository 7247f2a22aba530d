"""The coin in persistent contact with the table, in 3-D, until it cannot leave its well (numba).

When the bounces of :mod:`coinflight.core.bounce` die out (a rebound slower than
``rest_speed``), the coin is not at rest: it rocks, rolls and slides on its rim, spins and
precesses like Euler's disk, touches with two rim points or slaps its face. This module carries
that motion on until the coin's energy can no longer take it over the barrier between its well
and the next one, and says which well that is.

**Experimental, opt-in** (``Surface(ending="contact")``; the default end of a landing is the
planar rocking of :func:`coinflight.core.bounce.rock`).

**Speed** (issue 11 asks for 50,000 landings a second carried to rest on 2 cores). The changes
below (first same as last, the energy test's shortcut, one tangent basis) make a landing with
this ending 1.24-1.39× cheaper per CPU second in one thread, measured with ``python
benchmarks/bench_bounce.py --contact-rates N --old-src DIR`` (vigorous tosses of a US nickel, e
= 0.5, μ = 0.3, and each toss's own e ~ U(0.2, 0.8), μ ~ U(0.1, 0.6); rounds alternated with the
code before, main at 6061499, in a subprocess; medians of the rounds; the shared 2-core
machine): 300 tosses at load 10.6 (2026-11-23 23:56 UTC) 1.27× and 1.31×; 600 tosses at load
9.8-6.1 (00:31 UTC) 1.24× and 1.36×; a reviewer's runs at load 2.4-3.9 1.31×, 1.39× and 1.34×;
with the review's fixes (the arc's energy clamped at 0, the step tolerance a run-time argument,
no chunk size), 300 tosses at load 4.2-4.8 (00:57 UTC) 1.27× and 1.33×. Faces differed on 0-1
tosses of each run, statuses on none. The wall-clock rates with both threads move with the other
processes' load (1.08-1.39× in the first two runs; e.g. 783 against 562 landings a second at
load 10.6, 1,184 against 1,098 at 9.8-6.1) and are not the measure of the change. Quiet (load
1.4-1.8, 2026-11-24 01:46 UTC, the same command, 300 tosses, against the code before at
6061499): **2,954 a second against 2,245** (1.32×; one thread 1.29×), each toss its own e, μ
2,645 against 2,018 (1.31×; 1.34×); faces differing on 0 and 1 of 300. So 50,000 was then ~17×
away. The sliding-mass damper (2026-11-24, "Restitution") makes each derivative dearer: quiet
(load 0.8-1.1, 2026-11-24 04:25 UTC, the same command against main at 507692d, before it, and at
51e4b64, before it but with the DECIDED_UPRIGHT status) **1,998 a second against 2,998** (0.67×;
one thread 969 against 1,465 per CPU second, 0.66×), each toss its own e, μ 1,778 against 2,599
(0.68×; 0.69×); against 51e4b64 0.67× and 0.67-0.69× alike; against 51e4b64 with the damper
alone merged, 0.98× and 1.01× in one thread, faces identical: the cost is the damper's, not the
rigid contact's shared energy helper merged with it. Faces differing on 21 and 10 of 300 against
507692d. 50,000 was then ~25× away. Then (2026-11-24, "fastrho") each rim's arc, centroid and
collision-matrix row computed once per derivative and shared by the damper and m_eff
(:func:`_rim` with the friction, :func:`_damper`), the rim inlined into the derivative and the
tests after each step into the stepper (numba's ``inline="always"``; the derivative itself not,
for its compile time, :func:`_derivative`), all identical to the bit (:func:`_derivative`,
:func:`_integrate` say what was measured): the same command against main at 4f0dfa5 (2026-11-24
06:20 UTC, load 1.0-1.4) **1,736 a second against 989** (1.76×; one thread 1,455 against 977 per
CPU second, 1.49×), each toss its own e, μ 1,344 against 899 (1.50×; one thread 1,372 against
907, 1.51×): the rate before the damper (1.50× 4f0dfa5, 1.51× in one thread, from the quiet
figures above). Faces differing on 0 of 300 (the benchmark's "statuses 27/43" are its own
mapping of DECIDED_UPRIGHT for a tree that has it too); face, bounces, first contact, settling
time and status identical to the bit to 4f0dfa5's on 300 tosses in each of five settings (e, μ
0.5, 0.3; 0.2, 0; 0.6, 0.9 with resistances; 0.4, 0.5 with a 0.3 mm corner radius; each toss its
own e, μ). The derivative inlined too was 1.61× 4f0dfa5 (05:31 UTC, load 8.4-7.7; one thread
1.63×; each toss its own e, μ 1.64×, 1.70×), 1.10× the code now in one run (06:22 UTC, load
1.9-2.4; one thread 1.08×; each its own 1.08×, 1.13×), at twice the compile time; that code's
faces and statuses on 2 × 2,000 of the benchmark's tosses equal to 4f0dfa5's, and so were those
of the same tosses with ωx moved by one ulp (which moves 4 faces and 2 statuses of the 2,000
with each toss its own e, μ, and none of the 2,000 at e 0.5, μ 0.3, in either code). Scaled by
the quiet 1,998 a second, ~3,000 a second: 50,000 is ~17× away, and what is left is the number
of steps (see below), not their price.

The routes measured together on the same tosses (``python benchmarks/bench_ceiling.py 600``,
seed 7, 2026-11-24 07:36-07:43 UTC, load 8.5-5.9, one thread; e 0.5 μ 0.3, e 0.5 μ 0.6, each
toss its own e, μ; ℓ_r = ℓ_p = 1e-4 m): stopping each toss at its last well change (an oracle:
no sound "cannot leave its well" rule does better) 1.88×, 1.68×, 2.04×; RTOL 1e-5 1.57-2.00×;
both 3.71×, 2.78×, 3.83× (a product); hops flown at no cost, 31-45 % of what is left, 1.45-1.82×
more: the phase 4.0-6.7× cheaper, landings (the bounces, ~3 % of the CPU, unchanged) 3.7-5.7×,
**8,600-16,500 a second: 50,000 is 3.0-5.8× out of reach by these routes** (upper estimates:
``land``'s own and the batch's overhead left out; the rigid contact's fewer steps at the
compliant step's price, a hypothetical, 12,700-23,500). Against the steps' caps (``python
benchmarks/bench_ceiling.py 300``, 2026-11-24 08:02-08:06 UTC, load 2.1-4.5): steps at
:data:`MAX_STEP` (which binds: π/8 / |ω| only above 392.7 rad/s), stopped at the oracle, would
be 3.4-4.1× fewer (~9,000 a second), 6.3-8.3× with the hops in closed form (hops carry 62-73 %
of the rotation); only an ideal integrator unconstrained by :data:`MAX_STEP`, π/8 a step in
contact, with the hops in closed form and the oracle, would give 46,600-60,900 a second at
today's step price.

Where the time goes (the same 300 tosses, one thread, 23:33 UTC, load 2-5; measured with an
ad-hoc profile that is not in the repository: the steps by mode as :func:`advance`'s
``stats`` gives them, the costs per step by timing the pieces alone): 213 are handed to
this phase, which takes 98 % of the landings' CPU time; a handed toss takes a mean 823 steps
(median 605, largest 3,725; the 10 % longest hold 28 % of the steps): on one rim 73 % of the
steps (59 % of the simulated time, a mean step of 0.37 ms), hops 20 % (36 %, 0.85 ms:
:data:`MAX_STEP` holds them), on both rims 7 % (5 %), on the face ~0. A step was ~1.45 μs of
CPU (load 8-12): 12 % of the trial steps rejected (20,865 against 175,365 accepted) and a
seventh evaluation of the derivative after n's renormalisation in 96 % of the steps made ~7.7
evaluations per accepted step, ~90 ns each in contact (~50 ns in flight); the energy test
after each step ~210 ns (both rims' spring sums); the stepper's own arithmetic ~150 ns
(measured with a trivial derivative); :func:`upright_decided` ~30 ns. Nothing is allocated on
the heap per step (the stage arrays once per toss, vectors as tuples). Now a step is ~1.1 μs
(derived from the one-thread ratio ~1.3×, not measured itself): the energy test skips the
springs when the rest of the energy already reaches the barrier (:func:`below_barrier`,
decisions identical to the bit), the stepper keeps first same as last across the
renormalisation (six evaluations a step), the derivative builds the tangent basis once for both
rims. Before and after on 3 × 2,000 tosses (e 0.5, μ 0.3; e 0.5, μ 0.6; each toss its own e,
μ): faces differ on 6, 0 and 3, statuses on none; a change of the inputs by one ulp (ωx) flips
2, 0 and 6 faces (1 status) of the code before: the changes move outcomes no more than rounding
does. Tried and not kept: a PI step-size control (β = 0.04: 38 % fewer rejections, 6 % more
steps, no faster); numba's "numpy" error model (no change). What is left is the number of
steps, held
by the stiffness of the compliant contact and of the regularised friction (the explicit
stepper's stability) and, since the upright decision, by :data:`RTOL` too (1e-5: 44 % fewer
steps than 1e-7; see :data:`RTOL`). The sound routes measured together (above) give at most
~16,500 a second; what remains conceivable for 50,000 is steps several times longer in contact
(an integrator held neither by the contact's stiffness nor by the tolerance at the rotation's
scale; the rigid contact's measured steps are not that) with the hops flown in closed form and
the oracle, or a step 3-6× cheaper on top of those routes (none in view), or a predictor of the
final well, or a revised target. The figures below, to "Upright rollers", are from before the
upright decision and these changes. All figures of these notes not dated otherwise (the
costs, edge rates and MuJoCo comparisons below, the upright decision's counts) were measured
before the sliding-mass damper (2026-11-24, "Restitution"), which moves single landings as a
change of the dynamics does ("Convergence of a rim impact": faces of 2,000 tosses, edges not
significantly), and all of them but those the paragraph "Two rims" re-measures before the
joint damping of two pressed rims (2026-11-24, :data:`JOINT_DAMPING`).

Where the cost is, ``python benchmarks/bench_contact.py 300`` (the same kind of tosses, each
with its own e and μ, resistances 1e-4 m; load 3-7): 68-76 % of tosses are handed to this
phase (their whole energy is above the barrier when the bounces die out), bringing a median
2.5 barriers (m g ρ − m g h/2) above a face at rest: horizontal translation 0.25-0.37, spin
about n 0.03, tumbling 0.8, vertical motion and height 0.9 (the coin is tilted on its rim).
A handed toss is integrated for a median 0.30 s of simulated time and ~760 steps (quartiles
240-1,900), a mean of 2,500-3,000 steps, ~3-5 μs each as measured then (~1.45 μs of CPU before
the changes above, ~1.1 μs after them, derived): the 10 % longest tosses take 61 % of the
steps. By what
the coin is doing (:func:`contact_mode`): on both rims (upright in its edge band: coins rolling
in the sharp rim's edge well for up to ~9 s until the rolling resistance stops them) 75 % of
the simulated time and 67 % of the steps; on one rim point
(rolling, sliding, rocking) 17 % and 27 %; hops 7 % and 5 %; lying on the face ~0 %, so a
sound "a coin face-flat cannot tip" ending would decide nothing here. The step was then held by
the contact's stiffness (explicit stability), not by the tolerance: RTOL 1e-5 or MAX_STEP 4 ms
left the mean steps within 15 % (1,030 handed tosses; superseded since the upright decision,
see :data:`RTOL`). Endings looser than the rigorous one
either save little or end tosses in another well than carrying them on (each checked after
every step, its well compared with the end's; measured by ``bench_contact.py 300`` as it was
up to commit 60d1237, when these probes were removed from the integrator): the mechanical
energy less ½ m v_h² below the barrier saves 5-8 % of the steps and disagrees on 6 of 226
tosses; the tumbling energy (less ½ m v_h² and (L·n)²/2I3, as
:func:`coinflight.core.bounce.tumbling_energy`) saves 42-72 % and disagrees on 23-30 of
226-228 (≥ 7 % at 95 %). None is used.
(These figures are without the upright rollers' decision, "Upright rollers" below, which
ends the coins rolling upright in the band early and makes the landings 3-8× faster.)
The 50,000 a second would need this phase ~300-1,000 times cheaper: a decision at the
hand-off for nearly every toss, or a constrained (rolling/sliding rim) model integrated with
steps far longer than the compliant contact's ~0.5 ms; neither is here.

Its edge rates are not credible. Of the handed tosses above (1,030 of 1,500, ``python
benchmarks/bench_contact.py 1500 --corner a --contact-time t_c``), P(edge) is 0.207 with sharp
corners (t_c 1 ms; 0.181 at 0.5 ms, 0.078 at 4 ms), 0.187 at a corner radius a = 0.2 mm, 0.175
at 0.5 mm (0.004 at t_c = 4 ms), 0 at 0.95 mm (a rim without a flat band; the a > 0 values
measured while the flight and the impacts still met the sharp cylinder, not re-measured since
they meet the rounded rim); the rocking ending
gives ~1/100-1/1,000 and Murray & Teare 1 in 6,000. The edge rate converges as t_c falls (0.5
and 1 ms differ by 1.5 standard errors of the difference; 4 ms is too soft), so it is the
model's, not the numerics': any flat band on the rim holds a coin rolling slowly upright. The
dynamics are not the cause: a thin disc rolling on its rim falls below the critical spin of a
rolling disc, Ω_c² = m g r I1 / (I3 (I3 + m r²)) (O'Reilly 1996), and rolls on upright above it
(tests/test_contact_phase.py). The rim is: modelled as a flat band with sharp corners, it gives
a nickel a static edge well arctan(h/2r) = 5.3° wide, which holds a coin rolling slowly upright
until the rolling resistance stops it, where a thin disc falls (the same test). Rounded corners
(``Contact.build(corner_radius=a)``, the coin's ``Coin.corner_radius``: the rim circles are
those of a cylinder (r − a, h/2 − a) swept by a ball of radius a, the edge well
arctan((h/2 − a)/(r − a)) wide, none for a = h/2) narrow the well but leave it until a ≈ h/2,
and how fast the edges go depends on a and on the resistances, none of them measured for a
coin (``python benchmarks/bench_bounce.py --contact N`` prints the table). What a real coin
has and this model lacks (an uneven table, a rim that is not a perfect band) is not known
here.

An independent engine does not give these edges. ``python benchmarks/bench_mujoco_edges.py 1500
--pairs 0.5,0.3 0.5,0.6`` (:func:`coinflight.studies.landing.edge_check`, seed 2026; the project
machine's 2 cores shared, load 4-6, 2026-11-23 17:51-18:32 UTC: 2,406 s wall, 1,226 s of CPU)
lands the same 1,500 vigorous tosses here (sharp corners, ℓ_r = ℓ_p = 1e-4 m) and in MuJoCo 3.17
(a sharp cylinder, condim 6, rolling and torsional friction 1e-4 m: the same lengths, a torque
bounded by a length times the normal force; pyramidal cone, RK4 at 0.1 ms, contact time constant
1 ms, damping calibrated to e by a flat drop; each toss carried to rest or 20 s past its first
contact). Same well at the first contact 99.3 %. P(edge) among the tosses handed to this phase,
here against MuJoCo on the same tosses: **0.115 ± 0.010 against 0.012 ± 0.003** (e 0.5, μ 0.3;
1,077 handed) and **0.435 ± 0.015 against 0.043 ± 0.006** (μ 0.6; 1,067); of all tosses 0.083
against 0.011 and 0.309 against 0.035 (MuJoCo: 2 and 11 tosses still moving at 20 s, counted by
their well). On edge in both engines 2 and 20 tosses, here only 122 and 444, in MuJoCo only 14
and 33. MuJoCo's edge-enders stand on their rim at least as long as ours (median 14.6 and 10.9 s
upright, against 7.1 and 7.8 s here; this phase's figures of this paragraph re-measured with the
sliding-mass damper, 2026-11-24 04:59-05:44 UTC, main 4f0dfa5, load 1.9 at the start and 6.0
at the end: before it 0.123 and 0.439, of all 0.088 and 0.312, on edge in both 2 and 23, here
only 130 and 445, upright 6.7 and 7.9 s, from the hand-off states 49, 0.110 ± 0.015; MuJoCo's
are the 2026-11-23 run's, its runs do not involve this phase): both engines hold a coin that
rolls upright in the flat band until the rolling resistance stops it, but MuJoCo brings about
ten times fewer coins there.
Started from this phase's own hand-off states (the impacts left out; ``--handoff-only``, 600
tosses, seed 2026, 446 handed, e 0.5, μ 0.3, load 2), MuJoCo again leaves 0.013 ± 0.005 on edge
where this phase leaves 0.099 ± 0.014 (MuJoCo 6 of 446 with Euler and with RK4 alike, in 23 and
175 s; this phase 44; the same face on 66-68 %; on 104 of these, Euler or RK4, a pyramidal or
elliptic cone, a time constant of 1 or 0.5 ms, a stiffer impedance or no-slip friction all leave
0 or 1 on edge against 8 here). The rim is not the difference: MuJoCo's cylinder has the same
static edge well (two contact points; a coin tilted 5° from upright comes back, at 6° it falls)
and agrees with this phase on a coin rolling upright (0.1, 0.3, 1 m/s: upright 1.7, 5.0, 16.6 s
in MuJoCo, 1.2, 4.4, 15.8 s here to the end of its settle test). So the edge rate is not the
sharp rim's in both engines: it is this contact model's, in how it turns a wobbling, sliding
coin on its rim into an upright roller (in the one toss traced from the hand-off, a coin landing
near upright rolls here within 25 ms, while in MuJoCo it slides and falls flat).
Why, measured (2026-11-23, 19:00-19:29 UTC, load 1-4): this model's numerics are cleared and no
bug was found. From the same 446 hand-off states, ``python benchmarks/bench_edge_sensitivity.py
600`` with one parameter changed, this phase leaves on edge 49 (0.110 ± 0.015) by default; with
:data:`SLIP_SPEED` × 3, 0.3, 0.1, 0.03: 44, 47, 51, 53 (× 0.01, every 2nd toss: 23 of 223, 16 of
them stopped by MAX_STEPS and counted by their well), so the regularised friction is converged
to its Coulomb limit, not a viscous sticking; t_c 0.25, 0.5, 2 ms: 47, 43, 67; the damping ratio
× 0, 0.5, 2, 4: 35 (12 unsettled), 58, 43, 41; μ 0.1, 0.6, 1: 29, 91, 111; resistances 1e-6 m:
55 (47 stopped by MAX_STEPS). The energy never grows (112 of these tosses, 0.6 s each sampled
every 1 ms: the largest rise 1e-14 of the energy), and an upright coin sliding in its plane
comes to roll at the closed-form speed, time and friction work (tests/test_contact_phase.py).
Part of the gap is MuJoCo's: its condim 6 puts sliding, rolling and torsional friction in one
cone, so a coin that rolls while it slides is braked by less than μ F_n; with condim 3 (sliding
friction only; ``python benchmarks/bench_mujoco_edges.py 600 --handoff-only --condim 3``) MuJoCo
leaves 23 of the 446 on edge (0.052 ± 0.011; 32 still moving at 20 s, counted by their well; 17,
25 moving, with its damping calibrated at 4.556 m/s instead of 4.548: the tosses are chaotic),
with condim 6 and resistances 1e-6 m (``--resistance-factor 0.01``, calibrated at 4.556 m/s) 10;
at μ 0.6 from the same states 27 with condim 3 (calibrated at 4.556 m/s), against 94 here with
resistances 1e-6 m: a factor 2.4-3.5 remains, with no resistance in play in either engine. The
hand-off states are mid-impact (the coins hop again), and there the two soft contacts part:
oblique rim impacts of a spinning nickel (``python benchmarks/bench_rim_impacts.py 200
--friction μ``: tilt 9-80°, ω 50-300 rad/s, e 0.5), compared 3 ms after the touch with Stronge's
rigid impact (:func:`coinflight.core.impact.impact`, the law of the bounces). Frictionless,
MuJoCo follows the rigid law closely (velocity within a median 0.025 m/s, angular momentum 5 %
of I1 ω; kinetic energy lost 0.269 against 0.264) and this phase less so (0.064 m/s, 13 %,
0.276: a fast-spinning coin turns during a 1 ms contact; at t_c 0.25 ms less than half of it);
with μ 0.3 this phase stays as close (0.061 m/s, 20 %; energy lost 0.449 against the rigid
0.426) while MuJoCo moves away (0.146 m/s, 15 %) and takes less energy (0.371): its friction in
a short rim impact does less work than Coulomb's, as in the traced toss, where its coin keeps
sliding. That lead was tested and **ruled out** (2026-11-23, 21:00-22:05 UTC, load 7-14): made
Coulomb-hard (``bench_mujoco_edges.py 600 --handoff-only --condim 3`` with ``--cone elliptic
--impratio 10`` or ``100``, or ``--noslip 20``) MuJoCo leaves 22, 23 and 21 of the 446 on edge
(19 with its contact calibrated to e 0.45), not this phase's 49; per rim impact its friction
impulse is as large relative to μ J_n as the rigid law's (J_t/(μ J_n) 0.888, rigid 0.862, here
0.857; ``bench_rim_impacts.py 200 --condim 3``), its normal impulse ~12 % larger once friction
acts. Toss by toss (``python benchmarks/bench_edge_trace.py 600 --per-group 30``: 30 of this
phase's edge tosses and 30 matched others, 0.1 s at 0.1 ms) the engines part in the **normal
contact**: the first contact from the hand-off lasts a median 9.1 ms here (normal impulse 3.4 mN
s) and 0.8 ms in MuJoCo (0.5 mN s), the coin is in contact 51 % of the first 0.1 s here and 6 %
there (4.5 short episodes before the tilts part, ~30 ms in): MuJoCo's coin hops and slides on
its rim, this phase keeps it pressed long enough for friction to turn sliding into rolling. The
friction here is within μ F_n (largest 0.999996 μ F_n on 29,370 traced states) and opposes the
slip at the centre of pressure (tests/test_contact_friction.py). The normal law's shape and
softness are not what parts them (:mod:`coinflight.studies.mujoco_compare`'s notes, "Why the
engines part", measured): this phase with a linear rim law, or MuJoCo with a soft first touch
(``solimp``), leaves its edge count where it was; what differs is that MuJoCo's sliding contact
lifts the coin off the table (a flat nickel sliding at 0.5 m/s with μ 0.3 is in contact 7 % of
30 ms there, 100 % here), where this phase keeps it pressed by its weight, as a rigid coin
sliding on a table is.

On the landing report's tosses (no axial spin; ``--tosses report``, 400 tosses, seed 2026, e 0.5, μ
0.3, resistances 1e-4 m) it goes the other way: no edge here (85 % of them end at an impact,
their whole energy below the barrier), 10 in MuJoCo (0.025 ± 0.008 with RK4, 0.018 ± 0.007 with
Euler), 8 of them tosses this model ends at an impact, standing on their rim for seconds (median
8.4 s): there the engines differ at the impacts (instantaneous here, soft there), not in this
phase. MuJoCo's soft contact is no measurement either: which engine is closer to a coin is not
known, and the contact ending's edge rates are to be quoted, if at all, beside MuJoCo's.

The state is the height z of the centre of mass, its velocity v, the heads normal n and the
angular momentum L about the centre of mass (lab frame, SI); the spin angle about n does not
enter the contact of a cylinder with a plane, and neither does the horizontal position.

The contact model (compliant)
-----------------------------
A compliant (penalty) contact rather than a constrained one (issue 11 allows either):
rolling, sliding, pivoting, rocking, two-point and face contact and short hops then follow from
one force law, with no list of contact modes, no complementarity problem and no Painlevé
inconsistencies to resolve (the price: stiff equations, integrated with small steps). The coin
touches the plane with the two circles of its rims (the lowest points of a cylinder always lie
on them; with rounded corners, the circles of the core cylinder, a lower). A rim circle σ = ±1
(heads, tails), centre σ (h/2) n from the centre of mass, has at the angle φ from its
lowest point the penetration

    d(φ) = A + B cos φ,   A = −z − σ (h/2) n_z,   B = r s,   s = sqrt(1 − n_z²),

positive on the arc |φ| < φ* (cos φ* = −A/B; the whole circle when A ≥ B, a face flat on the
table). Each point of the arc carries a vertical force per radian

    f(φ) = κ d(φ) + γ ḋ_s(φ),

a linear spring along the rim whose total is Hertz-like on a short arc (F ∝ d0^(3/2), as a
curved rim pressed on a plane) and linear for a face (F = 2π κ d). The sums over the arc are in
closed form, so a rim contact is exact for any arc, with no sampling of the rim. ḋ_s is the
penetration rate without its part odd in φ (a rate ∝ sin φ, a sideways roll of the arc): then
the frictionless normal force of a rim acts on the arc's plane of symmetry, through the rim's
lowest point and n, and exerts no torque about n or about the vertical, as in a rigid
frictionless contact (Stronge 2000, §5), so that L·n and L_z are conserved with μ = 0. The total
force of a rim is clipped at zero (the surface pushes, never pulls).

* **Stiffness.** κ = π m / (2 t_c²), t_c :data:`CONTACT_TIME` by default: a coin dropped flat
  sinks for t_c (an undamped half period of m on 2π κ). It is a numerical softness, far below
  steel on wood, chosen so that t_c is short beside every time of the coin's motion (√(r/g) ≈
  30 ms); it enters the outcomes through the penetration m g / (2πκ) = g (t_c/π)² ≈ 1 μm, the
  length of a contact (a rim's lasts ∝ t_c^(4/5), the law being Hertz-like) and the length of
  the arc (∝ sqrt(depth): the pivoting friction μ r_t F_n below).
* **Restitution.** The damping is γ = ζ sqrt(2 φ* κ m_eff) / φ*: the arc's tangent stiffness
  K_t = dF/dd0 = 2 φ* κ and the effective mass m_eff = 1/K_zz of the arc's centroid (the
  collision matrix of :mod:`coinflight.core.impact`) give a damping force 2 ζ sqrt(K_t m_eff) ḋ.
  On a short arc (F = K d^(3/2)) this is the damping ∝ d^(1/4) of Tsuji, Tanaka & Ishida
  (Powder Technol. 71:239, 1992), whose coefficient of restitution does not depend on the impact
  speed; ζ is set from the surface's e by :func:`damping_ratio` so that a rim contact restitutes
  with e exactly (in the limit of a short contact). With friction the contact point's normal
  motion has another mass: its acceleration is (K_zz + K_zt·F_t/F_n) F_n, K_zt the collision
  matrix's coupling of the tangential force into the normal velocity, so a damper sized for
  1/K_zz restitutes a sliding impact with e′ ≠ e (0.46-0.54 at the start of the benchmark's
  200 random rim impacts, e = 0.5, μ = 0.3), where Stronge's law restitutes it with e (module
  notes, "Convergence of a rim impact"). Each rim's ζ is therefore taken as ζ / sqrt(ρ),
  ρ = 1 + K_zt·(F_t/F_n) / K_zz at the centroid of the rim's arc (where the damper's m_eff
  is taken) with the regularised friction's share F_t/F_n (:func:`_damper`; ρ ≥
  :data:`SLIDING_MASS_FLOOR`), so a rim impact sliding one way restitutes with e, as Stronge's law
  does (a slip of fixed direction leaves the normal velocity linear in the normal impulse, so the
  energetic coefficient is the kinematic one: Stronge 2000, ch. 4). A face slap (linear,
  Kelvin-Voigt clipped at zero force: Schwager & Pöschel, Granular Matter 9:465, 2007) restitutes
  with a slightly different e (:func:`restitution_of`).
* **Friction.** Coulomb's, regularised (a linear slope below :data:`SLIP_SPEED`, as in
  MuJoCo's soft contacts and Leine's regularised Euler-disk models), at the arc's centre of
  pressure: F_t = −μ F_n u_t / sqrt(|u_t|² + v_ε²), u_t the horizontal velocity of the coin's
  material point there.
* **Pivoting (drilling) resistance.** A torque −(μ r_t + ℓ_p) F_n ω_z / sqrt(ω_z² + ω_ε²)
  about the vertical: Coulomb friction spread over the arc, r_t = r sqrt(1 − (sin φ*/φ*)²) the
  arc's radius of gyration about its centroid (0 for a point, r for a face, whose rim bears the
  load), plus the surface's pivoting resistance ℓ_p (a length).
* **Rolling resistance.** A torque −ℓ_r F_n ω_h / sqrt(|ω_h|² + ω_ε²) against the horizontal
  part of ω, ℓ_r the surface's rolling resistance (a length). Both resistances as in MuJoCo's
  contact (torsional and rolling friction coefficients, lengths) and in Le Saux, Leine & Glocker
  (J. Nonlinear Sci. 15:27, 2005: rolling and drilling friction set how a rolling disk's spin
  decays). No source gives them for a coin's rim: they are assumptions, to be carried as a band.

**Two rims are damped as one pair (2026-11-24, :data:`JOINT_DAMPING`).** Each rim's damper
alone is sized for the effective mass at its own arc, m_eff = 1/K_zz, as if that rim carried
the coin. An upright coin presses both rims together: one contact of stiffness 2 K_t on the mass
m, which those two dampers damped at ζ sqrt(2 m_eff / m) = 1.39 ζ for a nickel
(m_eff = 1/(1/m + h′²/I1)), and the pair's rocking mode (the rims in antiphase, inertia I1 on
2 K_t h′²) at ζ sqrt(2 m_eff h′²/I1) = 0.25 ζ. So whenever both rims' arcs are in the table,
:func:`_pair` damps them together: with W the 2 × 2 normal mobility of the two arcs' centroids
(W_ij = 1/m + (rc_i × Z)·I⁻¹(rc_j × Z), the normal block of the collision matrix for two points,
Stronge 2000, eq 5.7), M = W⁻¹ and K_t = diag(2 φ₁ κ, 2 φ₂ κ), the damping matrix
C = 2 ζ M^½ (M^−½ K_t M^−½)^½ M^½ (:func:`joint_damping`, in closed form) puts every mode of
the linearised pair at ζ, is symmetric positive (the pair only dissipates), and is
:func:`_rim`'s 2 ζ sqrt(K_t m_eff) as one arc closes (continuous at a rim's touch). Each rim's
sliding correction ρ (above) stays its own: it scales that rim's row and column of W by
sqrt(ρ) (:func:`_pair`). The forces C ḋ act on the arcs' mean penetration rates, each rim's own
part spread over its arc as before, the coupling at the arc's centroid: in each arc's plane of
symmetry, so L·n and L_z stay conserved without friction. When the pair would pull on a rim (a
joint force not positive) each rim is damped alone, as before: a contact only pushes, and that
fall-back dissipates too. The switch is a discontinuity of the forces (the total normal
force nearly continuous, its split between the rims not): on an upright nickel rocked at 4 rad/s
the rim leaving the pair goes from 1.2e-5 N to 0.0101 N and the other from 0.0494 to 0.0389 N
(on random two-arc states near the switch, v ~ 0.05 m/s, ω ~ 20 rad/s, the other rim's force
jumps a median 19 %, up to 100 %: a reviewer's scratch measurement on 40,000 states, not
re-run here); the stepper crosses it in 1-2 steps of 10 μs and the energy
never grows (``test_stepping_across_the_fall_back_the_energy_never_grows``). Real tosses cross
it often: of bench_contact's handed tosses (seed 2026, e 0.5, sampled every 0.1 ms up to 3 s;
``python benchmarks/bench_two_rims.py --switches 300 --pairs 0.5,0.3 0.5,0.6``, 2026-11-24
09:00 UTC), 80 of the 88 that reach both arcs switch at μ 0.3 (385 switches) and 128
of 133 at μ 0.6 (588), though 98-99 % of their time on both arcs is damped jointly (64.4 of 65.9
s, 220.7 of 223.0 s). With at most one arc in the table the derivative is the one before to
the bit (15,480 random states of 20,000 against main 7d8c4d1, and
tests/test_two_rim_damping.py against a kept reference).

Measured, ``python benchmarks/bench_two_rims.py`` (frictionless nickel, sharp corners, not
turning, dropped from 1 mm, 1 cm, 10 cm, 50 cm; 2026-11-24 07:47 UTC): upright on both rims,
t_c 1 ms, **0.192-0.199 at e 0.2, 0.344-0.349 at 0.35, 0.495-0.499 at 0.5, 0.647-0.649 at
0.65, 0.798-0.800 at 0.8** from 1 cm to 50 cm (from 1 mm 0.315, 0.476, 0.635, 0.792 and no
release at 0.2: the weight, over a contact of 3.5 ms); at t_c 62.5 μs 0.199-0.200, 0.349-0.350,
0.499-0.500, 0.650, 0.800 (``--contact-time 2.5e-4,6.25e-5 --heights 0.01,0.1,0.5``). Each rim
damped alone had given (the same script at main 7d8c4d1, 2026-11-24) **0.123-0.132, 0.250-0.256,
0.394-0.399, 0.555-0.559, 0.735-0.737**, the prediction restitution_of(1.39 ζ, 3/2) = 0.132,
0.257, 0.399, 0.560, 0.737, at every t_c from 1 ms to 62.5 μs. The pair's rocking mode (the decay
of a small lean oscillation of an upright nickel resting on both rims) is now damped at
**1.139 ζ** at t_c 1 ms (0.760, 0.435, 0.265, 0.156, 0.077 at e 0.2-0.8 against ζ 0.668, 0.382,
0.233, 0.137, 0.068), 1.02 ζ at 0.25 ms and **1.003 ζ** at 62.5 μs, where each rim alone gave
0.29 ζ at 1 ms (0.193, 0.111, 0.068, 0.040, 0.020) and 0.256 ζ at 62.5 μs (its linearised
0.25 ζ; the factor 1.14 at 1 ms is the finite Hertz-like contact's, in both sizings): the
rocking restitution ~0.82 where the surface said 0.5 is gone. The bounce mode, lightly damped,
0.99 ζ (1.39 ζ before). One rim (tilted 45°) and a face are unchanged (one rim tends to e as t_c
falls: e 0.5, 10 cm: 0.613, 0.542, 0.515 at t_c 1, 0.25, 0.0625 ms, the coin turning during a
finite contact; a face restitutes with the linear law's :func:`restitution_of` (ζ, 1), 0.527 at
e 0.5). ``tests/test_bench_two_rims.py`` and ``tests/test_two_rim_damping.py`` pin these.

*What it moves* (every contact-ending outcome of a coin that spends time on both rims), measured
2026-11-24 against main 7d8c4d1 (each rim alone) with the same commands and tosses; the other
figures of these notes (the edge rates, the MuJoCo comparisons, the sensitivity and trace runs,
the speeds but the one below) are from before it. ``python benchmarks/bench_contact.py 600
--pairs 0.5,0.3 0.5,0.6`` and ``600`` (seed 2026, ℓ 1e-4 m, every handed toss carried to rest;
07:40-07:48 UTC, load 8.6-3.9): on edge at rest 61 of 429 handed tosses (0.142 ± 0.017) against
53 (0.124 ± 0.016) at e 0.5, μ 0.3; 176 of 446 (0.395 ± 0.023) against 178 at μ 0.6; 74 of 412
(0.180 ± 0.019) against 75 with each toss's own e, μ: within their binomial spread. The upright
decision would end 60, 175 and 72 of them (52, 176 and 73 before), **every one on edge at rest
(0 disagreements)**, and saves 52.3 %, 84.9 % and 66.3 % of the steps (51.1 %, 84.4 %, 66.0 %);
a handed toss takes a mean 1,869, 6,777 and 2,697 steps (1,770, 6,818, 2,680). With a 0.5 mm
corner (``--corner 5e-4``, the pairs): 43 of 417 decided (45 on edge at rest) and 170 of 425
(172), 0 disagreements: 520 decisions in these five runs, none wrong. The same with 1,500 tosses
(08:10 UTC, load 4.0-3.5; ``bench_contact.py 1500 --pairs 0.5,0.3 0.5,0.6`` and ``1500``): on
edge at rest 132 of 1,061 (0.124 ± 0.010) against 130, 429 of 1,028 (0.417 ± 0.015) against 421,
206 of 1,030 (0.200 ± 0.012) against 204; decided 126, 424 and 201 (126, 417, 200 before), 0
disagreements; mean steps 1,767, 7,326, 3,018 (1,768, 7,159, 2,981). So 1,271 decisions in eight
runs, none wrong. ``python benchmarks/bench_bounce.py --contact-rates 300 --old-src DIR`` (DIR
main's src; 07:48-07:50 UTC, load 3.5-3.3, a test run beside it): landings carried to rest per
CPU second in one thread **0.99× and 0.97×** main's (1,230 against 1,242; each toss its own e, μ
1,129 against 1,162), in four more runs 0.67× and 0.72× (07:51-07:53 UTC, load 5.4-7.3), 0.86×
and 0.90× (07:54 UTC, load 6.5-5.4), 0.84× and 0.90× (07:56 UTC, load 5.0-6.8) and, the code now
(:func:`_pair` not inlined, its fall-back from its own sums), 0.85× and 0.92× (08:05 UTC, load
4.1-4.4): noisy; measured by the lead on the merged tree at lower load (09:11 UTC, load 2.8-2.0,
the same command against main 8375028's src, 300 tosses, medians of 3): **2,745 against 2,741
landings a second (1.00×; one thread 1,350 against 1,404 per CPU second, 0.96×)**, each toss its
own e, μ 2,408 against 2,646 (0.91×; one thread 1,336 against 1,333, 1.00×): the cost, if any,
is within a few per cent, from the phase's steps (more at μ 0.3, above) and a derivative a
little dearer (one thread, CPU, median of 7, 2026-11-24 08:02 UTC, the random states of
``tests/test_two_rim_damping.py``'s kind at μ 0.3: 146-154 ns with one arc against main's
141-143, its test of both arcs; 257-264 ns with both, joint or not, against 222-244; settle's
first compile 12.7-13.2 s CPU against 10.2-10.3); faces differing on 9 and 1 of 300, statuses on
none; decided upright 30 and 43 (27 and 43 before); P(edge) of all 300 landings 0.100 against
0.090 (e 0.5, μ 0.3), 0.200 against 0.197 (e 0.2, μ 0.5), 0.057 against 0.053 (e 0.8, μ 0.1),
0.143 against 0.147 (each toss its own e, μ; main's from ``bench_bounce.py --contact-rates 300``
in its tree).

Every force is a spring that stores energy or opposes a velocity, so the mechanical energy
(kinetic + m g z + the springs') never grows but by integration error.

Integration and ending
----------------------
Dormand-Prince 5(4) with adaptive steps (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.5),
which take large steps through a hop (a lift-off is integrated here, not handed back to the
exact flight loop: the hops of the last phase are short and a step-size control resolves
them) and small ones through a slap. After each step the coin has *settled* when it cannot
leave its well any more:

* with friction or resistances, when the mechanical energy is below m g ρ, the height of the
  centre of mass balanced on the corner (ρ = sqrt(r² + h²/4); Vulović & Prange 1986, Yong &
  Mahadevan 2011): no force here adds energy, so the coin can never get over a corner again;
* frictionless (μ = 0, no resistances), the horizontal momentum, L_z and L·n are conserved, so
  only E − ½ m v_h² is free, and a corner at n_z = ±sin(edge) needs at least
  m g ρ + (L·n)²/2I3 + (L_z − (L·n) n_z)² / (2 I1 (1 − n_z²)) (the least rotational energy with
  those L_z and L·n there): the barrier of the well in 3-D.

The outcome is then the well the coin is in (:func:`coinflight.core.impact.resting_face`). A
coin at rest is below the barrier of its well, so it has settled too. After MAX_STEPS steps
(a coin rolling on its edge with no rolling resistance would roll for ever) the toss is
unsettled, with the well it was in; so is at once a coin with nothing to dissipate its
energy (e = 1, μ = 0, no resistances) above its barrier.

Upright rollers (the early decision)
------------------------------------
Most of this phase's steps go to coins rolling upright in the flat band of the rim, on both
rims, until the rolling resistance stops them (above: 75 % of the simulated time, 67 % of the
steps). The energy test cannot end them early: their rolling energy, ½ (m + I3/r²) v², is far
above the band's barrier m g (ρ − r) ≈ m g h²/8r (45 μm of height for a nickel, passed by
v ≈ 2.4 cm/s). With :data:`UPRIGHT_DECISION` (on; a compile-time constant), :func:`settle`
ends such a coin on edge (status DECIDED_UPRIGHT, :class:`coinflight.core.outcome.Status`,
so that a count of outcomes can tell the predicted ones from the coins carried to rest; time the
decision's) as soon as :func:`upright_decided` holds:

* **The turn a band holds.** Upright (n horizontal), rolling without slip at v = r ω (ω = ω·n)
  and turning at ψ' = ω_z, the coin's angular momentum about its centre I3 ω n + I1 ψ' Z turns
  at the rate I3 ω ψ' about t̂, the horizontal axis across n (the gyroscopic moment), and the
  centre's acceleration has the centripetal part v ψ' along n, whose friction force m v ψ'
  acts r below the centre. To keep the lean at zero, the two rims, h′ = h/2 − a either side of
  the middle (a the corner radius), must give (N₊ − N₋) h′ = (I3 ω + m r v) ψ' =
  (I3 + m r²) v ψ' / r = M, the steady turning of a rolling disc at zero lean (O'Reilly,
  Nonlinear Dyn. 10:287, 1996); both rims stay pressed while M < N h′ with N = m g, and the
  turn holds without slipping while m v ψ' (with the force m ℓ_r m g r / (I3 + m r²) the
  rolling resistance takes from the rolling) stays below μ N.
* **They only fall.** The rolling resistance brakes ω at the constant rate
  ℓ_r m g / (I3 + m r²) (a torque bounded by a length times the normal force, as in Le Saux,
  Leine & Glocker, J. Nonlinear Sci. 15:27, 2005; smaller below its regularisation), and ψ'
  is braked by the pivoting torque (μ r_t + ℓ_p) N and, on both rims, by their opposite
  longitudinal slips ±h′ψ' (a wheel of width h cannot turn without a rim slipping). So v and
  ψ' fall monotonically to zero, and with them M and the friction needed: what holds with a
  margin now holds to rest.
* **The lean's ridge.** Leaning by θ onto one rim (its pivot rolling on the corner's arc), the
  rigid coin's centre rises to H(θ) = (r − a) cos θ + h′ sin θ + a while M does the work M θ
  and the yaw's centrifugal moment (I3 − I1) ψ'² sin θ cos θ (tilting raises the moment of
  inertia about the vertical) ½ (I3 − I1) ψ'² sin² θ; the restoring moment
  m g (h′ cos θ − (r − a) sin θ) meets M at θ* = arccos(M / (m g ρ′)) − arccos(h′ / ρ′),
  ρ′ = sqrt((r − a)² + h′²). The compliant rims sink: each arc carries
  F = (4√2/3) κ d^(3/2) / sqrt(r − a) and stores (2/5) F d, so upright each rim sinks d_s
  (2F = m g, :func:`static_depth`: 30 μm for a nickel at t_c = 1 ms, beside the rigid
  barrier's 45 μm of height, or 11 μm with a 0.5 mm corner), one rim alone 2^(2/3) d_s. The
  least potential energy upright is at least m g (r − (3/5) d_s), on the ridge
  m g (H(θ*) − (3/5) 2^(2/3) d_s) (the exact arc is stiffer than its parabola: lower bounds),
  and a coin whose energy free to lean (the whole energy less ½ m (v·t̂)² + ½ I3 ω² +
  ½ I1 ψ'²) is below the ridge less the work of M from its present tilt cannot pass it.
  With a 0.5 mm corner the compliant band holds a coin by only about 0.6 μm of height; at a = h/2
  there is no band and no decision; μ = 0 neither, nor ℓ_r = 0 or a roller that would roll
  longer than the steps left can cover (carried on, it would end UNSETTLED after MAX_STEPS).

**What is proven and what is measured.** The bounds are the rigid wheel's, taken
quasi-statically: they do not bound the lean the gyroscopic coupling can drive from a lean
rate, the compliant contact's tilt and bounce beyond their energy, or the regularised
friction's creep. So :data:`UPRIGHT_MARGIN` asks each of them to hold with half to spare, and
the decision is adopted on measurement, not on proof: ``python benchmarks/bench_contact.py 1500
--pairs 0.5,0.3 0.5,0.6`` and the same without ``--pairs`` (each toss its own e ~ U(0.2, 0.8),
μ ~ U(0.1, 0.6)), which carry every handed toss to rest while recording where the decision
would have ended it (2026-11-23, 20:55-21:00 UTC, load 5-8): it would end 118 of 1,061
handed tosses (122 end on edge) at e 0.5, μ 0.3, 411 of 1,028 (412) at μ 0.6 and 208 of 1,030
(213) with each toss's own e and μ, and **every one of them ends on edge at rest (0
disagreements)**; the steps saved, 52 %, 85 % and 70 % of all the phase's steps. With a 0.5 mm
corner (``--corner 5e-4``): 119 of 1,062 (120 on edge), 419 of 1,017 (420), 159 of 1,041 (168),
0 disagreements. A looser bound was not safe: before the ridge took the rims' compliance
(the rigid barrier above the compliant floor), a 0.5 mm corner gave 2 disagreements in 708
decisions (coins decided while already leaning slowly over a corner they then passed).
Beyond these settings (the same tosses, the decision probed as above, 21:15-21:19 UTC): t_c
2 ms (the rims sink 2.5× deeper) 125 and 416 decided at μ 0.3 and 0.6, ℓ_r = ℓ_p = 1e-3 m 89,
248 and 131 (three surfaces), ℓ_r = ℓ_p = 1e-5 m (600 tosses, rollers rolling ten times
longer) 56 and 178 (as re-measured, ``bench_contact.py``'s notes), each time 0 disagreements;
91 % and 98 % of the steps saved at 1e-5 m.
Re-measured with the pair's joint damping (2026-11-24, "Two rims" above: 1,271 decisions in
eight runs of ``bench_contact.py`` 600 and 1,500, 0 disagreements); the figures of this
paragraph are from before it.
The margin costs little and is not what holds these tosses: with UPRIGHT_MARGIN 1 (no
margin; the same tosses, 20:59-21:03 UTC) the decision ends 119, 411 and 210 of them, again
every one on edge at rest, and saves 52.2 %, 85.8 % and 70.1 % of the steps instead of 52.1 %,
85.4 % and 69.8 %.
Through the whole landing (bounces and this phase, :func:`coinflight.core.bounce.land`),
``python benchmarks/bench_bounce.py --upright 1000 --rounds 3`` (the tosses of
``--contact-rates``; each setting in a child process of its own, rounds alternated, medians;
2026-11-23 20:58-21:04 UTC, the shared 2-core machine at load 8-10): carried to rest **660
tosses a second with the decision against 213 without** (3.1×) at e 0.5, μ 0.3; 477 against 57
(8.4×) at μ 0.6; 588 against 161 (3.6×) with each toss's own e and μ; the faces of all 3 × 1,000
tosses identical with and without it (83, 296 and 116 on edge), and their statuses too (then
the decided tosses were SETTLED_CONTACT; they are DECIDED_UPRIGHT since, the one difference). With
:data:`UPRIGHT_DECISION` False the landings are those of the code before the decision to the
bit (face, bounces, first contact, settle time and status of the same 3 × 1,000 tosses,
against main at e38e887). Issue
11's 50,000 a second stays out of reach: what is left is the tosses that do not end upright
(one-rim rolling, rocking and hops) and the phase's steps before a roller is decided.

Convergence of a rim impact
---------------------------
Does a single rim impact of this phase approach Stronge's rigid law
(:func:`coinflight.core.impact.impact`, the bounces' law) as t_c → 0? ``python
benchmarks/bench_rim_impacts.py 200 --friction μ --converge 2e-3,1e-3,...,3.125e-5
[--resistance 0] [--drill-factor F]`` follows the same 200 random impacts (tilt 9-80°, ω
50-300 rad/s, e = 0.5, seed 1) to the end of their contact at each t_c and compares them with
the rigid law and with this phase's own t_c → 0 limit (its rim law at a frozen contact point,
``bench_rim_impacts.frozen_limit``). Medians at t_c = 1, 0.5, 0.25, 0.125, 0.0625, 0.031 ms
(2026-11-24, 02:22-02:55 UTC, load 2-5; no resistances unless said):

* frictionless: the velocity 0.093, 0.050, 0.028, 0.016, 0.0092, 0.0052 m/s from the rigid
  law's, the angular momentum 0.145 ... 0.0090 I1 ω, J_n 1.053 ... 1.0025 of the rigid law's:
  a factor ~1.75 per halving of t_c, i.e. order 4/5, the order of the contact's duration (a
  Hertz-like law F ∝ d^(3/2) with κ ∝ 1/t_c² lasts ∝ t_c^(4/5): 1.97, 1.11, 0.65, 0.37, 0.21,
  0.12 ms). What is left is the coin turning during the contact. The frozen limit is the rigid
  law to 1e-5 (tests/test_rim_convergence.py).
* μ 0.3 as it was before 2026-11-24 (each rim's damper sized for the frictionless normal mass
  1/K_zz): velocity 0.085, 0.049, 0.029, 0.019, 0.014, 0.010 m/s, angular momentum 0.20,
  0.13, 0.090, 0.065, 0.046, 0.033 I1 ω, J_n 1.058 ... 1.010: "about half order". Two causes,
  found by the frozen limit and by switching each off:

  1. **A floor, not slow convergence** (a defect, fixed): the phase converged at order 4/5 to
     its own limit (0.084 ... 0.0054 m/s from it), but that limit was not Stronge's: 0.0061
     m/s (0.00613: ``frozen_limit(..., sliding_mass=False)``), J_n +0.9 % (medians; 0.0048
     m/s, J_n +1.3 % on the impacts sliding one way). The normal motion of a sliding contact point
     has the mass 1/(K_zz + K_zt·F_t/F_n) while the damper was sized for 1/K_zz, so it restituted
     with e′ ≠ e (see "Restitution" above; a planar sliding impact at e 0.5: e′ = 0.5457, J_n 3.0 %
     above Stronge's at any t_c). The median of a first-order term plus that floor looked like half
     order. Not the stick/slip transition: by the rigid law's slip, 179 of the 200 impacts slide
     throughout (their direction turning), 15 stick, 6 reverse, and the sliding ones carried the
     floor; not the friction's regularisation (the limit with v_ε × 0.01, and the phase with
     :data:`SLIP_SPEED` × 0.1, unchanged to the third digit); not the integrator (the frozen
     limit is integrated apart, at rtol 1e-10; the phase at :data:`RTOL`/100 moves a planar
     sliding impact by 4e-6 m/s at t_c 0.125 and 0.031 ms). Two rims touching in one impact
     were not examined: the floor is accounted for without them (each rim's ρ uses its own
     single-contact K; since 2026-11-24 two pressed rims are damped as one pair,
     :func:`_pair`, each ρ scaling its rim's row and column of their coupled normal mobility).
  2. **The arc's pivoting friction** (physics of the compliant model, kept): μ r_t F_n about
     the vertical, r_t ≈ r φ*/√3 ∝ sqrt(depth) ∝ t_c^(2/5), so its angular impulse vanishes
     only as t_c^(2/5): the vertical part of the angular-momentum error, 0.118, 0.081, 0.060,
     0.044, 0.033, 0.025 I1 ω, most of it at small t_c (with the arc's r_t set to 0,
     ``--drill-factor 0``: 0.019 ... 0.0012). The rigid law has one contact point and no such
     torque; a real coin's contact patch is microscopic, so this torque is the numerical
     softness's, like the resistances' ℓ F_n (which do not vanish at all: with ℓ_r = ℓ_p =
     1e-4 m the angular momentum stays 0.046 I1 ω from the rigid law at 0.031 ms).

* μ 0.3 now (the damper for the sliding mass, :func:`_damper`, ρ at the arc's
  centroid; ``--converge`` prints these): the limit is Stronge's law to 0.00056 m/s (median
  of the 200; 90th percentile 0.0043, largest 0.030 m/s, 1.6 % of the lowest point's approach
  speed, on an impact whose slip turns), 0.00002 on the 19 sliding one way (J_t/(μ J_n) ≥
  0.999), 0.0019 (90 % 0.0079) on the 84 whose slip turns most (J_t/(μ J_n) < 0.95), 0.003
  on those that stick or reverse, where a viscous damper and Stronge's energetic coefficient
  still part. "Restitutes with e" holds for a slip much faster than :data:`SLIP_SPEED`: below
  it the regularised friction is weaker than Coulomb's and the limit parts from the rigid
  law (a planar sliding impact scaled down, its slip ~20 v_ε: J_n 0.990 of Stronge's; ~2 v_ε:
  0.90). The phase converges to the limit as the frictionless one does (measured with ρ at
  the lowest rim point, 2026-11-24 before 03:20 UTC; at 1 ms with ρ at the centroid and
  resistances 1e-4 m: 0.082 m/s, J_n 1.053): velocity 0.083, 0.047, 0.028, 0.016, 0.0093,
  0.0058 m/s, J_n 1.051, 1.027, 1.014, 1.008, 1.005, 1.003 of the rigid law's; without the
  arc's pivoting friction the angular momentum 0.12 ... 0.0092 I1 ω (frictionless 0.0090),
  with it 0.20, 0.13, 0.088, 0.062, 0.043, 0.031 I1 ω (the t_c^(2/5) above). At the default
  t_c = 1 ms a rim impact is still 0.083 m/s and 0.20 I1 ω from the rigid law, J_n +5 %: the
  phase's impacts are not converged at its default softness, as they were not before.
* μ 0.6 (ρ at the lowest rim point, before 03:20 UTC): more impacts stick (63 of 200; 127 slide
  throughout, 10 reverse), and the limit is 0.0056 m/s from Stronge's on those that stick (0.0013 on
  the sliding ones); the phase 0.102, 0.057, 0.036, 0.023, 0.016, 0.011 m/s from the rigid law
  (0.0086 from its own limit at 0.031 ms).

The fix moves outcomes as a change of the dynamics does in this chaotic phase, not the edge
rates: on 2,000 seeded tosses carried to rest (``bench_bounce.py``'s vigorous tosses, the
contact ending, resistances 1e-4 m; against main at 507692d, 02:28 UTC; ρ at the arc's
centroid and the upright decision's rims with their sliding-mass dampers, 03:30 UTC, load
6-10) faces differ on 126, 125 and 92 (e 0.5 with μ 0.3, μ 0.6, and each toss its own e, μ),
all of them tosses this phase decides (1,423, 1,407, 1,402 of the 2,000), statuses on none;
on edge 152 against 164, 597 against 595, 268 against 278 (paired, 16 in and 28 out, 36 and
34, 15 and 25: McNemar p 0.10, 0.90, 0.15). With ρ at the lowest rim point (02:50 UTC) they
were 119, 126, 89 and 152, 599, 269: the two kernels differ on 52, 77, 52 faces, as chaos
moves them. The upright decision still ends only coins that end on edge at rest
(``bench_contact.py 300 --pairs 0.5,0.3 0.5,0.6``, its rims' force with these dampers: 27 of
213 handed at μ 0.3, 89 of 207 at μ 0.6, 0 disagreements, 03:30 UTC). The steps are the same
(a handed toss at μ 0.3: mean 1,787 now, 1,802 with ρ at the lowest point, 1,762 on main;
median 639 against 636); each costs more, the damper's size computed at every derivative: main's
landings carried to rest per CPU second in one thread were 1.10-1.30× these in two runs of
``bench_bounce.py --contact-rates 300 --old-src`` (03:00 UTC, load 3-5, noisy; quiet 1.5×,
"Speed" above, which also says how that cost was taken back).
"""

from __future__ import annotations

import math
from enum import IntEnum

import numpy as np

from coinflight.core._jit import njit
from coinflight.core.impact import (
    angular_velocity,
    cross,
    dot,
    inverse_inertia_apply,
    resting_face,
)
from coinflight.core.outcome import Status

CONTACT_TIME = 1e-3
"""Default duration t_c of a flat contact of the compliant model, s (a numerical softness; see
the module notes)."""
SLIP_SPEED = 5e-3
"""v_ε of the regularised Coulomb friction, m/s: below it friction grows linearly with the slip.
It sets the stiffest time of the contact, m_eff v_ε / (μ F_n) (~0.1 ms at μ = 1), hence the
cost of a rolling coin (steps ∝ 1/v_ε); a contact that would stick creeps at v_ε F_t/(μ F_n),
a few mm/s."""
MAX_STEPS = 400_000
"""Integration steps at most in one contact phase; then the toss is unsettled."""
RTOL = 1e-7
"""Relative tolerance of the step-size control.

What it decides, measured 2026-11-24 (05:00-05:14 UTC, load 6-8, one thread):
``python benchmarks/bench_tolerance.py 5000 --extra 1e-10 --subset 5000 --nudges
1e-9,1e-8,1e-7,1e-6`` (the vigorous nickel tosses of ``bench_bounce.py``, seed 2026; e 0.5 μ 0.3,
e 0.5 μ 0.6, each toss its own e, μ; 3,533, 3,513 and 3,482 handed to this phase). Against 1e-9,
faces differ on 3.9 %, 3.2 %, 2.7 % of the handed tosses at 1e-5; 2.1 %, 1.7 %, 1.1 % at 1e-6;
0.8 %, 1.0 %, 0.6 % at this default; 0.1 %, 0.2 %, 0.3 % at 1e-8; 1e-10 against 1e-9 differs
on 3, 2, 3. So at the default the faces are reproducible to 0.6-1.0 % of the handed tosses, the
error of a ~1e-6 relative nudge of the handed state (0.7 %, 0.5 %, 0.7 % of faces changed), and
a 1e-12 nudge changes about 1e-4 of them (1, 0, 0 faces at rtol 1e-9; 2, 0, 1 at the default).
That does not make them free of chaos at finer scales: the share of faces a nudge δ changes
grows as δ^0.45 (δ 1e-9 to 1e-4, the settings summed; ``bench_tolerance.py --recorded``), where
a smooth boundary between the faces' basins gives δ^1; an exponent below 1 is the signature of
final-state sensitivity (a fractal basin boundary; Grebogi, McDonald, Ott & Yorke, Phys. Lett. A
99 (1983) 415), and part of the 1e-12 count may be the step control's. No ensemble fraction
(heads, tails, edge) moves by more than 0.4 of its standard error at any tolerance (5,000
tosses); McNemar's paired test gives p < 0.05 in 2 of 36 applications (heads at 1e-6 in the
first and third settings, the same sign), tests correlated through the shared tosses and the
shared 1e-9 run, so not a count to set against chance. CPU a handed toss (median): 0.55, 0.99,
0.59 ms at 1e-5; 1.07, 1.70, 1.12 ms here; 2.33, 3.71, 2.55 ms at 1e-9; median steps 348 at
1e-5 against 626 here (e 0.5 μ 0.3). This supersedes the module notes' earlier "held by the
contact's stiffness, not by the tolerance" (RTOL 1e-5 leaving the mean steps within 15 %): that
was measured before the upright decision, when coins rolling upright in the edge band for
seconds, their steps bound by the contact's stiffness, made most of the steps. Kept: a looser
default (1.7-1.95x faster a handed toss at 1e-5) would leave the ensembles alone but change 1-4 %
of per-toss faces, where a 1e-12 nudge changes about 1 in 10,000."""
MAX_STEP = 1e-3
"""Longest step, s (also at most a sixteenth of a turn)."""
SLIDING_MASS_FLOOR = 0.1
"""Least ratio ρ = 1 + K_zt·(F_t/F_n)/K_zz of a sliding rim's normal stiffness to its
frictionless one that :func:`_damper` sizes the damper for (ρ ≤ 0 would be a contact
whose friction drives it into the table, where no mass fits; the damper is then at most
sqrt(10) times its frictionless size). At the start of the 200 random rim impacts of
``benchmarks/bench_rim_impacts.py`` (seed 1; the slip's direction then): ρ in 0.75-1.27 at
μ = 0.3, 0.50-1.54 at μ = 0.6, 0.17-1.89 at μ = 1 (ρ at the lowest rim point then). ρ ≤ 0
needs μ above μ* = K_zz / max K_zt·û, 1.12 for a nickel (near a tilt of 61°), and the floor
bites from μ ≈ 1.008; μ above 1 is not validated (:func:`_damper`)."""
UPRIGHT_DECISION = True
"""Whether :func:`settle` ends a coin rolling upright in its edge band as soon as
:func:`upright_decided` holds (the module notes, "Upright rollers"); False carries it on to
rest, to the bit the integration before this decision. A compile-time constant, not a run-time
switch: numba compiles :func:`settle` (cache=True) with the value this global had then, and its
on-disk cache ignores a later change, so setting it takes effect only after editing this source
and deleting ``src/coinflight/core/__pycache__`` (or in a process with a numba cache directory
of its own, as ``benchmarks/bench_bounce.py --upright`` does). At run time a coin is carried on
past the decision by :func:`advance` with ``decide=False`` (an argument, read at every call)."""


JOINT_DAMPING = True
"""Whether two rims pressed together are damped as one pair (:func:`_pair`: every mode of the
pair at the surface's ζ, so an upright coin restitutes with e; the module notes, "Two rims")
rather than each rim alone as if it carried the coin (False: the code before 2026-11-24's
joint damping, to the bit). A compile-time constant, as :data:`UPRIGHT_DECISION` (its notes
say how to change it): ``benchmarks/normal_law.py`` switches it off for its other rim laws,
whose tangent stiffness is not 2 φ κ."""
JOINT_DEGENERATE = 1e-9
"""Least det W / (W₁₁ W₂₂) of the two rims' normal mobility for which :func:`joint_damping`
damps them together: 0 when both rim circles are one (a corner radius a = h/2) or their arcs'
centroids lie on one vertical line; a nickel with a = h/2 − 25 μm still has ~1e-4."""


class Ending(IntEnum):
    """How :func:`_integrate` (and :func:`advance`) stopped: false when the coin has not
    settled, true when it has, and which way (numba compiles the members as their integers)."""

    RUNNING = 0
    """Not settled: the duration or the step limit ran out first."""
    SETTLED = 1
    """Its energy can no longer take it out of its well (at rest or below its barrier):
    status SETTLED_CONTACT in :func:`settle`."""
    DECIDED = 2
    """Ended on edge by :func:`upright_decided` (a measured predictor, not a proof; the coin
    may still be rolling): status DECIDED_UPRIGHT in :func:`settle`."""


UPRIGHT_MARGIN = 0.5
"""Share of each bound of :func:`upright_decided` the coin may use: the band's restoring moment
m g h′ against the turn's overturning moment, μ N against the friction the turn and the
rolling resistance need, and the lean barrier against the energy of the tilt and bounce
oscillations. The rest is the margin for what the rigid wheel of the proof leaves out (the
contact's compliance, the regularised friction, the yaw driven by a lean rate)."""


@njit(cache=True)
def _tangent_basis(n):
    """(s, ŵ): ŵ the unit vector of the coin's plane pointing most downwards, s = sqrt(1 − n_z²);
    for a coin lying flat any unit vector of its plane."""
    nz = n[2]
    sw = (nz * n[0], nz * n[1], nz * nz - 1.0)  # s ŵ = −Z + n_z n
    s = math.sqrt(dot(sw, sw))
    if s > 1e-12:
        w = (sw[0] / s, sw[1] / s, sw[2] / s)
    else:
        a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
        t = cross(n, a)
        size = math.sqrt(dot(t, t))
        w = (t[0] / size, t[1] / size, t[2] / size)
    return s, w


@njit(cache=True)
def rim_contact(
    sigma, z, v, n, omega, radius, hh, mass, i1, i3, stiffness, zeta, corner=0.0, friction=0.0
):
    """Normal force of one rim circle on the table: (F_n, centre of pressure q, r_t, energy).

    Its damper is sized for this rim alone; when both rims' arcs are in the table the
    derivative damps them as one pair (:func:`_pair`; both rims' forces as applied:
    :func:`rims_contact`).

    Parameters
    ----------
    sigma : float
        +1 the rim of the heads face, −1 that of the tails face.
    z, v, n, omega
        Height and velocity of the centre of mass, heads normal, angular velocity (lab, SI).
    radius, hh, mass, i1, i3 : float
        The coin: r, h/2, m, I1, I3.
    stiffness, zeta : float
        κ (N/m per radian of rim) and the damping ratio ζ (see the module notes).
    corner : float
        a, the radius of the rim's rounded corners, m: the circle is then that of the core
        cylinder (``radius`` and ``hh`` less a) swept by a ball of radius a, which touches the
        table a below the circle (0: sharp corners).
    friction : float
        μ: with μ > 0 the damper is sized for the normal mass that friction leaves, ζ / sqrt(ρ)
        (:func:`_damper`, the module notes' "Restitution"), as :func:`_derivative` sizes it;
        0 (the default) the frictionless ζ.

    Returns
    -------
    force : float
        Total vertical force F_n ≥ 0 of the arc, N.
    q : tuple of 3 floats
        Centre of pressure relative to the centre of mass (the normal force's torque is
        q × F_n Z), m.
    pivot_radius : float
        r_t, the arc's radius of gyration about its centroid, m.
    energy : float
        Elastic energy of the arc, κ ∫ d²/2 dφ, J.
    """
    s, w = _tangent_basis(n)
    return _rim(
        sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction
    )


@njit(cache=True)
def _arc(a, b):
    """(φ*, sin φ*, cos φ*) of the arc d(φ) = a + b cos φ > 0 (a + b > 0): φ* = arccos(−a/b),
    π for the whole circle (a ≥ b); the sine from the cosine, sqrt((1 − cos φ*)(1 + cos φ*)),
    exactly 0 at φ* = π."""
    if a >= b:
        return math.pi, 0.0, -1.0
    cp = -a / b
    return math.acos(cp), math.sqrt((1.0 - cp) * (1.0 + cp)), cp


@njit(cache=True)
def _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp):
    """The centroid of rim σ's arc of half-angle φ* relative to the centre of mass, m: σ (h/2) n
    + r (sin φ*/φ*) ŵ − a Z (``radius``, ``hh`` those of the core cylinder, a = ``corner``); the
    face's centre less a Z for the whole circle."""
    k = radius * sp / phi
    return (
        sigma * hh * n[0] + k * w[0],
        sigma * hh * n[1] + k * w[1],
        sigma * hh * n[2] + k * w[2] - corner,
    )


@njit(cache=True, inline="always")
def _rim(
    sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction=0.0
):
    """:func:`rim_contact` with the coin's tangent basis (s, ŵ) of :func:`_tangent_basis` given
    (it depends on n alone: :func:`_derivative` computes it once for both rims). The arc's
    half-angle φ* = arccos(−A/B), its sine from its cosine, sin φ* = sqrt((1 − cos φ*)(1 +
    cos φ*)): one sine and cosine fewer than from φ*, and exactly 0 at φ* = π. The arc's
    elastic energy is clamped at 0 (its closed form cancels on a short arc).

    With ``friction`` μ > 0 the damper is sized for the normal mass that friction leaves,
    ζ / sqrt(ρ) (:func:`_damper`), from the same arc and
    centroid and the same row of the collision matrix as the frictionless m_eff = 1/K_zz: one
    arccos, one centroid and one I⁻¹ product per rim and derivative, where the damper's own
    helper (``_sliding_damping``, gone) first computed them twice (results identical to the bit,
    ``tests/test_contact_friction.py``). ζ = 0 (the springs' energy alone, :func:`energy`)
    skips the damper."""
    radius -= corner
    hh -= corner
    a = corner - z - sigma * hh * n[2]
    b = radius * s
    if a + b <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0, 0.0
    phi, sp, cp = _arc(a, b)
    i0 = 2.0 * phi  # ∫ dφ over the arc
    ic = 2.0 * sp  # ∫ cos φ dφ
    icc = phi + sp * cp  # ∫ cos² φ dφ
    elastic = stiffness * (a * i0 + b * ic)
    moment = stiffness * (a * ic + b * icc)  # ∫ κ d cos φ dφ
    # ≥ 0 as the integral of a square; the closed form cancels on a short arc (down to
    # −5e-20 J measured), clamped so that below_barrier's shortcut holds to the bit.
    energy = max(0.0, 0.5 * stiffness * (a * a * i0 + 2.0 * a * b * ic + b * b * icc))
    # Penetration rate, its even part: ḋ = a0 + a1 cos φ (+ a2 sin φ, left out).
    wn = cross(omega, n)
    ww = cross(omega, w)
    a0 = -(v[2] + sigma * hh * wn[2])
    a1 = -radius * ww[2]
    # Damping 2 ζ sqrt(K_t m_eff) ḋ, K_t = 2 φ κ, m_eff at the arc's centroid.
    gamma = 0.0
    if zeta > 0.0:
        centroid = _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp)
        zeta, m_eff = _damper(centroid, v, n, omega, mass, i1, i3, friction, zeta)
        gamma = zeta * math.sqrt(2.0 * phi * stiffness * m_eff) / phi
    force = elastic + gamma * (a0 * i0 + a1 * ic)
    if force <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0, energy
    moment += gamma * (a0 * ic + a1 * icc)
    # q = Σ f (p − c) / F: p − c = σ (h/2) n + r (cos φ ŵ + sin φ e2); the sin part sums to 0.
    kq = radius * moment / force
    q = (
        sigma * hh * n[0] + kq * w[0],
        sigma * hh * n[1] + kq * w[1],
        sigma * hh * n[2] + kq * w[2] - corner,
    )
    ratio = sp / phi
    pivot = radius * math.sqrt(max(0.0, 1.0 - ratio * ratio))
    return force, q, pivot, energy


@njit(cache=True)
def _damper(rc, v, n, omega, mass, i1, i3, friction, zeta):
    """(ζ / sqrt(ρ), 1/K_zz) of a rim whose arc's centroid is rc (relative to the centre of
    mass, m): the damping ratio for the normal mass its friction leaves (ζ itself for μ = 0) and
    the frictionless normal mass m_eff = 1/K_zz there that :func:`_rim` sizes the damper with,
    from one row of the collision matrix K b = b/m + (I⁻¹(rc × b)) × rc
    (Stronge 2000, eq 5.7; :func:`coinflight.core.impact.collision_matrix`): K b·Z = b·Z/m +
    (rc × b)·I⁻¹(rc × Z), the product I⁻¹(rc × Z) shared by b = Z, X, Y. K_zz so is the one of
    ``impact._coupling(rc, Z, Z, ...)`` to the bit (rc × Z = (rc_y, −rc_x, 0) there too).

    The module notes' "Restitution": ρ = 1 + K_zt·(F_t/F_n) / K_zz with the mobility K, the slip
    u_t and F_t/F_n = −μ u_t / sqrt(u_t² + v_ε²) (the regularised friction's share) all taken at
    the centroid of the rim's arc, the point whose normal mass 1/K_zz sizes the damper (friction
    acts at the centre of pressure q, which depends on the damper's own force; q and the
    centroid lie on one line, both tend to the lowest point for a short arc and to the face's
    centre as the arc closes, so ρ is continuous as the arc becomes the whole circle, near 1 for
    a coin flat on the table); ρ at least :data:`SLIDING_MASS_FLOOR`.

    ρ ≤ 0 where μ K_zt·u_t/sqrt(u_t² + v_ε²) ≥ K_zz: friction then drives the contact into the
    table faster than the normal force pushes it out, a Painlevé-type jam. This needs μ above
    μ* = K_zz / max over slip directions of K_zt·û (for a nickel μ* ≈ 1.12 at a tilt near 61°; the
    floor 0.1 already bites from μ ≈ 1.008). The range μ > 1 is not validated: the t_c → 0
    limit (``frozen_limit``) of 60 of ``benchmarks/bench_rim_impacts.py``'s impacts (seed 1) is a
    median 0.0084, 0.0092, 0.0117 m/s from Stronge's law at μ 1.2, 1.5, 2 (largest 0.082 m/s, J_n
    0.95-1.02 of the rigid law's; 2026-11-24), against 0.00056 at μ 0.3.

    Each rim's ρ uses that rim's own single-contact K. When both rims' arcs are in the table
    (an impact across the edge band, and every coin rolling upright in it) the pair is damped
    together by :func:`_pair`, from the two centroids' coupled 2×2 normal mobility, each rim's
    ρ scaling its own row and column (the module notes, "Two rims"); this rim's damper alone
    then serves only when the pair's damping would pull on a rim."""
    turn, kzz = _normal_row(rc, n, mass, i1, i3)
    if friction > 0.0:
        zeta = zeta / math.sqrt(_sliding_ratio(rc, turn, kzz, v, omega, friction))
    return zeta, 1.0 / kzz


@njit(cache=True, inline="always")
def _normal_row(rc, n, mass, i1, i3):
    """(I⁻¹(rc × Z), K_zz) of the point rc (relative to the centre of mass, m): the product
    the collision matrix's normal row is built from and its normal entry K_zz = 1/m +
    (rc × Z)·I⁻¹(rc × Z), 1/kg (Stronge 2000, eq 5.7; :func:`_damper`)."""
    arm = (rc[1], -rc[0], 0.0)  # rc × Z
    turn = inverse_inertia_apply(arm, n, i1, i3)
    return turn, 1.0 / mass + dot(arm, turn)


@njit(cache=True, inline="always")
def _sliding_ratio(rc, turn, kzz, v, omega, friction):
    """ρ of :func:`sliding_mass_ratio` at the point rc, from :func:`_normal_row`'s (turn, K_zz)
    and the material point's slip v + ω × rc (:func:`_damper`)."""
    u = cross(omega, rc)
    kzx = dot((0.0, rc[2], -rc[1]), turn)  # rc × X
    kzy = dot((-rc[2], 0.0, rc[0]), turn)  # rc × Y
    return sliding_mass_ratio(kzx, kzy, kzz, v[0] + u[0], v[1] + u[1], friction, SLIP_SPEED)


@njit(cache=True)
def sliding_mass_ratio(kzx, kzy, kzz, ux, uy, friction, slip_speed):
    """ρ = max(1 + K_zt·(F_t/F_n) / K_zz, :data:`SLIDING_MASS_FLOOR`) of a contact point
    whose collision matrix has the normal row (K_zx, K_zy, K_zz) (1/kg) and whose slip is
    (u_x, u_y) (m/s), F_t/F_n = −μ u_t / sqrt(u_t² + v_ε²) the regularised friction's share
    (v_ε = ``slip_speed``): the ratio of the normal effective mass's inverse with that friction,
    K_zz + K_zt·F_t/F_n, to the frictionless K_zz (Stronge 2000, eq 5.7 and ch. 4), as
    :func:`_damper` sizes a rim's damper with it."""
    share = friction / math.sqrt(ux * ux + uy * uy + slip_speed * slip_speed)
    return max(1.0 - share * (kzx * ux + kzy * uy) / kzz, SLIDING_MASS_FLOOR)


@njit(cache=True, inline="always")
def _rims(z, v, n, omega, s, w, lower, c, stiffness, zeta):
    """Both rims' (F_n, q, r_t) as :func:`_derivative` applies them, the lower rim (σ =
    ``lower``) first: when both arcs are non-empty (:data:`JOINT_DAMPING`), :func:`_pair`'s,
    the pair damped together if both its forces are positive, else each rim alone (the module
    notes, "Two rims"); otherwise each rim's :func:`_rim` (its damper sized alone, ζ/sqrt(ρ)),
    as before. Inlined into the derivative and into :func:`upright_decided`. Also returned:
    whether the pair was damped jointly, and its damping matrix (C₁₁, C₁₂, C₂₂) then (NaNs
    otherwise; :func:`rims_contact`)."""
    if JOINT_DAMPING and zeta > 0.0 and _both_arcs(z, n, s, lower, c):
        joint, g1, p1, t1, g2, p2, t2, c11, c12, c22 = _pair(
            lower, z, v, n, omega, s, w, c, stiffness, zeta
        )
        if joint:
            return g1, p1, t1, g2, p2, t2, True, c11, c12, c22
        return g1, p1, t1, g2, p2, t2, False, math.nan, math.nan, math.nan
    f1, q1, r1 = 0.0, (0.0, 0.0, 0.0), 0.0
    f2, q2, r2 = 0.0, (0.0, 0.0, 0.0), 0.0
    for sigma in (lower, -lower):
        # each rim's damper for the normal mass its friction leaves (_damper's), in _rim
        fn, q, rt, _ = _rim(
            sigma,
            z,
            v,
            n,
            omega,
            s,
            w,
            c.radius,
            c.half_thickness,
            c.mass,
            c.i1,
            c.i3,
            stiffness,
            zeta,
            c.corner_radius,
            c.friction,
        )
        if sigma == lower:
            f1, q1, r1 = fn, q, rt
        else:
            f2, q2, r2 = fn, q, rt
    return f1, q1, r1, f2, q2, r2, False, math.nan, math.nan, math.nan


@njit(cache=True, inline="always")
def _both_arcs(z, n, s, lower, c):
    """Whether both rims' arcs are non-empty (d(φ) > 0 somewhere), decided as :func:`_rim`
    decides it (a + b > 0, the same operations)."""
    radius = c.radius - c.corner_radius
    hh = c.half_thickness - c.corner_radius
    b = radius * s
    upper = -lower
    return c.corner_radius - z - lower * hh * n[2] + b > 0.0 and (
        c.corner_radius - z - upper * hh * n[2] + b > 0.0
    )


@njit(cache=True)
def rims_contact(y, c, stiffness, zeta):
    """Both rims' normal forces as :func:`_derivative` applies them, for tests and studies:
    (σ₁, F₁, q₁, F₂, q₂, joint, C₁₁, C₁₂, C₂₂), rim 1 the lower one (σ₁ = −1, the tails rim,
    when n_z ≥ 0), rim 2 = −σ₁; F ≥ 0 (N) and the centres of pressure q (m, relative to the
    centre of mass) of :func:`rim_contact`; ``joint`` whether the pair is damped together
    (:func:`_pair`), and then its damping matrix C (N s/m), else NaNs."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    f1, q1, _, f2, q2, _, joint, c11, c12, c22 = _rims(
        y[0], v, n, omega, s, w, lower, c, stiffness, zeta
    )
    return lower, f1, q1, f2, q2, joint, c11, c12, c22


@njit(cache=True)
def joint_damping(w11, w12, w22, k1, k2, zeta):
    """(ok, C₁₁, C₁₂, C₂₂): the damping matrix C = 2 ζ M^½ (M^−½ K M^−½)^½ M^½ of two contacts
    with the normal mobility W (1/kg; M = W⁻¹ their mass matrix) and the tangent stiffnesses
    K = diag(k₁, k₂) (N/m), which damps every mode of M ẍ + C ẋ + K x = 0 at the ratio ζ
    (Caughey's modal damping; Caughey & O'Kelly, J. Appl. Mech. 32:583, 1965). It is 2 ζ
    times the geometric mean M # K of the two positive matrices, symmetric and positive
    definite (Bhatia, *Positive Definite Matrices*, 2007, §4.1), and for one contact
    (k₂ → 0) the single damper 2 ζ sqrt(k₁/W₁₁), which :func:`_rim` applies.

    In closed form, no matrix function evaluated: the square root of a 2 × 2 positive matrix,
    sqrt(A) = (A + sqrt(det A) I) / sqrt(tr A + 2 sqrt(det A)) (Cayley–Hamilton; Levinger,
    Math. Mag. 53:222, 1980), gives for det A = det B = 1 the geometric mean
    A # B = (A + B) / sqrt(det(A + B)) (the 2 × 2 case in Bhatia 2007, ch. 4: the positive
    solution of G A⁻¹ G = B, which ``tests/test_two_rim_damping.py`` checks against the
    definition with SciPy's sqrtm), and by its homogeneity
    M # K = sqrt(αβ) (M/α + K/β) / sqrt(det(M/α + K/β)), α = sqrt(det M) = 1/sqrt(det W),
    β = sqrt(k₁ k₂), M/α = adj(W)/sqrt(det W). det(M/α + K/β) ≥ 4 (two unit-determinant
    positive matrices), so nothing cancels but det W, which is the rims' separation: ok is
    False when det W ≤ :data:`JOINT_DEGENERATE` W₁₁ W₂₂ (two contacts on one vertical line, a
    rim without a flat band, a = h/2; the caller then damps each alone)."""
    det = w11 * w22 - w12 * w12
    if not det > JOINT_DEGENERATE * w11 * w22 or not k1 > 0.0 or not k2 > 0.0:
        return False, 0.0, 0.0, 0.0
    root = math.sqrt(det)
    ratio = math.sqrt(k1 / k2)
    s11 = w22 / root + ratio
    s22 = w11 / root + 1.0 / ratio
    s12 = -w12 / root
    scale = 2.0 * zeta * math.sqrt(math.sqrt(k1 * k2) / (root * (s11 * s22 - s12 * s12)))
    return True, scale * s11, scale * s12, scale * s22


@njit(cache=True, inline="always")
def _pair_rim(
    sigma, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
):
    """What :func:`_pair` needs of rim σ (``radius``, ``hh`` those of the core cylinder):
    (K_t = 2 φ κ, elastic force, its moment ∫ κ d cos φ, ∫ ḋ_s, ∫ ḋ_s cos φ, 2 φ, 2 sin φ, ρ,
    K_zz, I⁻¹(rc × Z), rc, r_t, φ*), from :func:`_rim`'s arc sums, in its operations; K_t 0
    for an empty arc."""
    zero = (0.0, 0.0, 0.0)
    a = corner - z - sigma * hh * n[2]
    b = radius * s
    if a + b <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, zero, zero, 0.0, 1.0
    phi, sp, cp = _arc(a, b)
    i0 = 2.0 * phi
    ic = 2.0 * sp
    icc = phi + sp * cp
    a0 = -(v[2] + sigma * hh * wn[2])
    a1 = -radius * ww[2]
    rc = _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp)
    turn, kzz = _normal_row(rc, n, mass, i1, i3)
    rho = _sliding_ratio(rc, turn, kzz, v, omega, friction) if friction > 0.0 else 1.0
    elastic = stiffness * (a * i0 + b * ic)
    moment = stiffness * (a * ic + b * icc)
    rate = a0 * i0 + a1 * ic
    turning = a0 * ic + a1 * icc
    ratio = sp / phi
    pivot = radius * math.sqrt(max(0.0, 1.0 - ratio * ratio))
    return i0 * stiffness, elastic, moment, rate, turning, i0, ic, rho, kzz, turn, rc, pivot, phi


@njit(cache=True, inline="always")
def _alone(sigma, rim, n, w, radius, hh, corner, friction, zeta):
    """(F_n, q, r_t) of rim σ damped alone from :func:`_pair_rim`'s sums ``rim``: :func:`_rim`'s
    force, in its operations (the damper ζ/sqrt(ρ) sqrt(K_t m_eff)/φ*, m_eff = 1/K_zz,
    :func:`_damper`), so the same to the bit. For :func:`_pair`'s fall-back, which so does not
    compute the rims' arcs twice."""
    k, elastic, moment, rate, turning, _, _, rho, kzz, _, _, pivot, phi = rim
    if friction > 0.0:
        zeta = zeta / math.sqrt(rho)
    gamma = zeta * math.sqrt(k * (1.0 / kzz)) / phi
    force = elastic + gamma * rate
    if force <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0
    moment += gamma * turning
    kq = radius * moment / force
    q = (
        sigma * hh * n[0] + kq * w[0],
        sigma * hh * n[1] + kq * w[1],
        sigma * hh * n[2] + kq * w[2] - corner,
    )
    return force, q, pivot


@njit(cache=True)
def _pair(lower, z, v, n, omega, s, w, c, stiffness, zeta):
    """Both rims' (ok, F₁, q₁, r_t₁, F₂, q₂, r_t₂, C₁₁, C₁₂, C₂₂) damped together (the module
    notes, "Two rims"), rim 1 σ = ``lower``, rim 2 σ = −``lower``; ok False when a rim's
    joint force would not be positive or the pair is degenerate (:func:`joint_damping`), and
    then the forces are each rim's alone (:func:`_alone`: :func:`_rim`'s to the bit, from the
    same sums; zeros when an arc is empty). The pivot radii r_t are :func:`_rim`'s, computed
    here; ``benchmarks/bench_rim_impacts.py``'s ``--drill-factor``, which wraps :func:`_rim`,
    so does not reach a coin with both arcs in the table (its impacts, tilted 9-80°, touch
    with one rim).

    Each rim's arc, its sums and its centroid rc_i are :func:`_rim`'s; the pair's normal
    mobility is W_ij = 1/m + (rc_i × Z)·I⁻¹(rc_j × Z) (the normal block of Stronge's collision
    matrix for two points, Stronge 2000, eq 5.7: :func:`_normal_row`), its tangent stiffnesses
    k_i = 2 φ_i κ. The sliding correction stays each rim's own (:func:`_damper`): ρ_i at the
    rim's centroid, entering as the congruence W̃ = P^½ W P^½, P = diag(ρ₁, ρ₂) (each rim's
    normal row and column scaled by sqrt(ρ_i), its K_zz by ρ_i as for one rim, the coupling by
    the geometric mean sqrt(ρ₁ ρ₂)), so that C stays symmetric positive and is :func:`_rim`'s
    damper 2 (ζ/sqrt(ρ_i)) sqrt(k_i/K_zz) when the other arc vanishes. The coupled friction
    terms between the rims (the collision matrix's K_zt of one rim's friction at the other's
    normal, not symmetric) are left out: a viscous damper needs a symmetric mass.

    The damping forces D = C ḋ act on the arcs' mean penetration rates ḋ_i = a0 + a1 sin φ/φ
    (the normal velocity of the centroid's material point): each rim's own part C_ii ḋ_i
    spread over its arc as :func:`_rim`'s, γ_i ḋ_s(φ) with γ_i = C_ii/(2 φ_i), the coupling
    C_ij ḋ_j spread evenly over the arc (acting at its centroid). Both act in the arc's plane
    of symmetry (no torque about n or the vertical: L·n and L_z conserved without friction),
    and the power they take, ḋᵀ C ḋ + Σ C_ii var_i(ḋ_s) ≥ 0 (var_i the spread of the even
    rate over arc i), is never negative: the pair still only dissipates."""
    mass, i1, i3, corner, friction = c.mass, c.i1, c.i3, c.corner_radius, c.friction
    radius = c.radius - corner
    hh = c.half_thickness - corner
    zero = (0.0, 0.0, 0.0)
    fail = (False, 0.0, zero, 0.0, 0.0, zero, 0.0, 0.0, 0.0, 0.0)
    wn = cross(omega, n)
    ww = cross(omega, w)
    one = _pair_rim(
        lower, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
    )
    two = _pair_rim(
        -lower, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
    )
    if one[0] <= 0.0 or two[0] <= 0.0:
        return fail
    k1, el1, mo1, d1, e1, i01, ic1, rho1, kz1, t1, _, r1, _ = one
    k2, el2, mo2, d2, e2, i02, ic2, rho2, kz2, _, c2, r2, _ = two
    w12 = (1.0 / mass + dot((c2[1], -c2[0], 0.0), t1)) * math.sqrt(rho1 * rho2)
    ok, c11, c12, c22 = joint_damping(rho1 * kz1, w12, rho2 * kz2, k1, k2, zeta)
    rate1 = d1 / i01  # the arcs' mean penetration rates
    rate2 = d2 / i02
    g1 = c11 / i01
    g2 = c22 / i02
    f1 = el1 + g1 * d1 + c12 * rate2
    f2 = el2 + g2 * d2 + c12 * rate1
    if not (ok and f1 > 0.0 and f2 > 0.0):
        # each rim alone, from the same sums (to the bit _rim's: the module notes, "Two rims")
        a1, b1, s1 = _alone(lower, one, n, w, radius, hh, corner, friction, zeta)
        a2, b2, s2 = _alone(-lower, two, n, w, radius, hh, corner, friction, zeta)
        return False, a1, b1, s1, a2, b2, s2, c11, c12, c22
    m1 = mo1 + g1 * e1 + c12 * rate2 * ic1 / i01
    m2 = mo2 + g2 * e2 + c12 * rate1 * ic2 / i02
    kq1 = radius * m1 / f1
    kq2 = radius * m2 / f2
    q1 = (
        lower * hh * n[0] + kq1 * w[0],
        lower * hh * n[1] + kq1 * w[1],
        lower * hh * n[2] + kq1 * w[2] - corner,
    )
    q2 = (
        -lower * hh * n[0] + kq2 * w[0],
        -lower * hh * n[1] + kq2 * w[1],
        -lower * hh * n[2] + kq2 * w[2] - corner,
    )
    return True, f1, q1, r1, f2, q2, r2, c11, c12, c22


@njit(cache=True)
def _derivative(y, out, c, stiffness, zeta):
    """dy/dt of the state y = (z, v, n, L) in contact (the forces of the module notes).

    Its cost (2026-11-24, one thread, load 5-9; 1,000 one-rim states, μ 0.3, resistances 1e-4 m,
    200 × 1,000 calls, CPU time, medians of 7): **126 ns a call**, against 228 at main 4f0dfa5
    (the sliding-mass damper then computed each rim's arc, centroid and I⁻¹ product twice, once
    in ``_sliding_damping``, now gone, and once in :func:`_rim`) and 142 before the damper
    (507692d).

    :func:`_rim` is inlined into it (``inline="always"``: numba's IR inlining; LLVM had left it
    a call with 17 arguments; ~8 % of a step, :func:`_integrate`): results identical to the bit
    (12,000 random states against 4f0dfa5). This one is **not** inlined into
    :func:`_integrate`'s seven calls, a trade measured (2026-11-24 06:12-06:19 UTC, load
    2.3-5.8; compilation: CPU time of :func:`settle`'s first call in a fresh NUMBA_CACHE_DIR;
    speed: 300 nickel tosses, e 0.5, μ 0.3, carried to rest by ``outcomes.table.land`` in one
    thread, landings a CPU second, median of 3; two runs each): inlined there too, **16.8-17.5
    s** to compile and **1,669** a CPU second; not (the code now) **8.8-9.3 s** and
    **1,500-1,503** (the same steps, so ~1,120 ns a step against ~1,010); 4f0dfa5 8.6-8.7 s and
    1,003-1,004. Inlining bought 11 % more speed for twice the compilation, which every fresh
    clone, CI run, docs build and edit of this module pays (a reviewer's run at higher load: 23
    s against 12 s, 2026-11-24): kept out, the rate is 1.50× 4f0dfa5's at its compile time.
    Tried too: :func:`_rim` not inlined but this one, 12.8-15.7 s and 1,514-1,532; this one and
    :func:`_rim` inlined but not :func:`below_barrier` and :func:`upright_decided`, 16.4 s and
    1,557-1,570. Measured and not kept: the coin's inverse inertia by reciprocals instead of
    divisions, and one square root and two divisions fewer in the damper's ζ sqrt(K_t
    m_eff)/sqrt(ρ) (no change beyond the noise: the divider is not what holds it; both would
    change results at rounding); the stages of :func:`_integrate` in one loop with a single
    inlined call (compile time as before, but 1,120 against 1,055 ns a step). What is left: the
    arc's arccos (libm's; ~35 ns of a call when knocked out), the square roots and divisions of
    the forces."""
    mass, i1, i3, radius = c.mass, c.i1, c.i3, c.radius
    mu, rolling, pivoting = c.friction, c.rolling_resistance, c.pivoting_resistance
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, i1, i3)
    spin_eps = SLIP_SPEED / radius
    fx, fy, fz = 0.0, 0.0, -mass * c.g
    tx, ty, tz = 0.0, 0.0, 0.0
    # The lower rim first: the same sums, in the same order, for the mirror toss (n → −n).
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    f1, q1, r1, f2, q2, r2, _, _, _, _ = _rims(y[0], v, n, omega, s, w, lower, c, stiffness, zeta)
    for k in range(2):
        fn, q, rt = (f1, q1, r1) if k == 0 else (f2, q2, r2)
        if fn <= 0.0:
            continue
        fz += fn
        tx += q[1] * fn  # q × (0, 0, F_n)
        ty -= q[0] * fn
        if mu > 0.0:
            u = cross(omega, q)
            ux, uy = v[0] + u[0], v[1] + u[1]
            k = -mu * fn / math.sqrt(ux * ux + uy * uy + SLIP_SPEED * SLIP_SPEED)
            gx, gy = k * ux, k * uy
            fx += gx
            fy += gy
            tx -= q[2] * gy  # q × (gx, gy, 0)
            ty += q[2] * gx
            tz += q[0] * gy - q[1] * gx
        drill = mu * rt + pivoting
        if drill > 0.0:
            tz -= drill * fn * omega[2] / math.sqrt(omega[2] * omega[2] + spin_eps * spin_eps)
        if rolling > 0.0:
            k = (
                -rolling
                * fn
                / math.sqrt(omega[0] * omega[0] + omega[1] * omega[1] + spin_eps * spin_eps)
            )
            tx += k * omega[0]
            ty += k * omega[1]
    nd = cross(omega, n)
    out[0] = v[2]
    out[1] = fx / mass
    out[2] = fy / mass
    out[3] = fz / mass
    out[4] = nd[0]
    out[5] = nd[1]
    out[6] = nd[2]
    out[7] = tx
    out[8] = ty
    out[9] = tz


@njit(cache=True)
def energy(y, c, stiffness):
    """Mechanical energy of the state y = (z, v, n, L): ½ m v² + ½ L·ω + m g z + the springs', J."""
    return _with_springs(_motion_energy(y, c), y, c, stiffness)


@njit(cache=True, inline="always")
def _motion_energy(y, c):
    """½ m v² + ½ L·ω + m g z of the state y, J: :func:`energy` without the springs'."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    return 0.5 * c.mass * dot(v, v) + 0.5 * dot(lm, omega) + c.mass * c.g * y[0]


@njit(cache=True, inline="always")
def _motion_free_energy(y, c):
    """(e, f): :func:`_motion_energy` and its part that :func:`free_energy` sets against the
    barrier without springs: all of it with friction or resistances, else less the horizontal
    kinetic energy (conserved, not free). Shared with
    :func:`coinflight.core.rigid_contact.below_barrier`."""
    e = _motion_energy(y, c)
    if _dissipative(c):
        return e, e
    return e, e - 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])


@njit(cache=True)
def _with_springs(e, y, c, stiffness):
    """e plus the elastic energy of both rims' arcs (:func:`rim_contact`), added in the order of
    :func:`energy`, J."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    for sigma in (lower, -lower):
        _, _, _, spring = _rim(
            sigma,
            y[0],
            v,
            n,
            omega,
            s,
            w,
            c.radius,
            c.half_thickness,
            c.mass,
            c.i1,
            c.i3,
            stiffness,
            0.0,
            c.corner_radius,
        )
        e += spring
    return e


@njit(cache=True)
def _corner_energy(ln, lz, nz, c):
    """Least energy of the coin balanced on a corner at n_z = nz with L·n = ln and L_z = lz."""
    return c.barrier + 0.5 * ln * ln / c.i3 + 0.5 * (lz - ln * nz) ** 2 / (c.i1 * (1.0 - nz * nz))


@njit(cache=True, inline="always")
def _dissipative(c):
    """Whether anything but the normal damping dissipates (friction or a resistance)."""
    return c.friction > 0.0 or c.rolling_resistance > 0.0 or c.pivoting_resistance > 0.0


@njit(cache=True, inline="always")
def _barrier(y, c):
    """The barrier of :func:`free_energy`, J: m g ρ with friction or resistances, else the least
    energy on the corners of the well at the conserved L·n, L_z."""
    if _dissipative(c):
        return c.barrier
    ln = y[4] * y[7] + y[5] * y[8] + y[6] * y[9]
    lz = y[9]
    nz = y[6]
    corner = c.edge_sine
    up = _corner_energy(ln, lz, corner, c)
    down = _corner_energy(ln, lz, -corner, c)
    if abs(nz) < corner:
        return min(up, down)
    return up if nz > 0.0 else down


@njit(cache=True)
def free_energy(y, c, stiffness):
    """(energy that can lift the coin, barrier of its well), J (module notes, "ending").

    With friction or resistances: the mechanical energy and m g ρ. Frictionless: the energy
    less ½ m v_h² and the least energy on the corners of the well at the conserved L·n, L_z.
    """
    e = energy(y, c, stiffness)
    if not _dissipative(c):
        e -= 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])
    return e, _barrier(y, c)


@njit(cache=True, inline="always")
def below_barrier(y, c, stiffness):
    """``free < barrier`` of :func:`free_energy`, decided alike to the bit, but without the
    springs' energy (two :func:`rim_contact` sums) when the rest of the energy already reaches
    the barrier: the springs' energies are ≥ 0 (:func:`rim_contact` clamps its energy at 0,
    where the closed form's cancellation on a short arc gives down to −5e-20 J) and rounded
    addition and subtraction are monotonic, so adding them cannot bring the sum below it. The
    test :func:`_integrate` makes after every step (~10 % of a step's time before this
    shortcut); inlined there (``inline="always"``, with the energy's pieces: ~3 % of a step,
    2026-11-24, :func:`_integrate`)."""
    e, free = _motion_free_energy(y, c)
    barrier = _barrier(y, c)
    if free >= barrier:
        return False
    e = _with_springs(e, y, c, stiffness)
    if not _dissipative(c):
        e -= 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])
    return e < barrier


SINGLE_RIM_DEPTH = 2.0 ** (2.0 / 3.0)
"""How much deeper one rim sinks carrying the whole weight than each of two carrying half of it
(F ∝ d^(3/2) on a short arc): the depth on the lean's ridge is this times :func:`static_depth`."""


@njit(cache=True)
def static_depth(c, stiffness):
    """d_s, m: how deep an upright coin at rest sinks into the table (module notes, "Upright
    rollers"), both rims' arcs in the parabolic approximation of the rim, 1 − cos φ ≈ φ²/2:
    each carries F = (4√2/3) κ d^(3/2) / sqrt(r − a) = m g / 2 and stores (2/5) F d. The exact
    arc's penetration d − (r − a)(1 − cos φ) is the larger at every φ, so its springs store more
    at every depth, and the least potential energy (gravity and springs) of an upright coin is
    at least that of the approximation, m g (r − d_s) + (2/5) m g d_s = m g (r − (3/5) d_s);
    so is, with the depth d_1 = 2^(2/3) d_s of one rim carrying m g alone, that of a coin on one
    rim whose rigid centre height is H: m g (H − (3/5) d_1) (the other rim's springs, dropped,
    only add)."""
    radius = c.radius - c.corner_radius
    weight = c.mass * c.g
    return (3.0 * weight * math.sqrt(radius) / (8.0 * math.sqrt(2.0) * stiffness)) ** (2.0 / 3.0)


BUDGET_STEP = 1e-4
"""Seconds a step of :func:`_integrate` is taken to cover when :func:`upright_decided` asks
whether the steps left can carry a roller to rest: below the mean step measured in upright
rolling (~0.6 ms: ~1,600 steps a simulated second at t_c 1 ms, 2026-11-23), so that a roller
which would run out of :data:`MAX_STEPS` is not decided (the decision turns no UNSETTLED toss
into a settled one);
:data:`MAX_STEP` (1 ms) was too loose (rollers of 250–400 s decided). A contact time far below
1 ms shortens the steps below this."""


@njit(cache=True, inline="always")
def upright_decided(y, c, stiffness, zeta, budget):
    """True if the coin in state y = (z, v, n, L) rolls upright on both rims of its edge band
    and the rigid wheel's bounds hold with :data:`UPRIGHT_MARGIN` to spare (module notes,
    "Upright rollers"): a measured predictor of ending on edge (0 disagreements in 961
    decisions at rolling and pivoting resistance 1e-5 m and in 737 at the default 1e-4 m, the
    latter counted before an unsettled carry counted as a disagreement,
    ``benchmarks/bench_contact.py``), not a proof that it stays upright to rest.

    In this order (cheap tests first): a band (h′ = h/2 − a > 0) and friction (μ > 0); the
    turn's overturning moment M = (I3 |ω·n| + m r |v_h|) |ω_z| at most :data:`UPRIGHT_MARGIN`
    of the band's m g h′; the friction the turn and the rolling resistance need,
    sqrt((m |v_h| |ω_z|)² + F_r²), F_r = m ℓ_r m g r / (I3 + m r²), at most that share of μ m g;
    both rims pressed (their forces as :func:`_derivative` applies them, :func:`_rims`: each
    rim's damper sized alone, :func:`_damper`, or the pair's joint damping, :func:`_pair`:
    the force they exert now); the
    band's middle not slipping (the horizontal velocity of its lowest point below
    :data:`SLIP_SPEED`); the tilt below the lean's ridge θ*; and the energy that can lean the
    coin (the whole energy less the rolling and yawing kinetic energy ½ m (v·t̂)² + ½ I3 (ω·n)²
    + ½ I1 (ω·ŵ)², t̂ the horizontal unit vector across n) above the least potential energy
    upright, m g (r − (3/5) d_s) (:func:`static_depth`), by at most that share of the ridge's
    height above it (the notes).

    First of all, the coin must come to rest within ``budget`` s (the time the integration's
    remaining steps can cover, (steps left) × :data:`BUDGET_STEP` in :func:`_integrate`):
    with no rolling resistance (ℓ_r ≤ 0) it never stops rolling, and otherwise the resistance
    brakes ω = v/r at most at the rate ℓ_r m g / (I3 + m r²) (the torque ℓ_r F_n of
    :func:`_derivative`, N = m g on the two rims, weaker below its regularisation), so it rolls
    at least (v/r) (I3 + m r²) / (ℓ_r m g). A roller that carried on would end UNSETTLED after
    :data:`MAX_STEPS` is not decided, so that the decision turns no UNSETTLED toss into a
    decided one.
    """
    hb = c.half_thickness - c.corner_radius  # h′: half the flat band
    if hb <= 0.0 or c.friction <= 0.0 or c.rolling_resistance <= 0.0:
        return False
    mass, i1, i3, g, radius = c.mass, c.i1, c.i3, c.g, c.radius
    weight = mass * g
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    across = math.sqrt(n[0] * n[0] + n[1] * n[1])
    if across < 0.5:
        return False  # not near upright (two rims touch only within the band's tilt)
    omega = angular_velocity(lm, n, i1, i3)
    spin = dot(omega, n)
    yaw = abs(omega[2])
    vh = math.sqrt(v[0] * v[0] + v[1] * v[1])
    brake = c.rolling_resistance * weight / (i3 + mass * radius * radius)  # dω/dt, rad/s²
    if vh / radius > brake * budget:
        return False  # rolls longer than the steps left can reach
    moment = (i3 * abs(spin) + mass * radius * vh) * yaw
    if moment > UPRIGHT_MARGIN * weight * hb:
        return False
    resist = mass * c.rolling_resistance * weight * radius / (i3 + mass * radius * radius)
    turn = mass * vh * yaw
    if math.sqrt(turn * turn + resist * resist) > UPRIGHT_MARGIN * c.friction * weight:
        return False
    s, w = _tangent_basis(n)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    f1, _, _, f2, _, _, _, _, _, _ = _rims(y[0], v, n, omega, s, w, lower, c, stiffness, zeta)
    if f1 <= 0.0 or f2 <= 0.0:  # both rims pressed, as _derivative presses them
        return False
    core = radius - c.corner_radius  # r − a, the rim circle's radius
    low = (core * w[0], core * w[1], core * w[2] - c.corner_radius)  # the band middle's lowest
    u = cross(omega, low)
    ux, uy = v[0] + u[0], v[1] + u[1]
    if ux * ux + uy * uy > SLIP_SPEED * SLIP_SPEED:
        return False
    t = (-n[1] / across, n[0] / across, 0.0)
    vt = dot(v, t)
    ww = dot(omega, w)
    rolling = 0.5 * mass * vt * vt + 0.5 * i3 * spin * spin + 0.5 * i1 * ww * ww
    free = energy(y, c, stiffness) - rolling
    # The ridge of the lean: the coin on one rim at the tilt θ* where the restoring moment
    # m g (h′ cos θ − (r − a) sin θ) of the rigid pivot meets M, sunk to the depth at which that
    # rim alone carries m g, the turn's work M (θ* + θ_now) and the spin's (I3 − I1) ω_z²
    # sin²θ* / 2 taken off (the notes).
    depth = static_depth(c, stiffness)
    floor = weight * (radius - 0.6 * depth)  # least potential energy upright, at most
    reach = math.sqrt(core * core + hb * hb)
    tip = math.acos(moment / (weight * reach)) - math.acos(hb / reach)
    lean = math.asin(min(abs(n[2]), 1.0))
    if lean >= tip:
        return False
    ridge = weight * (core * math.cos(tip) + hb * math.sin(tip) + c.corner_radius)
    ridge -= 0.6 * weight * SINGLE_RIM_DEPTH * depth + moment * (tip + lean)
    ridge -= 0.5 * max(i3 - i1, 0.0) * yaw * yaw * math.sin(tip) ** 2
    return ridge > floor and free <= floor + UPRIGHT_MARGIN * (ridge - floor)


# Dormand-Prince 5(4) (Hairer, Nørsett & Wanner, Solving ODEs I, table II.5.2).
_A21 = 1.0 / 5.0
_A31, _A32 = 3.0 / 40.0, 9.0 / 40.0
_A41, _A42, _A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
_A51, _A52, _A53, _A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
_A61, _A62, _A63 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0
_A64, _A65 = 49.0 / 176.0, -5103.0 / 18656.0
_B1, _B3, _B4, _B5, _B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
_E1, _E3, _E4 = 71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0
_E5, _E6, _E7 = -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0


MODES = ("free", "one rim", "two rims", "face")
"""What the coin is doing, as :func:`contact_mode` classes it: off the table (a hop), on one
rim's arc with less than half the rim pressed (rolling, sliding, pivoting or rocking on a rim
point), on both rims (the edge band, or two points of a coin rocking across its edge), on its
face (one rim pressed along more than half its circle: lying flat, spinning or sliding)."""


@njit(cache=True)
def contact_mode(y, c):
    """The index in :data:`MODES` of what the coin in state y = (z, v, n, L) is doing."""
    n = (y[4], y[5], y[6])
    s = math.sqrt(max(0.0, 1.0 - n[2] * n[2]))
    radius = c.radius - c.corner_radius
    hh = c.half_thickness - c.corner_radius
    touching = 0
    face = False
    for sigma in (-1.0, 1.0):
        a = c.corner_radius - y[0] - sigma * hh * n[2]
        b = radius * s
        if a + b > 0.0:
            touching += 1
            if a >= 0.0:  # the arc covers more than half the rim (cos φ* = −a/b ≤ 0)
                face = True
    if touching == 0:
        return 0
    if touching == 2:
        return 2
    return 3 if face else 1


@njit(cache=True)
def _integrate(y, duration, c, stiffness, zeta, settle, decide, max_steps, stats, rtol):
    """Advance y in place for ``duration`` s (math.inf: no limit) or, if ``settle``, until the
    coin has settled, whichever comes first; with ``settle`` and ``decide``, a coin for which
    :func:`upright_decided` holds has settled too (on edge). ``stats`` (shape (len(MODES), 2),
    or (0, 2) for none) accumulates, per :func:`contact_mode` at the end of each step, the time
    and the steps taken (for the benchmark); with one more row (shape (len(MODES) + 1, 2),
    filled with −1 by the caller), that row receives (time, steps) when
    :func:`upright_decided` first holds, with or without ``decide`` (so a run carried to rest
    says where the decision would have ended it; the test runs at every step then). ``rtol``
    is the step control's relative tolerance (:data:`RTOL` but in tests).

    Returns (time advanced, accepted steps, :class:`Ending`): RUNNING (not settled), SETTLED
    (by the energy test) or DECIDED (by :func:`upright_decided`, with ``decide``).

    A step's cost (2026-11-24, one thread, load 6-9: the 90 tosses of 120 vigorous nickel
    tosses, e 0.5, μ 0.3, seed 3, that :func:`coinflight.core.bounce.bounce_loop` hands here,
    each carried to rest, 73,262 steps, CPU time, best of 3, three runs): **1,055-1,069 ns**
    with :func:`_derivative` and :func:`_rim` inlined, 1,026-1,044 with :func:`below_barrier`
    inlined too and 1,006-1,019 with :func:`upright_decided` too; the code now leaves
    :func:`_derivative` a call (its compile time: :func:`_derivative`), ~1,120 (1,500 against
    1,669 landings a CPU second, the same steps), against 1,677-1,706 at main 4f0dfa5 and 1,136
    before the sliding-mass damper (507692d); the same steps to the one. Of it (0.1 s of each
    toss), ~960 ns without the tests after each step (:func:`below_barrier`,
    :func:`upright_decided`), ~70 ns more with them; the six derivatives ~6 × 126 ns
    (:func:`_derivative`); the stepper's own arithmetic (its error norm's ten divisions and one
    power) the rest.
    """
    k1 = np.empty(10)
    k2 = np.empty(10)
    k3 = np.empty(10)
    k4 = np.empty(10)
    k5 = np.empty(10)
    k6 = np.empty(10)
    k7 = np.empty(10)
    tmp = np.empty(10)
    new = np.empty(10)
    scale = np.empty(10)
    reach = c.reach
    speed = max(math.sqrt(c.g * reach), 0.01)  # velocity scale of the tolerances, m/s
    scale[0] = reach
    for i in range(1, 4):
        scale[i] = speed
        scale[i + 3] = 1.0
        scale[i + 6] = c.i1 * speed / reach
    contact_time = c.contact_time
    h = contact_time / 20.0
    t = 0.0
    _derivative(y, k1, c, stiffness, zeta)
    modes = len(MODES)
    probe = stats.shape[0] > modes
    for step in range(max_steps):
        if settle:
            if below_barrier(y, c, stiffness):
                return t, step, Ending.SETTLED
            if (decide or (probe and stats[modes, 1] < 0.0)) and upright_decided(
                y, c, stiffness, zeta, (max_steps - step) * BUDGET_STEP
            ):
                if probe and stats[modes, 1] < 0.0:
                    stats[modes, 0] = t
                    stats[modes, 1] = step
                if decide:
                    return t, step, Ending.DECIDED
        if t >= duration:
            return t, step, Ending.RUNNING
        lm = (y[7], y[8], y[9])
        n = (y[4], y[5], y[6])
        omega = angular_velocity(lm, n, c.i1, c.i3)
        turn = 0.125 * math.pi / (math.sqrt(dot(omega, omega)) + 1e-300)
        limit = min(MAX_STEP, turn, duration - t)
        if h > limit:
            h = limit
        for _ in range(60):
            for i in range(10):
                tmp[i] = y[i] + h * _A21 * k1[i]
            _derivative(tmp, k2, c, stiffness, zeta)
            for i in range(10):
                tmp[i] = y[i] + h * (_A31 * k1[i] + _A32 * k2[i])
            _derivative(tmp, k3, c, stiffness, zeta)
            for i in range(10):
                tmp[i] = y[i] + h * (_A41 * k1[i] + _A42 * k2[i] + _A43 * k3[i])
            _derivative(tmp, k4, c, stiffness, zeta)
            for i in range(10):
                tmp[i] = y[i] + h * (_A51 * k1[i] + _A52 * k2[i] + _A53 * k3[i] + _A54 * k4[i])
            _derivative(tmp, k5, c, stiffness, zeta)
            for i in range(10):
                tmp[i] = y[i] + h * (
                    _A61 * k1[i] + _A62 * k2[i] + _A63 * k3[i] + _A64 * k4[i] + _A65 * k5[i]
                )
            _derivative(tmp, k6, c, stiffness, zeta)
            for i in range(10):
                new[i] = y[i] + h * (
                    _B1 * k1[i] + _B3 * k3[i] + _B4 * k4[i] + _B5 * k5[i] + _B6 * k6[i]
                )
            _derivative(new, k7, c, stiffness, zeta)
            err = 0.0
            for i in range(10):
                e = h * (
                    _E1 * k1[i]
                    + _E3 * k3[i]
                    + _E4 * k4[i]
                    + _E5 * k5[i]
                    + _E6 * k6[i]
                    + _E7 * k7[i]
                )
                tol = rtol * (scale[i] + max(abs(y[i]), abs(new[i])))
                r = abs(e) / tol
                if r > err:
                    err = r
            if err <= 1.0:
                break
            h *= max(0.2, 0.9 * err**-0.2)
        t += h
        if stats.shape[0] > 0:
            mode = contact_mode(new, c)
            stats[mode, 0] += h
            stats[mode, 1] += 1.0
        # Keep n a unit vector (the exact flow does).
        size = math.sqrt(new[4] * new[4] + new[5] * new[5] + new[6] * new[6])
        for i in range(10):
            y[i] = new[i]
        y[4] /= size
        y[5] /= size
        y[6] /= size
        # First same as last: k7, the derivative at the step's end before n's renormalisation
        # (a change of |n| by ≲1e-10 at RTOL 1e-7, measured, far below the step's tolerance
        # ~2e-7; re-evaluating it cost a seventh derivative in 96 % of the steps).
        for i in range(10):
            k1[i] = k7[i]
        h *= min(5.0, 0.9 * err**-0.2) if err > 0.0 else 5.0
    return t, max_steps, Ending.RUNNING


@njit(cache=True)
def stiffness_of(c):
    """κ = π m / (2 t_c²), N/m per radian of rim (module notes)."""
    return math.pi * c.mass / (2.0 * c.contact_time * c.contact_time)


@njit(cache=True)
def damping_of(c):
    """ζ of the contact record's restitution: the one :meth:`coinflight.core.contact.Contact.build`
    solved for, or, for another e (a toss's own, :func:`coinflight.core.bounce.with_surface`),
    :func:`tabulated_damping_ratio`."""
    if c.damping_restitution == c.restitution and c.damping_ratio >= 0.0:
        return c.damping_ratio
    return tabulated_damping_ratio(c.restitution)


@njit(cache=True)
def settle(z, v, n, lm, c):
    """Carry the coin on in contact until it cannot leave its well: (face, status, time).

    Parameters
    ----------
    z : float
        Height of the centre of mass above the table, m.
    v, n, lm : tuple of 3 floats
        Velocity of the centre of mass, heads normal (unit), angular momentum about the centre
        of mass (lab frame, SI).
    c : Contact
        The coin, the surface (e, μ, rolling and pivoting resistance, contact time) and g.

    Returns
    -------
    face : int
        TAILS 0, HEADS 1, EDGE 2: the well the coin cannot leave.
    status : Status
        SETTLED_CONTACT (the energy test: at rest or below its well's barrier),
        DECIDED_UPRIGHT (ended on edge by :func:`upright_decided`, :data:`UPRIGHT_DECISION`, a
        compile-time constant: a measured predictor, not a proof), or UNSETTLED after
        :data:`MAX_STEPS` steps.
    time : float
        Duration of the contact phase, s: until the energy test or, for a coin ended upright by
        :func:`upright_decided`, until that decision, not until it is at rest.
    """
    y = np.empty(10)
    y[0] = z
    y[1], y[2], y[3] = v
    y[4], y[5], y[6] = n
    y[7], y[8], y[9] = lm
    conservative = c.friction == 0.0 and c.rolling_resistance == 0.0
    if conservative and c.pivoting_resistance == 0.0 and c.restitution >= 1.0:
        # Nothing dissipates: the free energy stays where it is, above the barrier or below.
        y0 = (z, v[0], v[1], v[2], n[0], n[1], n[2], lm[0], lm[1], lm[2])
        y[:] = y0
        free, barrier = free_energy(y, c, stiffness_of(c))
        status = Status.SETTLED_CONTACT if free < barrier else Status.UNSETTLED
        return resting_face(n[2], c.edge_sine), status, 0.0
    t, _, ended = _integrate(
        y,
        math.inf,
        c,
        stiffness_of(c),
        damping_of(c),
        True,
        UPRIGHT_DECISION,
        MAX_STEPS,
        np.empty((0, 2)),
        RTOL,
    )
    face = resting_face(y[6], c.edge_sine)
    if ended == Ending.DECIDED:
        return face, Status.DECIDED_UPRIGHT, t
    if ended == Ending.SETTLED:
        return face, Status.SETTLED_CONTACT, t
    return face, Status.UNSETTLED, t


def advance(
    state: np.ndarray,
    duration: float,
    c,
    *,
    settle_check: bool = False,
    decide: bool = False,
    max_steps: int = MAX_STEPS,
    stats: np.ndarray | None = None,
    rtol: float = RTOL,
) -> tuple[float, int, Ending]:
    """Advance ``state`` = (z, vx, vy, vz, nx, ny, nz, Lx, Ly, Lz) in place (for tests and
    studies): (time, steps, ending), stopping after ``duration`` s or, with ``settle_check``,
    when the coin has settled by its energy (or, with ``decide`` too, when
    :func:`upright_decided` holds, as :func:`settle` with :data:`UPRIGHT_DECISION`), whichever
    comes first. ``decide`` is read at every call: ``decide=False`` is the run-time way to carry
    a coin on past the upright decision (:data:`UPRIGHT_DECISION` is fixed when numba
    compiles). ``ending`` (:class:`Ending`) is false when the coin has not settled, else
    SETTLED (the energy test) or DECIDED (the upright decision, the case :func:`settle`
    reports as DECIDED_UPRIGHT). ``stats``, an array of shape (len(:data:`MODES`), 2),
    accumulates the time and steps spent in each mode; with one more row filled with −1 (shape
    (len(:data:`MODES`) + 1, 2)) it also receives the (time, steps) at which
    :func:`upright_decided` first held, decided or not (with ``settle_check``). ``rtol``: the
    step control's relative tolerance (:data:`RTOL`; another for tests of the stepper; it must
    be positive and finite, not checked here: 0 or NaN rejects every step up to ``max_steps``)."""
    zeta = damping_of(c)
    if stats is None:
        stats = np.empty((0, 2))
    t, steps, ended = _integrate(
        state, duration, c, stiffness_of(c), zeta, settle_check, decide, max_steps, stats, rtol
    )
    return t, steps, Ending(ended)


@njit(cache=True)
def restitution_of(zeta, exponent):
    """Coefficient of restitution of the compliant normal law with damping ratio ζ.

    The dimensionless contact x'' = −x^p − 2 ζ sqrt(p x^(p−1)) x' (force K x^p, damping
    2 ζ sqrt(K_t m), K_t = dF/dx; m = K = v0 = 1, which the coefficient does not depend on), from
    x = 0, x' = 1 until the force vanishes (clipped at zero: the surface does not pull); e = −x'
    then. p = 3/2: a rim (Tsuji et al. 1992); p = 1: a face (Kelvin-Voigt; Schwager & Pöschel
    2007 give it in closed form).
    """
    x = 0.0
    u = 1.0
    dt = 2e-3
    for _ in range(1_000_000):
        # RK4 on (x, u).
        a1 = _law(x, u, zeta, exponent)
        x2, u2 = x + 0.5 * dt * u, u + 0.5 * dt * a1
        a2 = _law(x2, u2, zeta, exponent)
        x3, u3 = x + 0.5 * dt * u2, u + 0.5 * dt * a2
        a3 = _law(x3, u3, zeta, exponent)
        x4, u4 = x + dt * u3, u + dt * a3
        a4 = _law(x4, u4, zeta, exponent)
        xn = x + dt * (u + 2.0 * u2 + 2.0 * u3 + u4) / 6.0
        un = u + dt * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0
        fn = -_law(xn, un, zeta, exponent)
        if xn <= 0.0 or (un < 0.0 and fn <= 0.0):
            # Interpolate the end (force or depth zero) linearly within the step.
            f0 = -a1
            if xn <= 0.0:
                frac = x / (x - xn)
            elif f0 > fn:
                frac = f0 / (f0 - fn)
            else:
                frac = 1.0
            return -(u + frac * (un - u))
        x, u = xn, un
    return 0.0


@njit(cache=True)
def _law(x, u, zeta, exponent):
    if x <= 0.0:
        return 0.0
    return -(x**exponent) - 2.0 * zeta * math.sqrt(exponent * x ** (exponent - 1.0)) * u


@njit(cache=True)
def damping_ratio(restitution):
    """ζ for which a rim contact (p = 3/2) restitutes with e (:func:`restitution_of`), by
    bisection; 0 for e = 1."""
    if restitution >= 1.0:
        return 0.0
    lo, hi = 0.0, 1.0
    for _ in range(60):
        if restitution_of(hi, 1.5) < restitution:
            break
        lo = hi
        hi *= 2.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if restitution_of(mid, 1.5) > restitution:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


ZETA_TABLE_LOWEST = 0.01
"""Smallest restitution of :data:`_ZETA_TABLE`; below it :func:`damping_ratio` is solved."""
_ZETA_TABLE = np.array(
    [
        4.388888727213681,
        4.221400079771877,
        4.059748558767703,
        3.9037248976689147,
        3.7531251643587344,
        3.6077541296044453,
        3.467421996847416,
        3.331947858843793,
        3.2011562187272924,
        3.074878061945392,
        2.952950611125499,
        2.8352170897952442,
        2.7215263228595985,
        2.6117318558318106,
        2.505694525918421,
        2.403277899752994,
        2.3043526785002895,
        2.208792172259913,
        2.116475880965738,
        2.0272872100500754,
        1.9411136638009094,
        1.8578469086279665,
        1.7773826158198394,
        1.6996203103280902,
        1.6244632254126299,
        1.5518174888938803,
        1.4815936742515041,
        1.4137053144368514,
        1.3480682581373595,
        1.2846028350681489,
        1.223231183087337,
        1.1638785833208662,
        1.1064734682500421,
        1.050946468857298,
        0.997230792268812,
        0.9452621254954408,
        0.8949785430468142,
        0.8463204183169135,
        0.7992303386456183,
        0.7536530239691319,
        0.7095351128240996,
        0.6668248754493242,
        0.6254734975538345,
        0.5854325148170854,
        0.5466566742869481,
        0.5091015618719124,
        0.4727242467688124,
        0.43748397440605347,
        0.40334119515412814,
        0.3702575342918304,
        0.33819656480248694,
        0.3071228995910036,
        0.27700246765563685,
        0.24780225880805018,
        0.21949066103892045,
        0.19203748075038574,
        0.1654131027380985,
        0.13958927327199921,
        0.11453882483925559,
        0.09023548053205088,
        0.06665387894642594,
        0.04376956430442336,
        0.02155919153534347,
        0.0,
    ]
)
"""ζ = :func:`damping_ratio` (e) at 64 restitutions spaced evenly in ln e from
ln :data:`ZETA_TABLE_LOWEST` to 0 (computed by that function; tests/test_contact_phase.py checks
nodes and interpolation)."""


@njit(cache=True)
def tabulated_damping_ratio(restitution):
    """ζ for the restitution e, interpolated (cubic Lagrange in ln e on :data:`_ZETA_TABLE`):
    the restitution of the returned ζ (:func:`restitution_of`) is e within 1e-6 e, in ~50 ns
    instead of the ~28 ms of :func:`damping_ratio`'s bisection, which it calls below
    :data:`ZETA_TABLE_LOWEST`. For tosses each with its own e (:func:`settle`)."""
    if restitution >= 1.0:
        return 0.0
    if restitution < ZETA_TABLE_LOWEST:
        return damping_ratio(restitution)
    count = _ZETA_TABLE.shape[0]
    lowest = math.log(ZETA_TABLE_LOWEST)
    spacing = -lowest / (count - 1)
    u = (math.log(restitution) - lowest) / spacing
    i = min(max(int(u) - 1, 0), count - 4)
    total = 0.0
    for j in range(4):
        weight = 1.0
        for k in range(4):
            if k != j:
                weight *= (u - (i + k)) / (j - k)
        total += weight * _ZETA_TABLE[i + j]
    return total

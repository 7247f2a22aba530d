"""One oblique rim impact of a spinning nickel in three laws: Stronge's rigid impact
(:func:`coinflight.core.impact.impact`, the bounces' law), the compliant contact phase
(:mod:`coinflight.core.contact_phase`) and MuJoCo (needs the ``mujoco`` extra).

    python benchmarks/bench_rim_impacts.py [N] [--friction MU] [--contact-time T] [--seed S]
        [--condim 6] [--cone pyramidal|elliptic] [--impratio R] [--noslip K]
        [--solimp D0,DMAX,WIDTH]

N impacts (default 100): tilt ~ U(0.15, 1.4) rad, a random azimuth, v_h ~ N(0, 0.3) m/s per
axis, v_z ~ −U(0.3, 1.5) m/s, ω of magnitude U(50, 300) rad/s in a random direction, the
lowest rim point at the table and approaching it (faster than 0.05 m/s); e 0.5 (MuJoCo's
damping calibrated by a flat drop at 2 m/s), resistances 1e-4 m. Each state is compared 3 ms
after the touch (the rigid law followed by 3 ms of flight); an impact still or again in
contact then, in either soft engine, is drawn again. Prints the medians and 90th percentiles of
the velocity's distance to the rigid law's, m/s, and of the angular momentum's, in I1 ω, and
the mean fraction of the kinetic energy each law takes (gravity's 3 ms added back), and the
mean ratio of the horizontal to μ times the vertical impulse the table gave (from the momentum:
1 for an impact that slides one way throughout) and the vertical impulse J_n over the rigid
law's. ``--condim``, ``--cone``, ``--impratio``,
``--noslip``: MuJoCo's contact dimension and friction solver
(:class:`coinflight.studies.mujoco_compare.FrictionSolver`; impratio > 1 with the elliptic
cone and the no-slip pass make its friction harder). ``--release``: each impact followed in
both soft engines until its contact ends, and the lowest point's normal velocity then over its
approach speed (:func:`release_rebound`). ``--converge T1,T2,...``: this phase alone, the same
N impacts for every t_c, each followed to the end of its contact (:func:`converge`);
``--resistance L`` its ℓ_r = ℓ_p there (default 1e-4 m), ``--slip-factor F`` its
SLIP_SPEED times F and ``--drill-factor F`` the arc's pivoting radius times F (all three
refused without ``--converge``).

Does a rim impact of this phase converge to the rigid law as t_c → 0? ``--converge`` prints,
for the same impacts at each t_c, the distances to the rigid law and to this phase's own
t_c → 0 limit (:func:`frozen_limit`), the vertical part of the angular momentum's, and first
that limit's distance to the rigid law by how the rigid law's slip goes (:func:`slip_class`:
slides throughout, sticks, reverses) and by J_t/(μ J_n); ``--drill-factor F`` scales the arc's
pivoting radius (the Coulomb friction spread over the arc about the vertical). The findings
and their tables are in :mod:`coinflight.core.contact_phase`'s notes, "Convergence of a rim
impact" (2026-11-24). In short: frictionless, order 4/5 in t_c (the rim contact's duration,
∝ t_c^(4/5) for the Hertz-like law); with friction the "half order" measured on 2026-11-23
(below) was that first-order convergence to a limit that was not Stronge's law (the damper
sized for the frictionless normal mass: J_n +0.9 %, fixed since, the limit now within 0.00056
m/s of Stronge's at μ 0.3, median; 90th percentile 0.0043, largest 0.030 m/s on a slip that
turns; a slip much faster than the regularisation's v_ε assumed) plus the arc's pivoting
friction μ r_t F_n, r_t ∝ t_c^(2/5), whose angular impulse vanishes at that order (kept: the model's
softness; ``--drill-factor 0`` shows it).

Measured 2026-11-23, 23:40-23:57 UTC, before that fix (load 8-14; ``python
benchmarks/bench_rim_impacts.py 200 --friction μ --converge
2e-3,1e-3,5e-4,2.5e-4,1.25e-4,6.25e-5 [--resistance 0] [--slip-factor F]``, seed 1.) Medians
over the same 200 impacts, at t_c = 2, 1, 0.5, 0.25, 0.125, 0.0625 ms:

* μ 0, ℓ 0: velocity 0.167, 0.093, 0.050, 0.028, 0.016, 0.009 m/s from the rigid law's;
  angular momentum 0.258, 0.145, 0.080, 0.048, 0.028, 0.016 I1 ω; J_n 1.103, 1.053, 1.028,
  1.015, 1.008, 1.004 of the rigid law's.
* μ 0, ℓ 1e-4 m: angular momentum 0.252, 0.152, 0.092, 0.059, 0.042, 0.032 I1 ω.
* μ 0.3, ℓ 0: velocity 0.147, 0.085, 0.049, 0.029, 0.019, 0.014 m/s; angular momentum 0.302,
  0.202, 0.133, 0.090, 0.065, 0.046 I1 ω; J_n 1.090, 1.058, 1.031, 1.019, 1.015, 1.012 (with
  ℓ 1e-4 m: velocity 0.144 ... 0.016, J_n 1.091 ... 1.015).
* the contact lasts 3.8, 2.2, 1.2, 0.70, 0.40, 0.23 ms (μ 0.3; 90th percentile 10.3, 6.7,
  1.8, 1.0, 0.58, 0.32 ms).

The resistances add a torque ℓ F_n whose angular impulse ℓ J_n does not vanish with t_c: a
residual of ~0.03 I1 ω for which the rigid law has no term. Not the friction's
regularisation: with ``--slip-factor 0.1`` (v_ε 0.5 mm/s) the figures were the same to the
third digit. At the default 1 ms a rim impact is not converged: 0.085 m/s and 0.20-0.22 I1 ω
from the rigid law, J_n +6 %, contacts of ~2 ms (6.7 ms at the 90th percentile); with the fix
0.083 m/s, 0.20 I1 ω, J_n +5 %.

The 3 ms comparison below is no convergence test: impacts still in contact at 3 ms are drawn
again, 1,749 of ~1,950 at t_c 2 ms, 217 at 1 ms and 54-60 from 0.5 ms down (μ 0.3), so each
t_c compares another set (at 0.125 ms this phase is within 0.019 m/s and 0.081 I1 ω of the rigid
law on its set, takes 0.469 of the kinetic energy against the rigid 0.443, J_n 1.013).

Measured (200 impacts, seed 1, μ 0.3 unless said; 2026-11-23 ~21:00 UTC, load 8-12). Kinetic
energy lost, mean: rigid 0.426, this phase 0.449, MuJoCo 0.370 (condim 3 and 6 alike), 0.380
with the elliptic cone and impratio 100, 0.370 with 20 no-slip iterations; frictionless 0.264,
0.276, 0.263. The friction's impulse over μ times the normal one, mean: rigid 0.862, this phase
0.857, MuJoCo **0.888** (0.968 at impratio 100, 0.889 with no-slip): MuJoCo's friction in a
rim impact is not weaker than Coulomb's, and making it harder leaves the energy it takes where
it was. Its **normal** impulse is what differs once friction acts: over the rigid law's, median
1.117 (quartiles 1.040-1.201; impratio 100: 1.140) against this phase's 1.023 (0.932-1.082),
and 0.994 against 1.003 frictionless. ``--release``: the lowest point leaves at 0.532 of its
approach speed in MuJoCo (quartiles 0.505-0.580), 0.478 here and 0.480 in the rigid law
(Stronge's energetic e = 0.5, which friction's coupling brings below e); frictionless 0.512,
0.503, 0.500. MuJoCo's contact is a spring-damper on the contact's normal coordinate in
constraint space, calibrated on a flat drop, so it rebounds the contact point at about e
whatever the friction does to the coupling (nearer Newton's kinematic restitution), while
Stronge's law and this phase restitute the energy of compression. The rim contact lasts a
median 0.80 ms in MuJoCo and ~2 ms here (the compliant rim is softer than a flat face of the
same t_c). (The 3 ms comparison redraws impacts still in contact at 3 ms, so it leaves out the
longest contacts of this phase.)
"""

from __future__ import annotations

import argparse
import math

import numpy as np


def draw(rng: np.random.Generator, c) -> tuple[np.ndarray, ...]:  # type: ignore[no-untyped-def]
    """One random rim impact (module notes): heads normal n (tilt ~ U(0.15, 1.4) rad, a random
    azimuth), velocity v (v_h ~ N(0, 0.3) m/s per axis, v_z ~ −U(0.3, 1.5) m/s), angular
    velocity ω (magnitude ~ U(50, 300) rad/s, a random direction) and angular momentum L of the
    coin of the contact record ``c``; the caller keeps it only if the lowest rim point
    approaches the table."""
    tilt, azimuth = rng.uniform(0.15, 1.4), rng.uniform(0.0, 2.0 * math.pi)
    n = np.array(
        [math.sin(tilt) * math.cos(azimuth), math.sin(tilt) * math.sin(azimuth), math.cos(tilt)]
    )
    v = np.array([*rng.normal(0.0, 0.3, 2), -rng.uniform(0.3, 1.5)])
    w = rng.normal(0.0, 1.0, 3)
    w *= rng.uniform(50.0, 300.0) / np.linalg.norm(w)
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    return n, v, w, lm


def slip_class(u0: np.ndarray, k: tuple[float, ...], mu: float, pz: float) -> str:
    """How the rigid law's slip goes over the impact (a diagnostic of :func:`converge`):
    ``"slide"`` (it slides throughout, its direction possibly turning), ``"stick"`` (the slip
    comes to rest and the cone holds it) or ``"reverse"`` (it comes to rest and slides on, on
    the ray of Batlle 1996). The sliding flow du_t/dp = K_tt (−μ û) + K_tz of
    :mod:`coinflight.core.impact` (Stronge 2000, ch. 5) is followed with SciPy's RK45 (rtol
    1e-8) up to the rigid law's P_z, stopped by a terminal event when the slip falls below 1 %
    of the impact speed, "at rest" (the law itself only gives the impulse at the end, not the
    slip on the way)."""
    from scipy.integrate import solve_ivp

    if mu == 0.0:
        return "frictionless"
    ktt = np.array([[k[0], k[1]], [k[1], k[3]]])
    ktz = np.array([k[2], k[4]])
    tol = 1e-2 * float(np.linalg.norm(u0))

    def rate(p: float, x: np.ndarray) -> np.ndarray:
        return ktt @ (-mu * x / np.linalg.norm(x)) + ktz

    def at_rest(p: float, x: np.ndarray) -> float:
        return float(np.linalg.norm(x)) - tol

    at_rest.terminal, at_rest.direction = True, -1  # type: ignore[attr-defined]
    if np.linalg.norm(u0[:2]) <= tol:
        stopped = True
    else:
        sol = solve_ivp(rate, (0.0, pz), np.array(u0[:2], dtype=float), rtol=1e-8, events=at_rest)
        stopped = sol.status == 1
    if not stopped:
        return "slide"
    holds = np.linalg.norm(np.linalg.solve(ktt, ktz)) <= mu
    return "stick" if holds else "reverse"


def frozen_limit(  # type: ignore[no-untyped-def]
    n: np.ndarray,
    v: np.ndarray,
    lm: np.ndarray,
    c,
    zeta: float,
    sliding_mass: bool = True,
    slip_speed: float | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """This phase's own rigid limit of one rim impact: (v, L) after it.

    As t_c → 0 the coin does not turn during the contact, so the contact point's velocity is
    u = u0 + K P (K the collision matrix at the lowest rim point, :mod:`coinflight.core.impact`)
    and the phase's law at that point is all that is left: a short arc's force K_h d^(3/2)
    with the damping 2 ζ sqrt(K_t m_eff) ḋ, K_t = (3/2) K_h d^(1/2), clipped at zero, and
    friction F_t = −μ F_n u_t / sqrt(u_t² + v_ε²) at the same point (v_ε = ``slip_speed``, by
    default :data:`~coinflight.core.contact_phase.SLIP_SPEED`). m_eff is the normal effective
    mass friction leaves, 1/(K_zz + K_zt·F_t/F_n) (:func:`coinflight.core.contact_phase.
    _damper`, its floor too); with ``sliding_mass`` False the frictionless 1/K_zz,
    the phase's damper before 2026-11-24 (for the measurements of its notes). The result does
    not depend on K_h (it sets the time scale only), so it is integrated with K_h = 1 (SciPy's
    RK45, rtol 1e-10) until the force vanishes in restitution."""
    from scipy.integrate import solve_ivp

    from coinflight.core import contact_phase as cp
    from coinflight.core import impact as im

    mu, radius, hh = c.friction, c.radius, c.half_thickness
    rc = im.contact_point(tuple(n), radius, hh)
    w = im.angular_velocity(tuple(lm), tuple(n), c.i1, c.i3)
    u0 = np.array(im.contact_velocity(tuple(v), w, rc))
    kx = im.collision_matrix(rc, tuple(n), c.mass, c.i1, c.i3)
    kmat = np.array([[kx[0], kx[1], kx[2]], [kx[1], kx[3], kx[4]], [kx[2], kx[4], kx[5]]])
    eps = cp.SLIP_SPEED if slip_speed is None else slip_speed

    def unclipped(y: np.ndarray) -> float:
        """The arc's force d^(3/2) + damper before it is clipped at zero (K_h = 1)."""
        ratio = 1.0
        if sliding_mass:  # the kernel's ρ, at this point and slip
            ratio = cp.sliding_mass_ratio(kx[2], kx[4], kx[5], y[1], y[2], mu, eps)
        d = max(y[0], 0.0)
        return d**1.5 - 2.0 * zeta * math.sqrt(1.5 * math.sqrt(d) / (kx[5] * ratio)) * y[3]

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        share = -mu * y[1:3] / math.sqrt(y[1] ** 2 + y[2] ** 2 + eps**2)  # F_t / F_n
        f = max(0.0, unclipped(y)) if y[0] > 0.0 else 0.0
        force = np.array([share[0] * f, share[1] * f, f])
        return np.concatenate(([-y[3]], kmat @ force, force))

    def released(t: float, y: np.ndarray) -> float:  # the force crosses zero in restitution
        return unclipped(y) if y[3] > 0.0 else 1.0

    released.terminal, released.direction = True, -1  # type: ignore[attr-defined]
    span = 50.0 * c.mass**0.4 * abs(u0[2]) ** -0.2  # ~30 contact durations
    y0 = np.concatenate(([0.0], u0, [0.0, 0.0, 0.0]))
    sol = solve_ivp(
        rhs, (0.0, span), y0, rtol=1e-10, atol=1e-14, events=released, max_step=span / 2000
    )
    impulse = sol.y[4:7, -1]
    return v + impulse / c.mass, lm + np.cross(rc, impulse)


def straight_slide_restitution(
    k: tuple[float, ...], direction: np.ndarray, mu: float, zeta: float
) -> float:
    """The kinematic restitution the phase's rim law gave before 2026-11-24 (its damper sized
    for the frictionless mass 1/K_zz: :func:`frozen_limit` with ``sliding_mass`` False), as
    t_c → 0, to an impact sliding in the fixed direction ``direction`` throughout: the normal
    motion of the contact point is that of the damped Hertz law with the mass
    1/(K_zz − μ K_zt·û), so its damping ratio is ζ sqrt(1 − μ K_zt·û / K_zz) and its
    restitution :func:`coinflight.core.contact_phase.restitution_of` of that (Stronge's law,
    and the phase now: e itself)."""
    from coinflight.core import contact_phase as cp

    ratio = 1.0 - mu * (k[2] * direction[0] + k[4] * direction[1]) / k[5]
    return float(cp.restitution_of(zeta * math.sqrt(ratio), 1.5))


def _drill_patch(factor: float) -> None:
    """Scale the arc's pivoting radius r_t (the Coulomb friction spread over the arc, μ r_t F_n
    about the vertical) by ``factor`` in the phase's kernels: ``contact_phase._rim`` is wrapped
    before any kernel using it is compiled, into the fresh numba cache :func:`main` made (the
    package's cache is not touched). A benchmark-only knob (``--drill-factor``)."""
    from numba import njit

    from coinflight.core import contact_phase as cp

    inner = cp._rim

    @njit(cache=False)
    def scaled(
        sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction=0.0
    ):  # type: ignore[no-untyped-def]
        f, q, rt, e = inner(
            sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction
        )
        return f, q, rt * factor, e

    cp._rim = scaled


def follow(y: np.ndarray, c, span: float = 0.03) -> tuple[float, bool]:  # type: ignore[no-untyped-def]
    """Follow the state y = (z, v, n, L) of a coin touching the table (in place) with the
    contact phase of the contact record ``c`` until its contact ends, sampled every t_c/50:
    the rims' force has been positive and is zero again. (time, whether it ended within
    ``span`` s)."""
    from coinflight.core import contact_phase as cp

    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    deriv = np.empty(10)
    touched, t, dt = False, 0.0, c.contact_time / 50.0
    while t < span:
        cp.advance(y, dt, c)
        t += dt
        cp._derivative(y, deriv, c, stiff, zeta)
        if c.mass * (deriv[3] + c.g) > 0.0:
            touched = True
        elif touched:
            return t, True
    return t, False


def converge(args: argparse.Namespace) -> None:
    """``--converge T1,T2,...``: does this phase's rim impact converge to the rigid law as
    t_c → 0? The same N impacts (``--seed``) for every t_c, each followed until its contact
    ends (sampled every t_c/50: the rims' force has been positive and is zero again, up to 30
    ms; those still in contact then are counted, not compared), against Stronge's impact
    followed by the same time of free fall: the velocity's distance, the angular momentum's (in
    I1 ω) and its vertical part's, the normal impulse's ratio, medians and 90th percentiles,
    and the contact's length; then the same distances to this phase's own t_c → 0 limit
    (:func:`frozen_limit`, followed by the same free fall), and, first, that limit's distance
    to the rigid law, by how the rigid law's slip goes (:func:`slip_class`) and by J_t/(μ J_n)."""
    import bench_contact
    from coinflight.core import contact_phase as cp
    from coinflight.core import impact as im

    cp.SLIP_SPEED *= args.slip_factor  # before any kernel reading it is compiled (main)
    if args.drill_factor != 1.0:
        _drill_patch(args.drill_factor)
    g, mu = 9.81, args.friction
    c0 = bench_contact.contact(0.5, mu, resistance=args.resistance)
    zeta = cp.damping_of(c0)
    rng = np.random.default_rng(args.seed)
    impacts = []
    while len(impacts) < args.n:
        n, v, w, lm = draw(rng, c0)
        rc = im.contact_point(tuple(n), c0.radius, c0.half_thickness)
        if im.contact_velocity(tuple(v), tuple(w), rc)[2] < -0.05:
            impacts.append((n, v, w, lm))
    print(
        f"{args.n} rim impacts (seed {args.seed}), e 0.5, μ {mu:g}, resistances "
        f"{c0.rolling_resistance:g} m, SLIP_SPEED {cp.SLIP_SPEED:g} m/s, arc's pivoting radius "
        f"× {args.drill_factor:g}: this phase followed to the end of its contact, against the "
        "rigid law (medians, 90 %):"
    )
    rigid, limit, kinds, share, approach = [], [], [], [], []
    for n, v, w, lm in impacts:
        v1, l1, _ = im.impact(
            tuple(v), tuple(lm), tuple(n), c0.radius, c0.half_thickness, c0.mass, c0.i1, c0.i3,
            0.5, mu,
        )  # fmt: skip
        rigid.append((np.array(v1), np.array(l1)))
        limit.append(frozen_limit(n, v, lm, c0, zeta))
        rc = im.contact_point(tuple(n), c0.radius, c0.half_thickness)
        u0 = np.array(im.contact_velocity(tuple(v), tuple(w), rc))
        k = im.collision_matrix(rc, tuple(n), c0.mass, c0.i1, c0.i3)
        pz = c0.mass * (v1[2] - v[2])
        kinds.append(slip_class(u0, k, mu, pz))
        approach.append(-u0[2])  # the lowest point's approach speed
        share.append(math.hypot(v1[0] - v[0], v1[1] - v[1]) / (mu * (v1[2] - v[2])) if mu else 1.0)
    scales = [c0.i1 * float(np.linalg.norm(w)) for _, _, w, _ in impacts]
    floor = np.array(
        [
            (
                float(np.linalg.norm(lv - rv)),
                float(np.linalg.norm(ll - rl)) / sc,
                (lv[2] - v[2]) / (rv[2] - v[2]),
            )
            for (lv, ll), (rv, rl), sc, (_, v, _, _) in zip(
                limit, rigid, scales, impacts, strict=True
            )
        ]
    )
    kinds_a, share_a = np.array(kinds), np.array(share)
    groups = [("all", np.ones(len(kinds_a), dtype=bool))]
    groups += [(f"slip: {k}", kinds_a == k) for k in ("frictionless", "slide", "stick", "reverse")]
    if mu > 0.0:
        groups += [
            ("J_t/(μ J_n) ≥ 0.999", share_a >= 0.999),
            ("0.95-0.999", (share_a >= 0.95) & (share_a < 0.999)),
            ("< 0.95", share_a < 0.95),
        ]
    print(
        "  this phase's t_c → 0 limit against the rigid law (medians; the velocity's 90th "
        "percentile and maximum, and its largest share of the lowest point's approach speed):"
    )
    for name, sel in groups:
        if sel.any():
            f50 = np.median(floor[sel], axis=0)
            vel = floor[sel, 0]
            print(
                f"    {name:22s} {int(sel.sum()):4d} impacts: velocity {f50[0]:.6f} m/s "
                f"(90 % {np.percentile(vel, 90):.6f}, max {vel.max():.6f}, max / approach "
                f"{np.max(vel / np.array(approach)[sel]):.4f}), angular momentum "
                f"{f50[1]:.6f} I1 ω, J_n / rigid {f50[2]:.5f}"
            )
    for tc in (float(x) for x in args.converge.split(",")):
        c = c0._replace(contact_time=tc)
        rows, own, stuck = [], [], 0
        for (n, v, _, lm), (v1, l1), (vl, ll), scale in zip(
            impacts, rigid, limit, scales, strict=True
        ):
            y = np.array([im.lowest_depth(n[2], c.radius, c.half_thickness), *v, *n, *lm])
            t, ended = follow(y, c)
            if not ended:
                stuck += 1
                continue
            fall = np.array([0.0, 0.0, g * t])
            rows.append(
                (
                    float(np.linalg.norm(y[1:4] + fall - v1)),
                    float(np.linalg.norm(y[7:10] - l1)) / scale,
                    abs(y[9] - l1[2]) / scale,
                    (y[3] + g * t - v[2]) / (v1[2] - v[2]),
                    t,
                )
            )
            own.append(
                (
                    float(np.linalg.norm(y[1:4] + fall - vl)),
                    float(np.linalg.norm(y[7:10] - ll)) / scale,
                    abs(y[9] - ll[2]) / scale,
                )
            )
        r, o = np.array(rows), np.array(own)
        p50, p90 = np.median(r, axis=0), np.percentile(r, 90, axis=0)
        o50 = np.median(o, axis=0)
        print(
            f"  t_c {tc * 1e3:6.3f} ms: velocity {p50[0]:.4f} m/s ({p90[0]:.4f}), angular "
            f"momentum {p50[1]:.4f} I1 ω ({p90[1]:.4f}; vertical part {p50[2]:.4f}), J_n / rigid "
            f"{p50[3]:.4f} (quartiles {np.percentile(r[:, 3], 25):.4f}-"
            f"{np.percentile(r[:, 3], 75):.4f}), contact {p50[4] * 1e3:.3f} ms "
            f"({p90[4] * 1e3:.3f}); still in contact at 30 ms: {stuck}; to its own limit: "
            f"velocity {o50[0]:.4f} m/s, angular momentum {o50[1]:.4f} I1 ω (vertical part "
            f"{o50[2]:.4f})",
            flush=True,
        )


def release_rebound(args: argparse.Namespace, solver) -> None:  # type: ignore[no-untyped-def]
    """``--release``: the same kind of impacts, each soft engine followed until its contact
    ends (coinflight's phase every 10 μs, MuJoCo every step); the lowest point's normal velocity
    then over its approach speed (the kinematic restitution the impact ends with), against the
    rigid law's (Stronge's energetic e, whose kinematic ratio falls below e with friction)."""
    import mujoco

    import bench_contact
    from coinflight.core import contact_phase as cp
    from coinflight.core import impact as im
    from coinflight.studies import landing as study
    from coinflight.studies import mujoco_compare as mc

    g, mu = 9.81, args.friction
    c = bench_contact.contact(0.5, mu)._replace(contact_time=args.contact_time)
    coin = study.EDGE_TOSSES["vigorous"]().coin
    model = mc._calibrated(coin, 0.5, mu, 2.0, g, args.condim, 1e-4, 1e-4, "RK4", solver)[0]
    data = mujoco.MjData(model)
    rot = np.empty(9)
    rng = np.random.default_rng(args.seed)
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    deriv = np.empty(10)

    def normal(v: np.ndarray, w: np.ndarray, n: np.ndarray) -> float:
        rc = np.array(im.contact_point(tuple(n), c.radius, c.half_thickness))
        return float((v + np.cross(w, rc))[2])

    rows = []
    while len(rows) < args.n:
        n, v, w, lm = draw(rng, c)
        u0 = normal(v, w, n)
        if u0 >= -0.05:
            continue
        v1, l1, _ = im.impact(
            tuple(v), tuple(lm), tuple(n), c.radius, c.half_thickness, c.mass, c.i1, c.i3, 0.5, mu
        )
        w1 = np.array(im.angular_velocity(l1, tuple(n), c.i1, c.i3))
        rigid = normal(np.array(v1), w1, n) / -u0
        z = im.lowest_depth(n[2], c.radius, c.half_thickness)
        y = np.array([z, *v, *n, *lm])
        touched, ours = False, math.nan
        for _ in range(2000):
            cp.advance(y, 1e-5, c)
            cp._derivative(y, deriv, c, stiff, zeta)
            if c.mass * (deriv[3] + g) > 0.0:
                touched = True
            elif touched:
                wl = np.array(im.angular_velocity(tuple(y[7:10]), tuple(y[4:7]), c.i1, c.i3))
                ours = normal(y[1:4], wl, y[4:7]) / -u0
                break
        q = mc._quaternion_to(n[None])[0]
        mujoco.mj_resetData(model, data)
        data.qpos[:3] = (0.0, 0.0, z)
        data.qpos[3:7] = q
        mujoco.mju_quat2Mat(rot, q)
        data.qvel[:3] = v
        data.qvel[3:6] = rot.reshape(3, 3).T @ w
        touched, theirs = False, math.nan
        for _ in range(200):
            mujoco.mj_step(model, data)
            mujoco.mj_forward(model, data)
            if data.ncon:
                touched = True
            elif touched:
                mujoco.mju_quat2Mat(rot, data.qpos[3:7])
                frame = rot.reshape(3, 3)
                theirs = normal(np.array(data.qvel[:3]), frame @ data.qvel[3:6], frame[:, 2])
                theirs /= -u0
                break
        if math.isfinite(ours) and math.isfinite(theirs):
            rows.append((rigid, ours, theirs))
    r = np.array(rows)
    print(
        f"{args.n} rim impacts, e 0.5, μ {mu:g}, t_c {args.contact_time:g} s (seed {args.seed}); "
        f"MuJoCo condim {args.condim}, {solver}; the lowest point's normal velocity when the "
        "contact ends over its approach speed, median (quartiles):"
    )
    for j, name in enumerate(("rigid law (energetic e)", "contact phase", "MuJoCo")):
        q1, q2, q3 = np.percentile(r[:, j], (25, 50, 75))
        print(f"  {name:24s}: {q2:.3f} ({q1:.3f}-{q3:.3f})")


def main() -> None:
    # SLIP_SPEED is compiled into the kernels: another value needs a numba cache of its own,
    # set before numba is imported (the package's cache is not touched).
    pre = argparse.ArgumentParser(add_help=False)
    pre.add_argument("--slip-factor", type=float, default=1.0)
    pre.add_argument("--drill-factor", type=float, default=1.0)
    known = pre.parse_known_args()[0]
    if known.slip_factor != 1.0 or known.drill_factor != 1.0:
        import normal_law

        normal_law.fresh_cache()
    import mujoco

    import bench_contact
    import mujoco_args
    from coinflight.core import contact_phase as cp
    from coinflight.core import impact as im
    from coinflight.studies import landing as study
    from coinflight.studies import mujoco_compare as mc

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=100)
    parser.add_argument("--friction", type=float, default=0.3)
    parser.add_argument("--contact-time", type=float, default=cp.CONTACT_TIME)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--condim", type=int, default=6)
    parser.add_argument("--cone", choices=mc.CONES, default=mc.CONE)
    parser.add_argument("--impratio", type=float, default=1.0)
    parser.add_argument("--noslip", type=int, default=0)
    parser.add_argument(
        "--solimp",
        type=mujoco_args.solimp,
        default=",".join(str(x) for x in mc.SOLIMP),
        help="MuJoCo's d0,dmax,width",
    )
    parser.add_argument(
        "--release", action="store_true", help="the kinematic restitution at the contact's end"
    )
    parser.add_argument(
        "--converge", default=None, metavar="T1,T2,...", help="t_c values, s (this phase only)"
    )
    parser.add_argument(
        "--resistance", type=float, default=None, help="this phase's ℓ_r = ℓ_p in --converge, m"
    )
    parser.add_argument(
        "--slip-factor", type=float, default=None, help="SLIP_SPEED times F in --converge"
    )
    parser.add_argument(
        "--drill-factor",
        type=float,
        default=None,
        help="the arc's pivoting radius times F in --converge (a benchmark-only knob)",
    )
    args = parser.parse_args()
    knobs = (args.resistance, args.slip_factor, args.drill_factor)
    if not args.converge and any(x is not None for x in knobs):
        parser.error("--slip-factor, --drill-factor and --resistance are for --converge only")
    if args.converge:
        args.resistance = 1e-4 if args.resistance is None else args.resistance
        args.slip_factor = 1.0 if args.slip_factor is None else args.slip_factor
        args.drill_factor = 1.0 if args.drill_factor is None else args.drill_factor
        converge(args)
        return
    solver = mc.FrictionSolver(args.cone, args.impratio, args.noslip, args.solimp)
    if args.release:
        release_rebound(args, solver)
        return
    mu, g, span = args.friction, 9.81, 0.003
    c = bench_contact.contact(0.5, mu)._replace(contact_time=args.contact_time)
    coin = study.EDGE_TOSSES["vigorous"]().coin
    model = mc._calibrated(coin, 0.5, mu, 2.0, g, args.condim, 1e-4, 1e-4, "RK4", solver)[0]
    data = mujoco.MjData(model)
    rot = np.empty(9)
    rng = np.random.default_rng(args.seed)
    dist: dict[str, list[tuple[float, ...]]] = {"contact phase": [], "MuJoCo": []}
    lost_rigid = []
    redrawn = [0, 0]  # still or again in contact at 3 ms: in this phase, in MuJoCo
    ratio_rigid = []

    def ratio(v_before: np.ndarray, v_after: np.ndarray) -> float:
        """Horizontal / (μ vertical) impulse of the table from the momentum over ``span``."""
        dv = v_after - v_before
        return float(math.hypot(dv[0], dv[1]) / (mu * (dv[2] + g * span))) if mu > 0 else 0.0

    def kinetic(v: np.ndarray, lm: np.ndarray, n: np.ndarray) -> float:
        return float(
            0.5 * c.mass * v @ v + 0.5 * (lm @ lm / c.i1 + (1 / c.i3 - 1 / c.i1) * (lm @ n) ** 2)
        )

    while len(dist["MuJoCo"]) < args.n:
        n, v, w, lm = draw(rng, c)
        rc = im.contact_point(tuple(n), c.radius, c.half_thickness)
        if im.contact_velocity(tuple(v), tuple(w), rc)[2] >= -0.05:
            continue
        v1, l1, _ = im.impact(
            tuple(v), tuple(lm), tuple(n), c.radius, c.half_thickness, c.mass, c.i1, c.i3, 0.5, mu
        )
        rigid_v = np.array(v1) - np.array([0.0, 0.0, g * span])
        rigid_l = np.array(l1)
        z = im.lowest_depth(n[2], c.radius, c.half_thickness)
        y = np.array([z, *v, *n, *lm])
        cp.advance(y, span, c)
        if y[0] < im.lowest_depth(y[6], c.radius, c.half_thickness) + 1e-6:
            redrawn[0] += 1
            continue
        q = mc._quaternion_to(n[None])[0]
        mujoco.mj_resetData(model, data)
        data.qpos[:3] = (0.0, 0.0, z)
        data.qpos[3:7] = q
        mujoco.mju_quat2Mat(rot, q)
        data.qvel[:3] = v
        data.qvel[3:6] = rot.reshape(3, 3).T @ w
        while data.time < span - 1e-9:
            mujoco.mj_step(model, data)
        if data.ncon:
            redrawn[1] += 1
            continue
        mujoco.mju_quat2Mat(rot, data.qpos[3:7])
        frame = rot.reshape(3, 3)
        wl, nm = frame @ data.qvel[3:6], frame[:, 2]
        lm_mj = c.i1 * wl + (c.i3 - c.i1) * (wl @ nm) * nm
        scale = c.i1 * float(np.linalg.norm(w))
        fall = np.array([0.0, 0.0, g * span])
        e0 = kinetic(v, lm, n)
        lost_rigid.append(1.0 - kinetic(rigid_v + fall, rigid_l, n) / e0)
        ratio_rigid.append(ratio(v, rigid_v))
        jn_rigid = rigid_v[2] - v[2] + g * span
        dist["contact phase"].append(
            (
                float(np.linalg.norm(y[1:4] - rigid_v)),
                float(np.linalg.norm(y[7:10] - rigid_l)) / scale,
                1.0 - kinetic(y[1:4] + fall, y[7:10], y[4:7]) / e0,
                ratio(v, y[1:4]),
                (y[3] - v[2] + g * span) / jn_rigid,
            )
        )
        dist["MuJoCo"].append(
            (
                float(np.linalg.norm(data.qvel[:3] - rigid_v)),
                float(np.linalg.norm(lm_mj - rigid_l)) / scale,
                1.0 - kinetic(data.qvel[:3] + fall, lm_mj, nm) / e0,
                ratio(v, np.array(data.qvel[:3])),
                (data.qvel[2] - v[2] + g * span) / jn_rigid,
            )
        )
    print(
        f"{args.n} rim impacts, e 0.5, μ {mu:g}, t_c {args.contact_time:g} s (seed {args.seed}); "
        f"MuJoCo condim {args.condim}, {solver}; kinetic energy lost, mean: rigid "
        f"{np.mean(lost_rigid):.3f}; J_t/(μ J_n) mean rigid {np.mean(ratio_rigid):.3f}; "
        f"drawn again (in contact at 3 ms): this phase {redrawn[0]}, MuJoCo {redrawn[1]}"
    )
    for name, rows in dist.items():
        r = np.array(rows)
        print(
            f"  {name:13s} against the rigid law: velocity median {np.median(r[:, 0]):.3f} m/s "
            f"(90 % {np.percentile(r[:, 0], 90):.3f}), angular momentum median "
            f"{np.median(r[:, 1]):.3f} I1 ω (90 % {np.percentile(r[:, 1], 90):.3f}); kinetic "
            f"energy lost, mean {np.mean(r[:, 2]):.3f}; J_t/(μ J_n) mean {np.mean(r[:, 3]):.3f}, "
            f"J_n / the rigid law's: median {np.median(r[:, 4]):.3f} (quartiles "
            f"{np.percentile(r[:, 4], 25):.3f}-{np.percentile(r[:, 4], 75):.3f})"
        )


if __name__ == "__main__":
    main()

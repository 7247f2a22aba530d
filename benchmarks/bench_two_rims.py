"""How the contact phase restitutes a coin dropped on its rim: on both rims (upright), on one
rim (tilted) and flat on its face, against the surface's e.

    python benchmarks/bench_two_rims.py [--restitution E,E,...] [--heights H,H,...]
        [--contact-time T,T,...] [--corner A]
    python benchmarks/bench_two_rims.py --switches N [--pairs 0.5,0.3 0.5,0.6]

A US nickel (sharp corners unless ``--corner``), frictionless and with no resistances (so
that nothing but the normal law acts: an upright or flat drop has no tangential motion
anyway), at rest in the air, its lowest point just touching the table, falling at
v = sqrt(2 g H) for each drop height H (default 1 mm, 1 cm, 10 cm, 50 cm) and each e (default
0.2, 0.35, 0.5, 0.65, 0.8), with gravity. The contact phase
(:func:`coinflight.core.contact_phase.advance`) carries it in steps of t_c/100 until the
table's force on it, m (a_z + g), falls to zero after it has pushed: the contact's end. The
rebound is then the lowest point's upward normal velocity over its approach speed (for the
upright and flat coin, the centre's), the kinematic restitution. For the symmetric drops
(upright on both rims, flat), whose contact force passes through the centre, that is the
impact's end and the ratio equals Stronge's energetic e of a frictionless impact. For the
one-rim drop it is not: the script stops at the first separation of that contact point, while
the coin still turns and its centre still falls, so its ratio is not a finished impact's
restitution and can exceed 1 (1.099 at e 0.8 from 50 cm, t_c 1 ms). Printed per case: the
rebound ratio for each H and e, and the contact's duration.

The upright coin is also compared with what the damper sizing predicts. Two rims pressed
together are damped as one pair (:data:`coinflight.core.contact_phase.JOINT_DAMPING`, since
2026-11-24): every mode of the pair at the surface's ζ, so the upright drop is predicted to
rebound at :func:`coinflight.core.contact_phase.restitution_of` (ζ, 3/2) = e, printed as
"predicted". Before, each rim's damper was γ = ζ sqrt(K_t m_eff) with m_eff = 1/K_zz, the
effective mass of that rim's contact point alone (1/m + (h/2)²/I1 upright: nearly the whole
coin); two rims pressed together then formed one contact of stiffness 2 K_t on the mass m,
damped by 2 γ: a damping ratio ζ sqrt(2 m_eff / m), not ζ, whose restitution
restitution_of(ζ sqrt(2 m_eff/m), 3/2) is printed as "per rim" (:func:`per_rim_upright`).

The pair's modes of an upright coin resting on both rims (at the static depth of
:func:`coinflight.core.contact_phase.static_depth`, gravity on): the damping ratio of each,
measured from the decay of a small oscillation (:func:`mode_damping`: a lean rate of 0.3 rad/s,
a fall of 2 mm/s), against ζ (the joint damping's linearised value for both modes) and the
per-rim sizing's linearised values (:func:`per_rim_modes`): the rocking mode (the rims in
antiphase, inertia I1 on the stiffness 2 K_t h′²) at ζ sqrt(2 m_eff h′²/I1), 0.25 ζ for a
nickel, and the bounce at ζ sqrt(2 m_eff/m) = 1.39 ζ. Per rim, the rocking mode measured
0.29 ζ at t_c 1 ms and 0.256 ζ at 62.5 μs (``--contact-time 1e-3,6.25e-5``, 2026-11-24, before
the joint damping). The bounce mode's decrement is read only where the mode is lightly damped
(linearised ζ′ < :data:`RELIABLE_ZETA`): heavily damped, its few extremes misread it (per rim,
at t_c 1 ms, e 0.2, 0.35, 0.5: 0.686, 0.273, 0.280 against the linearised 0.929, 0.532,
0.324), so there the line says "not read".
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from coinflight import Coin
from coinflight.core import contact_phase as cp
from coinflight.core import impact as im
from coinflight.model.surface import Surface
from coinflight.outcomes.table import contact_record

G = 9.81
HEIGHTS = (1e-3, 1e-2, 0.1, 0.5)
RESTITUTIONS = (0.2, 0.35, 0.5, 0.65, 0.8)
RELIABLE_ZETA = 0.3
"""The bounce mode's damping is read from its decay only below this linearised ζ′ (above it
the decrement of a few extremes misreads a heavily damped mode; module notes)."""
TILTS = {"upright, both rims": 0.5 * math.pi, "one rim, tilted 45°": 0.25 * math.pi, "flat": 0.0}
"""The drops: the angle of the heads normal from the vertical."""


def record(restitution: float, contact_time: float = cp.CONTACT_TIME, corner: float = 0.0):  # type: ignore[no-untyped-def]
    """The contact record of a frictionless, unresisted nickel on a table with this e."""
    coin = Coin.preset("us-nickel")
    if corner:
        coin = coin.with_corner_radius(corner)
    surface = Surface(
        "table",
        0.8,
        restitution,
        0.0,
        rolling_resistance=0.0,
        pivoting_resistance=0.0,
        contact_time=contact_time,
        ending="contact",
    )
    return contact_record(coin, surface, G)


def drop(c, tilt: float, speed: float) -> tuple[float, float]:  # type: ignore[no-untyped-def]
    """(rebound ratio, contact duration in s) of a coin with its normal ``tilt`` rad from the
    vertical, not turning, its lowest point touching the table at ``speed`` m/s downwards.

    Followed in steps of t_c/100 until the table's force falls to zero after it has pushed;
    NaN if it has not released after 100 t_c."""
    n = (math.sin(tilt), 0.0, math.cos(tilt))
    z = im.lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
    y = np.array([z, 0.0, 0.0, -speed, *n, 0.0, 0.0, 0.0])
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    deriv = np.empty(10)
    dt = c.contact_time / 100.0
    touched = False
    for k in range(10_000):
        cp.advance(y, dt, c)
        cp._derivative(y, deriv, c, stiff, zeta)
        if c.mass * (deriv[3] + c.g) > 0.0:
            touched = True
        elif touched:
            nn = (y[4], y[5], y[6])
            w = im.angular_velocity((y[7], y[8], y[9]), nn, c.i1, c.i3)
            rc = im.contact_point(nn, c.radius, c.half_thickness, c.corner_radius)
            up = y[3] + im.cross(w, rc)[2]
            return up / speed, (k + 1) * dt
    return math.nan, math.nan


def mode_damping(c, mode: str) -> float:  # type: ignore[no-untyped-def]
    """The damping ratio of an upright coin's small oscillation on both rims, ``mode``
    "rocking" (a lean rate of 0.3 rad/s about the horizontal axis across n) or "bounce" (the
    centre falling at 2 mm/s), from rest at the static depth: the mean logarithmic decrement δ
    of successive extremes (half periods) of the lean (n_z) or the height, ζ = δ/sqrt(π² + δ²),
    over the first eight extremes (0.4 s and 0.12 s of motion)."""
    depth = cp.static_depth(c, cp.stiffness_of(c))
    y = np.array([c.radius - depth, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    rocking = mode == "rocking"
    if rocking:
        y[8] = c.i1 * 0.3
    else:
        y[3] = -0.002
    dt, steps = (2e-4, 2000) if rocking else (2e-5, 6000)
    signal = np.empty(steps)
    for k in range(steps):
        cp.advance(y, dt, c)
        signal[k] = y[6] if rocking else y[0] - (c.radius - depth)
    a = np.abs(signal)
    peaks = a[1:-1][(a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])][:8]
    if len(peaks) < 3:
        return math.nan
    decrement = float(np.mean(np.log(peaks[:-1] / peaks[1:])))
    return decrement / math.sqrt(math.pi**2 + decrement**2)


def linearised_modes(c) -> tuple[float, float]:  # type: ignore[no-untyped-def]
    """(bounce, rocking) damping ratios of the two-rim pair, linearised, as the phase damps it:
    the modes of M ẍ + C ẋ + K x = 0 in the two rims' penetrations x at an upright coin's rest
    (:func:`modal_damping`), C the phase's own (:func:`coinflight.core.contact_phase.rims_contact`
    there, when it damps the pair jointly; else each rim's own damper 2 ζ sqrt(k_i/W_ii), the
    sizing of :func:`per_rim_modes`), K the phase's own (its elastic forces' slope in the depth,
    central differences of 1 nm), M = W⁻¹ from the two arcs' centroids (:func:`rest_mobility`)."""
    stiffness, zeta = cp.stiffness_of(c), cp.damping_of(c)
    depth = cp.static_depth(c, stiffness)
    y = np.array([c.radius - depth, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    _, _, _, _, _, joint, c11, c12, c22 = cp.rims_contact(y, c, stiffness, zeta)
    h = 1e-9
    below, above = y.copy(), y.copy()
    below[0] -= h
    above[0] += h
    low, high = cp.rims_contact(below, c, stiffness, 0.0), cp.rims_contact(above, c, stiffness, 0.0)
    k = np.array([low[1] - high[1], low[3] - high[3]]) / (2.0 * h)
    w = rest_mobility(c, depth)
    if joint:
        damping = np.array([[c11, c12], [c12, c22]])
    else:
        damping = np.diag(2.0 * zeta * np.sqrt(k / np.diag(w)))
    return modal_damping(w, damping, k)


def rest_mobility(c, depth: float) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The normal mobility W_ij = 1/m + (r_i × Z)·I⁻¹(r_j × Z) (1/kg; Stronge 2000, eq 5.7) of
    the two arcs' centroids r_σ = σ (h/2 − a) n − (R′ sin φ*/φ* + a) Z of an upright coin
    (n = x̂) pressed ``depth`` m into the table, its arcs' half-angle φ* = acos(1 − depth/R′),
    R′ = R − a (the phase's "Two rims" notes), I⁻¹ NumPy's inverse of the inertia tensor."""
    core, hh = c.radius - c.corner_radius, c.half_thickness - c.corner_radius
    phi = math.acos(1.0 - depth / core)
    n, z = np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, 1.0])
    inverse = np.linalg.inv(c.i1 * (np.eye(3) - np.outer(n, n)) + c.i3 * np.outer(n, n))
    arms = [
        np.cross(s * hh * n - (core * math.sin(phi) / phi + c.corner_radius) * z, z)
        for s in (-1.0, 1.0)
    ]
    return np.array([[1.0 / c.mass + a @ inverse @ b for b in arms] for a in arms])


def modal_damping(w: np.ndarray, damping: np.ndarray, k: np.ndarray) -> tuple[float, float]:
    """(bounce, rocking) damping ratios −Re λ/|λ| of M ẍ + C ẋ + K x = 0, M = W⁻¹, K = diag(k):
    the eigenvalues λ of its first-order form [[0, I], [−W K, −W C]] (the generalised
    eigenproblem det(λ² M + λ C + K) = 0), each mode named by its eigenvector's penetrations,
    the rims in phase (bounce) or in antiphase (rocking)."""
    system = np.block([[np.zeros((2, 2)), np.eye(2)], [-w @ np.diag(k), -w @ damping]])
    values, vectors = np.linalg.eig(system)
    out = {}
    for value, vector in zip(values, vectors.T, strict=True):
        x = vector[:2]
        name = "bounce" if abs(x[0] + x[1]) > abs(x[0] - x[1]) else "rocking"
        out[name] = float(-value.real / abs(value))
    return out["bounce"], out["rocking"]


def per_rim_modes(c) -> tuple[float, float]:  # type: ignore[no-untyped-def]
    """(bounce, rocking) damping ratios of the two-rim pair, linearised, with each rim damped
    alone (the sizing before the joint damping; module notes)."""
    hb = c.half_thickness - c.corner_radius
    ma = c.mass * hb * hb / c.i1
    zeta = cp.damping_of(c)
    return zeta * math.sqrt(2.0 / (1.0 + ma)), zeta * math.sqrt(2.0 * ma / (1.0 + ma))


def predicted_upright(c) -> float:  # type: ignore[no-untyped-def]
    """The upright coin's restitution predicted by the phase's damper sizing: e (restitution_of
    (ζ, 3/2)) with the joint damping, else :func:`per_rim_upright`."""
    if cp.JOINT_DAMPING:
        return cp.restitution_of(cp.damping_of(c), 1.5)
    return per_rim_upright(c)


def per_rim_upright(c) -> float:  # type: ignore[no-untyped-def]
    """The upright coin's restitution with each rim damped alone (module notes)."""
    hb = c.half_thickness - c.corner_radius
    m_eff = 1.0 / (1.0 / c.mass + hb * hb / c.i1)
    zeta = cp.damping_of(c) * math.sqrt(2.0 * m_eff / c.mass)
    return cp.restitution_of(zeta, 1.5)


def table(
    restitutions: tuple[float, ...], heights: tuple[float, ...], contact_time: float, corner: float
) -> dict[str, np.ndarray]:
    """The rebound ratios, case → array (len(restitutions), len(heights)), and durations."""
    out: dict[str, np.ndarray] = {}
    for name, tilt in TILTS.items():
        ratio = np.empty((len(restitutions), len(heights)))
        duration = np.empty_like(ratio)
        for i, e in enumerate(restitutions):
            c = record(e, contact_time, corner)
            for j, h in enumerate(heights):
                ratio[i, j], duration[i, j] = drop(c, tilt, math.sqrt(2.0 * G * h))
        out[name] = ratio
        out[name + " duration"] = duration
    return out


def switches(n: int, e: float, mu: float, dt: float = 1e-4, limit: float = 3.0) -> dict[str, float]:
    """How often handed tosses cross the switch between the pair damped jointly and each rim
    alone (a discontinuity of the rims' forces; the phase's "Two rims" notes): ``n`` of
    ``bench_contact.py``'s vigorous tosses (seed 2026) on the surface (e, μ), each contact
    phase advanced in windows of ``dt`` s (the stepper restarted at each) up to ``limit`` s or
    settled, :func:`coinflight.core.contact_phase.rims_contact`'s joint flag read at each
    window's start while both arcs press (so switches faster than ``dt`` are missed).

    Measured (``--switches 300 --pairs 0.5,0.3 0.5,0.6``, 2026-11-24 08:59-09:01 UTC, load
    2.1-2.5, 84 s wall in all): of 213 and 207 handed tosses, 88 and 133 reach both arcs, 80
    and 128 of them switch (385 and 588 switches), and 64.4 of 65.9 s and 220.7 of 223.0 s of
    their time on both arcs is damped jointly."""
    import bench_contact

    rng = np.random.default_rng(2026)
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    c = bench_contact.contact(e, mu)
    stiffness, zeta = cp.stiffness_of(c), cp.damping_of(c)
    out = dict.fromkeys(("handed", "two arcs", "switching", "switches", "time", "joint"), 0.0)
    for k in range(n):
        y, handed = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if not handed:
            continue
        out["handed"] += 1
        previous, count, reached, t = None, 0, False, 0.0
        while t < limit:
            both = cp.MODES[cp.contact_mode(y, c)] == "two rims"
            joint = bool(cp.rims_contact(y, c, stiffness, zeta)[5]) if both else None
            if both:
                reached = True
                out["time"] += dt
                out["joint"] += dt * joint
                count += previous is not None and joint != previous
            previous = joint
            t += dt
            if cp.advance(y, dt, c, settle_check=True)[2]:
                break
        out["two arcs"] += reached
        out["switching"] += count > 0
        out["switches"] += count
    return out


def _floats(text: str) -> tuple[float, ...]:
    return tuple(float(x) for x in text.split(","))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--restitution", type=_floats, default=RESTITUTIONS)
    parser.add_argument("--heights", type=_floats, default=HEIGHTS)
    parser.add_argument("--contact-time", type=_floats, default=(cp.CONTACT_TIME,))
    parser.add_argument("--corner", type=float, default=0.0)
    parser.add_argument("--switches", type=int, default=0, help="N tosses: count the switches")
    parser.add_argument("--pairs", nargs="*", default=["0.5,0.3"], metavar="E,MU")
    args = parser.parse_args()
    if args.switches:
        for pair in args.pairs:
            e, mu = _floats(pair)
            r = switches(args.switches, e, mu)
            print(
                f"e {e:g}, μ {mu:g}: {r['handed']:.0f} handed, {r['two arcs']:.0f} on both arcs, "
                f"{r['switching']:.0f} switching ({r['switches']:.0f} switches); on both arcs "
                f"{r['time']:.1f} s, {r['joint']:.1f} s of it damped jointly"
            )
        return
    heights = ", ".join(f"{h:g}" for h in args.heights)
    for tc in args.contact_time:
        print(
            f"US nickel, corner radius {args.corner:g} m, frictionless, t_c {tc:g} s; rebound "
            f"ratio at drop heights {heights} m (and contact durations, ms)"
        )
        rows = table(args.restitution, args.heights, tc, args.corner)
        for name in TILTS:
            print(f"  {name}:")
            for i, e in enumerate(args.restitution):
                ratios = "  ".join(f"{x:.3f}" for x in rows[name][i])
                ms = "  ".join(f"{1e3 * x:.2f}" for x in rows[name + " duration"][i])
                extra = ""
                if name.startswith("upright"):
                    c = record(e, tc, args.corner)
                    extra = (
                        f"; predicted {predicted_upright(c):.3f} (per rim {per_rim_upright(c):.3f})"
                    )
                print(f"    e {e:g}: {ratios}  ({ms} ms){extra}")
        print(
            "  an upright coin resting on both rims, damping ratio of each mode "
            "(measured; linearised; per rim, linearised):"
        )
        for e in args.restitution:
            c = record(e, tc, args.corner)
            bounce, rocking = linearised_modes(c)
            old_bounce, old_rocking = per_rim_modes(c)
            read = (
                f"{mode_damping(c, 'bounce'):.4f}"
                if bounce < RELIABLE_ZETA
                else f"not read (ζ′ ≥ {RELIABLE_ZETA:g}: too damped for its decrement)"
            )
            print(
                f"    e {e:g}: ζ {cp.damping_of(c):.4f}; bounce {read} ({bounce:.4f}; "
                f"{old_bounce:.4f}); rocking {mode_damping(c, 'rocking'):.4f} ({rocking:.4f}; "
                f"{old_rocking:.4f})"
            )


if __name__ == "__main__":
    main()

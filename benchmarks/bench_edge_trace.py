"""Toss by toss: where coinflight's contact ending and MuJoCo part on the same hand-off states.

    python benchmarks/bench_edge_trace.py [N] [--per-group K] [--span 0.1] [--condim 3]
        [--cone pyramidal|elliptic] [--impratio R] [--noslip K]
        [--solimp D0,DMAX,WIDTH] [--seed S]

From the hand-off states of ``bench_mujoco_edges.py --handoff-only`` (N vigorous nickel tosses,
default 600, seed 2026, e 0.5, μ 0.3, resistances 1e-4 m), K tosses (default 30) that end on
edge in coinflight's contact phase and, for each, the not-edge toss nearest to it at the
hand-off (in |n_z| and energy): both engines are traced over the first ``--span`` s (default
0.1 s) at MuJoCo's time step (0.1 ms; coinflight's phase advanced sample by sample with
:func:`coinflight.core.contact_phase.advance`), and MuJoCo is also carried to rest
(:func:`coinflight.studies.mujoco_compare.run_from`, same settings) for its face.

Per contact episode (a run of samples with a normal force, gaps shorter than :data:`MERGE`
samples bridged, coinflight's from its contact law,
MuJoCo's from ``mj_contactForce`` after ``mj_forward``): the impulse the table gave, from the
momentum, J = m (v_after − v_before) + m g Δt ẑ between the samples bracketing the episode
(exact in both engines, whatever the force's history); J_n its vertical part, J_t its
horizontal part, the ratio J_t / (μ J_n) (1 for an impact that slides one way throughout; less
if the contact sticks, turns or reverses); the slip speed of the coin's lowest point at the
episode's last sample; the tilt (angle of the heads normal from the vertical, 90° upright) and
the mechanical energy (kinetic + m g z) before and after. Per toss the time at which the two
engines' tilts first differ by more than 10° (where they part), and what the episodes before
it did in each engine. Prints medians per group (coinflight edge / not; MuJoCo edge / not),
and checks coinflight's friction at every traced sample in contact (its horizontal force
within μ F_n, opposing the slip of the material point at the centre of pressure).

Measured (``python benchmarks/bench_edge_trace.py 600 --per-group 30``, MuJoCo condim 3,
pyramidal cone, RK4; 2026-11-23 ~21:00 UTC, load 11-13; 775 s, run twice with identical
figures): of the 60 traced states MuJoCo leaves 9 on edge (7 of coinflight's 30 edges; 17
still moving at 20 s, counted by their well). Medians, coinflight | MuJoCo, all 60 (coinflight's
30 edges in brackets):

* the tilts part by 10° after 30 ms (31 ms); 26 (14) not within the 0.1 s;
* the first contact episode from the hand-off lasts 9.1 | 0.80 ms (9.3 | 0.85): here the rim
  is pressed up to ~0.1 mm into the compliant table by the coin's tumbling, in MuJoCo the coin
  is kicked off the table (its J_n 3.4 | 0.5 mN s);
* in contact for **51 % | 6 %** of the first 0.1 s (65 % | 8 %): MuJoCo's coins hop (1 | 4.5
  episodes before parting), ours stay on the rim; the total vertical impulse over 0.1 s is the
  same (4.8 | 4.5 mN s; 4.8 | 4.7). Why (measured since, ``bench_edge_sensitivity.py --trace``
  and :mod:`coinflight.studies.mujoco_compare`'s notes): not coinflight's soft rim law, since
  with a linear one whose impacts last 0.75 ms the first contact still lasts a median 15 ms (9
  ms for the edge-enders; 76 % of the first 0.1 s in contact) and frictionless 28 ms: the coin
  slides on its rim, pressed by its weight; MuJoCo's sliding contacts move apart (a flat coin
  sliding at 0.5 m/s with μ 0.3 is in contact 7 % of 30 ms there, 100 % here);
* the friction is no weaker in MuJoCo: its horizontal impulse over 0.1 s is 0.73 | 0.62 of
  μ times the vertical one (0.72 | 0.60), per episode before parting 0.85 | 0.67: MuJoCo's short
  contacts slide, ours last long enough to turn sliding into rolling;
* kinetic energy left at 0.1 s: 0.56 | 0.68 of the start (0.76 | 0.78); tilt then 72° | 67°.

coinflight's friction on the 29,370 traced samples in contact: at most 0.999996 μ F_n, and
opposing the slip at the centre of pressure (cosine −1.000000000 wherever one rim touches and
the slip exceeds 10 v_ε): regularised Coulomb, no bug there (tests/test_contact_friction.py
checks it on random states).
"""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np

G = 9.81
PART = math.radians(10.0)
"""The engines have parted when their tilts differ by more than this."""
MERGE = 5
"""Samples (0.5 ms) without a normal force within which a contact episode goes on (MuJoCo's
soft contact and a fast-wobbling rim touch and leave within a step or two)."""


def ours_trace(y0: np.ndarray, c, span: float, dt: float) -> dict[str, np.ndarray]:  # type: ignore[no-untyped-def]
    """coinflight's contact phase from y0 sampled every dt: t, v (k, 3), n, ω, z, F_n; and
    the friction checked at every sample in contact: ``cone`` = horizontal force / (μ F_n),
    ``against`` = cosine between it and the slip of the material point at the centre of
    pressure (one rim touching, slip above 10 v_ε; −1 when it opposes the slip; nan else)."""
    from coinflight.core import contact_phase as cp
    from coinflight.core.impact import angular_velocity, cross

    y = y0.copy()
    k = round(span / dt) + 1
    out = {name: np.zeros((k, 3)) for name in ("v", "n", "w")}
    out["z"] = np.zeros(k)
    out["fn"] = np.zeros(k)
    out["cone"] = np.full(k, np.nan)
    out["against"] = np.full(k, np.nan)
    deriv = np.empty(10)
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    for i in range(k):
        if i:
            cp.advance(y, dt, c)
        cp._derivative(y, deriv, c, stiff, zeta)
        out["z"][i] = y[0]
        out["v"][i] = y[1:4]
        out["n"][i] = y[4:7]
        out["w"][i] = angular_velocity(tuple(y[7:10]), tuple(y[4:7]), c.i1, c.i3)
        out["fn"][i] = c.mass * (deriv[3] + c.g)
        ft = c.mass * deriv[1:3]
        if out["fn"][i] > 0.0 and c.friction > 0.0:
            out["cone"][i] = math.hypot(*ft) / (c.friction * out["fn"][i])
            w = tuple(out["w"][i])
            rims = [
                cp.rim_contact(
                    sigma, y[0], tuple(y[1:4]), tuple(y[4:7]), w, c.radius, c.half_thickness,
                    c.mass, c.i1, c.i3, stiff, zeta, c.corner_radius,
                )
                for sigma in (-1.0, 1.0)
            ]  # fmt: skip
            touching = [r for r in rims if r[0] > 0.0]
            if len(touching) == 1:
                u = y[1:3] + np.array(cross(w, touching[0][1]))[:2]
                slip = math.hypot(*u)
                if slip > 10.0 * cp.SLIP_SPEED:
                    out["against"][i] = float(ft @ u) / (math.hypot(*ft) * slip)
    out["t"] = dt * np.arange(k)
    return out


def mujoco_trace(m, d, state: np.ndarray, span: float) -> dict[str, np.ndarray]:  # type: ignore[no-untyped-def]
    """MuJoCo from an mjSTATE_FULLPHYSICS row, every step: t, v, n, ω (lab), z, F_n."""
    import mujoco

    mujoco.mj_setState(m, d, state, mujoco.mjtState.mjSTATE_FULLPHYSICS)
    dt = float(m.opt.timestep)
    k = round(span / dt) + 1
    out = {name: np.zeros((k, 3)) for name in ("v", "n", "w")}
    out["z"] = np.zeros(k)
    out["fn"] = np.zeros(k)
    rot = np.empty(9)
    force = np.empty(6)
    for i in range(k):
        if i:
            mujoco.mj_step(m, d)
        mujoco.mj_forward(m, d)
        mujoco.mju_quat2Mat(rot, d.qpos[3:7])
        frame = rot.reshape(3, 3)
        out["z"][i] = d.qpos[2]
        out["v"][i] = d.qvel[:3]
        out["n"][i] = frame[:, 2]
        out["w"][i] = frame @ d.qvel[3:6]
        total = 0.0
        for j in range(d.ncon):
            mujoco.mj_contactForce(m, d, j, force)
            total += force[0] * abs(d.contact[j].frame[2])  # normal along the plane's z
        out["fn"][i] = total
    out["t"] = dt * np.arange(k)
    return out


def tilt(n: np.ndarray) -> np.ndarray:
    """Angle of the heads normal from the vertical folded to [0, 90°] (90° upright), rad."""
    return np.arccos(np.clip(np.abs(n[..., 2]), 0.0, 1.0))


def episodes(tr: dict[str, np.ndarray], c, mu: float) -> list[dict[str, float]]:  # type: ignore[no-untyped-def]
    """Contact episodes of a trace (module notes): impulses, ratio, slip, tilt, energy."""
    from coinflight.core.impact import contact_point

    on = tr["fn"] > 0.0
    # Gaps shorter than MERGE samples belong to the episode (soft contacts chatter).
    off = np.flatnonzero(~on)
    runs = np.split(off, np.flatnonzero(np.diff(off) > 1) + 1) if len(off) else []
    for gap in runs:
        if len(gap) and len(gap) < MERGE and gap[0] > 0 and gap[-1] < len(on) - 1:
            on[gap] = True
    m = c.mass
    k = len(on)
    rows = []
    i = 0
    energy = 0.5 * m * np.sum(tr["v"] ** 2, axis=1) + kinetic_rotation(tr, c) + m * G * tr["z"]
    while i < k:
        if not on[i]:
            i += 1
            continue
        j = i
        while j < k and on[j]:
            j += 1
        s, e = max(i - 1, 0), min(j, k - 1)
        dv = tr["v"][e] - tr["v"][s]
        dt = tr["t"][e] - tr["t"][s]
        jn = m * (dv[2] + G * dt)
        jt = m * math.hypot(dv[0], dv[1])
        last = j - 1
        n = tr["n"][last]
        rc = np.array(contact_point(tuple(n), c.radius, c.half_thickness))
        u = tr["v"][last] + np.cross(tr["w"][last], rc)
        rows.append(
            {
                "start": tr["t"][i],
                "length": tr["t"][j - 1] - tr["t"][i] + tr["t"][1],
                "jn": jn,
                "jt": jt,
                "ratio": jt / (mu * jn) if jn > 0 else math.nan,
                "slip": math.hypot(u[0], u[1]),
                "tilt0": math.degrees(tilt(tr["n"][s])),
                "tilt1": math.degrees(tilt(tr["n"][e])),
                "e0": energy[s],
                "e1": energy[e],
            }
        )
        i = j
    return rows


def kinetic_rotation(tr: dict[str, np.ndarray], c) -> np.ndarray:  # type: ignore[no-untyped-def]
    """½ ω·Iω of a trace, J."""
    n, w = tr["n"], tr["w"]
    wn = np.sum(w * n, axis=1)
    return 0.5 * (c.i1 * (np.sum(w * w, axis=1) - wn * wn) + c.i3 * wn * wn)


def main() -> None:
    import mujoco

    import bench_contact
    import mujoco_args
    from coinflight.core.impact import angular_velocity
    from coinflight.core.outcome import EDGE, Status
    from coinflight.outcomes.table import land
    from coinflight.studies import landing as study
    from coinflight.studies import mujoco_compare as mc

    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=600)
    parser.add_argument("--per-group", type=int, default=30)
    parser.add_argument("--span", type=float, default=0.1)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--restitution", type=float, default=0.5)
    parser.add_argument("--friction", type=float, default=0.3)
    parser.add_argument("--condim", type=int, default=3)
    parser.add_argument("--cone", choices=mc.CONES, default=mc.CONE)
    parser.add_argument("--impratio", type=float, default=1.0)
    parser.add_argument("--noslip", type=int, default=0)
    parser.add_argument(
        "--solimp",
        type=mujoco_args.solimp,
        default=",".join(str(x) for x in mc.SOLIMP),
        help="MuJoCo's d0,dmax,width",
    )
    parser.add_argument("--limit", type=float, default=mc.SETTLE)
    parser.add_argument("--save", default=None, help="write the episode tables to SAVE.npz")
    args = parser.parse_args()
    solver = mc.FrictionSolver(args.cone, args.impratio, args.noslip, args.solimp)
    e, mu = args.restitution, args.friction
    t0 = time.perf_counter()
    dist, omega, v0 = study.edge_draw(args.n, args.seed, "vigorous")
    out = land(dist.coin, omega, v0, 1.0, dist.g, study.edge_surface(e, mu))
    handed = np.flatnonzero(out.status != Status.SETTLED_ENERGY)
    c = bench_contact.contact(e, mu)
    states, faces = [], []
    for k in handed:
        y, ok = bench_contact.handoff(tuple(omega[k]), 1.0, v0[k], c)
        if ok:
            states.append(y)
            faces.append(out.face[k])
    y_all = np.array(states)
    ours_face = np.array(faces)
    energy0 = np.array(
        [
            0.5 * c.mass * y[1:4] @ y[1:4]
            + 0.5
            * (y[7:10] @ y[7:10] / c.i1 + (1 / c.i3 - 1 / c.i1) * float(y[4:7] @ y[7:10]) ** 2)
            + c.mass * G * y[0]
            for y in y_all
        ]
    )
    # The sample: coinflight's edges, each with the nearest not-edge toss at the hand-off.
    edges = np.flatnonzero(ours_face == EDGE)[: args.per_group]
    others = np.flatnonzero(ours_face != EDGE)
    feat = np.column_stack([np.abs(y_all[:, 6]), energy0 / energy0.std()])
    feat[:, 0] /= feat[:, 0].std()
    matched: list[int] = []
    for k in edges:
        dist2 = np.sum((feat[others] - feat[k]) ** 2, axis=1)
        dist2[np.isin(others, matched)] = np.inf
        matched.append(int(others[np.argmin(dist2)]))
    sample = np.concatenate([edges, np.array(matched, dtype=int)])
    ys = y_all[sample]
    w = np.array([angular_velocity(tuple(s[7:10]), tuple(s[4:7]), c.i1, c.i3) for s in ys])
    speed = math.sqrt(float(np.mean(v0)) ** 2 + 2.0 * G * study.DROP_HEIGHT)
    common = dict(
        condim=args.condim,
        torsional=study.EDGE_RESISTANCE,
        rolling=study.EDGE_RESISTANCE,
        integrator=study.EDGE_INTEGRATOR,
        solver=solver,
    )
    run = mc.run_from(
        dist.coin, ys[:, 0], ys[:, 1:4], ys[:, 4:7], w, e, mu, speed, limit=args.limit, **common
    )
    m = mc.model(
        dist.coin, mu, run.dampratio, G, common["integrator"], args.condim,
        study.EDGE_RESISTANCE, study.EDGE_RESISTANCE, solver,
    )  # fmt: skip
    d = mujoco.MjData(m)
    initial = mc._placed_states(m, d, ys[:, 0], ys[:, 1:4], ys[:, 4:7], w)
    dt = float(m.opt.timestep)
    print(
        f"{len(y_all)} hand-off states of {args.n} vigorous tosses (seed {args.seed}), e {e:g}, "
        f"μ {mu:g}; traced {len(edges)} coinflight edges + {len(matched)} matched not-edge, "
        f"{args.span:g} s at {dt:g} s; MuJoCo condim {args.condim}, {solver}, damping ratio "
        f"{run.dampratio:.4f}; load {os.getloadavg()[0]:.1f}"
    )
    rows = []
    cone_max, against_max, checked = 0.0, -1.0, 0
    for idx in range(len(sample)):
        ours = ours_trace(ys[idx], c, args.span, dt)
        cone_max = max(cone_max, float(np.nanmax(ours["cone"], initial=0.0)))
        against_max = max(against_max, float(np.nanmax(ours["against"], initial=-1.0)))
        checked += int(np.count_nonzero(np.isfinite(ours["cone"])))
        theirs = mujoco_trace(m, d, initial[idx], args.span)
        eps_o, eps_m = episodes(ours, c, mu), episodes(theirs, c, mu)
        gap = np.abs(tilt(ours["n"]) - tilt(theirs["n"]))
        parted = np.flatnonzero(gap > PART)
        t_part = float(ours["t"][parted[0]]) if len(parted) else math.nan
        energy_o = 0.5 * c.mass * np.sum(ours["v"] ** 2, 1) + kinetic_rotation(ours, c)
        energy_m = 0.5 * c.mass * np.sum(theirs["v"] ** 2, 1) + kinetic_rotation(theirs, c)

        def before(eps: list[dict[str, float]], t_end: float = t_part) -> list[dict[str, float]]:
            return [x for x in eps if math.isnan(t_end) or x["start"] <= t_end]

        bo, bm = before(eps_o), before(eps_m)

        def agg(eps: list[dict[str, float]], key: str) -> float:
            vals = [x[key] for x in eps if np.isfinite(x[key])]
            return float(np.mean(vals)) if vals else math.nan

        def sums(eps: list[dict[str, float]]) -> tuple[float, float]:
            jn = sum(x["jn"] for x in eps)
            jt = sum(x["jt"] for x in eps)
            return jn, jt

        jn_o, jt_o = sums(bo)
        jn_m, jt_m = sums(bm)
        all_jn_o, all_jt_o = sums(eps_o)
        all_jn_m, all_jt_m = sums(eps_m)

        def hop(tr: dict[str, np.ndarray]) -> float:
            depth = c.radius * np.sqrt(1 - tr["n"][:, 2] ** 2) + c.half_thickness * np.abs(
                tr["n"][:, 2]
            )
            return float(np.max(tr["z"] - depth))

        first_o = eps_o[0] if eps_o else None
        first_m = eps_m[0] if eps_m else None
        rows.append(
            {
                "ours_edge": ours_face[sample[idx]] == EDGE,
                "mj_edge": run.rest[idx] == EDGE,
                "t_part": t_part,
                "episodes_o": len(bo),
                "episodes_m": len(bm),
                "ratio_o": agg(bo, "ratio"),
                "ratio_m": agg(bm, "ratio"),
                "jn_o": jn_o,
                "jn_m": jn_m,
                "jt_o": jt_o,
                "jt_m": jt_m,
                "first_ratio_o": first_o["ratio"] if first_o else math.nan,
                "first_ratio_m": first_m["ratio"] if first_m else math.nan,
                "first_jn_o": first_o["jn"] if first_o else math.nan,
                "first_jn_m": first_m["jn"] if first_m else math.nan,
                "first_jt_o": first_o["jt"] if first_o else math.nan,
                "first_jt_m": first_m["jt"] if first_m else math.nan,
                "first_slip_o": first_o["slip"] if first_o else math.nan,
                "first_slip_m": first_m["slip"] if first_m else math.nan,
                "first_lost_o": (first_o["e0"] - first_o["e1"]) / first_o["e0"]
                if first_o
                else math.nan,
                "first_lost_m": (first_m["e0"] - first_m["e1"]) / first_m["e0"]
                if first_m
                else math.nan,
                "slip_end_o": agg(bo, "slip"),
                "slip_end_m": agg(bm, "slip"),
                "tilt_end_o": math.degrees(float(tilt(ours["n"][-1]))),
                "tilt_end_m": math.degrees(float(tilt(theirs["n"][-1]))),
                "ke_end_o": energy_o[-1] / energy_o[0],
                "ke_end_m": energy_m[-1] / energy_m[0],
                "ke_part_o": energy_o[parted[0]] / energy_o[0] if len(parted) else math.nan,
                "ke_part_m": energy_m[parted[0]] / energy_m[0] if len(parted) else math.nan,
                "span_ratio_o": all_jt_o / (mu * all_jn_o) if all_jn_o > 0 else math.nan,
                "span_ratio_m": all_jt_m / (mu * all_jn_m) if all_jn_m > 0 else math.nan,
                "span_jn_o": all_jn_o,
                "span_jn_m": all_jn_m,
                "hop_o": hop(ours) * 1e3,
                "hop_m": hop(theirs) * 1e3,
                "first_len_o": first_o["length"] * 1e3 if first_o else math.nan,
                "first_len_m": first_m["length"] * 1e3 if first_m else math.nan,
                "contact_o": float(np.mean(ours["fn"] > 0)),
                "contact_m": float(np.mean(theirs["fn"] > 0)),
            }
        )
    table = {key: np.array([r[key] for r in rows], dtype=float) for key in rows[0]}
    ours_e = table["ours_edge"] > 0
    mj_e = table["mj_edge"] > 0
    print(
        f"MuJoCo carried to rest ({run.elapsed:.0f} s): on edge {int(mj_e.sum())} of "
        f"{len(sample)} ({int((mj_e & ours_e).sum())} of coinflight's {int(ours_e.sum())} "
        f"edges; {int(run.unsettled)} still moving at {args.limit:g} s); whole run "
        f"{time.perf_counter() - t0:.0f} s"
    )
    print(
        f"coinflight's friction on {checked:,} sampled contact states: largest horizontal force "
        f"/ (μ F_n) {cone_max:.6f}; largest cosine to the slip at the centre of pressure (one "
        f"rim, slip > 10 v_ε) {against_max:.9f} (−1: opposing it)"
    )
    groups = {
        "coinflight edge": ours_e,
        "coinflight not edge": ~ours_e,
        "cf edge, MuJoCo not": ours_e & ~mj_e,
        "all": np.ones(len(sample), dtype=bool),
    }
    keys = (
        ("t_part", "parted at (s, tilts 10° apart)", None),
        ("first_len_o", "1st episode length (ms)", "first_len_m"),
        ("first_jn_o", "1st episode J_n (mN s)", "first_jn_m"),
        ("first_jt_o", "1st episode J_t (mN s)", "first_jt_m"),
        ("first_ratio_o", "1st episode J_t/(μ J_n)", "first_ratio_m"),
        ("first_slip_o", "1st episode slip at its end (m/s)", "first_slip_m"),
        ("first_lost_o", "1st episode energy lost (share)", "first_lost_m"),
        ("episodes_o", "episodes before parting", "episodes_m"),
        ("ratio_o", "mean J_t/(μ J_n) before parting", "ratio_m"),
        ("jn_o", "sum J_n before parting (mN s)", "jn_m"),
        ("jt_o", "sum J_t before parting (mN s)", "jt_m"),
        ("slip_end_o", "mean end-of-episode slip (m/s)", "slip_end_m"),
        ("ke_part_o", "kinetic energy at parting / start", "ke_part_m"),
        ("ke_end_o", f"kinetic energy at {args.span:g} s / start", "ke_end_m"),
        ("tilt_end_o", f"tilt at {args.span:g} s (deg)", "tilt_end_m"),
        ("contact_o", "share of samples in contact", "contact_m"),
        ("span_jn_o", f"sum J_n over {args.span:g} s (mN s)", "span_jn_m"),
        ("span_ratio_o", f"sum J_t / (μ sum J_n) over {args.span:g} s", "span_ratio_m"),
        ("hop_o", f"highest hop of the lowest point in {args.span:g} s (mm)", "hop_m"),
    )
    scale = {"first_jn_o": 1e3, "first_jt_o": 1e3, "jn_o": 1e3, "jt_o": 1e3, "span_jn_o": 1e3}
    for gname, mask in groups.items():
        print(f"\n{gname} ({int(mask.sum())} tosses): median coinflight | MuJoCo")
        for ko, label, km in keys:
            f = scale.get(ko, 1.0)
            a = np.nanmedian(table[ko][mask]) * f
            if km is None:
                print(f"  {label:38s}: {a:.4f} (not parted in {args.span:g} s: "
                      f"{int(np.isnan(table[ko][mask]).sum())})")  # fmt: skip
            else:
                b = np.nanmedian(table[km][mask]) * f
                print(f"  {label:38s}: {a:8.4f} | {b:8.4f}")
    if args.save:
        np.savez(f"{args.save}.npz", sample=sample, **table)


if __name__ == "__main__":
    main()

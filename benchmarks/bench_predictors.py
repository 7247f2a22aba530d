"""Can the contact phase's tosses be decided early? Predictors against carrying on (issue 11).

    python benchmarks/bench_predictors.py [N] [--seed S] [--chunk DT] [--resistance L]
        [--pairs E,MU ... own]

For N vigorous tosses of a US nickel (``bench_bounce.tosses``: ωx ~ U(150, 300), ωy, ωz ~ U(−30,
30) rad/s, v0 ~ U(1.5, 3) m/s, 0.8 m drop) handed to the contact phase as
``bench_contact.handoff`` does (the bounces of :func:`coinflight.core.bounce.bounce_loop` with
the contact ending; rolling and pivoting resistance ℓ_r = ℓ_p = L, default the surface's
1e-4 m, as ``bench_contact.py --resistance``), on each surface of ``--pairs``
(``own``: each toss its own e ~ U(0.2, 0.8) rounded to 0.01 and μ ~ U(0.1, 0.6), drawn from the
generator ``default_rng([S, 1])``, a stream apart from the tosses'), the phase is carried on to
rest by :func:`coinflight.core.contact_phase.advance` (``settle_check=True``, no upright
decision) in chunks of DT s simulated (default 2 ms), and after the hand-off and after every
chunk each predictor of ``face_predictors.py`` (beside this file, its ``SHARES``) is
evaluated; the first time it fires and the
face it names are recorded, and so is where
:func:`coinflight.core.contact_phase.upright_decided` first held (the integrator's probe row,
step-exact), for comparison. A decision disagrees when its face is not the face at rest or the
toss does not settle within :data:`~coinflight.core.contact_phase.MAX_STEPS` steps.

Beside them, an oracle: "last well change", the first chunk end after which the coin is never
seen outside the well it ends in (the earliest any rule naming the well the coin is in could
decide correctly because the coin cannot leave it, as an energy bound claims), and "first in
final well", the first chunk end at which the coin is in that well (a rule could be right
there only by luck: the coin still leaves and comes back); and the naive rule "the well at the
hand-off", which decides every toss at once. Results: ``face_predictors.py``'s notes (dated
2026-11-24). A toss is named by (N, seed, index): ``bench_bounce.tosses`` draws depend on N,
so the index printed with a wrong decision (its place among the N drawn) finds it again only
with the same N and seed.

Per predictor and surface: the handed tosses decided early (before the toss settles: every rule
fires once the energy is below m g ρ), at the hand-off and in all; the median share of the
toss's contact time the decision saves; disagreements with a 95 % Clopper-Pearson upper bound
(:func:`scipy.stats.binomtest`); the speed-up of the contact phase, its steps over the steps
left when each decided toss stops at its decision (steps of :func:`segmented`), and against the
phase as shipped (the upright decision on) the same with the upright decision and the predictor
both (the bounces before the hand-off not counted: they are ~2 % of a landing's CPU time,
``contact_phase`` module notes).

Chunking: each :func:`~coinflight.core.contact_phase.advance` call restarts the step size (and
the first derivative) and costs a few extra steps: 2 ms chunks make 1,298,984 steps of the
761,704 that these calls take on the same 429 tosses (seed 2026, e 0.5, μ 0.3; 1 ms chunks
1,834,764), mostly in the long upright rollers, which would inflate every saving. So the steps
are counted on a second run of each toss (:func:`segmented`) stopped only at the times the rules
first fired in the chunked run (at most seven restarts: eight times, the hand-off's 0 among
them), and its face at rest is compared with the
chunked run's (``chunked vs one call``: the restarts change the trajectory at the rounding
level, which a chaotic wobble can grow into another face). Firing is tested only at chunk ends:
a rule's first firing is late by up to a chunk, and the oracle misses an excursion out of the
final well and back within one chunk (``--chunk`` 1e-3 and 5e-3 show how much this moves).
The chunked run stops at :data:`~coinflight.core.contact_phase.MAX_STEPS` counted with its
restart steps (~70 % more at 2 ms), so it gives up earlier than the phase would: at 1e-4 m
no toss came near it (0 unsettled); at ``--resistance 1e-5`` 7 of 205 (e 0.5 μ 0.6) and 2 of
210 (own e, μ) edge rollers, seed 7, reach it after ~160 s simulated and count as unsettled."""

from __future__ import annotations

import argparse
import math
import os
import time

import numpy as np
from scipy.stats import binomtest

import bench_bounce
import bench_contact
import face_predictors as fp
from coinflight.core import contact_phase as cp
from coinflight.core.impact import resting_face


def draws(n: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """ω (n, 3), v0 (n,) of ``bench_bounce.tosses`` and each toss's own e, μ (module notes)."""
    omega, v0 = bench_bounce.tosses(n, seed)
    rng = np.random.default_rng([seed, 1])
    e = np.round(rng.uniform(0.2, 0.8, n), 2)
    mu = rng.uniform(0.1, 0.6, n)
    return omega, v0, e, mu


def last_well_change(wells: list[tuple[float, int, int]], final: int) -> int:
    """The index in ``wells`` (records (time, steps, well) in order) of the first record after
    which the well is never other than ``final``: the "last well change" oracle's stop (0 when
    every record is in ``final``; ``len(wells)`` when the last one is not)."""
    return max((i for i, w in enumerate(wells) if w[2] != final), default=-1) + 1


def carry(y: np.ndarray, c, chunk: float, rtol: float = cp.RTOL) -> dict:  # type: ignore[no-untyped-def]
    """Carry the handed state ``y`` on to rest in chunks of ``chunk`` s at the step tolerance
    ``rtol``: the first firing of each predictor (time, steps, face; NaN/−1 if never), the
    upright decision's first holding, the total time and steps, whether it settled and its
    face at rest; ``"oracle"`` is (time, steps) of the last well change
    (:func:`last_well_change`)."""
    k = fp.SHARES.shape[0]
    stiffness = cp.stiffness_of(c)
    fire_t = np.full(k + 4, np.nan)
    fire_s = np.full(k + 4, np.nan)
    fire_f = np.full(k + 4, -1)
    out = np.empty(k, dtype=np.int64)
    modes = len(cp.MODES)
    stats = np.zeros((modes + 1, 2))
    stats[modes] = -1.0
    t, steps, ended = 0.0, 0, cp.Ending.RUNNING
    scale = c.barrier - c.mass * c.g * c.half_thickness  # m g ρ − m g h/2
    ln = float(y[4:7] @ y[7:10])
    handed = (
        (cp.energy(y, c, stiffness) - c.barrier) / scale,
        0.5 * ln * ln / c.i3 / scale,
        (fp.corner_barrier(y, c, 1.0, 1.0) - c.barrier) / scale - 0.5 * ln * ln / c.i3 / scale,
        0.5 * c.mass * (y[1] ** 2 + y[2] ** 2) / scale,
    )
    wells = []  # (time, steps, well) after the hand-off and after each chunk
    while True:
        wells.append((t, steps, resting_face(y[6], c.edge_sine)))
        fp.predict_all(y, c, stiffness, fp.SHARES, out)
        new = (out >= 0) & (fire_f[:k] < 0)
        fire_t[:k][new], fire_s[:k][new], fire_f[:k][new] = t, steps, out[new]
        if ended or steps >= cp.MAX_STEPS:
            break
        before = stats[modes].copy()
        dt, ds, ended = cp.advance(
            y, chunk, c, settle_check=True, max_steps=cp.MAX_STEPS - steps, stats=stats, rtol=rtol
        )
        if before[1] < 0.0 <= stats[modes, 1]:  # upright_decided first held in this chunk
            fire_t[k], fire_s[k], fire_f[k] = t + stats[modes, 0], steps + stats[modes, 1], 2
        t += dt
        steps += ds
    final = resting_face(y[6], c.edge_sine)
    last = last_well_change(wells, final)
    fire_t[k + 1], fire_s[k + 1], fire_f[k + 1] = wells[last][0], wells[last][1], final
    first = min(i for i, w in enumerate(wells) if w[2] == final)
    fire_t[k + 2], fire_s[k + 2], fire_f[k + 2] = wells[first][0], wells[first][1], final
    fire_t[k + 3], fire_s[k + 3], fire_f[k + 3] = 0.0, 0, wells[0][2]
    return {
        "oracle": wells[last][:2],
        "handed": handed,
        "fire_t": fire_t,
        "fire_s": fire_s,
        "fire_f": fire_f,
        "time": t,
        "steps": steps,
        "settled": bool(ended),
        "face": final,
    }


def segmented(y: np.ndarray, c, times: np.ndarray) -> tuple[np.ndarray, int, int, bool]:  # type: ignore[no-untyped-def]
    """Carry ``y`` on to rest in as few calls as reach each of ``times`` (s; NaN: none): the
    steps taken by each of them (the total where the toss settled before it), the total steps,
    the face at rest and whether it settled. The steps of the benchmark's speed-ups: each
    chunk restarts the step size (2 ms chunks add ~70 % to a phase's steps, module notes), a
    handful of calls does not."""
    order = np.argsort(np.where(np.isnan(times), np.inf, times))
    at = np.full(times.shape, np.nan)
    t, steps, ended = 0.0, 0, cp.Ending.RUNNING
    for i in order:
        if math.isnan(times[i]):
            break
        if not ended and times[i] > t:
            dt, ds, ended = cp.advance(
                y, times[i] - t, c, settle_check=True, max_steps=cp.MAX_STEPS - steps
            )
            t += dt
            steps += ds
        at[i] = steps
    if not ended:
        _, ds, ended = cp.advance(y, math.inf, c, settle_check=True, max_steps=cp.MAX_STEPS - steps)
        steps += ds
    return at, steps, resting_face(y[6], c.edge_sine), bool(ended)


def _ratio(steps: float, left: float) -> str:
    """``steps / left`` as a speed-up, "every step" where none is left."""
    return f"{steps / left:.2f}x" if left > 0 else "every step saved"


def run(
    n: int,
    seed: int,
    chunk: float,
    surface: tuple[float, float] | None,
    resistance: float | None = None,
) -> None:
    """The table of the module notes for one surface (e, μ), or each toss's own; ``resistance``
    ℓ_r = ℓ_p, m (None: the surface's default)."""
    omega, v0, e, mu = draws(n, seed)
    if surface is not None:
        e[:], mu[:] = surface
    names = (
        *fp.NAMES,
        "upright_decided (reference)",
        "last well change (oracle)",
        "first in final well (oracle)",
        "the well at the hand-off",
    )
    rows = []
    one_face = []
    one_settled = []
    ell = bench_contact.contact(0.5, 0.3, resistance=resistance).rolling_resistance
    w0 = time.perf_counter()
    for j in range(n):
        c = bench_contact.contact(float(e[j]), float(mu[j]), resistance=resistance)
        y, handed = bench_contact.handoff((omega[j, 0], omega[j, 1], omega[j, 2]), 1.0, v0[j], c)
        if not handed:
            continue
        y1 = y.copy()
        row = carry(y, c, chunk)
        row["index"] = j
        row["fire_s"], row["steps"], one, ended = segmented(y1, c, row["fire_t"])
        one_face.append(one)
        one_settled.append(ended)
        rows.append(row)
    wall = time.perf_counter() - w0
    kind = "each toss its own e, μ" if surface is None else f"e {surface[0]}, μ {surface[1]}"
    h = len(rows)
    face = np.array([r["face"] for r in rows])
    settled = np.array([r["settled"] for r in rows])
    total_t = np.array([r["time"] for r in rows])
    total_s = np.array([r["steps"] for r in rows], dtype=float)
    print(
        f"\n{n} tosses, seed {seed}, {kind}, resistances {ell:g} m, chunk "
        f"{chunk * 1e3:g} ms: {h} handed; "
        f"{wall:.1f} s wall, load {os.getloadavg()[0]:.1f}; at rest (tails, heads, edge) "
        f"{np.bincount(face[settled], minlength=3).tolist()}, unsettled {(~settled).sum()}; "
        f"contact time median {np.median(total_t):.3f} s, steps {total_s.sum():,.0f}"
    )
    en = np.array([r["handed"] for r in rows])
    print(
        "  at the hand-off, in barriers m g ρ − m g h/2, medians: energy above m g ρ "
        f"{np.median(en[:, 0]):.2f}, spin (L·n)²/2I3 {np.median(en[:, 1]):.3f}, (a)'s "
        f"precession term {np.median(en[:, 2]):.3f}, ½ m v_h² {np.median(en[:, 3]):.3f}"
    )
    differ = int(np.sum((np.array(one_face) != face) | (np.array(one_settled) != settled)))
    print(f"  chunked vs one call: faces or settling differ on {differ} of {h}")
    k = fp.SHARES.shape[0]
    upright = np.array([r["fire_s"][k] for r in rows])
    shipped = np.where(np.isnan(upright), total_s, np.minimum(total_s, upright))
    for i, name in enumerate(names):
        ft = np.array([r["fire_t"][i] for r in rows])
        fs = np.array([r["fire_s"][i] for r in rows])
        ff = np.array([r["fire_f"][i] for r in rows])
        hit = (ff >= 0) & (ft < total_t)  # fired before the toss settled (every rule fires then)
        wrong = hit & ((ff != face) | ~settled)
        bad, m = int(wrong.sum()), int(hit.sum())
        upper = binomtest(bad, m).proportion_ci(0.95, method="exact").high if m else 1.0
        saved_s = (total_s[hit] - fs[hit]).sum()
        share = (total_t[hit] - ft[hit]) / np.maximum(total_t[hit], 1e-300)
        both = np.where(hit, np.minimum(shipped, np.nan_to_num(fs, nan=np.inf)), shipped)
        print(
            f"  {name:30s}: decides early {m} of {h} ({m / h:.0%}; {np.sum(hit & (fs == 0))} at "
            f"the hand-off), contact time saved median {np.median(share) if m else 0:.0%} of "
            f"those, mean {np.sum(share) / h:.0%} over all handed; "
            f"disagreements {bad} (95 % upper {upper:.3f}); speed-up "
            f"{_ratio(total_s.sum(), total_s.sum() - saved_s)} (with the upright decision "
            f"as shipped {_ratio(shipped.sum(), both.sum())})"
        )
        if bad:
            kinds = {}
            for j in np.flatnonzero(wrong):
                key = f"{'THE'[ff[j]]}->{'THE'[face[j]] if settled[j] else 'unsettled'}"
                kinds[key] = kinds.get(key, 0) + 1
            late = np.median((total_t - ft)[wrong])
            print(f"      (predicted->at rest: {kinds}; decision to rest, median {late:.2f} s)")
        for j in np.flatnonzero(wrong)[:4]:
            print(
                f"      toss {rows[j]['index']}: predicted {ff[j]} at {ft[j]:.3f} s, at rest "
                f"{face[j]} (settled {settled[j]}) at {total_t[j]:.3f} s"
            )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", type=int, nargs="?", default=300)
    parser.add_argument("--seed", type=int, default=2026)
    parser.add_argument("--chunk", type=float, default=2e-3, help="simulated s a chunk")
    parser.add_argument(
        "--resistance", type=float, default=None, help="ℓ_r = ℓ_p, m (default the surface's)"
    )
    parser.add_argument("--pairs", nargs="*", default=["0.5,0.3", "0.5,0.6", "own"])
    args = parser.parse_args()
    if args.n < 1:
        parser.error(f"N must be a whole number ≥ 1, got {args.n}")
    if not (math.isfinite(args.chunk) and args.chunk > 0.0):
        parser.error(f"--chunk must be a finite number > 0 (simulated s), got {args.chunk}")
    if args.resistance is not None and not (
        math.isfinite(args.resistance) and args.resistance >= 0.0
    ):
        parser.error(f"--resistance must be a finite number ≥ 0 (m), got {args.resistance}")
    for pair in args.pairs:
        surface = None if pair == "own" else tuple(float(x) for x in pair.split(","))
        run(args.n, args.seed, args.chunk, surface, args.resistance)  # type: ignore[arg-type]


if __name__ == "__main__":
    main()

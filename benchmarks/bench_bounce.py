"""Speed of the bouncing model (issue 6), and a general rigid-body engine beside it.

    python benchmarks/bench_bounce.py              # coinflight speed + MuJoCo on 200 tosses
    python benchmarks/bench_bounce.py --quick      # fewer tosses
    python benchmarks/bench_bounce.py --nickel     # also P(edge) of a US nickel vs (e, μ)
    python benchmarks/bench_bounce.py --contact N  # the opt-in contact phase: same side, edges

coinflight: the event-driven numba kernel (``coinflight.outcomes.table.land``; exact flights between
impacts, contacts found by root finding, parallel over tosses), on tosses of a US nickel
dropped onto a table 0.8 m below launch (e = 0.5, μ = 0.3): tosses per second, median of
repeats, all threads of the machine.

MuJoCo (optional: ``pip install coinflight[mujoco]``; skipped cleanly when not installed): the
same tosses as a free cylinder over a plane, time step 1e-4 s, RK4 and MuJoCo's default Euler
integrator, its default soft contact with friction μ, multithreaded rollouts; tosses per second,
and the agreement of outcomes with coinflight, (a) at the first contact (geometry and free
flight only: the well of the coin's orientation when it first touches) and (b) at rest after
2 s (depends on each engine's contact model).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import statistics
import time

import numpy as np

from coinflight import Coin
from coinflight.core.impact import resting_face
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land

COIN = Coin.preset("us-nickel")
G = 9.81
DROP = 0.8
SURFACE = Surface("table", drop_height=DROP, restitution=0.5, friction=0.3)


def tosses(n: int, seed: int = 2026) -> tuple[np.ndarray, np.ndarray]:
    """Vigorous tosses: ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30) rad/s, v0 ~ U(1.5, 3) m/s."""
    rng = np.random.default_rng(seed)
    omega = np.column_stack(
        [
            rng.uniform(150.0, 300.0, n),
            rng.uniform(-30.0, 30.0, n),
            rng.uniform(-30.0, 30.0, n),
        ]
    )
    return omega, rng.uniform(1.5, 3.0, n)


def face_fractions(face: np.ndarray) -> str:
    """'P(heads, tails, edge) = (…)' of an array of face codes (TAILS=0, HEADS=1, EDGE=2)."""
    share = np.bincount(face, minlength=3) / len(face)
    return f"P(heads, tails, edge) = ({share[HEADS]:.4f}, {share[TAILS]:.4f}, {share[EDGE]:.2e})"


def median_rate(fn, n: int, repeats: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return n / statistics.median(times)


def bench_coinflight(n: int, repeats: int) -> None:
    import numba

    omega, v0 = tosses(n)
    land(COIN, omega[:100], v0[:100], 1.0, G, SURFACE)  # compile (or load the cache)
    rate = median_rate(lambda: land(COIN, omega, v0, 1.0, G, SURFACE), n, repeats)
    first = median_rate(lambda: land(COIN, omega, v0, 1.0, G, SURFACE, max_bounces=0), n, repeats)
    out = land(COIN, omega, v0, 1.0, G, SURFACE)
    print(
        f"coinflight bouncing (default rocking ending), {n:,} tosses, {numba.get_num_threads()} "
        f"threads: {rate:,.0f} tosses/s carried to rest (median of {repeats}); first contact "
        f"only: {first:,.0f} tosses/s"
    )
    rocking = np.mean(out.status == Status.SETTLED_ROCKING)
    print(
        f"  mean bounces {out.bounces.mean():.2f}, max {out.bounces.max()}; decided by the "
        f"rocking hand-off {rocking:.1%}; unsettled {np.mean(out.status == Status.UNSETTLED):.2%}; "
        f"{face_fractions(out.face)}"
    )


def _mujoco_model(friction: float, integrator: str = "RK4"):  # type: ignore[no-untyped-def]
    import mujoco

    xml = f"""
    <mujoco>
      <option timestep="1e-4" gravity="0 0 -{G}" integrator="{integrator}"/>
      <worldbody>
        <geom type="plane" size="5 5 0.1" friction="{friction} 0.005 0.0001"/>
        <body name="coin" pos="0 0 1">
          <freejoint/>
          <geom type="cylinder" size="{COIN.radius} {COIN.thickness / 2}" mass="{COIN.mass}"
                friction="{friction} 0.005 0.0001"/>
        </body>
      </worldbody>
    </mujoco>"""
    return mujoco.MjModel.from_xml_string(xml)


def mujoco_outcomes(
    omega: np.ndarray, v0: np.ndarray, settle: float = 2.0, integrator: str = "RK4"
) -> tuple:  # type: ignore[type-arg]
    """(face at first contact, face at rest) for each toss: MuJoCo's multithreaded rollout."""
    import mujoco
    from mujoco import rollout

    model = _mujoco_model(SURFACE.friction, integrator)
    datas = [mujoco.MjData(model) for _ in range(os.cpu_count() or 1)]
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    size = mujoco.mj_stateSize(model, spec)
    r, hh = COIN.radius, COIN.thickness / 2
    edge_sine = hh / math.hypot(r, hh)
    nstep = int((2 * float(v0.max()) / G + 1.0 + settle) / model.opt.timestep)
    data = datas[0]
    first = np.empty(len(v0), dtype=np.int8)
    rest = np.empty(len(v0), dtype=np.int8)
    chunk = 8
    for a in range(0, len(v0), chunk):
        states = []
        for k in range(a, min(a + chunk, len(v0))):
            mujoco.mj_resetData(model, data)
            data.qpos[:3] = (0.0, 0.0, DROP)  # launch point DROP above the plane
            data.qpos[3:7] = (1.0, 0.0, 0.0, 0.0)  # heads up (scalar first)
            data.qvel[:3] = (0.0, 0.0, v0[k])
            data.qvel[3:6] = omega[k]  # free joint: angular velocity in the body frame
            state = np.empty(size)
            mujoco.mj_getState(model, data, state, spec)
            states.append(state)
        traj, _ = rollout.rollout(model, datas, np.array(states), nstep=nstep)
        z = traj[:, :, 3]
        w, x, y = traj[:, :, 4], traj[:, :, 5], traj[:, :, 6]
        nz = 1.0 - 2.0 * (x * x + y * y)  # third row of R(q): the normal's z component
        gap = z - r * np.sqrt(np.clip(1 - nz * nz, 0, 1)) - hh * np.abs(nz)
        del w
        for j in range(traj.shape[0]):
            apex = int(v0[a + j] / G / model.opt.timestep)
            hit = apex + int(np.argmax(gap[j, apex:] <= 0.0))
            first[a + j] = resting_face(float(nz[j, hit]), edge_sine)
            rest[a + j] = resting_face(float(nz[j, -1]), edge_sine)
    return first, rest


def bench_mujoco(m: int) -> None:
    try:
        import mujoco
    except ImportError:
        print("MuJoCo: not installed (pip install 'coinflight[mujoco]'), skipped")
        return
    omega, v0 = tosses(m)
    ours_first = land(COIN, omega, v0, 1.0, G, SURFACE, max_bounces=0).face
    ours = land(COIN, omega, v0, 1.0, G, SURFACE).face
    for integrator in ("RK4", "Euler"):
        t0 = time.perf_counter()
        first, rest = mujoco_outcomes(omega, v0, integrator=integrator)
        rate = m / (time.perf_counter() - t0)
        print(
            f"MuJoCo {mujoco.__version__} ({integrator}, dt = 1e-4 s, {os.cpu_count()} threads), "
            f"{m} tosses: {rate:,.1f} tosses/s"
        )
        print(
            f"  agreement with coinflight: first contact {np.mean(first == ours_first):.1%}, "
            f"at rest {np.mean(rest == ours):.1%} (MuJoCo's soft contact is not e = "
            f"{SURFACE.restitution}); MuJoCo at rest: {face_fractions(rest)}"
        )


def nickel_edge(n: int) -> None:
    """P(edge) of a US nickel for a few (e, μ), beside Murray & Teare's 1 in 6000."""
    omega, v0 = tosses(n, seed=6000)
    print(f"US nickel, {n:,} tosses onto a table {DROP} m below launch (Murray & Teare: 1/6000)")
    for e in (0.1, 0.35, 0.6):
        for mu in (0.1, 0.3, 1.0):
            out = land(COIN, omega, v0, 1.0, G, Surface("table", DROP, e, mu))
            k = int(np.sum(out.face == EDGE))
            ratio = f"1 in {n / k:,.0f}" if k else "none"
            print(f"  e = {e:.2f}, μ = {mu:.1f}: P(edge) = {k / n:.2e} ({ratio}; {k} edges)")


def contact_phase(n: int) -> None:
    """What the experimental contact phase (``ending="contact"``) decides, over the parameters
    nobody has measured (issue 11)."""
    rng = np.random.default_rng(11)
    # The axial-spin toss: ωx 150-300, ωz = ±20 rad/s, 0.8 m drop, started heads up.
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), np.zeros(n), rng.choice([-20.0, 20.0], n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    print(f"axial-spin tosses (ωx 150-300, ωz ±20 rad/s, {DROP} m drop), {n:,} per setting:")
    for mu in (0.0, 0.1, 0.3, 1.0):
        for resist in (1e-5, 1e-4, 1e-3):
            surface = Surface("table", DROP, 0.5, mu, resist, resist, ending="contact")
            t0 = time.perf_counter()
            out = land(COIN, omega, v0, 1.0, G, surface)
            rate = n / (time.perf_counter() - t0)
            same = np.mean(out.face == HEADS)
            se = math.sqrt(same * (1 - same) / n)
            print(
                f"  e = 0.5, μ = {mu:.1f}, rolling = pivoting = {resist:.0e} m: P(same side) = "
                f"{same:.3f} ± {se:.3f}, edge {np.mean(out.face == EDGE):.4f}, contact phase "
                f"{np.mean(out.status == Status.SETTLED_CONTACT):.1%}, unsettled "
                f"{np.mean(out.status == Status.UNSETTLED):.2%}, {rate:,.0f} tosses/s"
            )
    omega = np.column_stack([rng.uniform(150.0, 300.0, n), np.zeros(n), np.zeros(n)])
    print(f"planar tosses (ωx 150-300 only), {n:,} per setting: P(heads) − P(tails)")
    for e, mu in ((0.2, 0.1), (0.5, 0.3), (0.8, 1.0)):
        out = land(COIN, omega, v0, 1.0, G, Surface("table", DROP, e, mu, ending="contact"))
        h, t = np.mean(out.face == HEADS), np.mean(out.face == TAILS)
        se = math.sqrt((h + t - (h - t) ** 2) / n)
        print(f"  e = {e}, μ = {mu}: {h - t:+.4f} ± {se:.4f} (s.e.)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--nickel", action="store_true")
    parser.add_argument("--contact", type=int, default=0, metavar="N")
    args = parser.parse_args()
    if args.contact:
        contact_phase(args.contact)
        return
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs")
    bench_coinflight(200_000 if args.quick else 1_000_000, 3 if args.quick else 5)
    bench_mujoco(16 if args.quick else 100)
    if args.nickel:
        nickel_edge(100_000)


if __name__ == "__main__":
    main()

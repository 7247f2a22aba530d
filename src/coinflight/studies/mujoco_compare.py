"""The same tosses in a general rigid-body engine: MuJoCo beside coinflight's table landing.

MuJoCo (optional: ``pip install 'coinflight[mujoco]'``) integrates the coin as a free cylinder
over a plane with a fixed time step and its soft contact: a spring-damper in constraint space
with time constant ``timeconst`` and damping ratio ``dampratio`` (MuJoCo documentation,
"Computation", solver parameters ``solref``), a pyramidal friction cone (its default) with
sliding, torsional and rolling coefficients. coinflight flies the coin exactly between
impacts and resolves each impact with its restitution and friction
(:mod:`coinflight.core.bounce`); the bounces end in one of two ways (``Surface(ending=...)``):
the planar rocking hand-off (default) or the 3-D compliant contact phase
(:mod:`coinflight.core.contact_phase`, with rolling and pivoting resistance). What is
compared:

* the well the coin is in at its **first contact** (geometry and free flight only: the two
  engines must agree but for tosses within a time step of a boundary);
* the face **at rest** (depends on each engine's contact model: they may differ, and the
  report says why).

Settings, chosen to make the two engines' contacts as alike as MuJoCo allows:

* time step :data:`TIMESTEP` (the coin, 1.95 mm thick, moves at most ~0.5 mm a step);
* contact time constant :data:`TIMECONST` (MuJoCo's default 0.02 s lets a coin dropped flat at
  3 m/s sink 22 mm into the table; 1 ms keeps it within half a millimetre);
* damping ratio calibrated by a flat drop so that MuJoCo's normal restitution at the landing
  speed is coinflight's e (:func:`calibrated_damping`: MuJoCo's impedance makes the linear
  oscillator's ζ = −ln e / sqrt(π² + ln² e) rebound faster than e);
* sliding friction μ as coinflight's, and MuJoCo's default torsional (:data:`TORSIONAL`,
  0.005 m) and rolling (:data:`ROLLING`, 0.0001 m) friction, switched on by the contact
  dimension :data:`CONDIM` = 6. MuJoCo's default ``condim`` is 3, with which both
  coefficients are ignored (documentation, "Computation", Contact, ``condim``: 3 is "a
  regular frictional contact", 4 adds torsional friction, 6 adds rolling friction); the
  comparison of the last session ran with 3.

How MuJoCo's coefficients map onto coinflight's contact ending. In MuJoCo's friction cone
the torsional torque about the contact normal is bounded by μ_torsional f_n and each rolling
torque by μ_rolling f_n (elliptic cone: f_1² ≥ Σ f_i²/μ_(i−1)²; the pyramidal cone used here
by default bounds the same torques along its edges), both coefficients "have units of
length" ("the diameter of the surface contact patch" and "the depth of the local
deformation within which energy is dissipated"). coinflight's contact phase resists rolling
with a torque ℓ_r F_n and pivoting with (μ r_t + ℓ_p) F_n, ℓ_r, ℓ_p lengths
(:mod:`coinflight.core.contact_phase`): the same form, so ℓ_r = μ_rolling = 1e-4 m and
ℓ_p = μ_torsional = 5e-3 m (:data:`ROLLING`, :data:`TORSIONAL`). The map is one to one in
the bound only: (i) coinflight adds the Coulomb friction spread over the contact arc, μ r_t,
which MuJoCo gets from its several contact points of a cylinder on a plane; (ii) MuJoCo's
cone is pyramidal, so sliding and torsion share one budget along its edges, where
coinflight bounds them separately; (iii) MuJoCo's friction is a soft constraint that creeps
at a rate set by ``solref``, coinflight's a regularised Coulomb law (slip speed
:data:`coinflight.core.contact_phase.SLIP_SPEED`); (iv) coinflight's impacts are
instantaneous, MuJoCo's are the same soft contact, and only the last phase of coinflight's
landing has the resistances at all.

The benchmark ``benchmarks/bench_bounce.py`` and the landing report
(:mod:`coinflight.report.landing`) both call :func:`coinflight.studies.landing.mujoco_comparison`.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight import _validation as v

if TYPE_CHECKING:
    from coinflight.model.coin import Coin

TIMESTEP = 1e-4
"""MuJoCo's time step, s."""
TIMECONST = 1e-3
"""MuJoCo's contact time constant (``solref[0]``), s: at least 2 time steps (its stability
rule) and short enough for a millimetre-thin coin."""
TORSIONAL = 0.005
"""MuJoCo's default torsional friction coefficient, m (``friction="μ 0.005 0.0001"``); the
pivoting resistance ℓ_p of coinflight's contact ending in the comparison (module notes)."""
ROLLING = 0.0001
"""MuJoCo's default rolling friction coefficient, m; the rolling resistance ℓ_r of
coinflight's contact ending in the comparison (module notes)."""
CONDIM = 6
"""MuJoCo's contact dimension: 6 = normal, two sliding, torsional and two rolling directions, so
that :data:`TORSIONAL` and :data:`ROLLING` act (MuJoCo's default, 3, ignores them)."""
CONE = "pyramidal"
"""MuJoCo's friction cone (its default)."""
INTEGRATOR = "Euler"
"""MuJoCo's default integrator (semi-implicit Euler); RK4 costs four times as much per step."""
WINDOW = 0.1
"""After the first contact, the tosses are advanced in windows of this many seconds, and those
whose face can no longer change are set aside (:func:`_settled`)."""
SETTLE = 2.0
"""Longest simulated time after the first contact, s; tosses still moving then are counted
by the face they show and reported as unsettled. Long enough for the faces: on the landing
report's 500 tosses (seed 20261123, e = 0.5, μ = 0.3, condim 6), 10 s gave the same face for
every toss as 2 s; 31 of the 64 coins on edge were still moving at 10 s, the other 33 at rest
on their edge."""
REST_SPEED = 2e-3
"""A coin whose centre moves slower than this (m/s) ..."""
REST_SPIN = 0.2
"""... and turns slower than this (rad/s) is at rest."""
PROBE_SPEEDS = (0.1, 0.3, 1.0)
"""Impact speeds, m/s, at which the calibrated contact's flat-drop restitution is also reported
(MuJoCo's soft contact restitutes differently at different speeds; coinflight's impacts
restitute with e at every speed)."""
CHUNK = 64
"""Tosses per MuJoCo rollout call."""
TOSSES_PER_SECOND = 4.0
"""MuJoCo tosses a second on the busy 2-core machine (measured: 64 tosses in 14.7 s; for the
work bound)."""


def available() -> bool:
    """True when MuJoCo can be imported."""
    try:
        import mujoco  # noqa: F401
    except ImportError:
        return False
    return True


def _xml(
    coin: Coin, friction: float, dampratio: float, g: float, integrator: str, condim: int
) -> str:
    friction_text = f"{friction} {TORSIONAL} {ROLLING}"
    solref = f"{TIMECONST} {dampratio}"
    contact = f'friction="{friction_text}" solref="{solref}" condim="{condim}"'
    return f"""
    <mujoco>
      <option timestep="{TIMESTEP}" gravity="0 0 -{g}" integrator="{integrator}"
              cone="{CONE}"/>
      <worldbody>
        <geom type="plane" size="5 5 0.1" {contact}/>
        <body name="coin" pos="0 0 1">
          <freejoint/>
          <geom type="cylinder" size="{coin.radius} {coin.thickness / 2}" mass="{coin.mass}"
                {contact}/>
        </body>
      </worldbody>
    </mujoco>"""


def model(
    coin: Coin,
    friction: float,
    dampratio: float,
    g: float = 9.81,
    integrator: str = INTEGRATOR,
    condim: int = CONDIM,
) -> Any:
    """The MuJoCo model: the coin as a free cylinder over a plane (see the module notes);
    ``condim`` 1, 3, 4 or 6 (MuJoCo's contact dimensions)."""
    import mujoco

    if condim not in (1, 3, 4, 6):
        raise ValueError(f"MuJoCo condim must be 1, 3, 4 or 6, got {condim!r}")
    return mujoco.MjModel.from_xml_string(_xml(coin, friction, dampratio, g, integrator, condim))


def flat_drop_restitution(
    coin: Coin,
    speed: float,
    dampratio: float,
    g: float = 9.81,
    integrator: str = INTEGRATOR,
    condim: int = CONDIM,
) -> float:
    """MuJoCo's normal restitution: the coin dropped flat at ``speed`` (m/s), without spin;
    its largest upward speed after the impact over ``speed``."""
    import mujoco

    m = model(coin, 0.0, dampratio, g, integrator, condim)
    d = mujoco.MjData(m)
    d.qpos[:3] = (0.0, 0.0, coin.thickness / 2 + 1e-4)
    d.qvel[2] = -speed
    best = -speed
    for _ in range(int(5 * TIMECONST / TIMESTEP) + 100):
        mujoco.mj_step(m, d)
        best = max(best, float(d.qvel[2]))
    return best / speed


def calibrated_damping(
    coin: Coin, restitution: float, speed: float, g: float = 9.81, condim: int = CONDIM
) -> float:
    """The damping ratio whose flat-drop restitution (:func:`flat_drop_restitution`) at
    ``speed`` is ``restitution``; ValueError when MuJoCo's contact cannot reach it."""
    from scipy.optimize import brentq

    def excess(z: float) -> float:
        return flat_drop_restitution(coin, speed, z, g, condim=condim) - restitution

    lo, hi = 0.02, 3.0
    if not excess(lo) > 0.0 > excess(hi):
        raise ValueError(
            f"MuJoCo's contact (time constant {TIMECONST:g} s) cannot rebound at restitution "
            f"{restitution:g}: its flat drop gives {excess(hi) + restitution:.3g} to "
            f"{excess(lo) + restitution:.3g}"
        )
    return float(brentq(excess, lo, hi, xtol=1e-4))


@dataclass(frozen=True)
class MujocoRun:
    """Faces of tosses in MuJoCo, and how they were computed.

    Attributes
    ----------
    first, rest : ndarray of int8
        Face codes (TAILS 0, HEADS 1, EDGE 2) at the first contact and at rest.
    moving : ndarray of bool
        Tosses whose face could still change after :data:`SETTLE` s (most of them rolling on
        their edge; counted by the face they show then).
    dampratio, restitution : float
        The calibrated damping ratio and the flat-drop restitution it gives.
    elapsed : float
        Wall time, s.
    threads : int
    version : str
        MuJoCo's version.
    condim : int
        MuJoCo's contact dimension (:data:`CONDIM`).
    restitution_by_speed : dict
        Flat-drop restitution of the calibrated contact at :data:`PROBE_SPEEDS` and at the
        landing speed ({speed m/s: e}).
    """

    first: NDArray[np.int8]
    rest: NDArray[np.int8]
    moving: NDArray[np.bool_]
    dampratio: float
    restitution: float
    elapsed: float
    threads: int
    version: str
    condim: int = CONDIM
    restitution_by_speed: dict[float, float] = field(default_factory=dict)

    def settings(self, friction: float) -> dict[str, Any]:
        """Every setting of the run, for reports (JSON-ready)."""
        return {
            "mujoco": self.version,
            "integrator": INTEGRATOR,
            "timestep": TIMESTEP,
            "solref": [TIMECONST, self.dampratio],
            "flat_drop_restitution": self.restitution,
            "friction": [friction, TORSIONAL, ROLLING],
            "condim": self.condim,
            "flat_drop_restitution_by_speed": [
                [speed, e] for speed, e in sorted(self.restitution_by_speed.items())
            ],
            "cone": CONE,
            "settle_limit": SETTLE,
            "rest_speed": REST_SPEED,
            "rest_spin": REST_SPIN,
            "threads": self.threads,
        }


def _settled(
    states: NDArray[np.float64], coin: Coin, g: float, edge_sine: float
) -> NDArray[np.bool_]:
    """Tosses whose face can no longer change: at rest (:data:`REST_SPEED`, :data:`REST_SPIN`),
    or in a face's well with less total energy than the coin balanced on its corner, m g ρ
    (energy never grows: it can no longer reach the corner; Vulović & Prange 1986)."""
    i1, i3 = coin.moments
    v_lin = states[:, 8:11]
    w_body = states[:, 11:14]  # a free joint's angular velocity is in the body frame
    speed = np.linalg.norm(v_lin, axis=1)
    spin = np.linalg.norm(w_body, axis=1)
    energy = (
        0.5 * coin.mass * speed**2
        + 0.5 * (i1 * (w_body[:, 0] ** 2 + w_body[:, 1] ** 2) + i3 * w_body[:, 2] ** 2)
        + coin.mass * g * states[:, 3]
    )
    q = states[:, 4:8]
    nz = 1.0 - 2.0 * (q[:, 1] ** 2 + q[:, 2] ** 2)
    reach = math.hypot(coin.radius, coin.thickness / 2)
    trapped = (energy < coin.mass * g * reach) & (np.abs(nz) > edge_sine)
    return trapped | ((speed < REST_SPEED) & (spin < REST_SPIN))


def run(
    coin: Coin,
    omega: NDArray[np.float64],
    launch_speed: NDArray[np.float64],
    drop_height: float,
    restitution: float,
    friction: float,
    g: float = 9.81,
    threads: int | None = None,
    condim: int = CONDIM,
) -> MujocoRun:
    """The tosses (ω (n, 3) body frame rad/s, v0 (n,) m/s, heads up, launched ``drop_height``
    above the plane) in MuJoCo, multithreaded rollouts; see the module notes for the settings.

    ImportError when MuJoCo is not installed.
    """
    import mujoco
    from mujoco import rollout

    from coinflight.core.impact import resting_face

    t0 = time.perf_counter()
    omega = np.asarray(omega, dtype=float).reshape(-1, 3)
    v0 = np.asarray(launch_speed, dtype=float).reshape(-1)
    n = len(v0)
    v.work_bound(
        f"{n} MuJoCo tosses",
        n,
        TOSSES_PER_SECOND * v.MAX_RUN_SECONDS,
        "tosses",
        "use fewer tosses",
        TOSSES_PER_SECOND,
    )
    landing_speed = math.sqrt(float(np.mean(v0)) ** 2 + 2.0 * g * drop_height)
    zeta = (
        calibrated_damping(coin, restitution, landing_speed, g, condim) if restitution > 0 else 1.0
    )
    e_mujoco = flat_drop_restitution(coin, landing_speed, zeta, g, condim=condim)
    by_speed = {
        speed: flat_drop_restitution(coin, speed, zeta, g, condim=condim) for speed in PROBE_SPEEDS
    }
    by_speed[landing_speed] = e_mujoco
    m = model(coin, friction, zeta, g, condim=condim)
    workers = threads or os.cpu_count() or 1
    datas = [mujoco.MjData(m) for _ in range(workers)]
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    size = mujoco.mj_stateSize(m, spec)
    r, hh = coin.radius, coin.thickness / 2
    edge_sine = hh / math.hypot(r, hh)
    dt = m.opt.timestep
    first = np.empty(n, dtype=np.int8)
    rest = np.empty(n, dtype=np.int8)
    still = np.zeros(n, dtype=bool)
    data = datas[0]
    for a in range(0, n, CHUNK):
        idx = np.arange(a, min(a + CHUNK, n))
        states = np.empty((len(idx), size))
        for j, k in enumerate(idx):
            mujoco.mj_resetData(m, data)
            data.qpos[:3] = (0.0, 0.0, drop_height)
            data.qpos[3:7] = (1.0, 0.0, 0.0, 0.0)  # heads up (scalar first)
            data.qvel[:3] = (0.0, 0.0, v0[k])
            data.qvel[3:6] = omega[k]  # free joint: angular velocity in the body frame
            mujoco.mj_getState(m, data, states[j], spec)
        # The fall: from launch to a little after the latest first contact.
        vmax = float(v0[idx].max())
        fall = vmax / g + math.sqrt(2.0 * (drop_height + vmax * vmax / (2.0 * g)) / g) + 0.05
        traj, _ = rollout.rollout(m, datas, states, nstep=int(fall / dt))
        nz = 1.0 - 2.0 * (traj[:, :, 5] ** 2 + traj[:, :, 6] ** 2)  # R(q)[2, 2]
        gap = traj[:, :, 3] - r * np.sqrt(np.clip(1.0 - nz * nz, 0.0, 1.0)) - hh * np.abs(nz)
        for j, k in enumerate(idx):
            apex = int(v0[k] / g / dt)
            hit = apex + int(np.argmax(gap[j, apex:] <= 0.0))
            first[k] = resting_face(float(nz[j, hit]), edge_sine)
        states = np.ascontiguousarray(traj[:, -1, :])
        moving = np.arange(len(idx))
        for _ in range(math.ceil(SETTLE / WINDOW)):
            traj, _ = rollout.rollout(m, datas, states[moving], nstep=int(WINDOW / dt))
            states[moving] = traj[:, -1, :]
            moving = moving[~_settled(states[moving], coin, g, edge_sine)]
            if not len(moving):
                break
        still[idx[moving]] = True
        q = states[:, 4:8]
        nz_end = 1.0 - 2.0 * (q[:, 1] ** 2 + q[:, 2] ** 2)
        for j, k in enumerate(idx):
            rest[k] = resting_face(float(nz_end[j]), edge_sine)
    return MujocoRun(
        first,
        rest,
        still,
        zeta,
        e_mujoco,
        time.perf_counter() - t0,
        workers,
        mujoco.__version__,
        condim,
        by_speed,
    )


__all__ = [
    "CONDIM",
    "CONE",
    "INTEGRATOR",
    "ROLLING",
    "TIMECONST",
    "TIMESTEP",
    "TORSIONAL",
    "MujocoRun",
    "available",
    "calibrated_damping",
    "flat_drop_restitution",
    "model",
    "run",
]

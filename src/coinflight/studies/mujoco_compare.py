"""The same tosses in a general rigid-body engine: MuJoCo beside coinflight's table landing.

MuJoCo (optional: ``pip install 'coinflight[mujoco]'``) integrates the coin as a free cylinder
over a plane with a fixed time step and its soft contact: a spring-damper in constraint space
with time constant ``timeconst`` and damping ratio ``dampratio`` (MuJoCo documentation,
"Computation", solver parameters ``solref``), a pyramidal friction cone (its default) with
sliding, torsional and rolling coefficients. coinflight flies the coin exactly between
impacts and resolves each impact with its restitution and friction
(:mod:`coinflight.core.bounce`); when the bounces die out, the rigid 3-D phase carries it to
rest (:mod:`coinflight.core.rigid_ending`, with rolling and pivoting resistance). What is
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
  regular frictional contact", 4 adds torsional friction, 6 adds rolling friction).

How MuJoCo's coefficients map onto coinflight's landing. In MuJoCo's friction cone
the torsional torque about the contact normal is bounded by μ_torsional f_n and each rolling
torque by μ_rolling f_n (elliptic cone: f_1² ≥ Σ f_i²/μ_(i−1)²; the pyramidal cone used here
by default bounds the same torques along its edges), both coefficients "have units of
length" ("the diameter of the surface contact patch" and "the depth of the local
deformation within which energy is dissipated"). coinflight's landing resists rolling
with a torque ℓ_r F_n and pivoting with ℓ_p F_n at its point contact, ℓ_r, ℓ_p lengths
(:mod:`coinflight.core.rigid_contact`): the same form, so ℓ_r = μ_rolling = 1e-4 m and
ℓ_p = μ_torsional = 5e-3 m (:data:`ROLLING`, :data:`TORSIONAL`). The map is one to one in
the bound only: (i) MuJoCo's cone is pyramidal, so sliding and torsion share one budget
along its edges, where coinflight bounds them separately; (ii) MuJoCo's friction is a soft
constraint that creeps at a rate set by ``solref``, coinflight's is Coulomb's set-valued law
(its resistances regularised below :data:`coinflight.core.flight.SLIP_SPEED`); (iii)
coinflight's impacts are instantaneous, MuJoCo's are the same soft contact, and only the
last phase of coinflight's landing has the resistances at all.

Carried to rest. Each toss runs until its face can no longer change (:func:`_settled`: at rest
now and :data:`REST_CHECK` s before, or in a face's well with less energy than the corner),
checked at the end of every :data:`WINDOW`, or until :data:`SETTLE` s past its first contact;
up to :data:`POOL` tosses share MuJoCo's threaded rollouts and a settled toss leaves the pool at
once, so the cost is the steps each toss needs (a coin rolling on its rim for seconds costs
seconds, a coin that lands flat a window). Tosses still moving at the limit are counted
(:attr:`MujocoRun.moving`) and reported, never dropped. :attr:`MujocoRun.rest_time` and
:attr:`MujocoRun.edge_time` say how long each toss took to settle and how long it stood on its
rim. The work is bounded before anything runs (:func:`seconds_estimate`).

Harder friction. MuJoCo's friction is a soft constraint (it creeps below its limit and builds
up over the contact's time constant); :class:`FrictionSolver` selects MuJoCo's documented ways
to make it harder than the normal direction without changing μ: the elliptic cone with
``impratio`` > 1, and the no-slip pass (``noslip_iterations``).

Integrator. MuJoCo's default semi-implicit Euler drifts in a precessing flight, RK4 does not
(at several times Euler's cost a step): the landing report's comparison has no axial spin and
keeps Euler; tosses that precess should run RK4 (``Engine(integrator="RK4")``).

What the comparison found, and why the two engines part on edges, is in the documentation
(:ref:`physics-mujoco`); the landing report
(:mod:`coinflight.report.landing`) computes it through
:func:`coinflight.studies.landing.mujoco_comparison` and
:func:`coinflight.studies.edge_experiments.mujoco_check`.
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
    from collections.abc import Callable

    from coinflight.model.coin import Coin

TIMESTEP = 1e-4
"""MuJoCo's time step, s."""
TIMECONST = 1e-3
"""MuJoCo's contact time constant (``solref[0]``), s: at least 2 time steps (its stability
rule) and short enough for a millimetre-thin coin."""
TORSIONAL = 0.005
"""MuJoCo's default torsional friction coefficient, m (``friction="μ 0.005 0.0001"``); the
pivoting resistance ℓ_p coinflight's landing is given when compared (module notes)."""
ROLLING = 0.0001
"""MuJoCo's default rolling friction coefficient, m; the rolling resistance ℓ_r of
coinflight's landing when compared (module notes)."""
CONDIM = 6
"""MuJoCo's contact dimension: 6 = normal, two sliding, torsional and two rolling directions, so
that :data:`TORSIONAL` and :data:`ROLLING` act (MuJoCo's default, 3, ignores them)."""
CONE = "pyramidal"
"""MuJoCo's friction cone (its default)."""
INTEGRATOR = "Euler"
"""MuJoCo's default integrator (semi-implicit Euler); RK4 costs four times as much per step."""
WINDOW = 0.1
"""The tosses are advanced in windows of this many seconds; at the end of each, those whose face
can no longer change leave the run (:func:`_settled`), so each toss costs the steps it needs."""
SETTLE = 20.0
"""Longest simulated time after the first contact, s; tosses still moving then are counted by
the face they show and reported as moving (:attr:`MujocoRun.moving`), never dropped. Coins
rolling on the sharp rim roll for seconds: a limit of a few seconds leaves many of them
moving."""
REST_SPEED = 2e-3
"""A coin whose centre moves slower than this (m/s) ..."""
REST_SPIN = 0.2
"""... and turns slower than this (rad/s) is at rest ..."""
REST_CHECK = 0.01
"""... at the end of a window and this many seconds before it (a coin at the turning point of a
rock is not at rest: falling from its edge, it turns faster than :data:`REST_SPIN` within
10 ms)."""
PROBE_SPEEDS = (0.1, 0.3, 1.0)
"""Impact speeds, m/s, at which the calibrated contact's flat-drop restitution is also reported
(MuJoCo's soft contact restitutes differently at different speeds; coinflight's impacts
restitute with e at every speed)."""
POOL = 128
"""Tosses rolled out together (MuJoCo's threads share them); a toss that settles leaves the pool
and the next one takes its place."""
STEPS_PER_SECOND = 2.0e5
"""MuJoCo steps of one coin a wall second, both threads of the reference 2-core machine,
Euler (for the work bound; slower integrators by :data:`INTEGRATOR_COST`)."""
MEAN_CONTACT = 1.0
"""Mean simulated time after the first contact of a toss that settles, s (for the work bound:
the report's and the edge check's tosses take one to three seconds, more at higher
friction)."""
MOVING_SHARE = 0.1
"""Share of the limit added to :data:`MEAN_CONTACT` for the tosses that roll long (for the work
bound): 3 s expected after the first contact at the 20 s limit."""
FLIGHT = 0.7
"""Longest flight of the compared tosses, launch to first contact, s (v0 ≤ 3 m/s, 0.8 m drop;
for the work bound)."""


CONES = ("pyramidal", "elliptic")
"""MuJoCo's friction cones (``option/cone``)."""
MAX_NOSLIP_ITERATIONS = 100
"""Most no-slip iterations accepted (MuJoCo's default 0: no no-slip pass). A few tens already
make MuJoCo's friction hard and double a run's cost (:data:`NOSLIP_COST`); 100 would cost
about 5.5 times, more is work without a question it answers."""
IMPRATIO_COST = 1.2
"""Extra cost of a MuJoCo step per decade of ``impratio`` above 10 (for the work bound; a
stiffer friction needs more solver iterations: the elliptic cone at impratio 10 runs about as
fast as the default friction, at 100 about twice as slow)."""
NOSLIP_COST = 0.045
"""Extra cost of a MuJoCo step per no-slip iteration (for the work bound; each is one more
sweep over the friction dimensions: 20 iterations about double a run's cost)."""


SOLIMP = (0.9, 0.95, 0.001)
"""MuJoCo's default ``solimp`` (d0, dmax, width in m; midpoint 0.5 and power 2 not set here)."""
MIN_IMPEDANCE = 1e-4
"""Smallest impedance MuJoCo takes (its mjMINIMP; smaller values are clamped to it)."""
MAX_IMPEDANCE = 0.9999
"""Largest impedance MuJoCo takes (its mjMAXIMP)."""


def _checked_solimp(solimp: Any) -> tuple[float, float, float]:
    """(d0, dmax, width) as plain floats; ValueError in one line unless three numbers with d0
    and dmax within [MIN_IMPEDANCE, MAX_IMPEDANCE] and width positive and finite (the one
    wording, in :mod:`coinflight._validation`'s words for a range and a positive number: a
    bool inside a tuple is refused, which :func:`~coinflight._validation.as_float_array` would
    take as a number)."""
    words = (
        f"MuJoCo solimp must be three numbers: d0 and dmax between {MIN_IMPEDANCE:g} and "
        f"{MAX_IMPEDANCE:g}, width positive and finite (in m), got {solimp!r}"
    )
    try:
        values = tuple(solimp)
    except TypeError:
        raise ValueError(words) from None
    if len(values) != 3 or not all(
        isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)
        for x in values
    ):
        raise ValueError(words)
    d0, dmax, width = (float(x) for x in values)
    if not (
        MIN_IMPEDANCE <= d0 <= MAX_IMPEDANCE
        and MIN_IMPEDANCE <= dmax <= MAX_IMPEDANCE
        and math.isfinite(width)
        and width > 0.0
    ):
        raise ValueError(words)
    return d0, dmax, width


@dataclass(frozen=True)
class FrictionSolver:
    """How hard MuJoCo makes its friction: the cone, ``impratio`` and the no-slip pass.

    MuJoCo's friction is a soft constraint like its normal force: within the cone it is a
    spring-damper in constraint space that lets a contact creep, and in a short impact it
    builds up over the contact's time constant rather than at once. Its documented ways to
    make friction harder than the normal direction, without changing μ (MuJoCo 3.17,
    ``mjOption`` in ``mjmodel.h``; documentation, XML reference, ``option``):

    * ``impratio``, "the ratio of frictional-to-normal constraint impedance": the friction
      dimensions' impedance is the normal's times it, so friction is stiffer (less slip in a
      contact that should stick) for values above 1. Documented for the **elliptic** cone; with
      the pyramidal cone its edges mix the normal and frictional directions and MuJoCo advises
      against large values.
    * ``noslip_iterations``: a post-processing pass after the main solver (a projected
      Gauss-Seidel on the friction dimensions only, with the normal forces fixed) that removes
      the slip the soft-constraint model lets through; 0 (default) switches it off.

    It also carries the contact's time constant (``solref[0]``) and impedance ``solimp`` (of
    the normal direction as of the friction's), which the calibration of the damping sees as it
    sees the rest: how long MuJoCo's contact lasts, and how soft it is at first touch. MuJoCo
    solves its constraint so that the contact's acceleration is a_1 = (1 − d) a_0 − d (b v +
    k r) (a_0 the unconstrained acceleration, b and k from ``solref``; documentation,
    "Computation", Solver parameters), the impedance d(r) rising from d0 at zero penetration r
    to dmax at r = ``width``: a low d0 makes the first touch soft (a weak spring and damper, and
    a share 1 − d of the unconstrained acceleration let through), much as coinflight's rim law,
    whose stiffness grows from zero as the rim sinks (F ∝ d^(3/2)).

    Attributes
    ----------
    cone : str
        ``"pyramidal"`` (MuJoCo's default, :data:`CONE`) or ``"elliptic"``.
    impratio : float
        Ratio of frictional-to-normal impedance, > 0 (MuJoCo's default 1).
    noslip_iterations : int
        No-slip iterations, 0 to :data:`MAX_NOSLIP_ITERATIONS` (MuJoCo's default 0).
    solimp : tuple of 3 floats
        (d0, dmax, width) of both geoms' ``solimp``: impedances within
        [:data:`MIN_IMPEDANCE`, :data:`MAX_IMPEDANCE`] (MuJoCo's clamp) and a width > 0, m
        (MuJoCo's default :data:`SOLIMP`; its midpoint 0.5 and power 2 kept).
    timeconst : float
        The contact's time constant ``solref[0]``, s: at least 2 :data:`TIMESTEP` (MuJoCo's
        stability rule) and at most 0.1 s (default :data:`TIMECONST`).
    """

    cone: str = CONE
    impratio: float = 1.0
    noslip_iterations: int = 0
    solimp: tuple[float, float, float] = SOLIMP
    timeconst: float = TIMECONST

    def __post_init__(self) -> None:
        v.choice("MuJoCo cone", self.cone, CONES)
        ratio = self.impratio
        if not (
            isinstance(ratio, (int, float))
            and not isinstance(ratio, bool)
            and math.isfinite(ratio)
            and ratio > 0.0
        ):
            raise ValueError(f"MuJoCo impratio must be a positive number, got {ratio!r}")
        iterations = v.count(
            "MuJoCo noslip_iterations", self.noslip_iterations, 0, MAX_NOSLIP_ITERATIONS
        )
        # Plain Python numbers: NumPy's would reach MuJoCo's XML as "np.float64(10.0)".
        object.__setattr__(self, "impratio", float(ratio))
        object.__setattr__(self, "noslip_iterations", iterations)
        object.__setattr__(self, "solimp", _checked_solimp(self.solimp))
        name = "MuJoCo timeconst"
        tau = v.number(name, v.in_range(name, self.timeconst, 2.0 * TIMESTEP, 0.1, "s"), "s")
        object.__setattr__(self, "timeconst", tau)

    def option(self) -> str:
        """The attributes of MuJoCo's ``<option>`` element for these settings."""
        return (
            f'cone="{self.cone}" impratio="{self.impratio!r}" '
            f'noslip_iterations="{self.noslip_iterations}"'
        )

    def contact(self) -> str:
        """The ``solimp`` attribute of both geoms for these settings."""
        return 'solimp="{!r} {!r} {!r}"'.format(*self.solimp)

    def settings(self) -> dict[str, Any]:
        """JSON-ready: cone, impratio, noslip_iterations, solimp, timeconst."""
        return {
            "cone": self.cone,
            "impratio": self.impratio,
            "noslip_iterations": self.noslip_iterations,
            "solimp": list(self.solimp),
            "timeconst": self.timeconst,
        }

    def cost(self) -> float:
        """Cost of a MuJoCo step with these settings over one with MuJoCo's defaults (for the
        work bound): (1 + :data:`IMPRATIO_COST` max(0, log10(impratio / 10))) (1 +
        :data:`NOSLIP_COST` noslip_iterations); the cone alone costs nothing measurable."""
        stiffer = 1.0 + IMPRATIO_COST * max(0.0, math.log10(self.impratio / 10.0))
        return stiffer * (1.0 + NOSLIP_COST * self.noslip_iterations)


DEFAULT_SOLVER = FrictionSolver()
"""MuJoCo's defaults: pyramidal cone, impratio 1, no no-slip pass, ``solimp`` 0.9 0.95 0.001
(the comparison's settings)."""


def check_limit(limit: float) -> None:
    """ValueError unless ``limit`` (the settle limit, s) is a positive finite number."""
    if not (isinstance(limit, (int, float)) and math.isfinite(limit) and limit > 0.0):
        raise ValueError(f"the MuJoCo settle limit must be a positive number of s, got {limit!r}")


CONDIMS = (1, 3, 4, 6)
"""MuJoCo's contact dimensions: normal only; + two sliding; + torsional; + two rolling."""


@dataclass(frozen=True)
class Engine:
    """How MuJoCo computes a run, beyond the surface's restitution and friction (checked on
    construction; ValueError/TypeError in one line).

    Attributes
    ----------
    condim : int
        MuJoCo's contact dimension, one of :data:`CONDIMS` (default :data:`CONDIM`).
    torsional, rolling : float
        MuJoCo's torsional and rolling friction coefficients of both geoms, m (MuJoCo takes the
        larger of the two geoms'; defaults :data:`TORSIONAL`, :data:`ROLLING`).
    integrator : str
        MuJoCo's integrator (default :data:`INTEGRATOR`).
    solver : FrictionSolver
        The friction cone, impratio, no-slip pass and contact impedance.
    limit : float
        Longest simulated time after the first contact, s (default :data:`SETTLE`).
    """

    condim: int = CONDIM
    torsional: float = TORSIONAL
    rolling: float = ROLLING
    integrator: str = INTEGRATOR
    solver: FrictionSolver = DEFAULT_SOLVER
    limit: float = SETTLE

    def __post_init__(self) -> None:
        if self.condim not in CONDIMS:
            raise ValueError(f"MuJoCo condim must be 1, 3, 4 or 6, got {self.condim!r}")
        v.instance("solver", self.solver, FrictionSolver, "a mujoco_compare.FrictionSolver")
        check_limit(self.limit)


DEFAULT_ENGINE = Engine()
"""The comparison's settings: :data:`CONDIM`, MuJoCo's default torsional and rolling friction,
its default integrator and friction solver, carried up to :data:`SETTLE` s."""


def available() -> bool:
    """True when MuJoCo can be imported."""
    try:
        import mujoco  # noqa: F401
    except ImportError:
        return False
    return True


def _xml(coin: Coin, friction: float, dampratio: float, g: float, engine: Engine) -> str:
    solver = engine.solver
    friction_text = f"{friction} {engine.torsional} {engine.rolling}"
    solref = f"{solver.timeconst!r} {dampratio}"
    contact = (
        f'friction="{friction_text}" solref="{solref}" condim="{engine.condim}" {solver.contact()}'
    )
    return f"""
    <mujoco>
      <option timestep="{TIMESTEP}" gravity="0 0 -{g}" integrator="{engine.integrator}"
              {solver.option()}/>
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
    coin: Coin, friction: float, dampratio: float, g: float = 9.81, engine: Engine = DEFAULT_ENGINE
) -> Any:
    """The MuJoCo model: the coin as a free cylinder over a plane (see the module notes), with
    sliding friction ``friction``, the contact's damping ratio ``dampratio`` and ``engine``'s
    contact dimension, torsional and rolling friction, integrator and friction solver."""
    import mujoco

    v.instance("engine", engine, Engine, "a mujoco_compare.Engine")
    return mujoco.MjModel.from_xml_string(_xml(coin, friction, dampratio, g, engine))


def flat_drop_restitution(
    coin: Coin,
    speed: float,
    dampratio: float,
    g: float = 9.81,
    engine: Engine = DEFAULT_ENGINE,
) -> float:
    """MuJoCo's normal restitution: the coin dropped flat at ``speed`` (m/s), without spin;
    its largest upward speed after the impact over ``speed`` (with ``engine``'s integrator,
    contact dimension, friction cone and impedances, so that the calibration is that of the
    compared model)."""
    import mujoco

    m = model(coin, 0.0, dampratio, g, engine)
    d = mujoco.MjData(m)
    d.qpos[:3] = (0.0, 0.0, coin.thickness / 2 + 1e-4)
    d.qvel[2] = -speed
    best = -speed
    for _ in range(int(5 * engine.solver.timeconst / TIMESTEP) + 100):
        mujoco.mj_step(m, d)
        best = max(best, float(d.qvel[2]))
    return best / speed


def calibrated_damping(
    coin: Coin,
    restitution: float,
    speed: float,
    g: float = 9.81,
    engine: Engine = DEFAULT_ENGINE,
) -> float:
    """The damping ratio whose flat-drop restitution (:func:`flat_drop_restitution`, with
    ``engine``) at ``speed`` is ``restitution``; ValueError when MuJoCo's contact cannot reach
    it."""
    from scipy.optimize import brentq

    def excess(z: float) -> float:
        return flat_drop_restitution(coin, speed, z, g, engine) - restitution

    lo, hi = 0.02, 3.0
    if not excess(lo) > 0.0 > excess(hi):
        raise ValueError(
            f"MuJoCo's contact (time constant {engine.solver.timeconst:g} s) cannot rebound at "
            f"restitution {restitution:g}: its flat drop gives {excess(hi) + restitution:.3g} to "
            f"{excess(lo) + restitution:.3g}"
        )
    return float(brentq(excess, lo, hi, xtol=1e-4))


@dataclass(frozen=True)
class MujocoRun:
    """Faces of tosses in MuJoCo, and how they were computed.

    Attributes
    ----------
    first, rest : ndarray of int8
        Face codes (TAILS 0, HEADS 1, EDGE 2) at the first contact and at the end: at rest (or
        trapped in a face's well, :func:`_settled`), or, for the ``moving`` tosses, the well
        they were in at the limit.
    moving : ndarray of bool
        Tosses still able to change face ``limit`` s after their first contact (most of them
        rolling on their edge); never dropped: counted, and reported beside the settled ones.
    rest_time : ndarray
        Simulated time from the first contact to the end of each toss, s: to the end of the
        :data:`WINDOW` in which it was found settled (so to within a window), or ``limit`` for
        the moving ones.
    dampratio, restitution : float
        The calibrated damping ratio and the flat-drop restitution it gives.
    elapsed : float
        Wall time, s.
    threads : int
    version : str
        MuJoCo's version.
    engine : Engine
        MuJoCo's contact dimension, torsional and rolling friction, integrator, friction solver
        and the settle limit (:attr:`limit`).
    restitution_by_speed : dict
        Flat-drop restitution of the calibrated contact at :data:`PROBE_SPEEDS` and at the
        landing speed ({speed m/s: e}).
    steps : int
        MuJoCo steps taken in all (the cost: each toss stops at the window in which it settled).
    edge_time : ndarray
        Simulated time after the first contact spent in the edge band (the heads normal within
        arctan(h/d) of the horizontal: upright on the rim, rolling or standing), s.
    """

    first: NDArray[np.int8]
    rest: NDArray[np.int8]
    moving: NDArray[np.bool_]
    dampratio: float
    restitution: float
    elapsed: float
    threads: int
    version: str
    engine: Engine = DEFAULT_ENGINE
    restitution_by_speed: dict[float, float] = field(default_factory=dict)
    rest_time: NDArray[np.float64] = field(default_factory=lambda: np.empty(0))
    steps: int = 0
    edge_time: NDArray[np.float64] = field(default_factory=lambda: np.empty(0))

    @property
    def limit(self) -> float:
        """Longest simulated time after the first contact, s (the engine's)."""
        return self.engine.limit

    @property
    def unsettled(self) -> int:
        """Tosses still moving at the limit."""
        return int(np.count_nonzero(self.moving))

    def settings(self, friction: float) -> dict[str, Any]:
        """Every setting of the run, for reports (JSON-ready)."""
        engine = self.engine
        return {
            "mujoco": self.version,
            "integrator": engine.integrator,
            "timestep": TIMESTEP,
            "solref": [engine.solver.timeconst, self.dampratio],
            "flat_drop_restitution": self.restitution,
            "friction": [friction, engine.torsional, engine.rolling],
            "condim": engine.condim,
            "flat_drop_restitution_by_speed": [
                [speed, e] for speed, e in sorted(self.restitution_by_speed.items())
            ],
            **engine.solver.settings(),
            "settle_limit": engine.limit,
            "settle_window": WINDOW,
            "rest_speed": REST_SPEED,
            "rest_spin": REST_SPIN,
            "threads": self.threads,
            "steps": self.steps,
        }


def _energy(states: NDArray[np.float64], coin: Coin, g: float) -> NDArray[np.float64]:
    """Mechanical energy (kinetic + m g z) of MuJoCo states (mjSTATE_FULLPHYSICS rows), J."""
    i1, i3 = coin.moments
    v_lin = states[..., 8:11]
    w_body = states[..., 11:14]  # a free joint's angular velocity is in the body frame
    return (
        0.5 * coin.mass * np.sum(v_lin**2, axis=-1)
        + 0.5 * (i1 * (w_body[..., 0] ** 2 + w_body[..., 1] ** 2) + i3 * w_body[..., 2] ** 2)
        + coin.mass * g * states[..., 3]
    )


def _at_rest(states: NDArray[np.float64]) -> NDArray[np.bool_]:
    speed = np.linalg.norm(states[..., 8:11], axis=-1)
    spin = np.linalg.norm(states[..., 11:14], axis=-1)
    return (speed < REST_SPEED) & (spin < REST_SPIN)


def _normal_z(states: NDArray[np.float64]) -> NDArray[np.float64]:
    """n_z of the heads normal: R(q)[2, 2] of the free joint's quaternion (scalar first)."""
    return 1.0 - 2.0 * (states[..., 5] ** 2 + states[..., 6] ** 2)


def _settled(
    states: NDArray[np.float64],
    coin: Coin,
    g: float,
    edge_sine: float,
    before: NDArray[np.float64] | None = None,
) -> NDArray[np.bool_]:
    """Tosses whose face can no longer change: at rest (:data:`REST_SPEED`, :data:`REST_SPIN`;
    with ``before``, the states :data:`REST_CHECK` s earlier, at rest then too, so that a coin
    at the turning point of a rock is not taken for one at rest), or in a face's well with less
    total energy than the coin balanced on its corner, m g ρ (energy never grows: it can no
    longer reach the corner; Vulović & Prange 1986)."""
    reach = math.hypot(coin.radius, coin.thickness / 2)
    energy = _energy(states, coin, g)
    trapped = (energy < coin.mass * g * reach) & (np.abs(_normal_z(states)) > edge_sine)
    rest = _at_rest(states)
    if before is not None:
        rest &= _at_rest(before)
    return trapped | rest


def _contact_gap(states: NDArray[np.float64], coin: Coin) -> NDArray[np.float64]:
    """Height of the sharp cylinder's lowest point above the plane, m."""
    nz = _normal_z(states)
    r, hh = coin.radius, coin.thickness / 2
    return states[..., 3] - r * np.sqrt(np.clip(1.0 - nz * nz, 0.0, 1.0)) - hh * np.abs(nz)


INTEGRATOR_COST = {"Euler": 1.0, "implicitfast": 1.2, "implicit": 1.5, "RK4": 4.0}
"""Cost of a step with each of MuJoCo's integrators over Euler's (for the work bound; RK4
evaluates the dynamics four times)."""


def seconds_estimate(
    n: int,
    limit: float,
    integrator: str = INTEGRATOR,
    flight: float = FLIGHT,
    solver: FrictionSolver = DEFAULT_SOLVER,
) -> float:
    """Expected wall seconds of ``n`` MuJoCo tosses carried up to ``limit`` s past their first
    contact: ``n`` (``flight`` + the expected simulated time after the first contact,
    min(``limit``, :data:`MEAN_CONTACT` + :data:`MOVING_SHARE` ``limit``)) in steps of
    :data:`TIMESTEP` at :data:`STEPS_PER_SECOND` / :data:`INTEGRATOR_COST`, times the friction
    solver's cost (:meth:`FrictionSolver.cost`). An estimate, not a worst case (every toss
    rolling to the limit would cost ``limit`` / (:data:`MEAN_CONTACT` + :data:`MOVING_SHARE`
    ``limit``) times more)."""
    simulated = flight + min(limit, MEAN_CONTACT + MOVING_SHARE * limit)
    rate = STEPS_PER_SECOND / INTEGRATOR_COST.get(integrator, 4.0)
    return n * simulated / TIMESTEP / rate * solver.cost()


def bound(
    runs: list[int],
    limit: float,
    integrator: str = INTEGRATOR,
    solver: FrictionSolver = DEFAULT_SOLVER,
) -> None:
    """The work bound of MuJoCo runs of ``runs`` tosses each (:func:`seconds_estimate`, with
    ``solver``'s cost), before anything is allocated or computed."""
    seconds = sum(seconds_estimate(n, limit, integrator, solver=solver) for n in runs)
    v.work_bound(
        f"{v.quantity(sum(runs))} MuJoCo tosses carried up to {limit:g} s past their first contact",
        seconds,
        v.MAX_RUN_SECONDS,
        "s",
        "use fewer tosses or a shorter settle limit",
    )


@dataclass
class _Carried:
    first: NDArray[np.int8]
    rest: NDArray[np.int8]
    moving: NDArray[np.bool_]
    rest_time: NDArray[np.float64]
    edge_time: NDArray[np.float64]
    steps: int


def _carry(
    m: Any,
    datas: list[Any],
    initial: NDArray[np.float64],
    apex: NDArray[np.float64],
    coin: Coin,
    g: float,
    limit: float,
    flight_limit: float,
    pool: int = POOL,
) -> _Carried:
    """Each toss from ``initial`` until it has settled (:func:`_settled`, checked at the end of
    every :data:`WINDOW`) or ``limit`` s after its first contact (the first step after
    ``apex`` s at which the sharp cylinder touches the plane; a toss not down by
    ``flight_limit`` s counts as moving). Up to ``pool`` tosses are rolled out together in
    MuJoCo's threads; a settled toss leaves the pool at once and the next one takes its place,
    so the cost is the steps each toss needs."""
    from mujoco import rollout

    from coinflight.core.impact import resting_face

    n = len(initial)
    dt = float(m.opt.timestep)
    r, hh = coin.radius, coin.thickness / 2
    edge_sine = hh / math.hypot(r, hh)
    window = round(WINDOW / dt)
    check = round(REST_CHECK / dt)
    first = np.full(n, -1, dtype=np.int8)
    rest = np.full(n, -1, dtype=np.int8)
    moving = np.zeros(n, dtype=bool)
    rest_time = np.full(n, np.nan)
    edge_time = np.zeros(n)
    steps = 0
    queue = 0
    active = np.empty(0, dtype=np.int64)
    states = np.empty((0, initial.shape[1]))
    clock = np.empty(0)  # simulated time since the start of each active toss
    touched = np.empty(0)  # its first contact (nan before)
    while queue < n or len(active):
        if len(active) < pool and queue < n:
            new = np.arange(queue, min(n, queue + pool - len(active)))
            queue = int(new[-1]) + 1
            active = np.concatenate([active, new])
            states = np.concatenate([states, initial[new]])
            clock = np.concatenate([clock, np.zeros(len(new))])
            touched = np.concatenate([touched, np.full(len(new), np.nan)])
        traj, _ = rollout.rollout(m, datas, states, nstep=window)
        steps += len(active) * window
        times = clock[:, None] + dt * np.arange(1, window + 1)
        falling = np.flatnonzero(np.isnan(touched))
        if len(falling):
            sub = traj[falling]
            hit = (_contact_gap(sub, coin) <= 0.0) & (times[falling] > apex[active[falling], None])
            down = hit.any(axis=1)
            j = np.argmax(hit, axis=1)
            for f in np.flatnonzero(down):
                k = falling[f]
                touched[k] = times[k, j[f]]
                first[active[k]] = resting_face(float(_normal_z(sub[f, j[f]])), edge_sine)
        upright = (np.abs(_normal_z(traj)) < edge_sine) & (times > touched[:, None])
        edge_time[active] += dt * np.count_nonzero(upright, axis=1)
        states = np.ascontiguousarray(traj[:, -1, :])
        clock = clock + window * dt
        after = clock - touched  # nan before the first contact
        done = np.zeros(len(active), dtype=bool)
        landed = ~np.isnan(touched)
        settled = landed & _settled(states, coin, g, edge_sine, traj[:, -1 - check, :])
        late = landed & ~settled & (after >= limit - 0.5 * dt)
        lost = ~landed & (clock >= flight_limit)
        done = settled | late | lost
        for k in np.flatnonzero(done):
            toss = active[k]
            rest[toss] = resting_face(float(_normal_z(states[k])), edge_sine)
            moving[toss] = not settled[k]
            rest_time[toss] = after[k] if landed[k] else np.nan
            if not landed[k]:
                first[toss] = rest[toss]
        keep = ~done
        active, states, clock, touched = active[keep], states[keep], clock[keep], touched[keep]
    return _Carried(first, rest, moving, rest_time, edge_time, steps)


def _calibrated(
    coin: Coin, restitution: float, friction: float, speed: float, g: float, engine: Engine
) -> tuple[Any, float, float, dict[float, float]]:
    """(model, damping ratio, flat-drop restitution at ``speed``, restitution by speed): the
    contact's damping calibrated so that a flat drop at ``speed`` rebounds at e."""
    zeta = calibrated_damping(coin, restitution, speed, g, engine) if restitution > 0 else 1.0
    by_speed = {
        probe: flat_drop_restitution(coin, probe, zeta, g, engine)
        for probe in (*PROBE_SPEEDS, speed)
    }
    return model(coin, friction, zeta, g, engine), zeta, by_speed[speed], by_speed


def _rollout(
    coin: Coin,
    n: int,
    restitution: float,
    friction: float,
    calibration_speed: float,
    g: float,
    threads: int | None,
    engine: Engine,
    states: Callable[[Any, Any], NDArray[np.float64]],
    clocks: NDArray[np.float64],
    horizon: float,
) -> MujocoRun:
    """What :func:`run` and :func:`run_from` share: the work bound checked before anything is
    computed, the model calibrated at ``calibration_speed`` (m/s), one MjData per worker, the
    ``n`` initial ``states(model, data)`` carried (:func:`_carry`, from ``clocks`` s, for at
    most ``horizon`` s before a first contact) and the run reported."""
    import mujoco

    t0 = time.perf_counter()
    v.instance("engine", engine, Engine, "a mujoco_compare.Engine")
    bound([n], engine.limit, engine.integrator, engine.solver)
    m, zeta, e_mujoco, by_speed = _calibrated(
        coin, restitution, friction, calibration_speed, g, engine
    )
    workers = threads or os.cpu_count() or 1
    datas = [mujoco.MjData(m) for _ in range(workers)]
    carried = _carry(m, datas, states(m, datas[0]), clocks, coin, g, engine.limit, horizon)
    return MujocoRun(
        first=carried.first,
        rest=carried.rest,
        moving=carried.moving,
        dampratio=zeta,
        restitution=e_mujoco,
        elapsed=time.perf_counter() - t0,
        threads=workers,
        version=mujoco.__version__,
        engine=engine,
        restitution_by_speed=by_speed,
        rest_time=carried.rest_time,
        steps=carried.steps,
        edge_time=carried.edge_time,
    )


def run(
    coin: Coin,
    omega: NDArray[np.float64],
    launch_speed: NDArray[np.float64],
    drop_height: float,
    restitution: float,
    friction: float,
    g: float = 9.81,
    threads: int | None = None,
    engine: Engine = DEFAULT_ENGINE,
) -> MujocoRun:
    """The tosses (ω (n, 3) body frame rad/s, v0 (n,) m/s, heads up, launched ``drop_height``
    above the plane) in MuJoCo, multithreaded rollouts with ``engine``'s settings (see the
    module notes).

    Each toss is carried until it has settled (:func:`_settled`) or ``engine.limit`` s past its
    first contact, whichever comes first; those still moving at the limit are counted
    (:attr:`MujocoRun.moving`), never dropped. The work (:func:`seconds_estimate`) is bounded
    before anything is computed. ``engine.solver`` makes MuJoCo's friction harder than its
    default (:class:`FrictionSolver`). ImportError when MuJoCo is not installed.
    """
    omega = np.asarray(omega, dtype=float).reshape(-1, 3)
    v0 = np.asarray(launch_speed, dtype=float).reshape(-1)
    n = len(v0)
    vmax = float(v0.max()) if n else 0.0
    flight = vmax / g + math.sqrt(2.0 * (drop_height + vmax * vmax / (2.0 * g)) / g)
    mean = float(np.mean(v0)) if n else 0.0
    landing_speed = math.sqrt(mean**2 + 2.0 * g * drop_height)
    z = np.full(n, drop_height)
    vel = np.zeros((n, 3))
    vel[:, 2] = v0
    heads_up = np.tile((0.0, 0.0, 1.0), (n, 1))  # so the body frame of ω is the lab's
    return _rollout(
        coin, n, restitution, friction, landing_speed, g, threads, engine,
        lambda m, data: _placed_states(m, data, z, vel, heads_up, omega), v0 / g, flight + 0.5,
    )  # fmt: skip


def _quaternion_to(n: NDArray[np.float64]) -> NDArray[np.float64]:
    """Unit quaternions (scalar first) of the shortest rotations taking the body z axis onto the
    unit vectors ``n`` (k, 3); about x for n = −z."""
    w = 1.0 + n[:, 2]
    q = np.column_stack([w, -n[:, 1], n[:, 0], np.zeros(len(n))])  # (1 + z·n, z × n)
    flip = w < 1e-12
    q[flip] = (0.0, 1.0, 0.0, 0.0)
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def run_from(
    coin: Coin,
    height: NDArray[np.float64],
    velocity: NDArray[np.float64],
    normal: NDArray[np.float64],
    omega: NDArray[np.float64],
    restitution: float,
    friction: float,
    calibration_speed: float,
    g: float = 9.81,
    threads: int | None = None,
    engine: Engine = DEFAULT_ENGINE,
) -> MujocoRun:
    """Coins already at the table in MuJoCo: centre ``height`` (k,) m, ``velocity`` (k, 3) m/s,
    heads ``normal`` (k, 3) and angular velocity ``omega`` (k, 3) rad/s, all in the lab frame
    (coinflight's state when its bounces die out, for example), carried as in
    :func:`run` with ``engine``'s settings (the first contact is their first touch of the
    plane; the contact damping calibrated at ``calibration_speed``, m/s)."""
    z = np.asarray(height, dtype=float).reshape(-1)
    vel = np.asarray(velocity, dtype=float).reshape(-1, 3)
    nrm = np.asarray(normal, dtype=float).reshape(-1, 3)
    nrm = nrm / np.linalg.norm(nrm, axis=1, keepdims=True)
    w_lab = np.asarray(omega, dtype=float).reshape(-1, 3)
    return _rollout(
        coin, len(z), restitution, friction, calibration_speed, g, threads, engine,
        lambda m, data: _placed_states(m, data, z, vel, nrm, w_lab), np.zeros(len(z)), 1.0,
    )  # fmt: skip


def _placed_states(
    m: Any,
    data: Any,
    z: NDArray[np.float64],
    vel: NDArray[np.float64],
    nrm: NDArray[np.float64],
    w_lab: NDArray[np.float64],
) -> NDArray[np.float64]:
    """MuJoCo states (mjSTATE_FULLPHYSICS) of coins placed as :func:`run_from` gives them
    (centre height, lab velocity, unit heads normal, lab angular velocity); :func:`run`'s
    tosses are such coins, heads up at launch."""
    import mujoco

    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    initial = np.empty((len(z), mujoco.mj_stateSize(m, spec)))
    quats = _quaternion_to(nrm)
    rot = np.empty(9)
    for k in range(len(z)):
        mujoco.mj_resetData(m, data)
        data.qpos[:3] = (0.0, 0.0, z[k])
        data.qpos[3:7] = quats[k]
        mujoco.mju_quat2Mat(rot, quats[k])
        data.qvel[:3] = vel[k]
        data.qvel[3:6] = rot.reshape(3, 3).T @ w_lab[k]  # body frame
        mujoco.mj_getState(m, data, initial[k], spec)
    return initial


__all__ = [
    "CONDIM",
    "CONDIMS",
    "CONE",
    "CONES",
    "DEFAULT_ENGINE",
    "DEFAULT_SOLVER",
    "INTEGRATOR",
    "MAX_NOSLIP_ITERATIONS",
    "ROLLING",
    "SETTLE",
    "SOLIMP",
    "TIMECONST",
    "TIMESTEP",
    "TORSIONAL",
    "Engine",
    "FrictionSolver",
    "MujocoRun",
    "available",
    "bound",
    "calibrated_damping",
    "check_limit",
    "flat_drop_restitution",
    "model",
    "run",
    "run_from",
    "seconds_estimate",
]

"""A toss that ends on a table: bounces, settling, heads, tails or edge.

:class:`Landing` is one toss (or a batch) landing on a :class:`~coinflight.model.surface.Surface`;
:class:`TableLanding` plugs the same simulation into the probability estimators as an
:class:`~coinflight.outcomes.base.OutcomeModel`. The physics is in
:mod:`coinflight.core.bounce` and :mod:`coinflight.core.impact` (drag-free, exact flights
between impacts) and, with air drag, :mod:`coinflight.core.drag` (the same impacts and endings,
flights integrated through air).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core import ballistics
from coinflight.core.outcome import FACE_NAMES, STATUS_NAMES, Status
from coinflight.model.coin import Coin
from coinflight.model.ensemble import CONTACT
from coinflight.model.surface import TABLE_PARAMETERS, Drag, Surface
from coinflight.model.toss import STANDARD_GRAVITY, Toss, check_gravity
from coinflight.outcomes.air import check_air, drag_model
from coinflight.outcomes.base import (
    FaceArray,
    OutcomeModel,
    coin_body,
    describe_air,
    drag_dict,
    initial_conditions,
    single_name,
    toss_grid,
)

if TYPE_CHECKING:
    from collections.abc import Mapping

    from scipy.spatial.transform import Rotation

    from coinflight.core.contact import Contact
    from coinflight.model.distributions import Distribution
    from coinflight.model.ensemble import TossDistribution

FloatArray = NDArray[np.float64]

MAX_BOUNCES = 2_000
"""Largest ``max_bounces``: every landing stops after this many impacts anyway
(:data:`coinflight.core.bounce.MAX_IMPACTS`; the compiled kernel takes a 64-bit integer)."""


def check_max_bounces(value: object, name: str = "max_bounces") -> int:
    """``value`` as a whole number between 0 and :data:`MAX_BOUNCES`, else TypeError/ValueError."""
    return v.count(name, value, 0, MAX_BOUNCES)


BOUNCING_TOSSES_PER_SECOND = 2e4
"""Drag-free table landings a second that end without the rigid ending (e = 0, or stopped
after ``max_bounces`` bounces: the bounces alone), for the work bounds: vigorous nickel
tosses, e = 0.5, μ = 0.3, on 2 threads of a busy 2-core machine (a quiet one runs about five
times as many; ``python benchmarks/bench_bounce.py`` measures it), so that an estimated time
is never too short."""

RIGID_TOSSES_PER_SECOND = 70.0
"""Table landings carried to rest a second (the rigid ending, e > 0), drag-free or through air,
for the work bounds: US nickel, e = 0.5, μ = 0.3,
resistances 1e-4 m, on 2 threads of a busy 2-core machine, about half what it measures there
(``python benchmarks/bench_bounce.py``: human and vigorous tosses; the coins
roll for a median 1.5 s, up to 22 s: about 3,000 steps of the one-rim contact a landing)."""

RIGID_RESISTANCE = 1e-4
"""The rolling and pivoting resistance, m, at which :data:`RIGID_TOSSES_PER_SECOND` holds (the
surfaces' default); with less, a coin rolls and spins longer and its landing costs more
(:func:`rigid_rate`)."""

RIGID_SLOWEST = 2.0
"""Table landings carried to rest a second without rolling or pivoting resistance, for the work
bounds: coins that roll on until the ending's limit (60 s of motion,
:data:`coinflight.core.rigid_ending.DURATION`); about half of what human nickel tosses measure
on 2 threads of a 2-core machine."""


def rigid_rate(
    rolling_resistance: ArrayLike, pivoting_resistance: ArrayLike
) -> NDArray[np.float64]:
    """Table landings carried to rest a second, for the work bounds, at these resistances (m;
    arrays broadcast): :data:`RIGID_TOSSES_PER_SECOND` from :data:`RIGID_RESISTANCE` up, and
    below it that times the square root of the larger resistance over it, at least
    :data:`RIGID_SLOWEST`. The landings' cost is set by how long the coins roll and spin after
    their bounces, which the resistances set (the time scales as 1/ℓ for a rolling coin,
    less for the rest of a landing, and one of the two at 1e-4 m is enough): human tosses of
    a US nickel and of thick cylinders, e from 0.2 to 0.9 and μ from 0.1 to 1, land faster
    than this at every resistance (``python benchmarks/bench_bounce.py`` measures the default
    surface)."""
    ell = np.maximum(np.asarray(rolling_resistance, float), np.asarray(pivoting_resistance, float))
    scaled = RIGID_TOSSES_PER_SECOND * np.sqrt(np.minimum(ell, RIGID_RESISTANCE) / RIGID_RESISTANCE)
    return np.maximum(scaled, RIGID_SLOWEST)


AIR_LANDINGS_PER_SECOND = 1e4
"""Table landings through air a second that end without the rigid ending (e = 0, or a bounce
limit; 0.8 m drop, μ = 0.3, C_d = 1.17, vigorous nickel tosses), for the work bounds: 2
threads of a busy 2-core machine (a quiet one runs about five times as many; ``python
benchmarks/bench_air.py``)."""


RATE_QUANTILES = 64
"""Quantiles of each distributed resistance over which :meth:`TableLanding.rate_for`
averages the time of a landing."""


PER_TOSS = CONTACT
"""The contact parameters a landing takes toss by toss
(:data:`coinflight.model.ensemble.CONTACT`; the landing kernels'
:data:`coinflight.core.bounce.PER_TOSS`)."""


@dataclass(frozen=True, eq=False)
class LandingOutcome:
    """What a table landing shows.

    Attributes
    ----------
    face : ndarray of int8
        TAILS 0, HEADS 1, EDGE 2 (:mod:`coinflight.core.outcome`).
    bounces : ndarray of int32
        Impacts after which the coin left the surface again.
    first_contact : ndarray
        Time of the first contact with the surface since launch, s.
    settle_time : ndarray
        Time since launch at which the landing ended, s: the last impact for a landing that
        ended at one; after the rigid ending, the time the outcome was settled (the coin at
        rest, or its energy below its well's barrier, status "settled in contact"); for an
        unsettled toss, when it was stopped.
    status : ndarray of int8
        Why the landing ended (:class:`coinflight.core.outcome.Status`; its names
        :data:`~coinflight.core.outcome.STATUS_NAMES`).
    """

    face: NDArray[np.int8]
    bounces: NDArray[np.int32]
    first_contact: FloatArray
    settle_time: FloatArray
    status: NDArray[np.int8]

    @property
    def face_name(self) -> str:
        """ "heads", "tails" or "edge" for a single toss."""
        return single_name(self.face, FACE_NAMES, "face")

    @property
    def status_name(self) -> str:
        """Why a single toss ended."""
        return single_name(self.status, STATUS_NAMES, "status")


def check_clears(coin: Coin, apex: FloatArray, surface: Surface) -> None:
    """ValueError unless every toss rises high enough for its lowest point to clear the surface.

    The contact is looked for on the way down, from the apex on (the hand releases the coin
    above the surface): at the apex the centre of mass must be more than sqrt(r² + h²/4),
    the farthest reach of the coin, above the surface.
    """
    reach = float(np.hypot(coin.radius, 0.5 * coin.thickness))
    clearance = np.asarray(apex) + surface.drop_height
    if np.any(clearance <= reach):
        worst = float(np.min(clearance))
        raise ValueError(
            f"the coin must clear the surface: apex + drop height = {worst:.4g} m must exceed "
            f"the coin's reach {reach:.4g} m; raise --drop-height or the flight time"
        )


def contact_record(
    coin: Coin, surface: Surface, g: float, *, rest_speed: float | None = None
) -> Contact:
    """The coin, the surface and gravity as every landing kernel reads them, built once.

    The :class:`coinflight.core.contact.Contact` record of ``coin`` (radius, thickness, mass,
    moments, corner radius) on ``surface`` (drop height, e, μ, resistances, contact time, the
    impact's contact duration) under gravity ``g``, m/s²; ``rest_speed`` (m/s)
    defaults to :data:`coinflight.core.bounce.REST_SPEED`. Nothing is checked here beyond
    what ``Coin`` and ``Surface`` checked on construction (``g`` is the caller's).
    """
    from coinflight.core import bounce
    from coinflight.core.contact import Contact

    return Contact.build(
        **coin_body(coin),
        restitution=surface.restitution,
        friction=surface.friction,
        drop_height=surface.drop_height,
        g=g,
        rest_speed=bounce.REST_SPEED if rest_speed is None else rest_speed,
        rolling_resistance=surface.rolling_resistance,
        pivoting_resistance=surface.pivoting_resistance,
        corner_radius=coin.corner_radius,
        contact_duration=surface.contact_duration,
    )


def land(
    coin: Coin,
    omega: FloatArray,
    launch_speed: FloatArray,
    start_sign: float | FloatArray,
    g: float,
    surface: Surface,
    drag: Drag | None = None,
    max_bounces: int | None = None,
    parallel: bool = True,
    contact: dict[str, FloatArray] | None = None,
) -> LandingOutcome:
    """Land tosses given as arrays (ω (n, 3), v0 (n,)) on ``surface``; flat batch of n.

    Without drag this is the parallel event-driven kernel :func:`coinflight.core.bounce.land`;
    with drag the compiled integrator :func:`coinflight.core.drag.land` (the same impacts and
    endings). ``contact`` gives tosses their own ``restitution``, ``friction``,
    ``rolling_resistance``, ``pivoting_resistance`` and/or ``contact_duration``
    (:data:`PER_TOSS`; arrays of shape
    (n,), checked by the caller; :meth:`~coinflight.model.ensemble.TossDistribution.
    contact_values`) in place of the surface's, with or without drag.
    """
    if not isinstance(surface, Surface):
        raise TypeError(f"surface must be a Surface, got {type(surface).__name__}")
    if surface.kind != "table":
        raise ValueError("a landing needs surface kind 'table'; a hand catch is a Flight")
    if max_bounces is not None:
        check_max_bounces(max_bounces)
    omega = np.asarray(omega, dtype=float).reshape(-1, 3)
    speed = np.broadcast_to(np.asarray(launch_speed, dtype=float), (omega.shape[0],))
    sign = np.broadcast_to(np.asarray(start_sign, dtype=float), (omega.shape[0],))
    check_clears(coin, speed * speed / (2.0 * g), surface)
    from coinflight.core import bounce

    record = contact_record(coin, surface, g)
    limit = bounce.MAX_IMPACTS if max_bounces is None else int(max_bounces)
    per_toss = {} if contact is None else contact
    if drag is not None and not drag.is_zero:
        from coinflight.core import drag as drag_kernels

        check_air(coin, drag, g, speed, surface.drop_height, omega)
        air = drag_model(coin, drag, g)
        return LandingOutcome(
            *drag_kernels.land(
                omega, speed, sign, air, record, max_bounces=limit, parallel=parallel, **per_toss
            )
        )
    return LandingOutcome(
        *bounce.land(omega, speed, sign, record, max_bounces=limit, parallel=parallel, **per_toss)
    )


@dataclass(frozen=True, eq=False)
class StartState:
    """A coin's state at the start of a landing (:meth:`Landing.from_state`), SI, lab frame.

    Attributes
    ----------
    position, velocity, normal, angular_momentum : ndarray, shape (3,)
        Centre of mass (m; the table is z = 0), its velocity (m/s), the heads normal and the
        angular momentum about the centre of mass (kg m²/s).
    orientation : scipy.spatial.transform.Rotation
        Coin frame → lab, as given.
    i1, i3 : float
        The coin's principal moments, kg m².
    g : float
        Gravitational acceleration, m/s².
    """

    position: FloatArray
    orientation: Rotation
    velocity: FloatArray
    normal: FloatArray
    angular_momentum: FloatArray
    i1: float
    i3: float
    g: float

    @classmethod
    def build(
        cls,
        coin: Coin,
        position: ArrayLike,
        orientation: Rotation,
        velocity: ArrayLike,
        angular_velocity: ArrayLike,
        g: float,
    ) -> StartState:
        """The validated state (ValueError/TypeError naming the value)."""
        from scipy.spatial.transform import Rotation

        from coinflight.core.bounce import CONTACT_GAP
        from coinflight.core.impact import lowest_depth

        vectors = {}
        for name, value, unit in (
            ("position", position, "m"),
            ("velocity", velocity, "m/s"),
            ("angular_velocity", angular_velocity, "rad/s"),
        ):
            arr = v.finite(name, value, unit)
            if arr.shape != (3,):
                raise ValueError(
                    f"{name} must have 3 components (x, y, z, lab frame), got shape {arr.shape}"
                )
            vectors[name] = arr
        if not isinstance(orientation, Rotation):
            raise TypeError(
                "orientation must be a scipy.spatial.transform.Rotation, "
                f"got {type(orientation).__name__}"
            )
        if not orientation.single:
            raise ValueError(f"orientation must be one rotation, got a stack of {len(orientation)}")
        matrix = orientation.as_matrix()
        if not np.all(np.isfinite(matrix)):
            raise ValueError("orientation must be finite")
        gravity = check_gravity(g)
        normal = matrix[:, 2] / np.linalg.norm(matrix[:, 2])
        i1, i3 = (float(x) for x in coin.moments)
        omega = vectors["angular_velocity"]
        momentum = i1 * omega + (i3 - i1) * float(omega @ normal) * normal
        z = float(vectors["position"][2])
        depth = float(
            lowest_depth(float(normal[2]), coin.radius, 0.5 * coin.thickness, coin.corner_radius)
        )
        if z - depth < -CONTACT_GAP:
            raise ValueError(
                f"position z = {z:.6g} m puts the coin's lowest point {depth - z:.3g} m below "
                f"the table (z = 0); its lowest point is {depth:.6g} m below its centre in "
                "this orientation: raise z"
            )
        return cls(
            position=vectors["position"],
            orientation=orientation,
            velocity=vectors["velocity"],
            normal=normal,
            angular_momentum=momentum,
            i1=i1,
            i3=i3,
            g=gravity,
        )

    def omega(self, momentum: FloatArray, normal: FloatArray) -> FloatArray:
        """Angular velocity (…, 3), rad/s, of the angular momenta and normals (…, 3):
        ω = L/I1 + (1/I3 − 1/I1)(L·n) n (a symmetric top)."""
        along = np.sum(momentum * normal, axis=-1, keepdims=True)
        return momentum / self.i1 + (1.0 / self.i3 - 1.0 / self.i1) * along * normal


@dataclass(frozen=True, eq=False)
class LandingStates:
    """A landing's state at given times (:meth:`Landing.at`), SI, lab frame; arrays shaped
    like ``time`` with a last axis of 3.

    Attributes
    ----------
    time : ndarray
        s since the start state.
    position : ndarray
        Centre of mass, m (the table is z = 0).
    normal : ndarray
        Heads normal (the coin's angle about it is not followed: a cylinder's motion does not
        depend on it).
    velocity : ndarray
        Velocity of the centre of mass, m/s.
    angular_velocity : ndarray
        rad/s.
    angular_momentum : ndarray
        About the centre of mass, kg m²/s.

    At the time of an impact, the state just after it.
    """

    time: FloatArray
    position: FloatArray
    normal: FloatArray
    velocity: FloatArray
    angular_velocity: FloatArray
    angular_momentum: FloatArray


@dataclass(frozen=True, eq=False)
class Landing:
    """A toss (or a batch of tosses) that ends on a table.

    Parameters
    ----------
    coin : Coin
    toss : Toss
        Launch: ω and flight time T (the launch speed is v0 = g T / 2, as for a catch).
    surface : Surface
        Kind ``"table"``, with the drop height, restitution and friction.
    drag : Drag, optional
        Air drag on the flight (:mod:`coinflight.core.drag`).
    max_bounces : int, optional
        Stop at the contact that follows this many bounces (0: the first contact) and report
        the well the coin is in there; by default the coin bounces until it settles.
    start : StartState, optional
        Set by :meth:`from_state` (a landing from any state, no toss): build it there.

    Examples
    --------
    >>> surface = Surface("table", drop_height=0.8, restitution=0.5, friction=0.3)
    >>> landing = Landing(Coin.preset("us-nickel"), Toss((240.0, 5.0, 3.0), 0.49), surface)
    >>> landing.outcome.face_name, int(landing.outcome.bounces)  # rolls upright to rest
    ('edge', 13)
    """

    coin: Coin
    toss: Toss | None
    surface: Surface
    drag: Drag | None = None
    max_bounces: int | None = None
    start: StartState | None = None

    def __post_init__(self) -> None:
        checks: tuple[tuple[str, type], ...] = (("coin", Coin), ("surface", Surface))
        if self.start is None:
            checks += (("toss", Toss),)
        elif self.toss is not None or self.drag is not None:
            raise ValueError("a landing from a state (Landing.from_state) takes no toss or drag")
        for name, kind in checks:
            if not isinstance(getattr(self, name), kind):
                raise TypeError(
                    f"{name} must be a {kind.__name__}, got {type(getattr(self, name)).__name__}"
                )
        if self.drag is not None and not isinstance(self.drag, Drag):
            raise TypeError(f"drag must be a Drag, got {type(self.drag).__name__}")
        if self.max_bounces is not None:
            check_max_bounces(self.max_bounces)

    @classmethod
    def from_state(
        cls,
        coin: Coin,
        surface: Surface,
        *,
        position: ArrayLike,
        orientation: Rotation,
        velocity: ArrayLike,
        angular_velocity: ArrayLike,
        g: float = STANDARD_GRAVITY,
        max_bounces: int | None = None,
    ) -> Landing:
        """The landing of a coin started in any state above (or on) the table z = 0.

        Parameters
        ----------
        coin : Coin
        surface : Surface
            Kind ``"table"``: e, μ, the resistances and the contact duration (its drop height
            is not used: the state gives the height).
        position : array_like, shape (3,)
            Centre of mass, lab frame, m; the table is the plane z = 0, gravity along −z.
        orientation : scipy.spatial.transform.Rotation
            One rotation taking the coin's frame (heads normal along its z) to the lab.
        velocity : array_like, shape (3,)
            Velocity of the centre of mass, lab frame, m/s.
        angular_velocity : array_like, shape (3,)
            Angular velocity, lab frame, rad/s.
        g : float
            Gravitational acceleration, m/s².
        max_bounces : int, optional
            As :class:`Landing`.

        Returns
        -------
        Landing
            Its :attr:`outcome` as for a toss (times counted from the state, s), and
            :meth:`at`, the state at given times.

        Notes
        -----
        The coin may start anywhere whose lowest point is not below the table (within
        :data:`coinflight.core.bounce.CONTACT_GAP`); started touching it, it strikes at once
        if its lowest point moves down, else the verdict after an impact decides (trapped in
        its well, or handed to the ending when slower than the rest speed, or it flies off):
        :func:`coinflight.core.bounce.follow`. Bad input raises ValueError or TypeError
        naming the value. No air drag.

        Examples
        --------
        >>> from scipy.spatial.transform import Rotation
        >>> table = Surface("table", restitution=0.45, friction=0.3)
        >>> drop = Landing.from_state(
        ...     Coin.preset("us-nickel"), table, position=(0.0, 0.0, 0.35),
        ...     orientation=Rotation.identity(), velocity=(0.0, 0.0, 0.0),
        ...     angular_velocity=(1e-6, 0.0, 0.0))
        >>> drop.outcome.face_name  # a coin dropped flat lands on its start face
        'heads'
        """
        if not isinstance(coin, Coin):
            raise TypeError(f"coin must be a Coin, got {type(coin).__name__}")
        if not isinstance(surface, Surface) or surface.kind != "table":
            raise ValueError("a landing needs a Surface of kind 'table'")
        state = StartState.build(coin, position, orientation, velocity, angular_velocity, g)
        return cls(coin, None, surface, None, max_bounces, state)

    def at(self, times: ArrayLike) -> LandingStates:
        """The state at ``times`` (s since the start state; ≥ 0): the flights in closed form,
        the impacts, then what the landing's ending follows. Each time in the ending is reached
        by its run from the end of the bounces, stopped there (the uninterrupted run's steps
        up to the last), so the states do not depend on which other times are asked for; m
        times in the ending cost up to m runs of it (a few ms each for a tossed coin).

        Only a landing from a state (:meth:`from_state`). ValueError for a time the landing
        does not follow: after it ended at an impact (below the barrier, dead, at the bounce
        limit), or after the rigid ending settled or gave up (:attr:`followed_until`).
        """
        if self.start is None:
            raise TypeError("Landing.at follows a landing from a state: use Landing.from_state")
        t = v.non_negative("times", times, "s")
        flat = t.reshape(-1)
        order = np.argsort(flat, kind="stable")
        until = self.followed_until
        if flat.size and float(flat[order][-1]) > until:
            raise ValueError(
                f"times must be at most {until:.6g} s (where the landing ended: no motion is "
                f"followed after), got "
                f"{float(flat[order][-1]):.6g} s"
            )
        found, info = self._follow(flat[order])
        if int(info[6]) < flat.size:  # the ending stopped short of its own promise
            raise ValueError(f"times after {info[7]:.6g} s are not followed")
        states = np.empty_like(found)
        states[order] = found
        shape = t.shape
        normal = states[:, 3:6]
        momentum = states[:, 9:12]
        return LandingStates(
            time=t,
            position=states[:, 0:3].reshape(*shape, 3),
            normal=normal.reshape(*shape, 3),
            velocity=states[:, 6:9].reshape(*shape, 3),
            angular_velocity=self.start.omega(momentum, normal).reshape(*shape, 3),
            angular_momentum=momentum.reshape(*shape, 3),
        )

    @property
    def followed_until(self) -> float:
        """The time the landing's motion is followed to, s since the start state: the end of
        the bounces, or where the rigid ending settled the coin (or gave up). :meth:`at`
        follows every time up to it, each on the one motion the outcome comes from."""
        if self.start is None:
            raise TypeError("followed_until is a landing's from a state (Landing.from_state)")
        return float(self._follow(np.empty(0))[1][7])

    def _follow(self, times: FloatArray) -> tuple[FloatArray, FloatArray]:
        """(states (m, 12), (face, bounces, first, end of the bounces, settle, status,
        followed, until)) of :func:`coinflight.core.bounce.follow` at the sorted ``times``."""
        from coinflight.core import bounce

        assert self.start is not None
        record = contact_record(self.coin, self.surface, self.start.g)
        states = np.full((times.size, bounce.STATE_COLUMNS), np.nan)
        st = self.start
        limit = bounce.MAX_IMPACTS if self.max_bounces is None else int(self.max_bounces)
        out = bounce.follow(
            float(st.position[2]),
            (float(st.position[0]), float(st.position[1])),
            tuple(float(x) for x in st.velocity),
            tuple(float(x) for x in st.normal),
            tuple(float(x) for x in st.angular_momentum),
            record,
            limit,
            np.ascontiguousarray(times, dtype=np.float64),
            states,
        )
        return states, np.asarray(out, dtype=float)

    @cached_property
    def outcome(self) -> LandingOutcome:
        """Face, bounces and times, shaped like the toss batch (0-d from a state)."""
        if self.start is not None:
            _, (face, bounces, first, _, settle, status, _, _) = self._follow(np.empty(0))
            return LandingOutcome(
                face=np.asarray(face, dtype=np.int8),
                bounces=np.asarray(bounces, dtype=np.int32),
                first_contact=np.asarray(first),
                settle_time=np.asarray(settle),
                status=np.asarray(status, dtype=np.int8),
            )
        assert self.toss is not None
        shape = self.toss.shape
        omega = np.broadcast_to(self.toss.omega, (*shape, 3)).reshape(-1, 3)
        speed = np.broadcast_to(self.toss.launch_speed, shape).reshape(-1)
        out = land(
            self.coin,
            omega,
            speed,
            self.toss.start_sign,
            self.toss.g,
            self.surface,
            self.drag,
            self.max_bounces,
        )
        return LandingOutcome(
            face=out.face.reshape(shape),
            bounces=out.bounces.reshape(shape),
            first_contact=out.first_contact.reshape(shape),
            settle_time=out.settle_time.reshape(shape),
            status=out.status.reshape(shape),
        )


class TableLanding(OutcomeModel):
    """Outcome model for the probability estimators: the tosses land on ``surface``.

    Plugs into :func:`coinflight.probability.estimate` (``model=TableLanding(surface)``);
    counts (tails, heads, edge) and, as an extra tally, the tosses that had not settled when the
    simulation stopped (counted by the face they showed then).
    """

    name = "table landing"
    summary = "falls onto a hard surface, bounces and settles heads, tails or on edge"
    surface_parameters = TABLE_PARAMETERS
    can_end_on_edge = True

    tallies = ("unsettled",)

    contact_parameters = PER_TOSS
    """Restitution, friction, the rolling and pivoting resistances and the contact duration
    may vary toss by toss, with or without air."""

    @property
    def rate(self) -> float:  # type: ignore[override]
        """Tosses a second for the work bounds: landings carried to rest (e > 0, no bounce
        limit) :func:`rigid_rate` at the surface's resistances; else (the bounces alone)
        :data:`BOUNCING_TOSSES_PER_SECOND`, or with air drag :data:`AIR_LANDINGS_PER_SECOND`."""
        if self.surface.restitution > 0.0 and self.max_bounces is None:
            s = self.surface
            return float(rigid_rate(s.rolling_resistance, s.pivoting_resistance))
        if self.drag is not None:
            return AIR_LANDINGS_PER_SECOND
        return BOUNCING_TOSSES_PER_SECOND

    def rate_for(self, dist: TossDistribution | None) -> float:
        """:attr:`rate` for tosses that bring their own restitution or resistances
        (``dist.contact``, drawn toss by toss): landings carried to rest if any may bounce, at
        the harmonic mean of :func:`rigid_rate` over the resistances' distributions (the
        expected time a landing, on a grid of each one's quantiles, the two independent)."""
        spread = {} if dist is None else dist.contact
        if not spread or self.max_bounces is not None:
            return self.rate
        e = spread.get("restitution")
        if (self.surface.restitution if e is None else e.bounds[1]) <= 0.0:
            return self.rate
        u = (np.arange(RATE_QUANTILES) + 0.5) / RATE_QUANTILES

        def quantiles(name: str, own: float) -> NDArray[np.float64]:
            return spread[name].ppf(u) if name in spread else np.full(u.size, own)

        rolling = quantiles("rolling_resistance", self.surface.rolling_resistance)
        pivoting = quantiles("pivoting_resistance", self.surface.pivoting_resistance)
        rates = rigid_rate(rolling[:, None], pivoting[None, :])
        return float(1.0 / np.mean(1.0 / rates))

    def __init__(
        self, surface: Surface, drag: Drag | None = None, max_bounces: int | None = None
    ) -> None:
        if not isinstance(surface, Surface) or surface.kind != "table":
            raise ValueError("TableLanding needs a Surface of kind 'table'")
        if max_bounces is not None:
            check_max_bounces(max_bounces)
        self.surface = surface
        self.drag = drag
        self.max_bounces = max_bounces

    def faces(
        self, coin: Coin, omega: FloatArray, flight_time: FloatArray, start_sign: float, g: float
    ) -> FaceArray:
        """Faces of tosses launched at v0 = g T / 2 that land on the surface (:func:`land`); with
        ``max_bounces`` = K the well the coin is in at the contact after K bounces."""
        shape, flat_omega, t = toss_grid(omega, flight_time)
        out = land(
            coin,
            flat_omega,
            ballistics.launch_speed(t, g),
            start_sign,
            g,
            self.surface,
            self.drag,
            self.max_bounces,
        )
        return out.face.reshape(shape)

    def count(self, dist: TossDistribution, u: FloatArray) -> NDArray[np.int64]:
        """(tails, heads, edge, unsettled) counts for unit-cube points ``u``, (len(ranged), n):
        :attr:`tallies`."""
        omega, t = initial_conditions(dist, u)
        out = land(
            dist.coin,
            omega,
            ballistics.launch_speed(t, dist.g),
            dist.start_sign,
            dist.g,
            self.surface,
            self.drag,
            self.max_bounces,
            parallel=False,  # the estimators run batches in their own threads
            contact=dist.contact_values(u) if dist.contact else None,
        )
        faces = np.bincount(out.face, minlength=3).astype(np.int64)
        return np.append(faces, np.count_nonzero(out.status == Status.UNSETTLED))

    def describe(
        self, contact: Mapping[str, Distribution] | None = None, corner_radius: float = 0.0
    ) -> str:
        """One line: the table, its contact parameters and the air. ``contact`` gives
        distributions in place of the surface's values (the tosses' own, drawn toss by toss:
        :attr:`~coinflight.model.ensemble.TossDistribution.contact`). The rolling and pivoting
        resistances are named, a contact duration of an impact other than the default
        (:data:`coinflight.model.surface.DEFAULT_CONTACT_DURATION`) or spread, and a rounded rim
        when ``corner_radius`` (the coin's, m) is not 0."""
        s = self.surface
        spread = {} if contact is None else contact

        def text(name: str, unit: str = "") -> str:
            if name in spread:
                return spread[name].describe(unit)
            return f"{getattr(s, name):g}{' ' + unit if unit else ''}"

        ending = (
            f", rolling resistance {text('rolling_resistance', 'm')}, "
            f"pivoting resistance {text('pivoting_resistance', 'm')}"
        )
        if _duration_shown(s, spread):
            ending += f", contact duration {text('contact_duration', 's')}"
        if corner_radius:
            ending += f", rim corner radius {corner_radius:g} m"
        return (
            f"landing on a table {s.drop_height:g} m below launch (restitution "
            f"{text('restitution')}, friction {text('friction')}{ending}), "
            f"{describe_air(self.drag)}"
        )

    def to_dict(
        self, contact: Mapping[str, Distribution] | None = None, corner_radius: float = 0.0
    ) -> dict[str, Any]:
        """JSON settings; ``contact``'s distributions, if any, as objects (``{"kind":
        "uniform", ...}``) in place of the surface's numbers; the rolling and pivoting
        resistances (m) always; the impact's ``contact_duration`` (s) and the coin's rim
        ``corner_radius`` (m) when not the defaults
        (:data:`coinflight.model.surface.DEFAULT_CONTACT_DURATION`, sharp corners)."""
        s = self.surface
        spread = {} if contact is None else contact

        def value(name: str) -> Any:
            return spread[name].to_dict() if name in spread else getattr(s, name)

        out: dict[str, Any] = {
            "surface": s.kind,
            "drop_height": s.drop_height,
            "restitution": value("restitution"),
            "friction": value("friction"),
            "drag": drag_dict(self.drag),
        }
        if self.max_bounces is not None:
            out["max_bounces"] = self.max_bounces
        out["rolling_resistance"] = value("rolling_resistance")
        out["pivoting_resistance"] = value("pivoting_resistance")
        if _duration_shown(s, spread):
            out["contact_duration"] = value("contact_duration")
        if corner_radius:
            out["corner_radius"] = corner_radius
        return out


def _duration_shown(surface: Surface, spread: Mapping[str, Distribution]) -> bool:
    """Whether a landing's description names its contact duration: spread over the tosses, or a
    single value other than the default (which every other description leaves implied)."""
    from coinflight.model.surface import DEFAULT_CONTACT_DURATION

    return "contact_duration" in spread or surface.contact_duration != DEFAULT_CONTACT_DURATION


__all__ = [
    "AIR_LANDINGS_PER_SECOND",
    "BOUNCING_TOSSES_PER_SECOND",
    "MAX_BOUNCES",
    "PER_TOSS",
    "STATUS_NAMES",
    "Landing",
    "LandingOutcome",
    "LandingStates",
    "StartState",
    "TableLanding",
    "contact_record",
    "land",
]

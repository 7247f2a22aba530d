"""Validation of the table landing: every number of the landing report, computed by the library.

Six questions, each a function returning plain values with their seeds:

* :func:`dead_landings`: tosses landing dead (e = 0) against Yong & Mahadevan's dynamic model
  P(edge) = 2 arctan(h/d)/π (:func:`coinflight.studies.edge.edge_table`);
* :func:`bouncing_edges`: the same tosses bouncing (e, μ and the rolling and pivoting
  resistance over their ranges), P(edge) per ratio as a band beside the dead landings and the
  models. Hernández-Navarro & Piñero (2021, arXiv:2103.10927) derive P(edge) of a partially
  inelastic bouncing coin in closed form; only their abstract could be read for this project,
  so their curve is not drawn (see the report's words on what it predicts and whether ours
  agrees);
* :func:`contact_maps`: P(same side at rest) and P(edge) over a grid of restitution e and
  friction μ, the same tosses in every cell (common random numbers: the maps show the effect
  of e and μ, not noise);
* :func:`nickel_band`: the US nickel's P(edge) as a band over what is not measured (e and μ
  over each surface preset's ranges, :data:`coinflight.studies.presets.SURFACE_PRESETS`, the
  resistances and the rim's corner radius): the corners of that box, the probability
  integrated over it (the four drawn toss by toss) and how the edges ended, beside Murray &
  Teare's extrapolated 1 in 6000;
* :func:`mujoco_comparison`: identical tosses in coinflight and in MuJoCo
  (:mod:`coinflight.studies.mujoco_compare`), at the first contact and at rest, with the speed
  of each;
* :func:`thick_experiments`: the measured edge fractions of thick cylinders beside the
  landing's band (:mod:`coinflight.studies.edge_experiments`).

The landing is :func:`coinflight.outcomes.table.land`'s: Stronge's impacts while the coin
bounces, then the rigid, event-driven 3-D phase (:mod:`coinflight.core.rigid_ending`) carries
it to rest. These are validation runs, not predictions: every table number they give depends
on the restitution, friction, rolling and pivoting resistance and the rim's corner radius,
none measured for a coin. A number quoted from here goes with its band over those parameters
(:func:`contact_maps`, :func:`nickel_band`). Cost: a landing carried to rest is slow (the
coin may roll for seconds; :func:`coinflight.outcomes.table.rigid_rate`, at each cell's
resistance, is the rate the work bounds take), a dead landing (e = 0) ends at its first
impact, a hundred times faster; every function bounds its work before it starts.

Nothing here is a hard-coded result: re-running after a change of the contact physics gives
the new numbers. Every random draw comes from the seed through
:mod:`coinflight.probability.streams` (one child per question and cell, one stream per
parameter).
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core.outcome import EDGE
from coinflight.model.coin import Coin
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import DEFAULT_FRICTION, DEFAULT_RESTITUTION, RESISTANCE_BAND, Surface
from coinflight.probability import streams
from coinflight.probability.result import BinomialEstimate
from coinflight.studies.presets import bouncing_box

if TYPE_CHECKING:
    from coinflight.studies.edge_experiments import EdgeExperiments

DROP_HEIGHT = 0.8
"""The table lies this far below the launch point, m (as in the issue's measurements)."""
COIN = "us-nickel"
"""The coin of the maps, the band and the MuJoCo comparison (Murray & Teare's)."""
SPIN = (150.0, 300.0)
"""Spin about a diameter, rad/s, uniform: a vigorous toss."""
AXIAL_SPIN = (-20.0, 20.0)
"""Spin about the normal of the map and band tosses, rad/s, uniform: the coin precesses, so
that a frictionless impact (which keeps L·n and L_z) can favour the starting face."""
WOBBLE = (-30.0, 30.0)
"""Spin about the second diameter of the MuJoCo tosses, rad/s, uniform (no axial spin there:
MuJoCo's Euler integrator drifts in the precession phase; see :mod:`.mujoco_compare`)."""
LAUNCH_SPEED = (1.5, 3.0)
"""Upward launch speed, m/s, uniform."""
MURRAY_TEARE = 1.0 / 6000.0
"""Murray & Teare (1993, Phys. Rev. E 48:2547): a US nickel lands on edge "approximately 1 in
6000 tosses", extrapolated from their model (REFERENCES §5): a reference, not a target."""

# Children of the report's seed, one per question (streams.child(root, PART)).
# (2 and 5 belonged to questions since retired; the others keep their children, so their draws.)
_DEAD, _MAPS, _MUJOCO, _BOUNCING, _EXPERIMENTS, _BAND = 0, 1, 3, 4, 6, 7
EXPERIMENTS_CHILD = _EXPERIMENTS
"""The child of the report's seed the thick-cylinder comparison (:func:`thick_experiments`)
draws its tosses from."""


def map_tosses(coin: Coin | None = None) -> TossDistribution:
    """The tosses of the maps and the band: ωx ~ U(:data:`SPIN`), ωy = 0,
    ωz ~ U(:data:`AXIAL_SPIN`), v0 ~ U(:data:`LAUNCH_SPEED`), heads up."""
    return TossDistribution(
        Uniform(*SPIN),
        0.0,
        Uniform(*AXIAL_SPIN),
        coin=coin if coin is not None else Coin.preset(COIN),
        launch_speed=Uniform(*LAUNCH_SPEED),
    )


def mujoco_tosses(coin: Coin | None = None) -> TossDistribution:
    """The tosses compared with MuJoCo: ωx ~ U(:data:`SPIN`), ωy ~ U(:data:`WOBBLE`),
    ωz = 0, v0 ~ U(:data:`LAUNCH_SPEED`), heads up."""
    return TossDistribution(
        Uniform(*SPIN),
        Uniform(*WOBBLE),
        0.0,
        coin=coin if coin is not None else Coin.preset(COIN),
        launch_speed=Uniform(*LAUNCH_SPEED),
    )


def _draw(
    dist: TossDistribution, n: int, root: np.random.SeedSequence
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """n tosses of ``dist`` from ``root``'s streams: (ω (n, 3), v0 (n,))."""
    from coinflight.core import ballistics
    from coinflight.outcomes.base import initial_conditions

    u = np.concatenate(list(streams.unit_cube(root, n, len(dist.ranged))), axis=1)
    omega, t = initial_conditions(dist, u)
    return omega, np.asarray(ballistics.launch_speed(t, dist.g), dtype=float)


def _with_stderr(p: float, n: int) -> tuple[float, float]:
    """(P, its binomial standard error sqrt(P (1 − P) / n)) of a fraction of ``n`` tosses."""
    return p, math.sqrt(p * (1 - p) / n)


# --- dead landings -------------------------------------------------------------------------------
RATIOS = (0.1, 0.3, 0.577, 1.0)
"""Thickness / diameter ratios of the dead-landing check (the issue's)."""


@dataclass(frozen=True)
class DeadLanding:
    """Simulated P(edge) of dead landings at one ratio h/d, beside Yong & Mahadevan."""

    ratio: float
    dynamic: float
    geometric: float
    simulated: BinomialEstimate

    @property
    def z(self) -> float:
        """(p̂ − P_dynamic) / s.e., the s.e. of the model's binomial at n (finite at p̂ = 0)."""
        se = math.sqrt(self.dynamic * (1.0 - self.dynamic) / self.simulated.n)
        return (self.simulated.p - self.dynamic) / se


def dead_landings(
    n: int, seed: streams.SeedLike, ratios: tuple[float, ...] = RATIOS
) -> list[DeadLanding]:
    """P(edge) of ``n`` dead landings per ratio (:func:`coinflight.studies.edge.edge_table`,
    its default setting: Yong & Mahadevan's) against their dynamic and geometric models."""
    from coinflight.studies.edge import edge_table

    root = streams.seed_sequence(seed)
    rows = edge_table(list(ratios), n, streams.child(root, _DEAD))
    return [
        DeadLanding(
            r["ratio"],
            r["p_edge_dynamic"],
            r["p_edge_geometric"],
            BinomialEstimate(
                r["simulated"]["successes"], r["simulated"]["n"], streams.reported_seed(root)
            ),
        )
        for r in rows
    ]


# --- bouncing edges ---------------------------------------------------------------------------
@dataclass(frozen=True)
class BouncingEdges:
    """Simulated P(edge) of the dead-landing tosses when they bounce, over the box of e, μ and
    the rolling and pivoting resistance ℓ_r = ℓ_p.

    ``cells`` are the box's points (parameter name → value: ``restitution``, ``friction``,
    ``resistance`` in m; :func:`coinflight.studies.edge_experiments.box_cells`: every
    combination of ``points`` values per parameter, the centre last); ``edge`` has shape
    (len(ratios), len(cells)); ``n`` tosses per ratio, the same tosses in every cell (one seed
    child for all cells).
    """

    ratios: tuple[float, ...]
    cells: tuple[dict[str, float], ...]
    edge: NDArray[np.float64]
    n: int
    seed: int

    def ranges(self, name: str) -> tuple[float, float]:
        """The lowest and highest value of parameter ``name`` over the cells."""
        values = [c[name] for c in self.cells]
        return min(values), max(values)

    def low(self, k: int) -> tuple[float, float]:
        """(P, s.e.) of ratio ``k``'s lowest cell."""
        return _with_stderr(float(self.edge[k].min()), self.n)

    def high(self, k: int) -> tuple[float, float]:
        """(P, s.e.) of ratio ``k``'s highest cell."""
        return _with_stderr(float(self.edge[k].max()), self.n)


def bouncing_edges(
    n: int, seed: streams.SeedLike, ratios: tuple[float, ...] = RATIOS, points: int = 2
) -> BouncingEdges:
    """P(edge) of ``n`` tosses per ratio in the dead-landing setting
    (:func:`coinflight.studies.edge.simulate_edge`: vigorous planar spins, table
    :data:`coinflight.studies.edge.SIM_DROP` below), bouncing, at ``points`` values per
    parameter of the box of restitution and friction (:func:`bouncing_box`, the surface
    presets' union) and the rolling and pivoting resistance ℓ_r = ℓ_p (:data:`RESISTANCES`,
    geometric), every combination and the box's centre, the same tosses in every cell.

    Cost: len(ratios) × (points³, + 1 for even ``points``) × ``n`` landings carried to rest,
    bounded before anything runs."""
    from coinflight.studies.edge import simulate_edge
    from coinflight.studies.edge_experiments import box_cells

    n = v.count("tosses per ratio", n, 1, 10**7)
    points = v.count("points per parameter", points, 2, 9)
    (e_lo, e_hi), (mu_lo, mu_hi) = bouncing_box()
    box = {"restitution": (e_lo, e_hi), "friction": (mu_lo, mu_hi), "resistance": RESISTANCES}
    cells = box_cells(box, points)
    _bound(
        f"bouncing edges: {len(ratios)} ratios × {len(cells)} cells × {n} tosses",
        *((len(ratios) * n, cell["resistance"]) for cell in cells),
    )
    root = streams.seed_sequence(seed)
    edge = np.empty((len(ratios), len(cells)))
    child = streams.child(root, _BOUNCING)
    for j, cell in enumerate(cells):
        rows = simulate_edge(
            list(ratios),
            n,
            child,
            restitution=cell["restitution"],
            friction=cell["friction"],
            rolling_resistance=cell["resistance"],
            pivoting_resistance=cell["resistance"],
        )
        edge[:, j] = [s.p for _, s in rows]
    return BouncingEdges(tuple(ratios), tuple(cells), edge, n, streams.reported_seed(root))


# --- maps over (e, μ) ---------------------------------------------------------------------------
@dataclass(frozen=True)
class ContactMaps:
    """P(same side at rest) and P(edge) over a grid of restitution × friction.

    ``same`` and ``edge`` have shape (len(friction), len(restitution)); ``n`` tosses per cell,
    the same tosses in every cell; ``unsettled`` counts the tosses that had not settled when
    the simulation stopped, per cell.
    """

    restitution: NDArray[np.float64]
    friction: NDArray[np.float64]
    same: NDArray[np.float64]
    edge: NDArray[np.float64]
    unsettled: NDArray[np.int64]
    n: int
    seed: int
    elapsed: float

    def stderr(self, p: NDArray[np.float64]) -> NDArray[np.float64]:
        """Binomial standard errors of cell probabilities ``p``."""
        return np.sqrt(p * (1.0 - p) / self.n)


def _faces(
    coin: Coin, omega: NDArray[np.float64], v0: NDArray[np.float64], e: float, mu: float
) -> tuple[NDArray[np.int8], NDArray[np.int8]]:
    from coinflight.outcomes.table import land

    out = land(coin, omega, v0, 1.0, 9.81, Surface("table", DROP_HEIGHT, e, mu))
    return out.face, out.status


def contact_maps(
    n: int,
    seed: streams.SeedLike,
    restitution: NDArray[np.float64] | None = None,
    friction: NDArray[np.float64] | None = None,
) -> ContactMaps:
    """The maps over e ∈ [0, 0.9] × μ ∈ [0, 1] (default 10 × 11 cells), ``n`` tosses of
    :func:`map_tosses` per cell, landing on a table :data:`DROP_HEIGHT` below launch (the
    rolling and pivoting resistance, the contact duration and the rim's sharp corners at
    :class:`~coinflight.model.surface.Surface`'s defaults: :func:`nickel_band` varies them).

    Cost: cells × ``n`` landings carried to rest (those at e = 0 end at their first impact),
    bounded before anything runs."""
    from coinflight.core.outcome import EDGE, HEADS
    from coinflight.outcomes.table import STATUS_NAMES

    e = np.linspace(0.0, 0.9, 10) if restitution is None else np.asarray(restitution, float)
    mu = np.linspace(0.0, 1.0, 11) if friction is None else np.asarray(friction, float)
    n = v.count("tosses per cell", n, 1, 10**7)
    _bound(
        f"maps of {len(mu)} × {len(e)} cells × {n} tosses",
        (len(e) * len(mu) * n, Surface("table").rolling_resistance),
    )
    t0 = time.perf_counter()
    root = streams.seed_sequence(seed)
    dist = map_tosses()
    omega, v0 = _draw(dist, n, streams.child(root, _MAPS))
    same = np.empty((len(mu), len(e)))
    edge = np.empty_like(same)
    unsettled = np.empty(same.shape, dtype=np.int64)
    for i, m in enumerate(mu):
        for j, r in enumerate(e):
            face, status = _faces(dist.coin, omega, v0, float(r), float(m))
            same[i, j] = np.count_nonzero(face == HEADS) / n  # started heads up
            edge[i, j] = np.count_nonzero(face == EDGE) / n
            unsettled[i, j] = np.count_nonzero(status == STATUS_NAMES.index("unsettled"))
    return ContactMaps(
        e, mu, same, edge, unsettled, n, streams.reported_seed(root), time.perf_counter() - t0
    )


def _bound(what: str, *parts: tuple[int, ArrayLike]) -> None:
    """Refuse landings carried to rest beyond the run limit
    (:data:`coinflight._validation.MAX_RUN_SECONDS`): ``parts`` are (tosses, their rolling and
    pivoting resistance ℓ_r = ℓ_p, m; an array of them for tosses that draw it, each value as
    likely), each timed at :func:`coinflight.outcomes.table.rigid_rate` (dead landings are
    faster)."""
    from coinflight.outcomes.table import rigid_rate

    seconds = 0.0
    for tosses, resistance in parts:
        ell = np.atleast_1d(np.asarray(resistance, dtype=float))
        seconds += tosses * float(np.mean(1.0 / rigid_rate(ell, ell)))
    v.work_bound(what, seconds, v.MAX_RUN_SECONDS, "s", "use fewer cells or tosses (--quick)")


# --- the nickel's P(edge) band ----------------------------------------------------------------
RESISTANCES = RESISTANCE_BAND
"""Rolling and pivoting resistance ℓ_r = ℓ_p of the bands, m: the ends of the range
:mod:`coinflight.model.surface` carries (an assumption there: no source measures it for a
coin; a hard rim on hard wood to a rim on a soft cloth). Integrated log-uniformly."""
CORNER_RADIUS = 2.5e-4
"""The most rounded rim corner of the nickel's band, m: an assumption. No source gives the corner
radius of a nickel's rim; 0.25 mm (about a quarter of its half-thickness, 0.975 mm), our
choice of a clearly rounded corner, leaves a flat band 1.45 mm wide. Integrated uniformly from
0 (sharp)."""
EDGE_PATHS = ("at an impact", "rolled on its band", "upright, below the barrier", "not settled")
"""How a landing that ends on edge ended (:func:`traced_landings`): at an impact of
the bounces, its whole energy below the edge well's barrier; rolling straight on its band to
rest (:data:`coinflight.core.rigid_ending.ENDED_BAND`); upright on its band (spinning about the
vertical or rocking) until its energy fell below the edge well's barrier
(:data:`~coinflight.core.rigid_ending.ENDED_BARRIER`); or not settled within the landing's
limits (counted by the well it was in)."""
_AT_IMPACT, _BAND_ROLL, _UPRIGHT, _NOT_SETTLED = range(4)
_FACE_DOWN = -1  # ended lying on a face (not an edge: no path)


def traced_landings(
    coin: Coin,
    omega: NDArray[np.float64],
    v0: NDArray[np.float64],
    restitution: float | NDArray[np.float64],
    friction: float | NDArray[np.float64],
    resistance: float | NDArray[np.float64],
    corner: float | NDArray[np.float64],
    g: float = 9.81,
) -> tuple[NDArray[np.int8], NDArray[np.int8]]:
    """Land tosses (ω (n, 3) rad/s, v0 (n,) m/s, heads up) on a table :data:`DROP_HEIGHT`
    below, each with its own e, μ, ℓ_r = ℓ_p (m) and ``coin``'s rim
    corners rounded to ``corner`` (m; scalars or arrays of shape (n,)): (faces at rest, how
    each ended: an index of :data:`EDGE_PATHS`, −1 for a coin ended flat on a face).

    The same kernels as :func:`coinflight.outcomes.table.land` (the bounces of
    :func:`coinflight.core.bounce.bounce_loop`, then :func:`coinflight.core.rigid_ending.run`),
    called toss by toss from here to read how each landing stopped, which ``land`` does not
    return; the faces are ``land``'s (tests/test_landing_rigid_band.py). One thread; its work
    is not bounded here (:func:`nickel_band` bounds its own)."""
    from coinflight.core import bounce, rigid_ending
    from coinflight.core.outcome import Status
    from coinflight.outcomes.table import contact_record

    n = len(v0)
    e, mu, ell, a = (
        np.broadcast_to(np.asarray(x, dtype=float), (n,))
        for x in (restitution, friction, resistance, corner)
    )
    face = np.empty(n, dtype=np.int8)
    path = np.full(n, _FACE_DOWN, dtype=np.int8)
    records: dict[float, Any] = {}
    y = np.empty(10)
    counts = np.empty(8)
    ended = {
        rigid_ending.ENDED_BAND: _BAND_ROLL,
        rigid_ending.ENDED_BARRIER: _UPRIGHT,
        rigid_ending.ENDED_LIMIT: _NOT_SETTLED,
    }
    for k in range(n):
        rim = float(a[k])
        if rim not in records:
            table = Surface("table", DROP_HEIGHT)
            records[rim] = contact_record(coin.with_corner_radius(rim), table, g)
        record = records[rim]
        c = bounce.with_surface(record, e[k], mu[k], ell[k], ell[k], record.contact_duration)
        w = (float(omega[k, 0]), float(omega[k, 1]), float(omega[k, 2]))
        f, _, _, _, status, z, v, normal, lm = bounce.bounce_loop(
            w, 1.0, float(v0[k]), c, bounce.MAX_IMPACTS
        )
        if status == bounce.DIED_OUT:
            y[0] = z
            y[1:4] = v
            y[4:7] = normal
            y[7:10] = lm
            f, status, _ = rigid_ending.run(y, c, rigid_ending.RTOL, rigid_ending.DURATION, counts)
            way = ended.get(int(counts[7]), _FACE_DOWN)
        else:
            way = _AT_IMPACT if status == Status.SETTLED_ENERGY else _NOT_SETTLED
        face[k] = f
        if f == EDGE:
            path[k] = way
    return face, path


def _path_counts(face: NDArray[np.int8], path: NDArray[np.int8]) -> NDArray[np.int64]:
    """Edges by how they ended (:data:`EDGE_PATHS`)."""
    return np.bincount(path[face == EDGE], minlength=len(EDGE_PATHS)).astype(np.int64)


@dataclass(frozen=True)
class Band:
    """The nickel's P(edge) over one surface preset's e and μ, the
    resistances :data:`RESISTANCES` and the corner radius 0 to :data:`CORNER_RADIUS`: the
    box's 16 corners and its centre.

    Attributes
    ----------
    preset : str
    restitution, friction, resistance, corner : tuple of float
        The ends of each range (e, μ from the preset; ℓ_r = ℓ_p and a in m).
    edge : ndarray, shape (2, 2, 2, 2)
        P(edge) at the corners of the box, indexed [corner radius, resistance, friction,
        restitution] (low end 0, high end 1), the same ``n`` tosses in every cell.
    paths : ndarray, shape (2, 2, 2, 2, len(EDGE_PATHS))
        The cells' edges by how they ended (:data:`EDGE_PATHS`).
    centre : float
        P(edge) at the box's centre (e and μ mid-range, ℓ the geometric mean of its ends, a
        half the most rounded corner), the same tosses.
    integrated : BinomialEstimate
        Edges of ``integrated.n`` tosses with e and μ uniform over the preset, ℓ log-uniform
        and a uniform over their ranges, drawn toss by toss.
    integrated_paths : ndarray, shape (len(EDGE_PATHS),)
        Those edges by how they ended.
    """

    preset: str
    restitution: tuple[float, float]
    friction: tuple[float, float]
    resistance: tuple[float, float]
    corner: tuple[float, float]
    edge: NDArray[np.float64]
    paths: NDArray[np.int64]
    n: int
    integrated: BinomialEstimate
    integrated_paths: NDArray[np.int64]
    centre: float = math.nan
    sources: dict[str, str] = field(default_factory=dict)

    def _cells(self) -> NDArray[np.float64]:
        cells = self.edge.ravel()
        return cells if math.isnan(self.centre) else np.append(cells, self.centre)

    @property
    def low(self) -> tuple[float, float]:
        """(P, s.e.) of the lowest cell (corners and centre)."""
        return _with_stderr(float(self._cells().min()), self.n)

    @property
    def high(self) -> tuple[float, float]:
        """(P, s.e.) of the highest cell (corners and centre)."""
        return _with_stderr(float(self._cells().max()), self.n)

    def axis(self, k: int) -> tuple[tuple[float, float], tuple[float, float]]:
        """(P, s.e.) of the cells at the low and at the high end of axis ``k`` (0 corner
        radius, 1 resistance, 2 friction, 3 restitution), pooled over the other axes (the
        s.e. binomial over the 8 ``n`` landings; the cells share their tosses, so it is a
        scale rather than an exact error)."""
        tosses = self.n * self.edge.size // 2
        low, high = (float(np.take(self.edge, end, axis=k).mean()) for end in (0, 1))
        return _with_stderr(low, tosses), _with_stderr(high, tosses)


@dataclass(frozen=True)
class NickelBand:
    """The nickel's P(edge): one :class:`Band` per surface preset, and
    the limit of a fully rounded rim (a = h/2: no flat band) that must leave none on edge."""

    bands: tuple[Band, ...]
    round_rim: BinomialEstimate
    """Edges of the cell tosses with the parameters of the first preset's highest cell and the
    corners rounded to half the thickness (a = h/2)."""
    round_rim_parameters: dict[str, float]
    seed: int
    seconds: float


def nickel_band(n: int, seed: streams.SeedLike, integrated: int | None = None) -> NickelBand:
    """The US nickel's P(edge) as a band over what is not measured: for each surface preset
    (:data:`coinflight.studies.presets.SURFACE_PRESETS`), ``n`` tosses of :func:`map_tosses`
    in each of the 16 corners of the box of e, μ (the preset's), ℓ_r = ℓ_p
    (:data:`RESISTANCES`) and the corner radius (0 to :data:`CORNER_RADIUS`), and at its
    centre (:attr:`Band.centre`), the same tosses in every cell; ``integrated`` tosses (default
    4 ``n``) with the four drawn toss by toss (e, μ, a uniform, ℓ log-uniform); and the ``n``
    tosses once more with the corners rounded to h/2. Each edge is counted by how it ended
    (:data:`EDGE_PATHS`, :func:`traced_landings`). The contact duration is held at the
    surface's default (it decides only landings within a fraction of a degree of flat or
    upright).

    Cost: 2 × (17 ``n`` + ``integrated``) + ``n`` landings carried to rest, bounded before
    anything runs at :func:`~coinflight.outcomes.table.rigid_rate` of each cell's resistance;
    the cells at ℓ = 1e-5 m (coins rolling long on their rims) take most of it.
    """
    from coinflight.studies.presets import SURFACE_PRESETS

    t0 = time.perf_counter()
    n = v.count("tosses per cell", n, 1, 10**6)
    integrated = v.count("integrated tosses", 4 * n if integrated is None else integrated, 1, 10**7)
    presets = list(SURFACE_PRESETS.values())
    lo, hi = RESISTANCES
    drawn = np.exp(np.linspace(math.log(lo), math.log(hi), 64))  # log-uniform, integrated
    per_preset = ((8 * n, lo), (8 * n, hi), (n, math.sqrt(lo * hi)), (integrated, drawn))
    _bound(
        f"the nickel's band: {len(presets)} presets × (17 cells × {n} + {integrated}) + {n} tosses",
        *(per_preset * len(presets)),
        (n, lo),  # the rounded rim, in the cell of the highest P(edge): at most the slowest
    )
    root = streams.seed_sequence(seed)
    dist = map_tosses()
    coin = dist.coin
    omega, v0 = _draw(dist, n, streams.child(root, _BAND, 0))
    corners = (0.0, CORNER_RADIUS)
    bands = []
    for k, preset in enumerate(presets):
        e_ends = preset.restitution.bounds
        mu_ends = preset.friction.bounds
        edge = np.empty((2, 2, 2, 2))
        paths = np.empty((2, 2, 2, 2, len(EDGE_PATHS)), dtype=np.int64)
        for ia, a in enumerate(corners):
            for il, ell in enumerate(RESISTANCES):
                for im, mu in enumerate(mu_ends):
                    for ie, e in enumerate(e_ends):
                        face, path = traced_landings(coin, omega, v0, e, mu, ell, a, dist.g)
                        edge[ia, il, im, ie] = np.count_nonzero(face == EDGE) / n
                        paths[ia, il, im, ie] = _path_counts(face, path)
        mid = (
            float(np.mean(e_ends)),
            float(np.mean(mu_ends)),
            math.sqrt(RESISTANCES[0] * RESISTANCES[1]),
            CORNER_RADIUS / 2.0,
        )
        face, _ = traced_landings(coin, omega, v0, *mid, dist.g)
        centre = np.count_nonzero(face == EDGE) / n
        w, v_int = _draw(dist, integrated, streams.child(root, _BAND, 1 + k, 0))
        cube = streams.unit_cube(streams.child(root, _BAND, 1 + k, 1), integrated, 4)
        u = np.concatenate(list(cube), axis=1)  # (4, integrated): e, μ, ℓ, a
        log_lo, log_hi = (math.log(x) for x in RESISTANCES)
        face, path = traced_landings(
            coin,
            w,
            v_int,
            preset.restitution.ppf(u[0]),
            preset.friction.ppf(u[1]),
            np.exp(log_lo + (log_hi - log_lo) * u[2]),
            CORNER_RADIUS * u[3],
            dist.g,
        )
        estimate = BinomialEstimate(
            int(np.count_nonzero(face == EDGE)), integrated, streams.reported_seed(root)
        )
        bands.append(
            Band(
                preset.name,
                (float(e_ends[0]), float(e_ends[1])),
                (float(mu_ends[0]), float(mu_ends[1])),
                RESISTANCES,
                corners,
                edge,
                paths,
                n,
                estimate,
                _path_counts(face, path),
                centre,
                dict(preset.sources),
            )
        )
    first = bands[0]
    _, il, im, ie = (int(i) for i in np.unravel_index(int(np.argmax(first.edge)), (2, 2, 2, 2)))
    worst = {
        "restitution": first.restitution[ie],
        "friction": first.friction[im],
        "resistance": first.resistance[il],
        "corner_radius": coin.thickness / 2.0,
    }
    face, _ = traced_landings(
        coin,
        omega,
        v0,
        worst["restitution"],
        worst["friction"],
        worst["resistance"],
        worst["corner_radius"],
        dist.g,
    )
    round_rim = BinomialEstimate(
        int(np.count_nonzero(face == EDGE)), n, streams.reported_seed(root)
    )
    return NickelBand(
        tuple(bands), round_rim, worst, streams.reported_seed(root), time.perf_counter() - t0
    )


# --- MuJoCo --------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LandingRun:
    """coinflight's landing of the compared tosses: faces at rest, what did not settle, time."""

    rest: NDArray[np.int8]
    unsettled: int
    """Tosses that had not settled when the simulation stopped (counted by their well)."""
    seconds: float
    """Wall time of the landings (compiled before timing), s."""
    at_impact: int = 0
    """Tosses ended at an impact by the energy test (status SETTLED_ENERGY), before the
    rigid 3-D phase of the landing starts."""


@dataclass(frozen=True)
class MujocoComparison:
    """Identical tosses in coinflight and MuJoCo; see :func:`mujoco_comparison`.

    ``coinflight`` is coinflight's landing of the tosses (:class:`LandingRun`), with MuJoCo's
    torsional and rolling friction as its pivoting and rolling resistance; ``first``
    coinflight's wells at the first contact; ``mujoco`` MuJoCo's run (faces at the first
    contact and at the end, the tosses still moving at its limit, how long each took to
    settle).
    """

    n: int
    seed: int
    restitution: float
    friction: float
    first: NDArray[np.int8]
    coinflight: LandingRun
    mujoco: Any  # mujoco_compare.MujocoRun (a module importable without MuJoCo)
    settings: dict[str, Any]
    rolling_resistance: float = 0.0
    """coinflight's rolling resistance ℓ_r, m (MuJoCo's rolling friction)."""
    pivoting_resistance: float = 0.0
    """coinflight's pivoting resistance ℓ_p, m (MuJoCo's torsional friction)."""

    @property
    def mujoco_first(self) -> NDArray[np.int8]:
        """MuJoCo's wells at the first contact."""
        return np.asarray(self.mujoco.first)

    @property
    def mujoco_rest(self) -> NDArray[np.int8]:
        """MuJoCo's faces at the end (the moving tosses by the well they were in)."""
        return np.asarray(self.mujoco.rest)

    @property
    def mujoco_moving(self) -> NDArray[np.bool_]:
        """MuJoCo tosses still moving at its settle limit (most rolling on their edge)."""
        return np.asarray(self.mujoco.moving)

    @property
    def mujoco_seconds(self) -> float:
        """MuJoCo's wall time, s."""
        return float(self.mujoco.elapsed)

    @property
    def rest_agreement(self) -> float:
        """Fraction of tosses with the same face at rest in coinflight and in MuJoCo."""
        return float(np.mean(self.coinflight.rest == self.mujoco_rest))

    @property
    def speed_ratio(self) -> float:
        """coinflight's tosses a second over MuJoCo's (same tosses, same machine, one run)."""
        return self.mujoco_seconds / self.coinflight.seconds

    @property
    def first_agreement(self) -> float:
        """Fraction of tosses in the same well at the first contact."""
        return float(np.mean(self.first == self.mujoco_first))

    @property
    def mujoco_unsettled(self) -> int:
        """MuJoCo tosses still moving at the settle limit (most rolling on their edge)."""
        return int(np.count_nonzero(self.mujoco_moving))

    def fractions(self, faces: NDArray[np.int8]) -> NDArray[np.float64]:
        """(tails, heads, edge) fractions of face codes."""
        return np.bincount(faces, minlength=3) / self.n

    def stderrs(self, faces: NDArray[np.int8]) -> NDArray[np.float64]:
        """Binomial standard errors of :meth:`fractions`."""
        p = self.fractions(faces)
        return np.sqrt(p * (1.0 - p) / self.n)


def mujoco_comparison(
    n: int,
    seed: streams.SeedLike,
    restitution: float = DEFAULT_RESTITUTION,
    friction: float = DEFAULT_FRICTION,
    threads: int | None = None,
    limit: float | None = None,
) -> MujocoComparison:
    """``n`` tosses of :func:`mujoco_tosses` on a table :data:`DROP_HEIGHT` below launch, in
    coinflight (:func:`coinflight.outcomes.table.land`) and in MuJoCo
    (:func:`coinflight.studies.mujoco_compare.run`, each toss carried until it settles or
    ``limit`` s past its first contact, default
    :data:`~coinflight.studies.mujoco_compare.SETTLE`); ImportError without MuJoCo.

    coinflight's landing is given MuJoCo's rolling and torsional friction as its rolling and
    pivoting resistance (:data:`~coinflight.studies.mujoco_compare.ROLLING`,
    :data:`~coinflight.studies.mujoco_compare.TORSIONAL`). How the two contact models still
    differ (MuJoCo's pyramidal cone and soft, creeping friction, instantaneous against soft
    impacts) is listed in :mod:`coinflight.studies.mujoco_compare`. Cost: ``n`` landings
    carried to rest in coinflight, and MuJoCo's
    (:func:`~coinflight.studies.mujoco_compare.seconds_estimate`, bounded before it runs).
    """
    from coinflight.studies import mujoco_compare

    n = v.count("MuJoCo tosses", n, 1, 10**6)
    limit = mujoco_compare.SETTLE if limit is None else limit
    mujoco_compare.check_limit(limit)
    mujoco_compare.bound([n], limit)
    _bound(
        f"the MuJoCo comparison: {n} tosses in coinflight",
        (n, max(mujoco_compare.ROLLING, mujoco_compare.TORSIONAL)),
    )
    root = streams.seed_sequence(seed)
    dist = mujoco_tosses()
    omega, v0 = _draw(dist, n, streams.child(root, _MUJOCO))
    rolling, pivoting = mujoco_compare.ROLLING, mujoco_compare.TORSIONAL
    surface = Surface(
        "table",
        DROP_HEIGHT,
        restitution,
        friction,
        rolling_resistance=rolling,
        pivoting_resistance=pivoting,
    )
    ours, first, _ = _landing_run(dist, omega, v0, surface)
    engine = mujoco_compare.Engine(limit=limit)
    theirs = mujoco_compare.run(
        dist.coin, omega, v0, DROP_HEIGHT, restitution, friction, dist.g, threads, engine
    )
    return MujocoComparison(
        n,
        streams.reported_seed(root),
        restitution,
        friction,
        first,
        ours,
        theirs,
        theirs.settings(friction),
        rolling,
        pivoting,
    )


def _unsettled(status: NDArray[np.int8]) -> int:
    from coinflight.core.outcome import Status

    return int(np.count_nonzero(status == Status.UNSETTLED))


def _at_impact(status: NDArray[np.int8]) -> int:
    from coinflight.core.outcome import Status

    return int(np.count_nonzero(status == Status.SETTLED_ENERGY))


def _landing_run(
    dist: TossDistribution,
    omega: NDArray[np.float64],
    v0: NDArray[np.float64],
    surface: Surface,
) -> tuple[LandingRun, NDArray[np.int8], NDArray[np.int8]]:
    """(coinflight's run of the tosses on ``surface``, wells at the first contact, statuses);
    the landings compiled on two tosses before the timing."""
    from coinflight.outcomes.table import land

    land(dist.coin, omega[:2], v0[:2], 1.0, dist.g, surface)  # compile before timing
    t0 = time.perf_counter()
    out = land(dist.coin, omega, v0, 1.0, dist.g, surface)
    seconds = time.perf_counter() - t0
    first = land(dist.coin, omega, v0, 1.0, dist.g, surface, max_bounces=0).face
    run = LandingRun(out.face, _unsettled(out.status), seconds, _at_impact(out.status))
    return run, first, out.status


# --- thick cylinders against experiments ------------------------------------------------------
def thick_experiments(
    n: int,
    seed: streams.SeedLike,
    points: int = 2,
    psi: float | Literal["human"] | None = None,
) -> tuple[EdgeExperiments, list[str]]:
    """The measured thick-cylinder edge fractions shipped with coinflight
    (:func:`coinflight.datasets.edge_experiments`, those a setting simulates:
    :func:`coinflight.studies.edge_experiments.from_dataset`) beside the model's band
    (:func:`coinflight.studies.edge_experiments.edge_experiments`: ``n`` tosses per cell,
    ``points`` values per parameter; ``psi`` a wobble, "human" the toss preset's), from the
    seed's child for this question. Returns (EdgeExperiments, the records left out and why)."""
    from coinflight.datasets import edge_experiments as dataset
    from coinflight.studies.edge_experiments import edge_experiments, from_dataset

    records, left = from_dataset(dataset())
    root = streams.seed_sequence(seed)
    result = edge_experiments(records, n, streams.child(root, _EXPERIMENTS), points=points, psi=psi)
    return result, left


__all__ = [
    "COIN",
    "CORNER_RADIUS",
    "DROP_HEIGHT",
    "EDGE_PATHS",
    "EXPERIMENTS_CHILD",
    "MURRAY_TEARE",
    "RATIOS",
    "RESISTANCES",
    "Band",
    "BouncingEdges",
    "ContactMaps",
    "DeadLanding",
    "LandingRun",
    "MujocoComparison",
    "NickelBand",
    "bouncing_edges",
    "contact_maps",
    "dead_landings",
    "map_tosses",
    "mujoco_comparison",
    "mujoco_tosses",
    "nickel_band",
    "thick_experiments",
    "traced_landings",
]

"""Validation of the table landing: every number of the landing report, computed by the library.

Five questions, each a function returning plain values with their seeds:

* :func:`dead_landings`: tosses landing dead (e = 0) against Yong & Mahadevan's dynamic model
  P(edge) = 2 arctan(h/d)/π (:func:`coinflight.studies.edge.edge_table`);
* :func:`bouncing_edges`: the same tosses bouncing (e and μ over the surface presets' ranges),
  P(edge) per ratio as a band beside the dead landings and the models. Hernández-Navarro &
  Piñero (2021, arXiv:2103.10927) derive P(edge) of a partially inelastic bouncing coin in
  closed form; only their abstract could be read for this project, so their curve is not
  drawn (see the report's words on what it predicts and whether ours agrees);
* :func:`contact_maps`: P(same side at rest) and P(edge) over a grid of restitution e and
  friction μ, the same tosses in every cell (common random numbers: the maps show the effect
  of e and μ, not noise);
* :func:`nickel_band`: the US nickel's P(edge) over the literature's ranges of e and μ
  (:data:`coinflight.studies.presets.SURFACE_PRESETS`): the lowest and highest cell of a grid
  over each preset's box, and the probability integrated over the preset (e and μ drawn toss
  by toss) — a band, not a point, beside Murray & Teare's extrapolated 1 in 6000;
* :func:`mujoco_comparison`: identical tosses in coinflight and in MuJoCo
  (:mod:`coinflight.studies.mujoco_compare`), at the first contact and at rest, with the speed
  of each (coinflight's default ending, the planar rocking hand-off);
* :func:`rigid_nickel`: the US nickel's P(edge) in the rigid 3-D ending, a band over its
  unmeasured parameters, and how the edges ended.

These are validation runs, not predictions: every table number they give depends on the
restitution and friction (and, for the rigid ending, on the rolling and pivoting resistance
and the rim's corner radius), none measured for a coin. A number quoted from here goes with
its band over those parameters (:func:`contact_maps`, :func:`nickel_band`).

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
from numpy.typing import NDArray

from coinflight import _validation as v
from coinflight.core.outcome import EDGE
from coinflight.model.coin import Coin
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import DEFAULT_FRICTION, DEFAULT_RESTITUTION, Surface
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
_DEAD, _MAPS, _BAND, _MUJOCO, _BOUNCING, _EDGES, _EXPERIMENTS, _RIGID = 0, 1, 2, 3, 4, 5, 6, 7
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
    """Simulated P(edge) of the dead-landing tosses when they bounce, over a grid of e and μ.

    ``edge`` has shape (len(ratios), len(friction), len(restitution)); ``n`` tosses per ratio,
    the same tosses in every cell (one seed child for all cells).
    """

    ratios: tuple[float, ...]
    restitution: NDArray[np.float64]
    friction: NDArray[np.float64]
    edge: NDArray[np.float64]
    n: int
    seed: int

    def low(self, k: int) -> tuple[float, float]:
        """(P, s.e.) of ratio ``k``'s lowest cell."""
        p = float(self.edge[k].min())
        return p, math.sqrt(p * (1 - p) / self.n)

    def high(self, k: int) -> tuple[float, float]:
        """(P, s.e.) of ratio ``k``'s highest cell."""
        p = float(self.edge[k].max())
        return p, math.sqrt(p * (1 - p) / self.n)


def bouncing_edges(
    n: int, seed: streams.SeedLike, ratios: tuple[float, ...] = RATIOS, cells: int = 2
) -> BouncingEdges:
    """P(edge) of ``n`` tosses per ratio in the dead-landing setting
    (:func:`coinflight.studies.edge.simulate_edge`: vigorous planar spins, table
    :data:`coinflight.studies.edge.SIM_DROP` below), bouncing with restitution and friction
    on a ``cells`` × ``cells`` grid over :func:`bouncing_box` (ends included), the same
    tosses in every cell. Planar tosses: the rocking ending discards no spin or precession."""
    from coinflight.studies.edge import simulate_edge

    n = v.count("tosses per ratio", n, 1, 10**7)
    cells = v.count("cells per parameter", cells, 2, 20)
    _bound(
        f"bouncing edges: {len(ratios)} ratios × {cells}² cells × {n} tosses",
        len(ratios) * cells * cells * n,
    )
    root = streams.seed_sequence(seed)
    (e_lo, e_hi), (mu_lo, mu_hi) = bouncing_box()
    e = np.linspace(e_lo, e_hi, cells)
    mu = np.linspace(mu_lo, mu_hi, cells)
    edge = np.empty((len(ratios), cells, cells))
    child = streams.child(root, _BOUNCING)
    for i, m in enumerate(mu):
        for j, r in enumerate(e):
            rows = simulate_edge(list(ratios), n, child, restitution=float(r), friction=float(m))
            edge[:, i, j] = [s.p for _, s in rows]
    return BouncingEdges(tuple(ratios), e, mu, edge, n, streams.reported_seed(root))


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
    :func:`map_tosses` per cell, landing on a table :data:`DROP_HEIGHT` below launch."""
    from coinflight.core.outcome import EDGE, HEADS
    from coinflight.outcomes.table import STATUS_NAMES

    e = np.linspace(0.0, 0.9, 10) if restitution is None else np.asarray(restitution, float)
    mu = np.linspace(0.0, 1.0, 11) if friction is None else np.asarray(friction, float)
    n = v.count("tosses per cell", n, 1, 10**7)
    _bound(f"maps of {len(mu)} × {len(e)} cells × {n} tosses", len(e) * len(mu) * n)
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


def _bound(what: str, tosses: int, rigid: bool = False) -> None:
    """Refuse ``tosses`` landings beyond the run limit, at the bouncing rate (or the rigid
    ending's, ``rigid``)."""
    from coinflight.outcomes.table import BOUNCING_TOSSES_PER_SECOND, RIGID_TOSSES_PER_SECOND

    rate = RIGID_TOSSES_PER_SECOND if rigid else BOUNCING_TOSSES_PER_SECOND
    v.work_bound(
        what,
        tosses,
        rate * v.MAX_RUN_SECONDS,
        "tosses",
        "use fewer cells or tosses (--quick)",
        rate,
    )


# --- the nickel's P(edge) band ----------------------------------------------------------------
class _CellExtremes:
    """The lowest and the highest cell of a band of edge fractions (``edge``, ``n`` tosses a
    cell), each as (P, s.e.)."""

    edge: NDArray[np.float64]
    n: int

    @property
    def low(self) -> tuple[float, float]:
        """(P, s.e.) of the lowest cell."""
        p = float(self.edge.min())
        return p, math.sqrt(p * (1 - p) / self.n)

    @property
    def high(self) -> tuple[float, float]:
        """(P, s.e.) of the highest cell."""
        p = float(self.edge.max())
        return p, math.sqrt(p * (1 - p) / self.n)


@dataclass(frozen=True)
class Band(_CellExtremes):
    """The nickel's P(edge) over one surface preset's ranges of e and μ.

    Attributes
    ----------
    preset : str
    restitution, friction : ndarray
        The grid over the preset's box (its ends and interior points).
    edge : ndarray, shape (len(friction), len(restitution))
        P(edge) per cell, the same ``n`` tosses in every cell.
    integrated : BinomialEstimate
        Edges of ``n`` tosses with e and μ drawn toss by toss from the preset
        (:meth:`~coinflight.model.ensemble.TossDistribution.with_contact`, Monte Carlo).
    """

    preset: str
    restitution: NDArray[np.float64]
    friction: NDArray[np.float64]
    edge: NDArray[np.float64]
    n: int
    integrated: BinomialEstimate
    sources: dict[str, str] = field(default_factory=dict)


def nickel_band(n: int, seed: streams.SeedLike, cells: int = 3) -> list[Band]:
    """P(edge) of the US nickel over each surface preset's box (``cells`` × ``cells`` grid,
    ``n`` tosses of :func:`map_tosses` per cell) and integrated over it (``n`` tosses)."""
    from coinflight.core.outcome import EDGE
    from coinflight.outcomes.table import TableLanding
    from coinflight.probability import monte_carlo
    from coinflight.studies.presets import SURFACE_PRESETS

    n = v.count("tosses per cell", n, 1, 10**8)
    cells = v.count("cells per parameter", cells, 2, 50)
    _bound(
        f"the nickel band: {len(SURFACE_PRESETS)} presets × ({cells}² cells + 1) × {n} tosses",
        len(SURFACE_PRESETS) * (cells * cells + 1) * n,
    )
    root = streams.seed_sequence(seed)
    dist = map_tosses()
    omega, v0 = _draw(dist, n, streams.child(root, _BAND, 0))
    out = []
    for k, preset in enumerate(SURFACE_PRESETS.values()):
        e = np.linspace(*preset.restitution.bounds, cells)
        mu = np.linspace(*preset.friction.bounds, cells)
        edge = np.empty((cells, cells))
        for i, m in enumerate(mu):
            for j, r in enumerate(e):
                face, _ = _faces(dist.coin, omega, v0, float(r), float(m))
                edge[i, j] = np.count_nonzero(face == EDGE) / n
        spread = dist.with_contact(**preset.contact)
        model = TableLanding(Surface("table", drop_height=DROP_HEIGHT))
        result = monte_carlo.estimate(spread, n, streams.child(root, _BAND, 1 + k), model=model)
        assert result.counts is not None  # Monte Carlo counts its tosses
        integrated = BinomialEstimate(int(result.counts[2]), n, streams.reported_seed(root))
        out.append(Band(preset.name, e, mu, edge, n, integrated, dict(preset.sources)))
    return out


# --- the nickel's P(edge) band in the rigid ending ---------------------------------------------
RIGID_RESISTANCES = (1e-5, 1e-3)
"""Rolling and pivoting resistance ℓ_r = ℓ_p of the rigid band, m: the ends of the band
:mod:`coinflight.model.surface` carries (an assumption there: no source measures it for a
coin; a hard rim on hard wood to a rim on a soft cloth). Integrated log-uniformly."""
RIGID_CORNER = 2.5e-4
"""The most rounded rim corner of the rigid band, m: an assumption. No source gives the corner
radius of a nickel's rim; 0.25 mm (about a quarter of its half-thickness, 0.975 mm), our
choice of a clearly rounded corner, leaves a flat band 1.45 mm wide. Integrated uniformly from
0 (sharp)."""
RIGID_PATHS = ("at an impact", "rolled on its band", "upright, below the barrier", "not settled")
"""How a rigid-ending landing that ends on edge ended (:func:`rigid_landings`): at an impact of
the bounces, its whole energy below the edge well's barrier; rolling straight on its band to
rest (:data:`coinflight.core.rigid_ending.ENDED_BAND`); upright on its band (spinning about the
vertical or rocking) until its energy fell below the edge well's barrier
(:data:`~coinflight.core.rigid_ending.ENDED_BARRIER`); or not settled within the ending's
limits (counted by the well it was in)."""
_AT_IMPACT, _BAND_ROLL, _UPRIGHT, _NOT_SETTLED = range(4)
_FACE_DOWN = -1  # ended lying on a face (not an edge: no path)


def rigid_landings(
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
    below with the rigid ending, each with its own e, μ, ℓ_r = ℓ_p (m) and ``coin``'s rim
    corners rounded to ``corner`` (m; scalars or arrays of shape (n,)): (faces at rest, how
    each ended: an index of :data:`RIGID_PATHS`, −1 for a coin ended flat on a face).

    The same kernels as :func:`coinflight.outcomes.table.land` (the bounces of
    :func:`coinflight.core.bounce.bounce_loop`, then :func:`coinflight.core.rigid_ending.run`),
    called toss by toss from here to read how each ending stopped, which ``land`` does not
    return; the faces are ``land``'s (tests/test_landing_rigid_band.py). One thread; its work
    is not bounded here (:func:`rigid_nickel` bounds its own)."""
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
            table = Surface("table", DROP_HEIGHT, ending="rigid")
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
    """Edges by how they ended (:data:`RIGID_PATHS`)."""
    return np.bincount(path[face == EDGE], minlength=len(RIGID_PATHS)).astype(np.int64)


@dataclass(frozen=True)
class RigidBand(_CellExtremes):
    """The nickel's P(edge) in the rigid ending over one surface preset's e and μ, the
    resistances :data:`RIGID_RESISTANCES` and the corner radius 0 to :data:`RIGID_CORNER`.

    Attributes
    ----------
    preset : str
    restitution, friction, resistance, corner : tuple of float
        The ends of each range (e, μ from the preset; ℓ_r = ℓ_p and a in m).
    edge : ndarray, shape (2, 2, 2, 2)
        P(edge) at the corners of the box, indexed [corner radius, resistance, friction,
        restitution] (low end 0, high end 1), the same ``n`` tosses in every cell.
    paths : ndarray, shape (2, 2, 2, 2, len(RIGID_PATHS))
        The cells' edges by how they ended (:data:`RIGID_PATHS`).
    integrated : BinomialEstimate
        Edges of ``integrated.n`` tosses with e and μ uniform over the preset, ℓ log-uniform
        and a uniform over their ranges, drawn toss by toss.
    integrated_paths : ndarray, shape (len(RIGID_PATHS),)
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
    sources: dict[str, str] = field(default_factory=dict)

    def axis(self, k: int) -> tuple[tuple[float, float], tuple[float, float]]:
        """(P, s.e.) of the cells at the low and at the high end of axis ``k`` (0 corner
        radius, 1 resistance, 2 friction, 3 restitution), pooled over the other axes (the
        s.e. binomial over the 8 ``n`` landings; the cells share their tosses, so it is a
        scale rather than an exact error)."""
        out = []
        for end in (0, 1):
            p = float(np.take(self.edge, end, axis=k).mean())
            tosses = self.n * self.edge.size // 2
            out.append((p, math.sqrt(p * (1 - p) / tosses)))
        return out[0], out[1]


@dataclass(frozen=True)
class RigidNickel:
    """The nickel's P(edge) in the rigid ending: one :class:`RigidBand` per surface preset, and
    the limit of a fully rounded rim (a = h/2: no flat band) that must leave none on edge."""

    bands: tuple[RigidBand, ...]
    round_rim: BinomialEstimate
    """Edges of the cell tosses with the parameters of the first preset's highest cell and the
    corners rounded to half the thickness (a = h/2)."""
    round_rim_parameters: dict[str, float]
    seed: int
    seconds: float


def rigid_nickel(n: int, seed: streams.SeedLike, integrated: int | None = None) -> RigidNickel:
    """The US nickel's P(edge) with the rigid ending (``Surface(ending="rigid")``), a band over
    what is not measured: for each surface preset
    (:data:`coinflight.studies.presets.SURFACE_PRESETS`), ``n`` tosses of :func:`map_tosses`
    in each of the 16 corners of the box of e, μ (the preset's), ℓ_r = ℓ_p
    (:data:`RIGID_RESISTANCES`) and the corner radius (0 to :data:`RIGID_CORNER`), the same
    tosses in every cell; ``integrated`` tosses (default
    4 ``n``) with the four drawn toss by toss (e, μ, a uniform, ℓ log-uniform); and the ``n``
    tosses once more with the corners rounded to h/2. Each edge is counted by how it ended
    (:data:`RIGID_PATHS`, :func:`rigid_landings`). The contact duration is held at the
    surface's default (it decides only landings within a fraction of a degree of flat or
    upright).

    Cost: 2 × (16 ``n`` + ``integrated``) + ``n`` rigid landings (the report's 100 and 400:
    about 4,100, half a minute on 2 cores), bounded before anything runs at
    :data:`~coinflight.outcomes.table.RIGID_TOSSES_PER_SECOND`; the cells at ℓ = 1e-5 m
    (coins rolling long on their rims) take most of it.
    """
    from coinflight.studies.presets import SURFACE_PRESETS

    t0 = time.perf_counter()
    n = v.count("tosses per cell", n, 1, 10**6)
    integrated = v.count("integrated tosses", 4 * n if integrated is None else integrated, 1, 10**7)
    presets = list(SURFACE_PRESETS.values())
    total = len(presets) * (16 * n + integrated) + n
    _bound(
        f"the nickel's rigid band: {len(presets)} presets × (16 cells × {n} + {integrated}) "
        f"+ {n} tosses",
        total,
        rigid=True,
    )
    root = streams.seed_sequence(seed)
    dist = map_tosses()
    coin = dist.coin
    omega, v0 = _draw(dist, n, streams.child(root, _RIGID, 0))
    corners = (0.0, RIGID_CORNER)
    bands = []
    for k, preset in enumerate(presets):
        e_ends = preset.restitution.bounds
        mu_ends = preset.friction.bounds
        edge = np.empty((2, 2, 2, 2))
        paths = np.empty((2, 2, 2, 2, len(RIGID_PATHS)), dtype=np.int64)
        for ia, a in enumerate(corners):
            for il, ell in enumerate(RIGID_RESISTANCES):
                for im, mu in enumerate(mu_ends):
                    for ie, e in enumerate(e_ends):
                        face, path = rigid_landings(coin, omega, v0, e, mu, ell, a, dist.g)
                        edge[ia, il, im, ie] = np.count_nonzero(face == EDGE) / n
                        paths[ia, il, im, ie] = _path_counts(face, path)
        w, v_int = _draw(dist, integrated, streams.child(root, _RIGID, 1 + k, 0))
        cube = streams.unit_cube(streams.child(root, _RIGID, 1 + k, 1), integrated, 4)
        u = np.concatenate(list(cube), axis=1)  # (4, integrated): e, μ, ℓ, a
        log_lo, log_hi = (math.log(x) for x in RIGID_RESISTANCES)
        face, path = rigid_landings(
            coin,
            w,
            v_int,
            preset.restitution.ppf(u[0]),
            preset.friction.ppf(u[1]),
            np.exp(log_lo + (log_hi - log_lo) * u[2]),
            RIGID_CORNER * u[3],
            dist.g,
        )
        estimate = BinomialEstimate(
            int(np.count_nonzero(face == EDGE)), integrated, streams.reported_seed(root)
        )
        bands.append(
            RigidBand(
                preset.name,
                (float(e_ends[0]), float(e_ends[1])),
                (float(mu_ends[0]), float(mu_ends[1])),
                RIGID_RESISTANCES,
                corners,
                edge,
                paths,
                n,
                estimate,
                _path_counts(face, path),
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
    face, _ = rigid_landings(
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
    return RigidNickel(
        tuple(bands), round_rim, worst, streams.reported_seed(root), time.perf_counter() - t0
    )


# --- MuJoCo --------------------------------------------------------------------------------------
@dataclass(frozen=True)
class EndingRun:
    """coinflight's faces at rest of the compared tosses with one ending of the landing."""

    ending: str
    """``"rocking"`` (:class:`~coinflight.model.surface.Surface` ``ending``)."""
    rest: NDArray[np.int8]
    unsettled: int
    """Tosses that had not settled when the simulation stopped (counted by their well)."""
    seconds: float
    """Wall time of the landings (compiled before timing), s."""
    at_impact: int = 0
    """Tosses ended at an impact by the energy test (status SETTLED_ENERGY), before the
    ending proper starts."""


@dataclass(frozen=True)
class MujocoComparison:
    """Identical tosses in coinflight and MuJoCo; see :func:`mujoco_comparison`.

    ``rocking`` is coinflight's landing of the tosses with its default ending
    (:class:`EndingRun`); ``first`` coinflight's wells at the first contact; ``mujoco``
    MuJoCo's run (faces at the first contact and at the end, the tosses still moving at its
    limit, how long each took to settle).
    """

    n: int
    seed: int
    restitution: float
    friction: float
    first: NDArray[np.int8]
    rocking: EndingRun
    mujoco: Any  # mujoco_compare.MujocoRun (a module importable without MuJoCo)
    settings: dict[str, Any]

    @property
    def endings(self) -> tuple[EndingRun, ...]:
        """coinflight's runs: the rocking ending's."""
        return (self.rocking,)

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

    def agreement(self, run: EndingRun) -> float:
        """Fraction of tosses with the same face at rest in ``run`` and in MuJoCo."""
        return float(np.mean(run.rest == self.mujoco_rest))

    def ratio(self, run: EndingRun) -> float:
        """``run``'s tosses a second over MuJoCo's (same tosses, same machine, one run)."""
        return self.mujoco_seconds / run.seconds

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

    coinflight lands them with its default ending (planar rocking). How the two contact models
    differ (MuJoCo's pyramidal cone and soft, creeping friction, instantaneous against soft
    impacts) is listed in :mod:`coinflight.studies.mujoco_compare`.
    """
    from coinflight.studies import mujoco_compare

    n = v.count("MuJoCo tosses", n, 1, 10**6)
    limit = mujoco_compare.SETTLE if limit is None else limit
    mujoco_compare.check_limit(limit)
    mujoco_compare.bound([n], limit)
    root = streams.seed_sequence(seed)
    dist = mujoco_tosses()
    omega, v0 = _draw(dist, n, streams.child(root, _MUJOCO))
    surface = Surface("table", DROP_HEIGHT, restitution, friction)
    rocking, first, _ = _ending_run(dist, omega, v0, surface)
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
        rocking,
        theirs,
        theirs.settings(friction),
    )


def _unsettled(status: NDArray[np.int8]) -> int:
    from coinflight.core.outcome import Status

    return int(np.count_nonzero(status == Status.UNSETTLED))


def _at_impact(status: NDArray[np.int8]) -> int:
    from coinflight.core.outcome import Status

    return int(np.count_nonzero(status == Status.SETTLED_ENERGY))


def _ending_run(
    dist: TossDistribution,
    omega: NDArray[np.float64],
    v0: NDArray[np.float64],
    surface: Surface,
) -> tuple[EndingRun, NDArray[np.int8], NDArray[np.int8]]:
    """(coinflight's run of the tosses on ``surface``, wells at the first contact, statuses);
    the landings compiled on two tosses before the timing."""
    from coinflight.outcomes.table import land

    land(dist.coin, omega[:2], v0[:2], 1.0, dist.g, surface)  # compile before timing
    t0 = time.perf_counter()
    out = land(dist.coin, omega, v0, 1.0, dist.g, surface)
    seconds = time.perf_counter() - t0
    first = land(dist.coin, omega, v0, 1.0, dist.g, surface, max_bounces=0).face
    run = EndingRun(
        surface.ending, out.face, _unsettled(out.status), seconds, _at_impact(out.status)
    )
    return run, first, out.status


# --- thick cylinders against experiments ------------------------------------------------------
def thick_experiments(
    n: int,
    seed: streams.SeedLike,
    points: int = 2,
    rigid: int = 0,
    psi: float | Literal["human"] | None = None,
) -> tuple[EdgeExperiments, list[str]]:
    """The measured thick-cylinder edge fractions shipped with coinflight
    (:func:`coinflight.datasets.edge_experiments`, those a setting simulates:
    :func:`coinflight.studies.edge_experiments.from_dataset`) beside the model's band
    (:func:`coinflight.studies.edge_experiments.edge_experiments`: ``n`` rocking tosses per
    cell, ``points`` values per parameter, ``rigid`` rigid-ending tosses per cell; ``psi`` a
    wobble, "human" the toss preset's), from the seed's child for this question.
    Returns (EdgeExperiments, the records left out and why)."""
    from coinflight.datasets import edge_experiments as dataset
    from coinflight.studies.edge_experiments import edge_experiments, from_dataset

    records, left = from_dataset(dataset())
    root = streams.seed_sequence(seed)
    result = edge_experiments(
        records,
        n,
        streams.child(root, _EXPERIMENTS),
        points=points,
        rigid=rigid,
        psi=psi,
    )
    return result, left


__all__ = [
    "COIN",
    "DROP_HEIGHT",
    "EXPERIMENTS_CHILD",
    "MURRAY_TEARE",
    "RATIOS",
    "RIGID_CORNER",
    "RIGID_PATHS",
    "RIGID_RESISTANCES",
    "Band",
    "BouncingEdges",
    "ContactMaps",
    "DeadLanding",
    "EndingRun",
    "MujocoComparison",
    "RigidBand",
    "RigidNickel",
    "bouncing_edges",
    "contact_maps",
    "dead_landings",
    "map_tosses",
    "mujoco_comparison",
    "mujoco_tosses",
    "nickel_band",
    "rigid_landings",
    "rigid_nickel",
    "thick_experiments",
]

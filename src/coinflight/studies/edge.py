"""Thick coins: the probability of landing on edge as a function of thickness / diameter.

Two closed-form models of Yong & Mahadevan (2011, "Probability, geometry, and dynamics in the
tossing of thin disks", Am. J. Phys. 79:1195, arXiv:1008.4559; REFERENCES §5), and the root
finding that gives the ratio h/d for a chosen P(edge) (1/3 for a fair "three-sided coin").
The simulated P(edge) of real bounces comes from :mod:`coinflight.outcomes.table`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core.outcome import EDGE
from coinflight.probability import streams
from coinflight.probability.result import BinomialEstimate

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.distributions import Distribution

EdgeModel = Literal["geometric", "dynamic"]
MODELS: tuple[EdgeModel, ...] = ("geometric", "dynamic")


def edge_probability(ratio: ArrayLike, model: EdgeModel = "dynamic") -> NDArray[np.float64]:
    """P(edge) of a coin of thickness / diameter ``ratio`` = h/d.

    Parameters
    ----------
    ratio : array_like
        h/d ≥ 0.
    model : {"geometric", "dynamic"}
        ``"geometric"``: the coin comes to rest in a uniformly random orientation; it stands on
        its edge when its centre of mass lies above the edge, i.e. when the vertical, seen in
        the coin's frame, points within arctan(h/d) of the coin's plane: a band of the sphere of
        solid-angle fraction sin(arctan(h/d)) = (h/d)/sqrt(1 + (h/d)²).
        ``"dynamic"``: a vigorous toss spinning in a vertical plane lands, without bouncing, at
        a uniformly random angle in that plane: the edge takes 4 arctan(h/d) of the 2π,
        P(edge) = 2 arctan(h/d)/π.

    Notes
    -----
    Yong & Mahadevan 2011, §II (geometric, "solid angle") and §III (dynamic, "planar").
    """
    x = v.non_negative("thickness/diameter ratio", ratio)
    v.choice("edge model", model, MODELS)
    if model == "geometric":
        return np.asarray(x / np.sqrt(1.0 + x * x))
    return np.asarray(2.0 * np.arctan(x) / np.pi)


def ratio_for(probability: float = 1.0 / 3.0, model: EdgeModel = "dynamic") -> float:
    """The ratio h/d at which P(edge) equals ``probability`` (root of :func:`edge_probability`).

    Yong & Mahadevan 2011 find, for P(edge) = 1/3, h/d = 1/(2√2) ≈ 0.354 (geometric) and
    1/√3 ≈ 0.577 (dynamic).

    Examples
    --------
    >>> round(ratio_for(1 / 3, "geometric"), 4), round(ratio_for(1 / 3, "dynamic"), 4)
    (0.3536, 0.5774)
    """
    from scipy.optimize import brentq

    p = v.in_range("edge probability", probability, 0.0, 1.0)
    if p.ndim:
        raise TypeError("edge probability must be a single number")
    if not 0.0 < float(p) < 1.0:
        raise ValueError(f"edge probability must be strictly between 0 and 1, got {float(p)!r}")
    v.choice("edge model", model, MODELS)
    target = float(p)

    def excess(x: float) -> float:
        return float(edge_probability(x, model)) - target

    high = 1.0
    while excess(high) < 0.0:  # both models tend to 1 as h/d → ∞
        high *= 2.0
    return float(brentq(excess, 0.0, high, xtol=1e-15, rtol=4 * np.finfo(float).eps))


SIM_RATIOS = (1e-3, 100.0)
"""Ratios h/d a simulation takes: from a 24 µm foil to a 2.4 m rod (the plot's axis ends at
100 at most, :data:`coinflight.plotting.edge.MAX_RATIO`)."""
MAX_SIM_TOSSES = 10**7
"""Most simulated tosses per ratio (an hour's work bounds the whole run as well)."""
SIM_DIAMETER = 0.024
"""Diameter of the simulated coins, m (a thickness h = ratio × d is made for each ratio)."""
SIM_SPIN = (150.0, 300.0)
"""Spin about a diameter of the simulated tosses, rad/s, uniform: vigorous and planar."""
SIM_LAUNCH_SPEED = (1.5, 3.0)
"""Upward launch speed of the simulated tosses, m/s, uniform."""
SIM_DROP = 0.5
"""The table lies this far below the launch point, m; the coin lands dead on it (e = 0)."""


SIM_RESTITUTION = 0.0
"""Restitution of the simulated landings: dead, as in the dynamic model."""
SIM_FRICTION = 0.3
"""Coulomb friction of the simulated landings, as the table's default
(:data:`coinflight.model.surface.DEFAULT_FRICTION`)."""
SIM_BOUNCING_TOSSES_PER_SECOND = 2_000.0
"""Landings that bounce (restitution above 0), each carried to rest by the rigid ending, a
second, for the work bounds of :func:`simulate_edge`'s own tosses (vigorous planar spins
:data:`SIM_SPIN`, launch speeds :data:`SIM_LAUNCH_SPEED`, coins :data:`SIM_DIAMETER` across,
the table at most :data:`SIM_DROP` below) on a table of restitution up to 0.6: on 2 threads of
a busy 2-core machine they run 4,500 to 29,000 a second (h/d 0.1–3, e 0.3–0.6, μ 0.05–0.6,
resistances 1e-5–1e-3 m; most settle at an impact within 2 s of the launch); this is under
half the slowest. Any other toss (a wobble, a spin, launch speed or diameter of one's own, a
higher drop or restitution) takes the table's rate
(:attr:`coinflight.outcomes.table.TableLanding.rate`): a wobbling cylinder can roll on its
rim for seconds, and on a table of little resistance runs at a few landings a second."""


def simulate_edge(
    ratios: ArrayLike,
    n: int,
    seed: streams.SeedLike = None,
    *,
    g: float = 9.81,
    restitution: float = SIM_RESTITUTION,
    friction: float = SIM_FRICTION,
    drop_height: float = SIM_DROP,
    spin: Distribution | None = None,
    launch_speed: Distribution | None = None,
    rolling_resistance: float | None = None,
    pivoting_resistance: float | None = None,
    corner_radius: float = 0.0,
    diameter: float = SIM_DIAMETER,
    axial_spin: Distribution | None = None,
    executor: Any = None,
    progress: Callable[[int], None] | None = None,
) -> list[tuple[float, BinomialEstimate]]:
    """P(edge) from the full flight and landing (:func:`coinflight.outcomes.table.land`), per ratio.

    Each ratio gets ``n`` tosses of a coin of diameter :data:`SIM_DIAMETER` and thickness
    ratio × d (uniform density), spinning about a diameter at ωx ~ U(:data:`SIM_SPIN`) rad/s,
    launched at v0 ~ U(:data:`SIM_LAUNCH_SPEED`) m/s and landing dead (restitution 0) on a
    table :data:`SIM_DROP` m below: the setting of Yong & Mahadevan's dynamic model, which the
    points should follow.

    Returns (ratio, estimate) pairs, the estimate
    (:class:`~coinflight.probability.result.BinomialEstimate`) counting the tosses on edge.
    Ratio i draws
    from child i of the seed's ``SeedSequence`` through
    :func:`coinflight.probability.streams.unit_cube` (spin and launch speed each from its own
    stream), so the points are independent, a run of n tosses is the first n of a longer run,
    and the first ratios of a longer list give the same points. No seed: a fresh one from the
    OS, reported in every estimate.

    The keywords change the setting (their defaults are the one above): ``restitution``,
    ``friction`` and ``drop_height`` of the table (:class:`coinflight.model.surface.Surface`);
    ``spin`` (ωx, rad/s) and ``launch_speed`` (v0, m/s) as distributions
    (:mod:`coinflight.model.distributions`, drawn through their ``ppf`` from the same streams);
    the launch speed must be positive with certainty; the rigid ending's
    ``rolling_resistance`` and ``pivoting_resistance`` (m;
    :class:`coinflight.model.surface.Surface`), which act only on landings that bounce
    (``restitution`` > 0); ``corner_radius`` a (m, default 0: sharp), the
    rounded rim corners of every ratio's coin (:attr:`coinflight.model.coin.Coin.corner_radius`:
    the impacts, the endings and the face/edge wells take it), at most half the thinnest
    coin's thickness; ``diameter`` (m, default :data:`SIM_DIAMETER`) the coins' diameter d
    (each ratio's thickness is ratio × d); ``axial_spin`` (ωz, rad/s, a distribution; default
    none: ωz = 0, planar tosses) a spin about the coin's axis as well, so that the normal
    precesses on a cone of angle ψ, cot ψ = I3 ωz / (I1 ωx) (Diaconis, Holmes & Montgomery
    2007, §2; :func:`coinflight.core.precession.axial_spin`). ωz is drawn from a third stream
    of each block (the unit cube's third coordinate), so ωx and v0 are the same draws with or
    without it, and without it every result is what it was before the keyword existed.

    ``executor`` (an object with ``map``, or a ``distributed.Client``: :mod:`coinflight.
    probability.distributed`) runs the blocks of :data:`~coinflight.probability.streams.BLOCK`
    tosses of each ratio as separate tasks, each landing its tosses in one thread; the counts
    are the same as without it, bit for bit. ``progress`` is called with the tosses of each
    finished task.
    """
    from coinflight.model.distributions import Distribution, Uniform
    from coinflight.model.ensemble import check_launch_speed
    from coinflight.model.surface import Surface

    x = check_ratios(ratios)
    n = v.count("number of tosses", n, 1, MAX_SIM_TOSSES)
    d = check_diameter(diameter)
    corner = _corner_radius(corner_radius, float(np.min(x)), d)
    resistances = {
        name: value
        for name, value in (
            ("rolling_resistance", rolling_resistance),
            ("pivoting_resistance", pivoting_resistance),
        )
        if value is not None
    }
    surface = Surface(
        "table",
        drop_height=drop_height,
        restitution=restitution,
        friction=friction,
        **resistances,
    )
    rate = landing_rate(surface, spin is None and launch_speed is None and axial_spin is None
                        and d == SIM_DIAMETER)  # fmt: skip
    v.work_bound(
        f"{v.quantity(len(x))} ratios × {v.quantity(n)} tosses",
        len(x) * n,
        rate * v.MAX_RUN_SECONDS,
        "tosses",
        "use fewer ratios or tosses",
        rate,
    )
    streams.check_seed(seed)
    wx = Uniform(*SIM_SPIN) if spin is None else spin
    for name, dist in (("spin", spin), ("launch speed", launch_speed), ("axial spin", axial_spin)):
        if dist is not None and not isinstance(dist, Distribution):
            raise TypeError(f"{name} must be a distribution, got {type(dist).__name__}")
    v0 = check_launch_speed(
        Uniform(*SIM_LAUNCH_SPEED) if launch_speed is None else launch_speed, "launch speed"
    )
    from coinflight.probability._runner import check_runner, executor_or_threads, run_tasks

    check_runner(executor, None, progress)
    root = streams.seed_sequence(seed)
    coins = [cylinder(float(ratio), d, corner) for ratio in x]
    tasks: list[tuple[Any, ...]]
    if executor is None:  # one ratio at a time, each landing on all of numba's threads
        tasks = [(coin, streams.child(root, i), n, 0, None, wx, v0, axial_spin, g, surface, True)
                 for i, coin in enumerate(coins)]  # fmt: skip
        sizes = [n] * len(coins)
    else:  # one task per block of tosses, each in one thread of its worker
        blocks = -(-n // streams.BLOCK)
        tasks = [
            (coin, streams.child(root, i), n, b, b + 1, wx, v0, axial_spin, g, surface, False)
            for i, coin in enumerate(coins)
            for b in range(blocks)
        ]
        sizes = [min(streams.BLOCK, n - b * streams.BLOCK) for _ in coins for b in range(blocks)]
    with executor_or_threads(executor, 1) as ex:
        counts = run_tasks(ex, _edge_task, tasks, sizes, progress)
    per_ratio = len(tasks) // len(coins)
    out = []
    for i, ratio in enumerate(x):
        part = np.asarray(counts[i * per_ratio : (i + 1) * per_ratio]).sum(axis=0)
        estimate = BinomialEstimate(int(part[0]), n, streams.reported_seed(root))
        out.append((float(ratio), estimate))
    return out


def landing_rate(surface: Any, own_toss: bool) -> float:
    """Landings a second on ``surface`` (a table :class:`~coinflight.model.surface.Surface`)
    for the work bounds: :data:`SIM_BOUNCING_TOSSES_PER_SECOND` for landings that bounce
    (restitution above 0, at most 0.6), the table at most :data:`SIM_DROP` below, of
    :func:`simulate_edge`'s own tosses (``own_toss``: its spin, launch speed and diameter, no
    axial spin); else the table's rate (:attr:`coinflight.outcomes.table.TableLanding.rate`:
    the bounces alone for dead landings, the rigid ending's generic rate for bouncing ones)."""
    from coinflight.outcomes.table import TableLanding

    if own_toss and 0.0 < surface.restitution <= 0.6 and surface.drop_height <= SIM_DROP:
        return SIM_BOUNCING_TOSSES_PER_SECOND
    return float(TableLanding(surface).rate)


SIM_DENSITY = 7800.0
"""Density of the simulated cylinders, kg/m³ (steel); uniform, so it sets the mass, not the
outcome (the torque-free flight, the impacts and the wells scale with it)."""


def cylinder(ratio: float, diameter: float = SIM_DIAMETER, corner_radius: float = 0.0) -> Coin:
    """The simulated cylinder of thickness/diameter ``ratio``: ``diameter`` m across, uniform
    density :data:`SIM_DENSITY`, rim corners rounded by ``corner_radius`` m; the one coin of
    :func:`simulate_edge` and of :mod:`coinflight.studies.edge_experiments`."""
    from coinflight.model.coin import Coin

    r, h = 0.5 * diameter, float(ratio) * diameter
    return Coin(radius=r, thickness=h, mass=SIM_DENSITY * np.pi * r * r * h,
                corner_radius=corner_radius)  # fmt: skip


def check_ratios(ratios: ArrayLike) -> NDArray[np.float64]:
    """The ratios h/d as a 1-D array, each inside :data:`SIM_RATIOS`, else ValueError."""
    x = np.atleast_1d(v.in_range("thickness/diameter ratio", ratios, *SIM_RATIOS))
    if x.ndim != 1:
        raise ValueError(f"ratios must be a list of numbers, got shape {x.shape}")
    return x


def check_diameter(value: object) -> float:
    """The simulated coins' diameter ``value`` (m): one positive finite number, else
    TypeError or ValueError naming it."""
    d = v.number("coin diameter", value, "m")
    return float(v.positive("coin diameter", d, "m"))


def simulated_corner_radius(
    value: object, ratios: ArrayLike, diameter: float = SIM_DIAMETER
) -> float:
    """The corner radius ``value`` (m) of the simulated coins of these ratios and ``diameter``
    (m), checked as :func:`simulate_edge` checks it (the thinnest coin bounds it), else
    ValueError."""
    return _corner_radius(value, float(np.min(check_ratios(ratios))), check_diameter(diameter))


def _corner_radius(value: object, thinnest: float, diameter: float = SIM_DIAMETER) -> float:
    """The simulated coins' corner radius ``value`` (m), checked against the thinnest coin's
    half thickness (ratio ``thinnest`` × ``diameter`` / 2) and the coins' radius
    ``diameter`` / 2: the coin's own wording, naming that coin."""
    from coinflight.model.coin import check_corner_radius

    h = thinnest * diameter
    try:
        return check_corner_radius(value, h, 0.5 * diameter)
    except ValueError as exc:
        raise ValueError(f"{exc} of the thinnest coin (h/d = {thinnest:g}, h = {h:g} m)") from None


def _edge_task(args: tuple[Any, ...]) -> NDArray[np.int64]:
    """(tosses on edge,) among blocks ``first`` to ``last`` of one ratio's stream."""
    from coinflight.outcomes.table import land

    coin, stream, n, first, last, wx, v0, wz, g, surface, parallel = args
    counts = np.zeros(1, dtype=np.int64)
    # Row r of each block comes from its own generator (streams.block_generators): a third
    # row for ωz leaves the rows of ωx and v0 as they are.
    k = 2 if wz is None else 3
    for u in streams.unit_cube(stream, n, k, first_block=first, last_block=last):
        omega = np.zeros((u.shape[1], 3))
        omega[:, 0] = wx.ppf(u[0])
        if wz is not None:
            omega[:, 2] = wz.ppf(u[2])
        speed = v0.ppf(u[1])
        out = land(coin, omega, speed, 1.0, g, surface, parallel=parallel)
        counts[0] += int(np.sum(out.face == EDGE))
    return counts


def edge_table(
    ratios: ArrayLike,
    n: int | None = None,
    seed: streams.SeedLike = None,
    *,
    executor: Any = None,
    progress: Callable[[int], None] | None = None,
    **setting: Any,
) -> list[dict[str, Any]]:
    """P(edge) per ratio h/d, one dict each: both closed-form models and, with ``n``, a simulation.

    Each dict has ``ratio``, ``p_edge_geometric`` and ``p_edge_dynamic``
    (:func:`edge_probability`) and, when ``n`` is given, ``simulated``: ``p_edge``, ``stderr``,
    ``n``, ``successes`` and ``seed`` of :func:`simulate_edge` (``n`` tosses per ratio, its
    keyword ``setting``: restitution, friction, drop height, spin, launch speed, g,
    rolling and pivoting resistance, corner radius, diameter, axial spin) and, for rounded
    coins, ``corner_radius`` (m; left out for sharp corners, so that every other row is as it
    was). Ratios
    must lie in :data:`SIM_RATIOS` (a coin of no thickness is not a coin); ``setting`` needs
    ``n``. ``executor`` and ``progress``: as for :func:`simulate_edge`.

    Examples
    --------
    >>> [round(row["p_edge_dynamic"], 4) for row in edge_table([0.577, 1.0])]
    [0.3332, 0.5]
    """
    x = check_ratios(ratios)
    if n is None and (setting or seed is not None):
        given = ", ".join(["seed"] * (seed is not None) + sorted(setting))
        raise ValueError(f"{given} set the simulation: give the number of tosses n as well")
    geometric = edge_probability(x, "geometric")
    dynamic = edge_probability(x, "dynamic")
    rows: list[dict[str, Any]] = [
        {"ratio": float(r), "p_edge_geometric": float(pg), "p_edge_dynamic": float(pd)}
        for r, pg, pd in zip(x, geometric, dynamic, strict=True)
    ]
    if n is not None:
        simulated = simulate_edge(x, n, seed, executor=executor, progress=progress, **setting)
        for row, (_, s) in zip(rows, simulated, strict=True):
            row["simulated"] = {
                "p_edge": s.p,
                "stderr": s.stderr,
                "n": s.n,
                "successes": s.successes,
                "seed": s.seed,
            }
            if setting.get("corner_radius"):
                row["simulated"]["corner_radius"] = float(setting["corner_radius"])
    return rows


__all__ = [
    "MODELS",
    "check_diameter",
    "check_ratios",
    "edge_probability",
    "edge_table",
    "landing_rate",
    "ratio_for",
    "simulate_edge",
    "simulated_corner_radius",
]

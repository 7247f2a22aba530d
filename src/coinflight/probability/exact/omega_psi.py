"""Exact P(same side) with the spins in (Ω, ψ) coordinates: the band measure over T in
closed form (a fixed or uniform T, or the wrapped-normal series of a normal one), the azimuth
of (ωx, ωy) integrated out, and Gauss–Legendre over Ω (inner) and ψ (outer) cut at every
curve where the integrand changes form (:func:`_omega_psi`, whose docstring derives it;
Diaconis, Holmes & Montgomery 2007, section 2). Any uniform or normal ranged spins, up to all
three, with a fixed or uniform T; three ranged spins with a normal T. Chosen by
:mod:`coinflight.probability.exact`."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.core import bands
from coinflight.model.distributions import Distribution, Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.exact import common

POLAR_ORDERS = (8, 12, 16, 24, 32)
"""Gauss–Legendre nodes per panel tried in turn by the (Ω, ψ) rule (:func:`_omega_psi`); the
result is the first whose change from the previous order is within :data:`~.common.TOLERANCE`."""
MAX_POLAR_POINTS = 4e7
"""Most integrand points the (Ω, ψ) rule may evaluate over its first two orders and each later
one, bounded before its nodes are allocated (about half a minute on the 2-core machine)."""
POLAR_POINTS_PER_SECOND = 3e6
"""Integrand points the (Ω, ψ) rule evaluates a second (2-core machine)."""
MAX_CROSSING_SAMPLES = 1e8
"""Most curve-pair samples the search for the outer cuts of the (Ω, ψ) rule may take (each
pair sampled twice over, in √(1 − t) and in geometric steps: :func:`_crossings`)."""
_CROSSING_SAMPLES = 257
"""Samples along t = cot ψ (equal steps in √(1 − t), and as many in geometric steps) on
which each pair of curves is searched for a crossing (a sign change, then bisection)."""
_PSI_PANEL = 0.05
"""Widest outer panel in t = cot ψ."""
NEGLIGIBLE_AXIAL = 1e-8
"""An axial spin A = (I3/I1)|ω_z| at most this fraction of the smallest Ω⊥ is taken as
ω_z = 0: then (A / Ω⊥)² < 1e-16 changes neither Ω = √(Ω⊥² + A²) nor the gaps' half-width
arccos(cot²ψ) in double precision, so the answer is that of ω_z = 0 to rounding (and ψ,
within 1e-16 of 90°, need not be resolved)."""
_UNDERFLOW = 1e-290
"""Below this fraction of the largest Ω⊥, cot ψ = A / Ω⊥ nears the subnormal numbers, whose
few digits would misplace the panels; such an axial spin is taken as ω_z = 0 even when Ω⊥
reaches 0 (the Ω⊥ < A/1e-8 it would matter for hold no measurable probability)."""
_POLAR_CHUNK = 1 << 18
"""Integrand points evaluated at once by the (Ω, ψ) rule."""
NARROWEST = 1e-9
"""Narrowest ranged spin the (Ω, ψ) rule takes, as a fraction of its size (the largest
magnitude in its support): the density of √(ωx² + ωy²) of a box of width w at distance x from
the origin is a difference of angles of about x / w times rounding (1e-16), so that below
1e-9 it keeps fewer than 7 digits and the 1e-9 promised cannot be kept (the rule's orders
then disagree until its time budget is spent). Such a range is refused at once
(:func:`_check_widths`)."""
PLANE_PIECES_PER_SECOND = 100.0
"""Pieces of :class:`_PlaneInterpolant` fitted a second on one core of the reference machine
(each piece 25 arcs of Gauss–Legendre), for the work bounds."""


class _Radial:
    """The distribution of Ω⊥ = √(ωx² + ωy²) (the plane) or of A = (I3/I1) |ω_z| (axial):
    an atom at ``value`` (``density`` None), or a density on [lo, hi], smooth between
    consecutive ``breaks`` (where it may have a square-root onset, an inverse square root or
    a jump: the outer rule cuts where a band edge crosses them) and ``soft`` points (where it
    is smooth or negligible, a normal's mean ± 3 sd or ± 9 sd: only inner cuts, so that no
    piece is much wider than the density's scale); ``graded`` holds all of them with the
    points of :func:`_graded` (so that two breaks close together, a narrow range, do not
    spoil the pieces beside them)."""

    def __init__(
        self,
        density: Callable[[np.ndarray], np.ndarray] | None,
        breaks: list[float] | None = None,
        soft: list[float] | None = None,
        value: float = math.nan,
    ) -> None:
        self.density = density
        self.value = value
        hard = np.asarray(breaks if breaks is not None else [], dtype=float)
        both = np.unique(np.concatenate((hard, np.asarray(soft or [], dtype=float))))
        if density is None:
            both = np.array([value])
        self.breaks = np.unique(hard)
        self.points = both
        self.lo, self.hi = float(both[0]), float(both[-1])
        self.graded = _graded(both)


def _graded(pts: np.ndarray, factor: float = 4.0) -> np.ndarray:
    """``pts`` (sorted, unique) with, on each side of each point, points at distances
    h·4, h·16, … out to half the gap on that side, h being the distance to its nearest
    neighbour: a mesh graded towards clusters of breaks, so that each piece is about as long
    as its distance from the nearest break. A singularity just beyond a piece's end (the next
    break of a narrow range) then slows Gauss–Legendre down on no piece (hp-graded meshes:
    Schwab 1998, p-and hp-Finite Element Methods, §4.4)."""
    p = np.unique(pts)
    if p.size < 3:
        return p
    gaps = np.diff(p)
    near = np.minimum(np.r_[np.inf, gaps], np.r_[gaps, np.inf])
    d0 = factor * near
    out = [p]
    for side, gap in ((-1.0, np.r_[0.0, gaps]), (1.0, np.r_[gaps, 0.0])):
        half = 0.5 * gap
        # How many of d0·factor^j (j = 0, 1, …) lie below half the gap: one more than the
        # logarithm says, the surplus dropped below (so that rounding loses none).
        with np.errstate(divide="ignore", invalid="ignore"):
            logs = np.log(half / d0) / math.log(factor)
        count = np.where(d0 < half, np.floor(np.nan_to_num(logs)) + 2.0, 0.0).astype(np.int64)
        k = np.repeat(np.arange(p.size), count)
        j = np.arange(k.size) - np.repeat(np.cumsum(count) - count, count)
        d = d0[k] * factor ** j.astype(float)
        ok = d < half[k]
        out.append(p[k[ok]] + side * d[ok])
    return np.unique(np.concatenate(out))


def _folded(d: Distribution) -> tuple[list[float], list[float]]:
    """Breaks and soft points (as :class:`_Radial` has them) of |X| for a ranged spin X, its
    support folded onto [0, ∞): a uniform's ends and 0 inside its range are breaks; a
    normal's 0 inside its support is a break (the fold), its mean, ±3 sd and its support's
    ends (±9 sd, density below 1e-17) soft points."""
    s1, s2 = common._support(d)
    zero = [0.0] if s1 < 0.0 < s2 else []
    lo = [0.0 if s1 <= 0.0 <= s2 else min(abs(s1), abs(s2)), max(abs(s1), abs(s2))]
    if isinstance(d, Normal):
        pts = common._normal_marks(d)
        return zero, [*lo, *(abs(float(p)) for p in pts)]
    return [*zero, *lo, abs(s1), abs(s2)], []


def _axial(dz: Distribution, ratio: float) -> _Radial:
    """A = (I3/I1) |ω_z|: its density on A ≥ 0 is (p(A/ratio) + p(−A/ratio)) / ratio."""
    if dz.is_fixed:
        return _Radial(None, value=ratio * abs(dz.mean))
    hard, soft = _folded(dz)

    def density(a: np.ndarray) -> np.ndarray:
        z = a / ratio
        return (common._pdf(dz, z) + common._pdf(dz, -z)) / ratio

    return _Radial(density, [ratio * f for f in hard], [ratio * f for f in soft])


def _plane(dx: Distribution, dy: Distribution) -> _Radial:
    """Ω⊥ = √(ωx² + ωy²): an atom when both are fixed; for one fixed at c and the other y
    ranged, the density (p(s) + p(−s)) ρ / s, s = √(ρ² − c²) (an inverse square root at
    ρ = |c|); for two uniform ranges, ρ times the circle's angle in the box over its area
    (:func:`coinflight.core.bands.circle_in_box_angle`); for two ranged components of which
    one is normal, an interpolant (:class:`_PlaneInterpolant`). Breaks: the support's ends,
    the box's corner radii and the sides' distances (a circle's tangent)."""
    if dx.is_fixed and dy.is_fixed:
        return _Radial(None, value=math.hypot(dx.mean, dy.mean))
    if dx.is_fixed or dy.is_fixed:
        c, d = (dx.mean, dy) if dx.is_fixed else (dy.mean, dx)
        hard, soft = _folded(d)

        def one(rho: np.ndarray) -> np.ndarray:
            s = np.sqrt(np.maximum(rho * rho - c * c, 0.0))
            safe = np.where(s > 0.0, s, 1.0)
            return np.where(s > 0.0, (common._pdf(d, s) + common._pdf(d, -s)) * rho / safe, 0.0)

        # ρ = |c| (s = 0) holds the inverse square root: a break whatever y's kind.
        hard = [*hard, 0.0] if common._support(d)[0] <= 0.0 <= common._support(d)[1] else hard
        return _Radial(one, [math.hypot(c, f) for f in hard], [math.hypot(c, f) for f in soft])
    (x1, x2), (y1, y2) = common._support(dx), common._support(dy)
    near = math.hypot(
        0.0 if x1 <= 0.0 <= x2 else min(abs(x1), abs(x2)),
        0.0 if y1 <= 0.0 <= y2 else min(abs(y1), abs(y2)),
    )
    far = max(math.hypot(x, y) for x in (x1, x2) for y in (y1, y2))
    pts = [near, far, *(math.hypot(x, y) for x in (x1, x2) for y in (y1, y2))]
    pts += [abs(e) for e in (x1, x2, y1, y2)]
    pts = sorted({p for p in pts if near <= p <= far})
    if isinstance(dx, Uniform) and isinstance(dy, Uniform):
        area = (x2 - x1) * (y2 - y1)

        def box(rho: np.ndarray) -> np.ndarray:
            return rho * bands.circle_in_box_angle(rho, x1, x2, y1, y2) / area

        return _Radial(box, pts)
    # A normal component: its side lines (±9 sd) are negligible; a uniform one's are breaks.
    sides = [
        abs(e) for d, es in ((dx, (x1, x2)), (dy, (y1, y2))) if isinstance(d, Uniform) for e in es
    ]
    hard = [p for p in sides if near <= p <= far]
    return _Radial(_PlaneInterpolant(dx, dy, pts), hard, pts)


class _PlaneInterpolant:
    """Density of Ω⊥ = √(ωx² + ωy²) for two ranged spins of which one is normal:
    W(ρ) = ρ ∫ p_x(ρ cos φ) p_y(ρ sin φ) dφ over the circle's arcs in the support box
    (:func:`coinflight.core.bands.circle_in_box_arcs`), by composite Gauss–Legendre in φ at
    Chebyshev points, and then a Chebyshev interpolant on each piece between consecutive
    ``breaks`` (cut to at most 1.5 sd wide), in the smoothstep variable u of
    ρ = a + (b − a)(3u² − 2u³) that makes the square-root onsets at a tangent side smooth.
    Each piece is halved until its interpolant's last coefficients are below 1e-13 of W's
    largest value (:func:`numpy.polynomial.chebyshev.chebinterpolate`)."""

    DEGREE = 24
    MAX_PIECES = 4000

    def __init__(self, dx: Distribution, dy: Distribution, breaks: list[float]) -> None:
        self.dx, self.dy = dx, dy
        self.box = (*common._support(dx), *common._support(dy))
        self.sd = min(d.sd for d in (dx, dy) if isinstance(d, Normal))
        self.breaks = np.asarray(breaks, dtype=float)
        self.coefs = np.empty((0, 0))  # built on first use (:meth:`_build`)
        # Bounded before anything is allocated: a narrow normal beside a wide range asks
        # for (range / 1.5 sd) pieces (1e14 for sd 1e-13: 1 PiB before this bound).
        v.work_bound(
            "the exact (Ω, ψ) rule's interpolant of the density of √(ωx² + ωy²), in pieces "
            f"1.5 sd = {1.5 * self.sd:.3g} rad/s wide,",
            self.pieces(),
            self.MAX_PIECES,
            "pieces",
            common._USE_INSTEAD,
            rate=PLANE_PIECES_PER_SECOND,
        )

    def pieces(self) -> float:
        """Pieces the interpolant starts from (:meth:`_build`), counted without allocating."""
        gaps = np.diff(self.breaks) / (1.5 * self.sd)
        return float(np.sum(np.maximum(1.0, np.ceil(gaps))))

    def _build(self) -> None:
        ends = _refine_width(self.breaks, 1.5 * self.sd)
        pieces = list(itertools.pairwise(ends))
        coefs = [self._fit(a, b) for a, b in pieces]
        scale = max(np.max(np.abs(c)) for c in coefs)
        done: list[tuple[float, float, np.ndarray]] = []
        while pieces:
            (a, b), c = pieces.pop(), coefs.pop()
            small = np.max(np.abs(c[-4:])) <= 1e-13 * scale
            if small or len(done) + len(pieces) > self.MAX_PIECES:
                done.append((a, b, c))
                continue
            m = 0.5 * (a + b)
            pieces += [(a, m), (m, b)]
            coefs += [self._fit(a, m), self._fit(m, b)]
        done.sort(key=lambda piece: piece[0])
        self.starts = np.array([d[0] for d in done])
        self.widths = np.array([d[1] - d[0] for d in done])
        self.coefs = np.array([d[2] for d in done]).T.copy()  # (degree + 1, pieces)
        self.lo, self.hi = float(ends[0]), float(ends[-1])

    def _exact(self, rho: np.ndarray) -> np.ndarray:
        """W at a few radii by Gauss–Legendre over each arc, panels at most sd / 4 long."""
        out = np.zeros_like(rho)
        g, gw = np.polynomial.legendre.leggauss(16)
        for sx, sy, lo, hi in bands.circle_in_box_arcs(rho, *self.box):
            panels = max(1, math.ceil(float(np.max(rho * (hi - lo))) / (0.25 * self.sd)))
            k = np.arange(panels)
            width = (hi - lo)[:, None] / panels
            phi = lo[:, None] + width * (k[:, None] + 0.5 * (g + 1.0)).ravel()[None, :]
            w = (0.5 * width) * np.tile(gw, panels)[None, :]
            r = rho[:, None]
            val = common._pdf(self.dx, sx * r * np.cos(phi)) * common._pdf(
                self.dy, sy * r * np.sin(phi)
            )
            out += rho * np.sum(w * val, axis=1)
        return out

    def _fit(self, a: float, b: float) -> np.ndarray:
        def f(t: np.ndarray) -> np.ndarray:
            u = 0.5 * (t + 1.0)
            return self._exact(a + (b - a) * u * u * (3.0 - 2.0 * u))

        return np.polynomial.chebyshev.chebinterpolate(f, self.DEGREE)

    def __call__(self, rho: np.ndarray) -> np.ndarray:
        if not self.coefs.size:
            self._build()
        r = np.asarray(rho, dtype=float)
        inside = (r > self.lo) & (r < self.hi)
        i = np.clip(np.searchsorted(self.starts, r, side="right") - 1, 0, self.starts.size - 1)
        y = np.clip((r - self.starts[i]) / self.widths[i], 0.0, 1.0)
        u = 0.5 - np.sin(np.arcsin(1.0 - 2.0 * y) / 3.0)  # the smoothstep's inverse
        t = 2.0 * u - 1.0
        c = self.coefs
        # Clenshaw's recurrence, each point with its piece's coefficients.
        b1 = np.zeros_like(t)
        b2 = np.zeros_like(t)
        t2 = 2.0 * t
        for k in range(c.shape[0] - 1, 0, -1):
            b1, b2 = t2 * b1 - b2 + c[k][i], b1
        return np.where(inside, t * b1 - b2 + c[0][i], 0.0)


def _refine_width(pts: np.ndarray, width: float) -> np.ndarray:
    """``pts`` (sorted) with each gap cut into equal pieces at most ``width`` wide."""
    out = [pts[:1]]
    for a, b in itertools.pairwise(pts):
        out.append(np.linspace(a, b, max(1, math.ceil((b - a) / width)) + 1)[1:])
    return np.concatenate(out)


def _times(t: Distribution) -> tuple[float, float, float]:
    """(T1, T2, 0) of a uniform flight time, (T, T, 0) of a fixed one, (mean, mean, sd) of a
    normal one."""
    if isinstance(t, Normal):
        return t.mean, t.mean, t.sd
    return (t.value, t.value, 0.0) if isinstance(t, Fixed) else (t.low, t.high, 0.0)  # type: ignore[attr-defined]


def _curves(table: tuple[np.ndarray, ...], t: Any) -> Any:
    """Ω along the curves of the (Ω, ψ) plane where the integrand changes form, at
    t = cot ψ ∈ [0, 1]: kind 0, a band edge Ω = ((2j + 1)π ± b) / T (p = (2j + 1)π,
    sgn = ±1, b = arccos t² from :func:`coinflight.core.bands.gap_half_width`); kind 1, a
    circle Ω⊥ = p, Ω = p √(1 + t²); kind 2, a plane A = p, Ω = p √(1 + t²) / t.
    ``table`` = (kind, p, sgn, T). Broadcasts. In t rather than ψ so that a small axial spin
    (ψ within 1e-16 of 90°, which ψ itself cannot resolve) keeps its digits."""
    kind, p, sgn, tt = table
    r = np.sqrt(1.0 + t * t)
    b = bands.gap_half_width(t * t)
    with np.errstate(divide="ignore", invalid="ignore"):
        axial = p * r / t
    return np.where(kind == 0, (p + sgn * b) / tt, np.where(kind == 1, p * r, axial))


_BLUR = (-3.0, -1.0, 1.0, 3.0)
"""Where a normal flight time's blur of a band edge is cut, in its s.d.s (:func:`_edge_times`)."""


def _edge_times(times: tuple[float, ...], om_hi: float) -> list[float]:
    """The flight times whose band edges cut the integrals: T1 and T2 (uniform or fixed T);
    for a normal T (mean, sd) its mean, and where the blur of an edge (Ω sd / T wide) is
    narrower than a band (π / T: Ω sd < 1 up to ``om_hi``), mean ± 1 and 3 sd in the edge's
    place: cut there too, the graded mesh resolves the blur however narrow, and sd → 0 tends
    to the fixed T's step (without them the rule refused 1e-6 ≤ sd/T ≤ 1e-3)."""
    t1, t2, sd = (*times[:2], times[2] if len(times) > 2 else 0.0)
    if sd > 0.0 and om_hi * sd < 1.0:
        return sorted({t1, *(t1 / (1.0 + k * sd / t1) for k in _BLUR)})
    return sorted({t1, t2})


def _edges(times: tuple[float, ...], om_lo: float, om_hi: float) -> tuple[np.ndarray, ...]:
    """The band-edge curves (kind, p, sgn, T) that may meet Ω in [om_lo, om_hi]."""
    cols: list[list[float]] = [[], [], [], []]
    for t in _edge_times(times, om_hi):
        j = np.arange(
            max(0, math.ceil((om_lo * t - 1.5 * math.pi) / (2 * math.pi))),
            max(0, math.floor((om_hi * t - 0.5 * math.pi) / (2 * math.pi))) + 1,
        )
        for sgn in (-1.0, 1.0):
            cols[0] += [0.0] * j.size
            cols[1] += list((2 * j + 1) * math.pi)
            cols[2] += [sgn] * j.size
            cols[3] += [t] * j.size
    return tuple(np.asarray(c, dtype=float) for c in cols)


def _edge_count(times: tuple[float, ...], om_lo: float, om_hi: float) -> float:
    """How many curves :func:`_edges` returns, counted without allocating them."""
    count = 0.0
    for t in _edge_times(times, om_hi):
        first = max(0, math.ceil((om_lo * t - 1.5 * math.pi) / (2 * math.pi)))
        last = max(0, math.floor((om_hi * t - 0.5 * math.pi) / (2 * math.pi)))
        count += 2.0 * max(0, last - first + 1)
    return count


def _stack(*curves: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    """Curve tables (kind, p, sgn, T) joined."""
    return tuple(np.concatenate([c[i] for c in curves]) for i in range(4))


def _box(kind: int, values: np.ndarray) -> tuple[np.ndarray, ...]:
    """Curve table of circles (kind 1) or planes (kind 2) at ``values``."""
    vals = np.asarray(values, dtype=float)
    return (np.full(vals.size, float(kind)), vals, np.zeros(vals.size), np.ones(vals.size))


def _crossings(
    first: tuple[np.ndarray, ...],
    second: tuple[np.ndarray, ...],
    t_lo: float,
    t_hi: float,
    floor: float,
) -> np.ndarray:
    """t = cot ψ in (t_lo, t_hi) where a curve of ``first`` crosses one of ``second``.

    Each pair is sampled at :data:`_CROSSING_SAMPLES` points equally spaced in √(1 − t) (the
    band edges move like that square root near ψ = 45°, t = 1) and as many in geometric
    steps from ``floor`` (at most the smallest t where a box curve can meet a band edge) to
    t_hi (where a plane curve A / t sweeps past the edges near ψ = 90°); every sign change
    is bisected to rounding. Pairs that cross twice between two samples are missed; the
    comparison of successive Gauss orders judges what that leaves.
    """
    na, nb = first[0].size, second[0].size
    if na == 0 or nb == 0 or t_hi <= t_lo:
        return np.empty(0)
    u = np.linspace(math.sqrt(1.0 - t_hi), math.sqrt(1.0 - t_lo), _CROSSING_SAMPLES)
    samples = [1.0 - u * u]
    low = max(t_lo, floor)
    if 0.0 < low < t_hi:
        samples.append(np.geomspace(low, t_hi, _CROSSING_SAMPLES))
    ts = np.unique(np.clip(np.concatenate([*samples, np.array([t_lo, t_hi])]), t_lo, t_hi))
    fb = _curves(tuple(c[:, None] for c in second), ts)
    roots = []
    step = max(1, int(4e6 // (nb * ts.size)))
    for start in range(0, na, step):
        part = tuple(c[start : start + step] for c in first)
        fa = _curves(tuple(c[:, None] for c in part), ts)
        with np.errstate(invalid="ignore"):
            d = fa[:, None, :] - fb[None, :, :]
        pos = d > 0.0
        ok = np.isfinite(d)
        change = (pos[..., :-1] != pos[..., 1:]) & ok[..., :-1] & ok[..., 1:]
        ia, ib, m = np.nonzero(change)
        if ia.size == 0:
            continue
        lo, hi = ts[m], ts[m + 1]
        sign_lo = pos[ia, ib, m]
        ca = tuple(c[ia] for c in part)
        cb = tuple(c[ib] for c in second)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            with np.errstate(invalid="ignore"):
                same = (_curves(ca, mid) - _curves(cb, mid) > 0.0) == sign_lo
            lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
        roots.append(0.5 * (lo + hi))
    return np.concatenate(roots) if roots else np.empty(0)


def _smooth_rule(ends: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre with ``n`` nodes on each panel between consecutive ``ends`` (last axis),
    through the smoothstep x = a + (b − a)(3u² − 2u³): its slope vanishes at both ends, so
    that a square root or inverse square root at a panel's end (the gap's width at ψ = 45°, a
    circle touching a side of the box, a fixed ωx) becomes smooth in u."""
    g, gw = np.polynomial.legendre.leggauss(n)
    u, wu = 0.5 * (g + 1.0), 0.5 * gw
    lo, hi = ends[..., :-1, None], ends[..., 1:, None]
    width = hi - lo
    x = lo + width * (u * u * (3.0 - 2.0 * u))
    w = width * (6.0 * u * (1.0 - u) * wu)
    shape = (*ends.shape[:-1], -1)
    return x.reshape(shape), w.reshape(shape)


def _panels(cuts: np.ndarray, lo: float, hi: float, width: float = _PSI_PANEL) -> np.ndarray:
    """Panel ends: ``cuts`` inside (lo, hi) with lo and hi, each gap cut to at most ``width``."""
    pts = np.unique(np.concatenate(([lo, hi], cuts[(cuts > lo) & (cuts < hi)])))
    out = [pts[:1]]
    for a, b in itertools.pairwise(pts):
        out.append(np.linspace(a, b, max(1, math.ceil((b - a) / width)) + 1)[1:])
    return np.concatenate(out)


def _turning(om: np.ndarray, cot2: np.ndarray, times: tuple[float, float, float]) -> np.ndarray:
    """1 − P(same side) at rate Ω and cot²ψ over the flight times: the fraction of T uniform
    on [T1, T2] (:func:`coinflight.core.bands.time_average_uniform`) with the band half-width
    a = :func:`coinflight.core.bands.half_width`, whether the one T puts Ω T in a gap, or the
    wrapped-normal series of a normal T (:func:`coinflight.core.bands.same_side_normal_time`)."""
    t1, t2, sd = times
    if sd > 0.0:
        om, cot2 = np.broadcast_arrays(om, cot2)
        perp2 = om * om / (1.0 + cot2)
        same = bands.same_side_normal_time(perp2.ravel(), (perp2 * cot2).ravel(), t1, sd)
        return 1.0 - same.reshape(om.shape)
    a = bands.half_width(cot2)
    if t1 == t2:
        return (~bands.in_band(om * t1, a)).astype(float)
    return 1.0 - bands.time_average_uniform(om, a, t1, t2)


class _PolarPlan:
    """The (Ω, ψ) integral of a case: its outer panel ends in t = cot ψ, and per order its
    points."""

    def __init__(self, dist: TossDistribution) -> None:
        i1, i3 = dist.moments
        self.ratio = i3 / i1
        self.times = _times(dist.flight_time)
        self.plane = _plane(dist.omega_x, dist.omega_y)
        self.axial = _axial(dist.omega_z, self.ratio)
        p, ax = self.plane, self.axial
        self.ranged = sum(not getattr(dist, name).is_fixed for name in common._SPINS)
        self.empty = False
        if p.density is None and ax.density is None:  # pragma: no cover - closed form in T
            raise AssertionError("both atoms: the closed form in T")
        self.flat = False
        if p.density is None:
            self.kind = "plane fixed"
            if p.value == 0.0:  # no spin in the plane: the coin never turns over
                self.empty = True
                return
            if ax.hi <= NEGLIGIBLE_AXIAL * p.value:  # as if ω_z = 0 (to rounding)
                self.flat = True
                return
            # Along Ω⊥ = p: t = A / Ω⊥ from A's bottom to where A reaches its top (or Ω⊥).
            if ax.lo >= p.value:  # ψ ≤ 45° throughout: never turns over
                self.empty = True
                return
            t_lo, t_hi = ax.lo / p.value, min(ax.hi, p.value) / p.value
            curve = _box(1, np.array([p.value]))
            om_hi = p.value * math.sqrt(1.0 + t_hi * t_hi)
            fixed_cuts = ax.points[ax.points < p.value] / p.value
        elif ax.hi <= NEGLIGIBLE_AXIAL * p.lo or ax.hi <= _UNDERFLOW * p.hi:
            # ω_z = 0, or so small beside Ω⊥ that Ω and the bands are those of ω_z = 0 to
            # rounding (a near-zero Ω⊥ below it holds no measurable probability).
            self.kind = "diameter"  # ψ = 90°, Ω = Ω⊥, the gaps' half-width π/2
            self._bound_points(_edge_count(self.times, p.lo, p.hi))
            edges = _edges(self.times, p.lo, p.hi)
            cuts = (edges[1] + edges[2] * 0.5 * math.pi) / edges[3]
            self.ends = _panels(_graded(np.concatenate((cuts, p.graded))), p.lo, p.hi, math.inf)
            return
        elif ax.density is None:
            self.kind = "axial fixed"
            # Along A = value: t = A / Ω⊥ from Ω⊥'s top to where it reaches its bottom (or A).
            t_lo, t_hi = ax.value / p.hi, ax.value / max(p.lo, ax.value)
            curve = _box(2, np.array([ax.value]))
            om_hi = math.hypot(p.hi, ax.value)
            fixed_cuts = ax.value / p.graded[p.graded >= ax.value]
        else:
            self.kind = "2-D"
            # t from where the box's top A meets the largest Ω⊥ to where its bottom meets
            # the smallest (ψ ≥ 45°: t ≤ 1).
            t_lo = ax.lo / p.hi
            t_hi = min(1.0, ax.hi / p.lo) if p.lo > 0.0 else 1.0
            om_hi = min(math.hypot(p.hi, ax.hi), math.sqrt(2.0) * p.hi)
            count = _edge_count(self.times, p.lo, om_hi)
            self._bound_points(count, inner=True)
            circles, planes = _box(1, p.breaks), _box(2, ax.breaks[ax.breaks > 0.0])
            self.box_curves = _stack(circles, planes)
            self._bound_crossings(count * self.box_curves[0].size)
            self.edges = _edges(self.times, p.lo, om_hi)
            # The inner cuts: the box's curves with the soft points and the graded radii.
            self.inner_curves = _stack(_box(1, p.graded), _box(2, ax.points[ax.points > 0.0]))
            # Where a circle meets a plane (t = A / Ω⊥), breaks and soft points alike: so
            # that a narrow axial range near ψ = 90° has panels of its own width.
            a_pts, p_pts = ax.points[ax.points > 0.0], p.points[p.points > 0.0]
            meets = (a_pts[:, None] / p_pts[None, :]).ravel()
            floor = 0.25 * float(np.min(meets)) if meets.size else 0.0
            cuts = np.concatenate(
                (_crossings(self.edges, self.box_curves, t_lo, t_hi, floor), meets)
            )
            self.empty = t_hi <= t_lo
            if not self.empty:
                self.ends = _panels(_graded(_inside(cuts, t_lo, t_hi)), t_lo, t_hi)
            self.inner = self.edges[0].size + self.inner_curves[0].size + 1
            return
        if t_hi <= t_lo:
            self.empty = True
            return
        count = _edge_count(self.times, 0.0, om_hi)
        self._bound_points(count)
        self._bound_crossings(count)
        edges = _edges(self.times, 0.0, om_hi)
        floor = (
            t_lo if t_lo > 0.0 else 0.25 * float(np.min(fixed_cuts[fixed_cuts > 0.0], initial=t_hi))
        )
        cuts = np.concatenate((_crossings(edges, curve, t_lo, t_hi, floor), fixed_cuts))
        self.ends = _panels(_graded(_inside(cuts, t_lo, t_hi)), t_lo, t_hi)

    def _bound_points(self, edges: float, inner: bool = False) -> None:
        """The refusal of :func:`_omega_psi` (its words), decided from the band edges alone
        before they or the panels are allocated: each edge cuts at least one panel, on which
        the first two orders put n points each (n² with ``inner``, the 2-D rule's inner
        pieces), a lower bound of the points the plan will count."""
        per_edge = sum(n * n if inner else n for n in POLAR_ORDERS[:2])
        v.work_bound(
            f"the exact (Ω, ψ) rule over {self.ranged} ranged spins",
            edges * per_edge,
            MAX_POLAR_POINTS,
            "integrand points",
            common._USE_INSTEAD,
            rate=POLAR_POINTS_PER_SECOND,
        )

    def _bound_crossings(self, pairs: float) -> None:
        v.work_bound(
            "the exact (Ω, ψ) rule's search for where band edges cross the spin box",
            float(pairs) * 2 * _CROSSING_SAMPLES,
            MAX_CROSSING_SAMPLES,
            "curve samples",
            common._USE_INSTEAD,
            rate=POLAR_POINTS_PER_SECOND * 10,
        )

    def points(self, n: int) -> int:
        """Integrand points of order ``n``, counted before any allocation."""
        if self.empty or self.flat:
            return 1
        outer = (self.ends.size - 1) * n
        return outer * self.inner * n if self.kind == "2-D" else outer

    def integral(self, n: int) -> float:
        """∫ of the density times 1 − P(same side | spins) over the spins, order ``n``."""
        if self.empty:
            return 0.0
        p, ax, times = self.plane, self.axial, self.times
        if self.flat:
            return float(_turning(np.array([p.value]), np.zeros(1), times)[0])
        x, w = _smooth_rule(self.ends, n)
        if self.kind == "diameter":
            assert p.density is not None
            return math.fsum(w * p.density(x) * _turning(x, np.zeros_like(x), times))
        # x is t = cot ψ; dψ = dt / (1 + t²).
        cot2 = x * x
        root = np.sqrt(1.0 + cot2)
        if self.kind == "plane fixed":
            # A = Ω⊥ t: the integral over A, dA = Ω⊥ dt.
            assert ax.density is not None
            r0 = p.value
            g = ax.density(r0 * x) * _turning(r0 * root, cot2, times) * r0
            return math.fsum(w * g)
        if self.kind == "axial fixed":
            # Ω⊥ = A / t: the integral over Ω⊥, dΩ⊥ = A dt / t².
            assert p.density is not None
            a0 = ax.value
            rho = a0 / x
            g = p.density(rho) * _turning(rho * root, cot2, times) * rho / x
            return math.fsum(w * g)
        assert p.density is not None and ax.density is not None
        s, c = 1.0 / root, x / root
        w = w / (1.0 + cot2)
        total = []
        rows = max(1, _POLAR_CHUNK // (self.inner * n))
        for start in range(0, x.size, rows):
            sl = slice(start, start + rows)
            ss, cc, tt = s[sl, None], c[sl, None], cot2[sl, None]
            with np.errstate(divide="ignore", invalid="ignore"):
                lo = np.maximum(p.lo / ss, np.where(ax.lo > 0.0, ax.lo / cc, 0.0))
                hi = np.minimum(p.hi / ss, ax.hi / cc)
            hi = np.maximum(hi, lo)
            brk = _curves(tuple(q[None, :] for q in self.inner_curves), x[sl, None])
            edge = _curves(tuple(q[None, :] for q in self.edges), x[sl, None])
            ends = np.sort(np.clip(np.concatenate((lo, edge, brk, hi), axis=1), lo, hi), axis=1)
            # Only the pieces of positive width (most curves lie outside a row's range).
            keep = ends[:, 1:] > ends[:, :-1]
            row = np.nonzero(keep)[0]
            if row.size == 0:
                continue
            pieces = np.stack((ends[:, :-1][keep], ends[:, 1:][keep]), axis=-1)
            om, wo = _smooth_rule(pieces, n)
            ss, cc, tt = ss[row], cc[row], tt[row]
            val = p.density(om * ss) * ax.density(om * cc) * om * _turning(om, tt, times)
            total.append(float(np.sum(w[sl][row, None] * wo * val)))
        return math.fsum(total)


def _inside(cuts: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """``cuts`` within [lo, hi], with lo and hi."""
    return np.r_[lo, hi, cuts[(cuts > lo) & (cuts < hi)]]


_OMEGA_PSI = "closed form in T, Gauss–Legendre over the spins in (Ω, ψ)"


def _polar_seconds(dist: TossDistribution) -> float:
    """An upper estimate of the seconds of :func:`_omega_psi`'s first two orders, without its
    search for crossings: at most about one outer cut per pair of a band edge and a box curve
    (measured 0.2-1.2 of that on the test boxes) plus the panels' width limit, and the inner
    pieces counted as the plan counts them; 0.2 s more to build a normal plane's interpolant."""
    i1, i3 = dist.moments
    times = _times(dist.flight_time)
    _check_widths(dist)
    p, ax = _plane(dist.omega_x, dist.omega_y), _axial(dist.omega_z, i3 / i1)
    setup = 0.0
    if isinstance(p.density, _PlaneInterpolant):
        setup = p.density.pieces() / PLANE_PIECES_PER_SECOND
    orders = sum(n * n for n in POLAR_ORDERS[:2])
    if p.density is None or ax.density is None:
        om_hi = math.hypot(p.hi, ax.hi)
        edges = _edge_count(times, 0.0, om_hi)
        return 1e-3 + setup + (edges + p.graded.size + 64) * orders / POLAR_POINTS_PER_SECOND
    om_hi = min(math.hypot(p.hi, ax.hi), math.sqrt(2.0) * p.hi)
    edges = _edge_count(times, p.lo, om_hi)
    curves = p.breaks.size + ax.breaks.size
    panels = edges * curves + edges + 32
    inner = edges + p.graded.size + ax.points.size + 1
    return 1e-3 + setup + panels * inner * orders / POLAR_POINTS_PER_SECOND


def _text(x: float) -> str:
    """A float as typed: the shortest text that reads back to it, no trailing ".0"."""
    return repr(float(x)).removesuffix(".0")


def _check_widths(dist: TossDistribution) -> None:
    """Refuse at once (ValueError) a ranged spin narrower than :data:`NARROWEST` of its size:
    the (Ω, ψ) rule's densities lose those digits (a normal spin's width is its support's,
    mean ± 9 sd)."""
    for name in common._SPINS:
        d = getattr(dist, name)
        if d.is_fixed:
            continue
        lo, hi = common._support(d)
        size = max(abs(lo), abs(hi))
        if hi - lo < NARROWEST * size:
            shown = (
                f"{_text(lo)}:{_text(hi)}"
                if isinstance(d, Uniform)
                else f"normal:{_text(d.mean)},{_text(d.sd)}"
            )
            raise ValueError(
                f"the exact (Ω, ψ) rule cannot resolve {name} = {shown} rad/s: {hi - lo:.3g} "
                f"rad/s wide, less than {NARROWEST:g} of its size {size:.6g} rad/s; give "
                f"{name} one value, or {common._USE_INSTEAD}"
            )


def _omega_psi_applies(dist: TossDistribution, ranged: list[str]) -> bool:
    """T fixed or uniform with some spin ranged, or T normal with three ranged spins; every
    ranged spin uniform or normal."""
    t = dist.flight_time
    return (
        (isinstance(t, Fixed | Uniform) or (isinstance(t, Normal) and len(ranged) == 3))
        and bool(ranged)
        and all(isinstance(getattr(dist, n), Uniform | Normal) for n in ranged)
    )


def _omega_psi(
    dist: TossDistribution, ranged: list[str], details: common._Details
) -> tuple[float, float]:
    """Band measure over T in closed form, Gauss–Legendre over the spins in (Ω, ψ).

    P(same side | spins) depends on the spins through Ω = √(Ω⊥² + A²) and ψ with
    cot ψ = A / Ω⊥, A = (I3/I1) ω_z, Ω⊥ = √(ωx² + ωy²) (Diaconis, Holmes & Montgomery 2007,
    section 2): the coin shows the other face iff Ω T lies in a gap (2j + 1)π ± b(ψ),
    b = arccos(cot²ψ), only for ψ > 45°. With the density of Ω⊥ (:func:`_plane`, the azimuth
    integrated out) and of A (:func:`_axial`, ω_z's sign folded), 1 − P(same side) is

        ∫ dψ ∫ dΩ  (Ω / ratio)·p⊥(Ω sin ψ)·p_A(Ω cos ψ)·(1 − P(same | Ω, ψ))

    over ψ ∈ (45°, 90°], the Jacobian of (Ω⊥, ω_z) → (Ω, ψ) being Ω / ratio (the ratio's
    1/ratio is in p_A). For fixed ψ every place where the integrand changes form is explicit
    in Ω: the band edges ((2j + 1)π ± b(ψ)) / T1,2 (1 − P is linear in Ω T between them,
    for T uniform: Keller 1986), the radii where p⊥ has a kink (corners of a uniform box, a
    side's tangent circle) over sin ψ, and the ends of ω_z's range over cos ψ. The inner
    integral over Ω is cut at all of them; the outer one at 45°, 90°, where a circle meets
    a plane and where two of these curves cross (:func:`_crossings`), in the variable
    t = cot ψ ∈ [0, 1] (dψ = dt / (1 + t²)), which keeps its digits near ψ = 90° where ψ
    itself does not (a small ω_z: ψ within 1e-16 of 90° for |ω_z| ≤ 1e-14 rad/s beside
    Ω⊥ = 60 rad/s). Each panel takes Gauss–Legendre through a smoothstep
    (:func:`_smooth_rule`), which makes the square roots at ψ = 45° and at a tangent circle
    smooth. With one of Ω⊥, A fixed the integral is along one curve, over A (Ω⊥ fixed) or
    over Ω⊥ (A fixed); an axial spin below :data:`NEGLIGIBLE_AXIAL` of Ω⊥ is ω_z = 0.
    Orders :data:`POLAR_ORDERS` are tried until two in a row agree within
    :data:`~.common.TOLERANCE`.
    """
    _check_widths(dist)
    plan = _PolarPlan(dist)
    details["spin integral"] = plan.kind
    return common._by_orders(
        "the exact (Ω, ψ) rule",
        len(ranged),
        POLAR_ORDERS,
        plan.points,
        lambda n: 1.0 - plan.integral(n),
        (MAX_POLAR_POINTS, 2 * MAX_POLAR_POINTS),
        "integrand points",
        POLAR_POINTS_PER_SECOND,
        details,
    )

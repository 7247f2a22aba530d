"""The one protocol every estimator and map asks of an outcome model, and its tally helpers.

An :class:`OutcomeModel` turns initial conditions into faces. It answers two questions:

- :meth:`OutcomeModel.faces`: the face of each toss of an array (ω (..., 3), T (...)), for maps
  (:func:`coinflight.studies.basin.basin_map`) and single tosses;
- :meth:`OutcomeModel.count`: face counts of a batch given as points of the unit cube, for the
  probability estimators (by default through :meth:`~OutcomeModel.faces`).

and declares what it can do instead of being recognised by its class: ``closed_form_bands``
(the hand catch: the exact method and the grid's band counting may use the closed-form bands
of :mod:`coinflight.core.bands`), ``can_end_on_edge``, ``deterministic``, its ``rate``
(tosses a second, for the work bounds) and its extra ``tallies``. The models:
:mod:`~coinflight.outcomes.hand`, :mod:`~coinflight.outcomes.table`,
:mod:`~coinflight.outcomes.air`; the factory that picks one:
:func:`coinflight.outcomes.outcome_model`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight.core.outcome import FACE_NAMES
from coinflight.model.surface import CONTACT_UNITS

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution
    from coinflight.model.surface import Drag, Surface
    from coinflight.model.toss import Toss

FloatArray = NDArray[np.float64]
FaceArray = NDArray[np.int8]
Counts = NDArray[np.int64]
"""(tails, heads, edge) counts, shape (3,), followed by the model's extra tallies if any."""


class OutcomeModel:
    """How a toss ends. Subclasses implement :meth:`faces` (and may override :meth:`count`)."""

    name = "outcome model"
    closed_form_bands: bool = False
    """True when the face is the sign of n(T)·n0 at the flight time T (the hand catch): the
    exact method and the grid's band counting then use :mod:`coinflight.core.bands` and never
    call :meth:`count`."""
    can_end_on_edge: bool = False
    """True when a toss may end on its edge (face code EDGE)."""
    deterministic: bool = True
    """True when the same initial conditions always give the same face."""
    tallies: tuple[str, ...] = ()
    """Names of extra counts :meth:`count` returns after (tails, heads, edge), e.g.
    ``("unsettled",)`` for tosses a landing model could not settle (their faces are still
    counted). The estimators add them up and report them in ``details`` (count and fraction)."""
    contact_parameters: tuple[str, ...] = ()
    """Contact parameters (:data:`coinflight.model.ensemble.CONTACT`: restitution, friction)
    this model can take toss by toss from a distribution of tosses; the estimators refuse a
    distribution that sets any other (:func:`check_contact`)."""
    contact_refusal: str = ""
    """Why this model takes no contact distributions, when it is not obvious (one line)."""
    rate: float = 1e5
    """Tosses a second on the reference 2-core machine, all threads: the estimators' work
    bounds (:func:`coinflight.probability.monte_carlo.check_work` …) turn a size into a time
    with it. Subclasses state their own measured rate."""
    summary: str = ""
    """One line: how a toss ends on this model's surface kind (--surface's help, the page's
    menu; empty: its :attr:`name`)."""
    surface_parameters: tuple[str, ...] = ()
    """Which of the table's parameters (:data:`coinflight.model.surface.TABLE_PARAMETERS`:
    ending, drop_height, restitution, friction, the resistances, corner_radius, max_bounces)
    this model reads: a :class:`~coinflight.model.surface.Surface` of its kind, the command
    line and the web API refuse the others given (in :attr:`surface_refusal`'s words)."""
    surface_refusal: str = ""
    """Why a parameter it does not take is refused, after what was given (one line); empty:
    "does not apply to --surface KIND ..., which takes ..." built from
    :attr:`surface_parameters` (:func:`coinflight.outcomes.register`)."""

    @classmethod
    def from_surface(cls, surface: Surface) -> OutcomeModel:
        """The model for ``surface`` (of its registered kind), with no air and no bounce
        limit; :func:`coinflight.outcomes.register`'s default builder calls it. By default
        ``cls()``: a model that reads the surface's parameters overrides it."""
        del surface
        return cls()

    def faces(
        self,
        coin: Coin,
        omega: FloatArray,
        flight_time: FloatArray,
        start_sign: float,
        g: float,
    ) -> FaceArray:
        """Face codes (:mod:`coinflight.core.outcome`) of tosses ω (..., 3), T (...), shape (...).

        The launch speed is v0 = g T / 2 (T: the flight time back to launch height).
        """
        raise NotImplementedError

    def count(self, dist: TossDistribution, u: FloatArray) -> Counts:
        """Face counts for unit-cube points ``u``, shape (len(dist.ranged), n).

        Returns (tails, heads, edge, *tallies), shape (3 + len(:attr:`tallies`),). Row r of
        ``u`` drives parameter ``dist.ranged[r]`` through its distribution's ``ppf``
        (:meth:`~coinflight.model.ensemble.TossDistribution.values`). By default the faces of
        :meth:`faces`, counted.
        """
        omega, t = initial_conditions(dist, u)
        face = self.faces(dist.coin, omega, t, dist.start_sign, dist.g)
        return np.bincount(face, minlength=3).astype(np.int64)

    def rate_for(self, dist: TossDistribution | None) -> float:
        """:attr:`rate` for the tosses ``dist`` (a model whose speed depends on what the tosses
        spread, their own contact parameters, says so); the estimators' work bounds use it."""
        return self.rate

    def describe(self) -> str:
        """One line for text output: where the toss ends and the air."""
        return self.name

    def to_dict(self) -> dict[str, Any]:
        """JSON description of the model's settings (surface and air)."""
        return {"surface": self.name}

    def report(self, coin: Coin, toss: Toss) -> tuple[dict[str, Any], str]:
        """One toss: (JSON fields, one line of text). By default the face of :meth:`faces`."""
        face = self.faces(
            coin,
            np.asarray(toss.omega, dtype=float).reshape(1, 3),
            np.asarray(toss.flight_time, dtype=float).reshape(1),
            toss.start_sign,
            toss.g,
        )
        name = FACE_NAMES[int(face[0])]
        return {"outcome": name}, f"ends {name.upper()} up ({self.describe()})"


def check_contact(dist: TossDistribution, model: OutcomeModel) -> None:
    """ValueError (one line) when ``dist`` sets contact parameters ``model`` cannot take.

    A hand catch has no contact: the distribution would be silently ignored, so it is refused
    (as by any model whose :attr:`OutcomeModel.contact_parameters` leave it out).
    """
    extra = [name for name in dist.contact if name not in model.contact_parameters]
    if not extra:
        return
    given = ", ".join(
        " ".join([name.replace("_", " "), dist.contact[name].describe()])
        + (f" {CONTACT_UNITS[name]}" if name in CONTACT_UNITS else "")
        for name in extra
    )
    why = model.contact_refusal or (
        f"{model.name} has no contact with a surface; contact parameter distributions apply to "
        "a table landing (surface kind 'table', --surface table)"
    )
    raise ValueError(f"{given}: {why}")


def faces_from_same_side(same: int, n: int, start_sign: float) -> Counts:
    """(tails, heads, edge) from the number of tosses that show the starting face."""
    heads = same if start_sign > 0 else n - same
    return np.array([n - heads, heads, 0], dtype=np.int64)


def tally_details(model: OutcomeModel, counts: NDArray[np.int64]) -> dict[str, float]:
    """``{name: count, name_fraction: count / tosses}`` for the model's extra tallies."""
    n = int(np.sum(counts[:3]))
    out: dict[str, float] = {}
    for name, c in zip(model.tallies, counts[3:], strict=True):
        out[name] = int(c)
        out[f"{name}_fraction"] = int(c) / n if n else 0.0
    return out


def initial_conditions(dist: TossDistribution, u: FloatArray) -> tuple[FloatArray, FloatArray]:
    """(ω (n, 3), T (n,)) for unit-cube points u, shape (len(dist.ranged), n)."""
    wx, wy, wz, t = dist.values(np.asarray(u, dtype=float))
    n = np.asarray(u).shape[1]
    omega = np.column_stack(
        [np.broadcast_to(np.asarray(w, dtype=float), (n,)) for w in (wx, wy, wz)]
    )
    return omega, np.broadcast_to(np.asarray(t, dtype=float), (n,))


def toss_grid(
    omega: FloatArray, flight_time: FloatArray
) -> tuple[tuple[int, ...], FloatArray, FloatArray]:
    """(shape, ω (m, 3), T (m,)): tosses ω (..., 3), T (...) broadcast together and flattened."""
    omega = np.asarray(omega, dtype=float)
    t = np.asarray(flight_time, dtype=float)
    shape = np.broadcast_shapes(omega.shape[:-1], t.shape)
    flat_omega = np.broadcast_to(omega, (*shape, 3)).reshape(-1, 3)
    return shape, flat_omega, np.broadcast_to(t, shape).reshape(-1)


def single_name(codes: NDArray[Any], names: tuple[str, ...], what: str) -> str:
    """The name of the code of a single toss; TypeError for a batch."""
    if codes.ndim:
        raise TypeError(f"{what}_name is for a single toss; use {what} for a batch")
    return names[int(codes)]


def describe_air(drag: Drag | None) -> str:
    """The air part of a model's one-line description."""
    if drag is None:
        return "no air drag"
    air = f"air drag C_d = {drag.coefficient:g}" if drag.coefficient > 0 else "no air drag"
    if drag.spin_damping > 0:
        air += f", spin damping K = {drag.spin_damping:g} N m s"
    return air


def coin_body(coin: Coin) -> dict[str, float]:
    """The coin as the kernels' record builders take it (``Contact.build``, ``Air.build``):
    ``radius``, ``thickness``, ``mass`` and the principal moments ``i1``, ``i3`` (SI)."""
    i1, i3 = coin.moments
    return {
        "radius": coin.radius,
        "thickness": coin.thickness,
        "mass": coin.mass,
        "i1": float(i1),
        "i3": float(i3),
    }


def drag_dict(drag: Drag | None) -> dict[str, float] | None:
    """JSON description of the air drag (None: no air)."""
    if drag is None:
        return None
    return {
        "coefficient": drag.coefficient,
        "spin_damping": drag.spin_damping,
        "air_density": drag.air_density,
    }


__all__ = [
    "Counts",
    "OutcomeModel",
    "check_contact",
    "coin_body",
    "describe_air",
    "drag_dict",
    "faces_from_same_side",
    "initial_conditions",
    "single_name",
    "tally_details",
    "toss_grid",
]

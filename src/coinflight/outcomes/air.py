"""Caught in the hand at launch height after a flight through air (drag and spin damping).

The flight is the compiled integrator of :mod:`coinflight.core.drag` (quadratic drag on the
coin's projected area, spin damping; parallel over the tosses); without drag it reduces to the
hand catch's closed form.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight import _validation as v
from coinflight.core import ballistics
from coinflight.model.surface import Drag
from coinflight.outcomes.base import (
    Counts,
    FaceArray,
    FloatArray,
    OutcomeModel,
    describe_air,
    drag_dict,
    initial_conditions,
    toss_grid,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution

DRAG_TOSSES_PER_SECOND = 4e4
"""Hand catches through air a second, for the work bounds: a US nickel, ωx 150-300 rad/s,
C_d = 1.17, on 2 threads of a busy 2-core machine (a quiet one runs 3 to 4 times as many;
``python benchmarks/bench_air.py`` measures it). The table landing's rate is
:data:`coinflight.outcomes.table.AIR_LANDINGS_PER_SECOND`."""


def drag_model(coin: Coin, drag: Drag, g: float, projected: bool = True) -> Any:
    """The kernels' :class:`coinflight.core.drag.Air` of this coin in this air (``projected``:
    drag on the projected area, else on the face area whatever the attitude)."""
    from coinflight.core import drag as drag_kernels

    i1, i3 = coin.moments
    return drag_kernels.Air.build(
        mass=coin.mass,
        radius=coin.radius,
        thickness=coin.thickness,
        i1=i1,
        i3=i3,
        g=g,
        drag_coefficient=drag.coefficient,
        spin_damping=drag.spin_damping,
        air_density=drag.air_density,
        projected=projected,
    )


def check_air(
    coin: Coin,
    drag: Drag,
    g: float,
    launch_speed: Any,
    drop_height: float = 0.0,
    omega: Any = None,
) -> None:
    """ValueError, before any work, unless a toss through this air ends within the step bound
    :data:`coinflight.core.drag.MAX_STEPS` (only an extreme drag on a light, wide coin can fail:
    its fall at terminal speed would need more; spin damping never does)."""
    from coinflight.core import drag as drag_kernels

    spin = 0.0 if omega is None else float(np.max(np.linalg.norm(omega, axis=-1), initial=0.0))
    steps = drag_kernels.steps_needed(
        drag_model(coin, drag, g), float(np.max(launch_speed, initial=0.0)), drop_height, spin
    )
    if steps > drag_kernels.MAX_STEPS:
        needed, most = v.over_limit(steps, drag_kernels.MAX_STEPS)
        raise ValueError(
            f"air drag C_d = {drag.coefficient:g} in air of density {drag.air_density:g} kg/m³ on "
            f"this coin (radius {coin.radius:g} m, mass {coin.mass:g} kg) would need about "
            f"{needed} integration steps a toss, more than the {most} "
            "allowed; use a smaller C_d, spin, flight time or drop height, or a heavier coin"
        )


def catch_with_drag(
    coin: Coin,
    omega: FloatArray,
    launch_speed: FloatArray,
    start_sign: float | FloatArray,
    g: float,
    drag: Drag,
    parallel: bool = True,
) -> tuple[NDArray[np.int8], FloatArray]:
    """Caught in the hand at launch height after a flight through air: (face, catch time).

    The face is the sign of the heads normal's vertical component when the centre of mass
    comes back down to launch height (:func:`coinflight.core.drag.catch`); without drag this
    is the closed form's heads iff n(T)·Z > 0. ``parallel``: numba's threads (False for callers
    that run batches in their own threads).
    """
    from coinflight.core import drag as drag_kernels

    if not isinstance(drag, Drag):
        raise TypeError(f"drag must be a Drag, got {type(drag).__name__}")
    omega = np.asarray(omega, dtype=float).reshape(-1, 3)
    speed = np.broadcast_to(np.asarray(launch_speed, dtype=float), (omega.shape[0],))
    check_air(coin, drag, g, speed, omega=omega)
    face, when, _ = drag_kernels.catch(
        omega, speed, start_sign, drag_model(coin, drag, g), parallel=parallel
    )
    if np.any(when < 0.0):  # pragma: no cover - check_air refuses such tosses beforehand
        raise ValueError(
            f"a toss through air needed more than {drag_kernels.MAX_STEPS:,} integration steps"
        )
    return face, when


class DragCatch(OutcomeModel):
    """Outcome model: caught in the hand at launch height after a flight through air."""

    name = "hand catch with drag"
    rate = DRAG_TOSSES_PER_SECOND

    def __init__(self, drag: Drag) -> None:
        if not isinstance(drag, Drag):
            raise TypeError(f"drag must be a Drag, got {type(drag).__name__}")
        self.drag = drag

    def faces(
        self, coin: Coin, omega: FloatArray, flight_time: FloatArray, start_sign: float, g: float
    ) -> FaceArray:
        """Faces at the catch, launched at v0 = g T / 2 (:func:`catch_with_drag`)."""
        shape, flat_omega, t = toss_grid(omega, flight_time)
        face, _ = catch_with_drag(
            coin, flat_omega, ballistics.launch_speed(t, g), start_sign, g, self.drag
        )
        return face.reshape(shape)

    def count(self, dist: TossDistribution, u: FloatArray) -> Counts:
        """(tails, heads, edge) for unit-cube points ``u``, in the calling thread (the
        estimators run batches in their own threads)."""
        omega, t = initial_conditions(dist, u)
        face, _ = catch_with_drag(
            dist.coin,
            omega,
            ballistics.launch_speed(t, dist.g),
            dist.start_sign,
            dist.g,
            self.drag,
            parallel=False,
        )
        return np.bincount(face, minlength=3).astype(np.int64)

    def describe(self) -> str:
        return f"caught in the hand, {describe_air(self.drag)}"

    def to_dict(self) -> dict[str, Any]:
        return {"surface": "hand", "drag": drag_dict(self.drag)}


__all__ = ["DRAG_TOSSES_PER_SECOND", "DragCatch", "catch_with_drag", "check_air", "drag_model"]

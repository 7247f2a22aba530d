"""Caught in the hand at launch height after a flight through air (drag and spin damping).

The flight is integrated numerically by :mod:`coinflight.core.drag` (one SciPy integration per
toss); without drag it reduces to the hand catch's closed form.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight.core import ballistics
from coinflight.model.surface import Drag
from coinflight.outcomes.base import (
    FaceArray,
    FloatArray,
    OutcomeModel,
    describe_air,
    drag_dict,
    toss_grid,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.toss import Toss

DRAG_TOSSES_PER_SECOND = 20
"""Table landings a second with air drag (one SciPy integration each, one thread): 100 tosses
in 5.3 s on the 2-core reference machine."""


def drag_model(coin: Coin, drag: Drag, g: float) -> Any:
    """The kernels' :class:`coinflight.core.drag.DragModel` of this coin in this air."""
    from coinflight.core import drag as drag_kernels

    i1, i3 = coin.moments
    return drag_kernels.DragModel(
        coin.mass,
        coin.radius,
        (i1, i1, i3),
        g,
        drag.coefficient,
        drag.spin_damping,
        drag.air_density,
    )


def catch_with_drag(
    coin: Coin,
    omega: FloatArray,
    launch_speed: FloatArray,
    start_sign: float | FloatArray,
    g: float,
    drag: Drag,
) -> tuple[NDArray[np.int8], FloatArray]:
    """Caught in the hand at launch height after a flight through air: (face, catch time).

    The face is the sign of the heads normal's vertical component when the centre of mass
    comes back down to launch height (:func:`coinflight.core.drag.catch`); without drag this
    is the closed form's heads iff n(T)·Z > 0. One SciPy integration per toss.
    """
    from coinflight.core import drag as drag_kernels
    from coinflight.core.outcome import HEADS, TAILS

    if not isinstance(drag, Drag):
        raise TypeError(f"drag must be a Drag, got {type(drag).__name__}")
    model = drag_model(coin, drag, g)
    omega = np.asarray(omega, dtype=float).reshape(-1, 3)
    n = omega.shape[0]
    speed = np.broadcast_to(np.asarray(launch_speed, dtype=float), (n,))
    sign = np.broadcast_to(np.asarray(start_sign, dtype=float), (n,))
    face = np.empty(n, dtype=np.int8)
    when = np.empty(n)
    for k in range(n):
        when[k], state = drag_kernels.catch(model, omega[k], float(speed[k]), float(sign[k]))
        nz = float(drag_kernels.normal(state[9:13])[2])
        face[k] = HEADS if nz > 0.0 else TAILS
    return face, when


class DragCatch(OutcomeModel):
    """Outcome model: caught in the hand at launch height after a flight through air."""

    name = "hand catch with drag"

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

    def describe(self) -> str:
        return f"caught in the hand, {describe_air(self.drag)}"

    def to_dict(self) -> dict[str, Any]:
        return {"surface": "hand", "drag": drag_dict(self.drag)}

    def report(self, coin: Coin, toss: Toss) -> tuple[dict[str, Any], str]:
        from coinflight.core.outcome import FACE_NAMES

        face, when = catch_with_drag(
            coin, toss.omega.reshape(1, 3), toss.launch_speed, toss.start_sign, toss.g, self.drag
        )
        name = FACE_NAMES[int(face[0])]
        line = f"caught at launch height at t = {float(when[0]):.4f} s, {name.upper()} up"
        return {"outcome": name, "catch_time": float(when[0])}, line


__all__ = ["DRAG_TOSSES_PER_SECOND", "DragCatch", "catch_with_drag"]

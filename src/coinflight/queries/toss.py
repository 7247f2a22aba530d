"""One toss (``coinflight toss --json``, ``GET /api/toss``): the face it shows, and the flight
sampled in time for a drawing."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from coinflight.queries.landing import (
    build_drag,
    check_bounces,
    landing_coin,
    settings_for,
    surface_from,
)
from coinflight.queries.values import AirArgs, TableArgs, TossArgs, build_toss

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.surface import Drag, Surface
    from coinflight.model.toss import Flight, Toss
    from coinflight.outcomes.base import OutcomeModel
    from coinflight.outcomes.table import LandingOutcome

MAX_TRAJECTORY = 2000
"""Most times a sampled flight (``trajectory=K``) holds: 2,000 frames are 33 s at 60 frames per
second, more than a student watches of one toss."""


@dataclass(frozen=True)
class TossQuery:
    """One toss as the options describe it, checked: coin, toss, surface, air, bounces."""

    coin: Coin
    toss: Toss
    surface: Surface
    drag: Drag | None
    bounces: int | None

    @property
    def caught(self) -> bool:
        """True for the plain hand catch (the closed form), False for another surface kind (a
        table) or air."""
        return self.surface.kind == "hand" and self.drag is None


def toss_query(
    coin: Coin, args: TossArgs, table: TableArgs, air: AirArgs, bounces: int | None
) -> TossQuery:
    """The options of ``coinflight toss`` checked in the command line's order (surface, air,
    bounces, the coin's corner radius, then the toss)."""
    surface = surface_from(table)
    drag = build_drag(*air)
    check_bounces(surface, bounces)
    return TossQuery(landing_coin(coin, table), build_toss(args), surface, drag, bounces)


def toss_payload(query: TossQuery) -> dict[str, Any]:
    """The JSON object of ``coinflight toss --json``: the catch in the hand by the closed form,
    or the model's report of a table landing or a flight through air."""
    if query.caught:
        from coinflight.model.toss import Flight

        return catch_payload(Flight(query.coin, query.toss))
    payload, _, _ = landing_report(query.coin, query.toss, query.surface, query.drag, query.bounces)
    return payload


def catch_payload(flight: Flight) -> dict[str, Any]:
    """The JSON object of one toss caught in the hand at launch height."""
    out, catch, t = flight.outcome, flight.catch, flight.toss
    return {
        "outcome": out.face_name,
        "same_side": bool(out.same_side),
        "rotations": float(out.rotations),
        "psi": float(out.psi),
        "psi_deg": math.degrees(float(out.psi)),
        "normal": catch.normal,
        "angular_momentum": catch.angular_momentum,
        "omega_at_catch": catch.omega,
        "cos_theta": float(out.alignment),
        "flight_time": float(t.flight_time),
        "launch_speed": float(t.launch_speed),
        "apex": float(t.apex),
        "omega": [float(w) for w in t.omega],
        "start": t.start,
        "g": t.g,
        "coin": flight.coin.to_dict(),
    }


def landing_fields(out: LandingOutcome) -> dict[str, Any]:
    """The JSON fields of one table landing: face, bounces, times (s since launch) and why it
    ended."""
    return {
        "outcome": out.face_name,
        "bounces": int(out.bounces),
        "first_contact": float(out.first_contact),
        "settle_time": float(out.settle_time),
        "status": out.status_name,
    }


def landing_line(out: LandingOutcome) -> str:
    """One line for one table landing: when it lands, how often it bounces, how it ends."""
    first, settle, bounces = float(out.first_contact), float(out.settle_time), int(out.bounces)
    face, status = out.face_name.upper(), out.status_name
    if status == "unsettled":
        return (
            f"lands on the table at t = {first:.4f} s and has NOT settled after {bounces} "
            f"impacts (status unsettled, stopped at t = {settle:.4f} s): the face up then "
            f"was {face}, not a resting face"
        )
    start = f"lands on the table at t = {first:.4f} s, bounces {bounces} times and ends {face}"
    if status == "settled in contact":
        # The rigid ending's time is the decision's: at rest or below the barrier.
        return (
            f"{start} (decided at t = {settle:.4f} s: at rest or below its well's barrier; "
            f"{status})"
        )
    return f"{start} (at t = {settle:.4f} s; {status})"


def air_catch(coin: Coin, toss: Toss, drag: Drag) -> tuple[dict[str, Any], str]:
    """One toss caught in the hand at launch height after its flight through air
    (:func:`coinflight.outcomes.air.catch_with_drag`): the JSON fields (face, catch time in s
    since launch) and one line."""
    from coinflight.core.outcome import FACE_NAMES
    from coinflight.outcomes.air import catch_with_drag

    face, when = catch_with_drag(
        coin, toss.omega.reshape(1, 3), toss.launch_speed, toss.start_sign, toss.g, drag
    )
    name, t = FACE_NAMES[int(face[0])], float(when[0])
    return {"outcome": name, "catch_time": t}, (
        f"caught at launch height at t = {t:.4f} s, {name.upper()} up"
    )


def landing_report(
    coin: Coin, toss: Toss, surface: Surface, drag: Drag | None, bounces: int | None
) -> tuple[dict[str, Any], str, OutcomeModel]:
    """A table landing or a flight through air: the JSON object, the one-line report (a table
    landing's by :func:`landing_fields` and :func:`landing_line`, a catch through air's by
    :func:`air_catch`, a model registered from outside its own ``report``) and the model (for
    its description)."""
    from coinflight.outcomes import outcome_model
    from coinflight.outcomes.air import DragCatch
    from coinflight.outcomes.table import Landing, TableLanding

    model = outcome_model(surface, drag, bounces)
    if isinstance(model, TableLanding):
        landed = Landing(coin, toss, model.surface, model.drag, model.max_bounces).outcome
        payload, line = landing_fields(landed), landing_line(landed)
    elif isinstance(model, DragCatch):
        payload, line = air_catch(coin, toss, model.drag)
    else:  # a model registered from outside: its own report
        payload, line = model.report(coin, toss)
    payload.update(settings_for(model))
    payload.update(
        omega=[float(w) for w in toss.omega],
        start=toss.start,
        g=toss.g,
        flight_time=float(toss.flight_time),
        launch_speed=float(toss.launch_speed),
        apex=float(toss.apex),
        coin=coin.to_dict(),
    )
    return payload, line, model


def trajectory(flight: Flight, k: int) -> dict[str, Any]:
    """The flight sampled at ``k`` equally spaced times from launch to catch, for a drawing,
    by the closed form (:meth:`coinflight.model.toss.Flight.at`, the one
    :func:`coinflight.plotting.animation.animate_toss` draws).

    Returns ``t`` (s), ``normal`` (the heads normal n, lab frame, k × 3), ``quaternion`` (the
    body → lab attitude as [x, y, z, w], scalar last, k × 4: the coin's body z axis is its heads
    normal), ``height`` (m above launch) and, constant over the flight, ``axis`` (the unit
    angular momentum S/|S|, lab frame) and ``cone_half_angle_deg`` (ψ, the angle of n about
    S). The lab frame has z up; the coin starts with its heads normal along +z (heads up) or
    −z (tails up).
    """
    if isinstance(k, bool) or not isinstance(k, int) or not 2 <= k <= MAX_TRAJECTORY:
        raise ValueError(f"trajectory must be a whole number from 2 to {MAX_TRAJECTORY}, got {k!r}")
    import numpy as np

    times = np.linspace(0.0, float(flight.toss.flight_time), k)
    states = flight.at(times)
    s = np.asarray(states.angular_momentum[0], dtype=np.float64)
    size = float(np.linalg.norm(s))
    axis = (s / size).tolist() if size > 0.0 else [0.0, 0.0, 1.0]
    return {
        "t": times,
        "normal": states.normal,
        "quaternion": states.attitude.as_quat(),
        "height": states.height,
        "axis": axis,
        "cone_half_angle_deg": math.degrees(float(flight.outcome.psi)),
    }


__all__ = [
    "MAX_TRAJECTORY",
    "TossQuery",
    "air_catch",
    "catch_payload",
    "landing_fields",
    "landing_line",
    "landing_report",
    "toss_payload",
    "toss_query",
    "trajectory",
]

"""The endpoints of the web application: the page and the JSON API, one module-level function
each on :data:`router` (assembled by :func:`coinflight.web.app.create_app`).

Each endpoint reads its query parameters (:mod:`coinflight.web.params`) and hands the work to
the server's worker processes (:class:`Lanes`): the computing is in
:mod:`coinflight.web.endpoints`, the JSON in :mod:`coinflight.queries`.
"""

from __future__ import annotations

import pickle
from collections.abc import Callable
from contextvars import ContextVar
from dataclasses import dataclass
from functools import lru_cache
from typing import Annotated, Any

from fastapi import APIRouter, Depends, Request
from fastapi.responses import FileResponse, Response
from pydantic import BaseModel

from coinflight._provenance import invoked
from coinflight.model.surface import (
    SurfaceKind,
    add_surface_kind,
    remove_surface_kind,
    surface_kinds,
)
from coinflight.queries.encoding import json_text
from coinflight.web import endpoints
from coinflight.web import params as p
from coinflight.web.runner import Overloaded, Runner

JSON = "application/json"


class OneLine(BaseModel):
    """A refusal: one line naming the value and what is allowed (the command line's words)."""

    detail: str


ANSWERS: dict[int | str, dict[str, Any]] = {
    200: {"content": {JSON: {}}, "description": "The object of the command's --json."},
    422: {"model": OneLine, "description": "A bad value, or work beyond the server's limits."},
    503: {"model": OneLine, "description": "Over the time limit, or every worker busy."},
}

router = APIRouter()
"""The page (``/``) and the API's endpoints (``/api/...``)."""


@dataclass(frozen=True)
class Lanes:
    """Where a request's work runs: the application's worker pool (``app.state.runner``, there
    while the application runs) and its time limit (``app.state.time_limit``), s."""

    state: Any

    @property
    def time_limit(self) -> float:
        return float(self.state.time_limit)

    async def answer(self, fn: Callable[..., Any], *args: Any, long: bool = False) -> Response:
        """``fn(*args)`` as JSON text, computed and encoded in a worker process. ``long``: the
        work grows with what is asked; it is first read, refused or answered among the short
        requests, and moved to the long lane when its estimate is beyond
        :data:`coinflight.web.endpoints.SHORT_SECONDS`, so that short requests never wait
        behind long ones."""
        runner: Runner | None = getattr(self.state, "runner", None)
        if runner is None:
            raise Overloaded("the server is starting or stopping; try again in a few seconds")
        request, kinds = _REQUEST.get(), _portable_kinds()
        if not long:
            return Response(await runner.run(_encoded, request, kinds, fn, *args), media_type=JSON)
        try:
            text = await runner.run(_encoded, request, kinds, fn, *args, True)
        except endpoints.LongWork:
            text = await runner.run(_encoded, request, kinds, fn, *args, False, long=True)
        return Response(text, media_type=JSON)

    async def timed(self, fn: Callable[..., Any], *args: Any, long: bool = True) -> Response:
        """:meth:`answer` for work bounded by the time limit: ``fn(*args, time_limit)``."""
        return await self.answer(fn, *args, self.time_limit, long=long)


def _lanes(request: Request) -> Lanes:
    return Lanes(request.app.state)


Server = Annotated[Lanes, Depends(_lanes)]
"""The application's worker pool and time limit, a dependency of every API endpoint."""


@lru_cache(maxsize=256)
def _portable(kind: SurfaceKind) -> bool:
    """True when ``kind`` can be sent to a worker process (its model and builder importable by
    name: defined at the top level of a module, not a lambda)."""
    try:
        pickle.dumps(kind)
    except (pickle.PicklingError, AttributeError, TypeError):
        return False
    return True


def _portable_kinds() -> tuple[SurfaceKind, ...]:
    """The registered surface kinds, as this process has them now, that a worker can receive."""
    return tuple(kind for kind in surface_kinds().values() if _portable(kind))


def _use_kinds(kinds: tuple[SurfaceKind, ...]) -> None:
    """Make the worker's surface kinds those of the server process (:func:`_portable_kinds`):
    a kind registered or unregistered after the workers started is seen by the next request."""
    for name in list(surface_kinds()):
        remove_surface_kind(name)
    for kind in kinds:
        add_surface_kind(kind)


def _encoded(
    request: str, kinds: tuple[SurfaceKind, ...], fn: Callable[..., Any], *args: Any
) -> str:
    """``fn(*args)`` as JSON text, with the plausibility warnings the library issued while
    computing it in its ``"warnings"`` (as ``--json`` carries them; a worker's standard error
    reaches no one), and ``request`` as its ``"command"`` (:mod:`coinflight._provenance`),
    on the server's surface ``kinds`` (:func:`_use_kinds`)."""
    from coinflight.queries.plausibility import heard, with_warnings

    _use_kinds(kinds)
    with invoked(request), heard() as texts:
        payload = fn(*args)
        return json_text(with_warnings(payload, texts))


_REQUEST: ContextVar[str] = ContextVar("coinflight_request")
"""The request being answered, as ``GET /api/toss?omega=80,0,0`` (set by
:func:`remember_request` for the endpoint, which runs in the same context)."""


async def remember_request(request: Request) -> None:
    """Keep the request's method, path and query (as sent) for its answer's ``"command"``."""
    query = request.url.query
    _REQUEST.set(f"{request.method} {request.url.path}" + (f"?{query}" if query else ""))


@router.get("/", include_in_schema=False)
async def page(request: Request) -> FileResponse:
    """The page (``app.state.index``: its file, in the package's static folder)."""
    return FileResponse(request.app.state.index, media_type="text/html")


@router.get("/api/surfaces", tags=["toss"], response_class=Response, responses=ANSWERS)
async def surfaces(server: Server) -> Response:
    """The surface kinds a toss may end on (the `surface` parameter, --surface): each one's
    name, one line on how a toss ends there, the table's parameters it takes, whether a toss
    may end on edge there and the exact method applies, and the number of random tosses
    this server answers there within its time limit (``suggested_n``). Those the server's
    workers can receive: a kind registered with a lambda is not listed, and refused."""
    from coinflight.queries.landing import surfaces_payload

    seconds = endpoints.BUDGET_SHARE * server.time_limit
    with invoked(_REQUEST.get()):
        payload = surfaces_payload(_portable_kinds(), seconds)
        return Response(json_text(payload), media_type=JSON)


@router.get("/api/toss", tags=["toss"], response_class=Response, responses=ANSWERS)
async def toss(
    *,
    omega: p.Omega = "80,0,0",
    flight_time: p.FlightTime = None,
    launch_speed: p.LaunchSpeed = None,
    start: p.Start = "heads",
    g: p.Gravity = 9.81,
    coin: p.CoinQuery,
    table: p.TableQuery,
    air: p.AirQuery,
    bounces: p.Bounces = None,
    trajectory: p.Trajectory = None,
    server: Server,
) -> Response:
    """One toss: the face it shows and how it turned, as `coinflight toss --json`; with
    `trajectory=K` also the flight sampled at K times from launch to catch (the closed
    form: normal, attitude quaternion, height, the angular momentum's direction and the
    cone half-angle), for drawing it."""
    args = p.toss_args(omega, flight_time, launch_speed, start, g)
    return await server.answer(endpoints.toss, coin, args, table, air, bounces, trajectory)


@router.get("/api/probability", tags=["probability"], response_class=Response, responses=ANSWERS)
async def probability(
    request: Request,
    *,
    omega_x: p.OmegaX = "80",
    omega_y: p.OmegaY = "0",
    omega_z: p.OmegaZ = "0",
    flight_time: p.FlightTimes = None,
    launch_speed: p.LaunchSpeeds = None,
    start: p.Start = "heads",
    g: p.Gravity = 9.81,
    preset: p.TossPreset = None,
    coin: p.CoinQuery,
    table: p.TableQuery,
    air: p.AirQuery,
    method: p.Method = "exact",
    n: p.Size = None,
    seed: p.Seed = None,
    grid_cells: p.GridCells = None,
    server: Server,
) -> Response:
    """The chance of heads for tosses spread over ranges of spin and flight time, as
    `coinflight probability --json` (the server runs each request on one thread; the
    answer does not depend on it)."""
    from coinflight.queries.probability import INPUT_NAMES, PRESET_OPTIONS
    from coinflight.queries.values import DistArgs

    g = p.gravity(g)
    typed = {
        "omega_x": omega_x,
        "omega_y": omega_y,
        "omega_z": omega_z,
        "flight_time": flight_time,
        "launch_speed": launch_speed,
        "g": g,
        "preset": preset,
    }
    given = {k: str(typed[k]) for k in PRESET_OPTIONS if k in request.query_params}
    options = {
        "method": method,
        "n": n,
        "seed": seed,
        "grid_cells": grid_cells,
        "preset": preset,
        "overrides": given if preset is not None else None,
        "inputs": {k: typed[k] for k in INPUT_NAMES},
    }
    tosses = DistArgs(omega_x, omega_y, omega_z, flight_time, launch_speed, start, g)
    return await server.timed(endpoints.probability, coin, tosses, table, air, options)


@router.get("/api/basin", tags=["basin"], response_class=Response, responses=ANSWERS)
async def basin(
    *,
    box: p.BasinBox,
    coin: p.CoinQuery,
    table: p.TableQuery,
    server: Server,
) -> Response:
    """Heads and tails over a box of flight times and spins: the map `coinflight plot
    basin` draws, as JSON (`face`: one row per `spin` value, face codes along
    `flight_time`; `faces` names the codes). At most 640,000 cells."""
    options = {**box, "g": p.gravity(box["g"])}
    bounces, boundaries = options.pop("bounces"), options.pop("boundaries")
    return await server.timed(endpoints.basin, coin, options, table, bounces, boundaries)


@router.get("/api/bias", tags=["bias"], response_class=Response, responses=ANSWERS)
async def bias(
    *,
    psi: p.Psi = None,
    psis: p.Psis = None,
    psi_dist: p.PsiDist = None,
    preset: p.PsiPreset = None,
    monte_carlo: p.MonteCarlo = None,
    seed: p.Seed = None,
    coin: p.CoinQuery,
    server: Server,
) -> Response:
    """The probability that a precessing coin lands on the side it started (Diaconis,
    Holmes & Montgomery 2007), as `coinflight bias --json`; with `psis` a list of those
    objects, one for each fixed ψ, in one request."""
    if psis is not None:
        others = {"psi": psi, "psi_dist": psi_dist, "preset": preset,
                  "monte_carlo": monte_carlo}  # fmt: skip
        given = [name for name, value in others.items() if value is not None]
        if given:
            raise ValueError(f"psis is the closed form at each ψ: leave out {', '.join(given)}")
        return await server.answer(endpoints.bias_curve, coin, p.number_list(psis, "psis"))
    long = monte_carlo is not None
    return await server.timed(
        endpoints.bias, coin, psi, psi_dist, preset, monte_carlo, seed, long=long
    )


@router.get("/api/data", tags=["data"], response_class=Response, responses=ANSWERS)
async def data(
    dataset: p.Dataset = None,
    interval: p.Interval = "exact",
    psi_sd: p.PsiSd = 0.0,
    seed: p.SplitSeed = None,
    folds: p.Folds = None,
    repeats: p.Repeats = None,
    *,
    server: Server,
) -> Response:
    """Same-side and heads rates of real flips (Bartoš et al.'s 350,757), the precession
    angle ψ that explains them and the people's ψ population, as `coinflight data --json`."""
    return await server.timed(
        endpoints.data, dataset, interval, psi_sd, seed, folds, repeats, long=False
    )


__all__ = ["ANSWERS", "Lanes", "remember_request", "router"]

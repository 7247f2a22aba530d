"""The ASGI application: the page, its static files and the JSON API (see
:mod:`coinflight.web`)."""

from __future__ import annotations

from collections.abc import AsyncIterator, Callable, Sequence
from contextlib import asynccontextmanager
from contextvars import ContextVar
from importlib.resources import as_file, files
from typing import Any

from fastapi import Depends, FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.middleware.trustedhost import TrustedHostMiddleware
from fastapi.responses import FileResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel

from coinflight import __version__
from coinflight._provenance import invoked
from coinflight._validation import shortened as shortened_text
from coinflight._validation import unreadable
from coinflight.queries.encoding import json_text
from coinflight.web import params as p
from coinflight.web.runner import DEFAULT_TIME_LIMIT, Overloaded, Runner, check_runner

JSON = "application/json"


class OneLine(BaseModel):
    """A refusal: one line naming the value and what is allowed (the command line's words)."""

    detail: str


ANSWERS: dict[int | str, dict[str, Any]] = {
    200: {"content": {JSON: {}}, "description": "The object of the command's --json."},
    422: {"model": OneLine, "description": "A bad value, or work beyond the server's limits."},
    503: {"model": OneLine, "description": "Over the time limit, or every worker busy."},
}


def create_app(
    *,
    time_limit: float = DEFAULT_TIME_LIMIT,
    workers: int | None = None,
    backlog: int = 64,
    allowed_hosts: Sequence[str] | None = None,
) -> FastAPI:
    """The coinflight web application.

    Parameters
    ----------
    time_limit : float
        Seconds a request may take, waiting for a worker included; beyond it the answer is
        HTTP 503 with one line.
    workers : int or None
        Worker processes computing the long requests (a probability, a map, a Monte Carlo
        check; default: the CPU count, 1 to 4); one or two more compute the short ones
        (:mod:`coinflight.web.runner`).
    backlog : int
        Requests of each kind that may wait for a worker; beyond them HTTP 503 ("busy") at once.
    allowed_hosts : list of str, optional
        The names a request's ``Host`` header may give (``*`` any); another is answered 400
        (Starlette's ``TrustedHostMiddleware``: a page on another site cannot reach this
        server through a name it controls, DNS rebinding). None: any (``coinflight serve``
        passes the address it is bound to, :func:`coinflight.web.server.allowed_hosts`).
    """
    check_runner(workers, time_limit, backlog)
    running: list[Runner] = []  # the pool, while the application runs (its lifespan)

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        runner = Runner(workers, time_limit, backlog)
        try:
            await runner.start()
            running.append(runner)
            app.state.runner = runner
            yield
        finally:
            running.clear()
            runner.close()

    app = FastAPI(
        # FastAPI's /docs and /redoc pages load their scripts from a CDN; the server must work
        # offline, so only the schema (/openapi.json) is served.
        docs_url=None,
        redoc_url=None,
        title="coinflight",
        version=__version__,
        summary="The physics of coin tossing: the command line's answers as JSON.",
        description=(
            "Each endpoint answers as `coinflight COMMAND --json` does: the parameters are the "
            "command's options with underscores (`flight_time` for `--flight-time`), the "
            'answer the same JSON object. Bad input: HTTP 422 `{"detail": "one line"}` '
            "with the command line's words; work over the server's limits: 422 before it "
            "starts, or 503 after the time limit."
        ),
        lifespan=lifespan,
        dependencies=[Depends(_known_parameters), Depends(_remember_request)],
    )
    if allowed_hosts is not None:
        app.add_middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts))
    _errors(app)
    _static(app)

    async def answer(fn: Callable[..., Any], *args: Any, long: bool = False) -> Response:
        """``fn(*args)`` as JSON text, computed and encoded in a worker process. ``long``: the
        work grows with what is asked; it is first read, refused or answered among the short
        requests, and moved to the long lane when its estimate is beyond
        :data:`coinflight.web.endpoints.SHORT_SECONDS`, so that short requests never wait
        behind long ones."""
        from coinflight.web.endpoints import LongWork

        if not running:
            raise Overloaded("the server is starting or stopping; try again in a few seconds")
        runner, request = running[0], _REQUEST.get()
        if not long:
            return Response(await runner.run(_encoded, request, fn, *args), media_type=JSON)
        try:
            text = await runner.run(_encoded, request, fn, *args, True)
        except LongWork:
            text = await runner.run(_encoded, request, fn, *args, False, long=True)
        return Response(text, media_type=JSON)

    @app.get("/api/toss", tags=["toss"], response_class=Response, responses=ANSWERS)
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
    ) -> Response:
        """One toss: the face it shows and how it turned, as `coinflight toss --json`; with
        `trajectory=K` also the flight sampled at K times from launch to catch (the closed
        form: normal, attitude quaternion, height, the angular momentum's direction and the
        cone half-angle), for drawing it."""
        from coinflight.web import endpoints

        args = p.toss_args(omega, flight_time, launch_speed, start, g)
        return await answer(
            endpoints.toss,
            coin,
            args,
            table,
            air,
            bounces,
            trajectory,
        )

    @app.get("/api/probability", tags=["probability"], response_class=Response, responses=ANSWERS)
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
    ) -> Response:
        """The chance of heads for tosses spread over ranges of spin and flight time, as
        `coinflight probability --json` (the server runs each request on one thread; the
        answer does not depend on it)."""
        from coinflight.queries.probability import INPUT_NAMES, PRESET_OPTIONS
        from coinflight.queries.values import DistArgs
        from coinflight.web import endpoints

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
        return await answer(
            endpoints.probability,
            coin,
            DistArgs(omega_x, omega_y, omega_z, flight_time, launch_speed, start, g),
            table,
            air,
            options,
            time_limit,
            long=True,
        )

    @app.get("/api/basin", tags=["basin"], response_class=Response, responses=ANSWERS)
    async def basin(
        *,
        flight_time: p.FlightTimeRange = None,
        launch_speed: p.LaunchSpeedRange = None,
        omega_x: p.OmegaXRange = None,
        omega_y: p.OmegaYFixed = 0.0,
        omega_z: p.OmegaZFixed = 0.0,
        psi: p.PsiFixed = None,
        precession_rate: p.PrecessionRange = None,
        resolution: p.Resolution = "500",
        start: p.Start = "heads",
        g: p.Gravity = 9.81,
        coin: p.CoinQuery,
        table: p.TableQuery,
        bounces: p.Bounces = None,
        boundaries: p.Boundaries = False,
    ) -> Response:
        """Heads and tails over a box of flight times and spins: the map `coinflight plot
        basin` draws, as JSON (`face`: one row per `spin` value, face codes along
        `flight_time`; `faces` names the codes). At most 640,000 cells."""
        from coinflight.web import endpoints

        options = {
            "flight_time": flight_time,
            "launch_speed": launch_speed,
            "omega_x": omega_x,
            "omega_y": omega_y,
            "omega_z": omega_z,
            "psi": psi,
            "precession_rate": precession_rate,
            "resolution": resolution,
            "start": start,
            "g": p.gravity(g),
        }
        return await answer(
            endpoints.basin,
            coin,
            options,
            table,
            bounces,
            boundaries,
            time_limit,
            long=True,
        )

    @app.get("/api/bias", tags=["bias"], response_class=Response, responses=ANSWERS)
    async def bias(
        *,
        psi: p.Psi = None,
        psis: p.Psis = None,
        psi_dist: p.PsiDist = None,
        preset: p.PsiPreset = None,
        monte_carlo: p.MonteCarlo = None,
        seed: p.Seed = None,
        coin: p.CoinQuery,
    ) -> Response:
        """The probability that a precessing coin lands on the side it started (Diaconis,
        Holmes & Montgomery 2007), as `coinflight bias --json`; with `psis` a list of those
        objects, one for each fixed ψ, in one request."""
        from coinflight.web import endpoints

        if psis is not None:
            others = {"psi": psi, "psi_dist": psi_dist, "preset": preset,
                      "monte_carlo": monte_carlo}  # fmt: skip
            given = [name for name, value in others.items() if value is not None]
            if given:
                raise ValueError(f"psis is the closed form at each ψ: leave out {', '.join(given)}")
            return await answer(endpoints.bias_curve, coin, p.number_list(psis, "psis"))
        return await answer(
            endpoints.bias,
            coin,
            psi,
            psi_dist,
            preset,
            monte_carlo,
            seed,
            time_limit,
            long=monte_carlo is not None,
        )

    @app.get("/api/data", tags=["data"], response_class=Response, responses=ANSWERS)
    async def data(
        dataset: p.Dataset = None,
        interval: p.Interval = "exact",
        psi_sd: p.PsiSd = 0.0,
        seed: p.SplitSeed = None,
        folds: p.Folds = None,
        repeats: p.Repeats = None,
    ) -> Response:
        """Same-side and heads rates of real flips (Bartoš et al.'s 350,757), the precession
        angle ψ that explains them and the people's ψ population, as `coinflight data --json`."""
        from coinflight.web import endpoints

        return await answer(
            endpoints.data, dataset, interval, psi_sd, seed, folds, repeats, time_limit
        )

    return app


def _encoded(request: str, fn: Callable[..., Any], *args: Any) -> str:
    """``fn(*args)`` as JSON text, with the plausibility warnings the library issued while
    computing it in its ``"warnings"`` (as ``--json`` carries them; a worker's standard error
    reaches no one), and ``request`` as its ``"command"`` (:mod:`coinflight._provenance`)."""
    from coinflight.queries.plausibility import heard, with_warnings

    with invoked(request), heard() as texts:
        payload = fn(*args)
        return json_text(with_warnings(payload, texts))


_REQUEST: ContextVar[str] = ContextVar("coinflight_request")
"""The request being answered, as ``GET /api/toss?omega=80,0,0`` (set by
:func:`_remember_request` for the endpoint, which runs in the same context)."""


async def _remember_request(request: Request) -> None:
    """Keep the request's method, path and query (as sent) for its answer's ``"command"``."""
    query = request.url.query
    _REQUEST.set(f"{request.method} {request.url.path}" + (f"?{query}" if query else ""))


async def _known_parameters(request: Request) -> None:
    """A parameter the endpoint does not take is an error, as an unknown option is on the
    command line (a typo such as ``flight-time=`` is not silently ignored)."""
    route = request.scope.get("route")
    dependant = getattr(route, "dependant", None)
    if dependant is None:
        return
    known = _query_names(dependant)
    for name in request.query_params:
        if name not in known:
            raise ValueError(f"No such option: {p.flag(name)}")


def _query_names(dependant: Any) -> set[str]:
    """The query parameters of an endpoint and of its dependencies (the coin, the table, …)."""
    names = {param.alias for param in dependant.query_params}
    for sub in dependant.dependencies:
        names |= _query_names(sub)
    return names


ECHO_LIMIT = 200
"""Most characters of one value of a request an error repeats (longer: its start and end
around an ellipsis); the whole line is at most :data:`DETAIL_LIMIT`."""
DETAIL_LIMIT = 1000


def shortened(message: str, values: Sequence[str]) -> str:
    """``message`` on one line, each of ``values`` (the request's names and values) longer
    than :data:`ECHO_LIMIT` in it shortened, as typed or quoted, and the line cut to
    :data:`DETAIL_LIMIT` (a client's 100 kB value is not sent back to it)."""
    for value in sorted(set(values), key=len, reverse=True):
        if len(value) > ECHO_LIMIT:
            short = shortened_text(value, ECHO_LIMIT)
            message = message.replace(repr(value), repr(short)).replace(value, short)
    return shortened_text(" ".join(message.split()), DETAIL_LIMIT)


def _errors(app: FastAPI) -> None:
    """Bad input → 422 with one line; over time or busy → 503 with one line."""

    def one_line(request: Request, status: int, message: str) -> JSONResponse:
        values = [x for pair in request.query_params.multi_items() for x in pair]
        return JSONResponse({"detail": shortened(message, values)}, status_code=status)

    async def bad_value(request: Request, exc: Exception) -> JSONResponse:
        return one_line(request, 422, str(exc))

    async def bad_request(request: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, RequestValidationError)
        return one_line(request, 422, _validation_line(exc))

    async def overloaded(request: Request, exc: Exception) -> JSONResponse:
        return one_line(request, 503, str(exc))

    app.add_exception_handler(ValueError, bad_value)
    app.add_exception_handler(TypeError, bad_value)
    app.add_exception_handler(RequestValidationError, bad_request)
    app.add_exception_handler(Overloaded, overloaded)


def _validation_line(exc: RequestValidationError) -> str:
    """The first error of a request FastAPI could not read, as the command line says it
    (typer's words: ``Invalid value for '--n': '1.5' is not a valid integer``)."""
    error = exc.errors()[0]
    name = str(error.get("loc", ("", "?"))[-1])
    reading = unreadable(error)
    if reading is not None:
        return f"Invalid value for '{p.flag(name)}': {reading}"
    return f"Invalid value for '{p.flag(name)}': {error.get('msg', 'not valid')}"


def _static(app: FastAPI) -> None:
    """``/``: the page; ``/static/...``: its files (package data, read-only)."""
    static = files("coinflight.web").joinpath("static")
    with as_file(static) as folder:  # a real folder for an installed (unzipped) package
        app.mount("/static", StaticFiles(directory=folder), name="static")
        index = folder / "index.html"

    @app.get("/", include_in_schema=False)
    async def page() -> FileResponse:
        return FileResponse(index, media_type="text/html")


__all__ = ["create_app"]

"""The ASGI application: the page, its static files and the JSON API (see
:mod:`coinflight.web`)."""

from __future__ import annotations

from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager
from importlib.resources import as_file, files
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import FileResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles

from coinflight import __version__
from coinflight.queries.encoding import json_text
from coinflight.web import params as p
from coinflight.web.runner import DEFAULT_TIME_LIMIT, Overloaded, Runner

JSON = "application/json"


def create_app(
    *, time_limit: float = DEFAULT_TIME_LIMIT, workers: int | None = None, backlog: int = 64
) -> FastAPI:
    """The coinflight web application.

    Parameters
    ----------
    time_limit : float
        Seconds a request may compute; beyond it the answer is HTTP 503 with one line.
    workers : int or None
        Worker threads computing answers (default: the CPU count, 2 to 8).
    backlog : int
        Requests that may wait for a worker; beyond them HTTP 503 ("busy") at once.
    """
    runner = Runner(workers, time_limit, backlog)

    @asynccontextmanager
    async def lifespan(_: FastAPI) -> AsyncIterator[None]:
        yield
        runner.close()

    app = FastAPI(
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
    )
    app.state.runner = runner
    _errors(app)
    _static(app)

    async def answer(fn: Callable[..., dict[str, Any]], *args: Any) -> Response:
        return Response(json_text(await runner.run(fn, *args)), media_type=JSON)

    @app.get("/api/toss", tags=["toss"], response_class=Response)
    async def toss(
        omega: p.Omega = "80,0,0",
        flight_time: p.FlightTime = None,
        launch_speed: p.LaunchSpeed = None,
        start: p.Start = "heads",
        g: p.Gravity = 9.81,
        coin: p.CoinName = None,
        radius: p.Radius = None,
        thickness: p.Thickness = None,
        mass: p.Mass = None,
        surface: p.Surface = "hand",
        drop_height: p.DropHeight = None,
        restitution: p.Restitution = None,
        friction: p.Friction = None,
        drag: p.Drag = None,
        spin_damping: p.SpinDamping = None,
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
            (coin, radius, thickness, mass),
            args,
            p.table_args(surface, drop_height, restitution, friction),
            p.air_args(drag, spin_damping),
            bounces,
            trajectory,
        )

    return app


def _errors(app: FastAPI) -> None:
    """Bad input → 422 with one line; over time or busy → 503 with one line."""

    def one_line(status: int, message: str) -> JSONResponse:
        return JSONResponse({"detail": " ".join(message.split())}, status_code=status)

    async def bad_value(_: Request, exc: Exception) -> JSONResponse:
        return one_line(422, str(exc))

    async def bad_request(_: Request, exc: Exception) -> JSONResponse:
        assert isinstance(exc, RequestValidationError)
        return one_line(422, _validation_line(exc))

    async def overloaded(_: Request, exc: Exception) -> JSONResponse:
        return one_line(503, str(exc))

    app.add_exception_handler(ValueError, bad_value)
    app.add_exception_handler(TypeError, bad_value)
    app.add_exception_handler(RequestValidationError, bad_request)
    app.add_exception_handler(Overloaded, overloaded)


_READING = {
    "float_parsing": "is not a number",
    "int_parsing": "is not a valid integer",
    "int_from_float": "is not a valid integer",
}


def _validation_line(exc: RequestValidationError) -> str:
    """The first error of a request FastAPI could not read, as the command line says it."""
    error = exc.errors()[0]
    name = str(error.get("loc", ("", "?"))[-1])
    what = _READING.get(str(error.get("type")), str(error.get("msg", "is not valid")))
    return p.invalid(name, error.get("input"), what)


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

"""The ASGI application: the page, its static files and the JSON API (see
:mod:`coinflight.web`)."""

from __future__ import annotations

from collections.abc import AsyncIterator, Sequence
from contextlib import asynccontextmanager
from importlib.resources import as_file, files
from typing import Any

from fastapi import Depends, FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.middleware.trustedhost import TrustedHostMiddleware
from fastapi.responses import JSONResponse
from fastapi.staticfiles import StaticFiles

from coinflight import __version__
from coinflight._validation import shortened as shortened_text
from coinflight._validation import unreadable
from coinflight.web import params as p
from coinflight.web.routes import remember_request, router
from coinflight.web.runner import DEFAULT_TIME_LIMIT, Overloaded, Runner, check_runner


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
        lifespan=_lifespan,
        dependencies=[Depends(_known_parameters), Depends(remember_request)],
    )
    app.state.pool = (workers, time_limit, backlog)
    app.state.time_limit = time_limit
    if allowed_hosts is not None:
        app.add_middleware(TrustedHostMiddleware, allowed_hosts=list(allowed_hosts))
    _errors(app)
    _static(app)
    app.include_router(router)
    return app


@asynccontextmanager
async def _lifespan(app: FastAPI) -> AsyncIterator[None]:
    """The worker pool (``app.state.runner``) while the application runs."""
    runner = Runner(*app.state.pool)
    try:
        await runner.start()
        app.state.runner = runner
        yield
    finally:
        app.state.runner = None
        runner.close()


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
    """``/static/...``: the page's files (package data, read-only); ``app.state.index``: the
    page that ``/`` answers."""
    static = files("coinflight.web").joinpath("static")
    with as_file(static) as folder:  # a real folder for an installed (unzipped) package
        app.mount("/static", StaticFiles(directory=folder), name="static")
        app.state.index = folder / "index.html"


__all__ = ["create_app"]

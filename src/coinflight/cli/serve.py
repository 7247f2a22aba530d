"""``coinflight serve``: the classroom page and its JSON API on a local web server."""

from __future__ import annotations

import sys
from typing import Annotated

import typer

from coinflight.cli.exits import say
from coinflight.cli.options import number

Host = Annotated[
    str,
    typer.Option(
        "--host",
        metavar="ADDRESS",
        help="Address to listen on. The default answers this machine only; 0.0.0.0 (any "
        "address not a loopback) serves every machine that can reach it, with a warning.",
    ),
]
Port = Annotated[
    int,
    typer.Option("--port", min=0, max=65535, help="TCP port (0: any free port, printed)."),
]
TimeLimit = Annotated[
    float,
    typer.Option(
        "--time-limit",
        parser=number,
        metavar="S",
        help="Seconds one request may take, waiting for a worker included, before it is "
        "answered 503.",
    ),
]


Workers = Annotated[
    int | None,
    typer.Option(
        "--workers",
        min=1,
        max=64,
        metavar="N",
        help="Worker processes computing the long requests (a probability, a map, a Monte "
        "Carlo check); one or two more answer the short ones, which never wait behind them "
        "[default: the CPU count, at most 4].",
    ),
]


AllowedHost = Annotated[
    list[str] | None,
    typer.Option(
        "--allowed-host",
        metavar="NAME",
        help="A name the server may be reached by besides its address (repeat for more; * "
        "any), e.g. the machine's name on your network. Requests giving another host are "
        "refused (400): a web page elsewhere cannot reach the server through a name it "
        "controls (DNS rebinding). [default: the --host address, with localhost on "
        "loopback; any on 0.0.0.0 or ::]",
    ),
]


def serve(
    host: Host = "127.0.0.1",
    port: Port = 8000,
    time_limit: TimeLimit = 30.0,
    workers: Workers = None,
    allowed_host: AllowedHost = None,
) -> None:
    """Serve the interactive page and its JSON API (/api/..., /openapi.json) until Ctrl-C.

    Example: coinflight serve, then open http://127.0.0.1:8000/
    """
    from coinflight.web.server import serve as run

    if not time_limit > 0:
        raise ValueError(f"--time-limit must be a positive number of seconds, got {time_limit:g}")
    import coinflight.core._jit  # noqa: F401  (the workers' numba environment, checked here)

    run(
        host,
        port,
        time_limit=time_limit,
        workers=workers,
        allowed=allowed_host or (),
        announce=_announce,
        warn=lambda line: say(f"coinflight: warning: {line}"),
    )


def _announce(line: str) -> None:
    """The address, on stdout at once (a script reading it through a pipe sees it now)."""
    typer.echo(line)
    sys.stdout.flush()


__all__ = ["serve"]

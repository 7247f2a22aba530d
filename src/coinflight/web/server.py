"""Running the application on uvicorn: the socket bound first (a port in use is one line, not a
traceback), the address announced, then served until Ctrl-C."""

from __future__ import annotations

import ipaddress
import socket
from collections.abc import Callable, Sequence

from coinflight.web.runner import DEFAULT_TIME_LIMIT


def is_loopback(host: str) -> bool:
    """True for an address only this machine reaches (127.0.0.0/8, ::1, localhost)."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


WILDCARDS = ("0.0.0.0", "::", "")
"""Addresses that listen on every interface of the machine."""


def allowed_hosts(host: str, extra: Sequence[str] = ()) -> list[str]:
    """The names a request's ``Host`` header may give to a server bound to ``host``: that
    address (IPv6 in brackets, as a Host header writes it), ``localhost`` with the loopback
    addresses for a loopback server, and each of ``extra`` (``*``: any). A server on every
    address (0.0.0.0, ::) cannot know the names it is reached by: any, unless ``extra``
    names them."""
    for name in extra:
        if not name or (any(c in name for c in "/ :\t") and not name.startswith("[")):
            raise ValueError(
                f"--allowed-host {name!r} is not a host name (e.g. coins.example.org, "
                "192.168.1.20, [fe80::1]) or *"
            )
        if "*" in name[1:] or (name.startswith("*") and name != "*" and not name.startswith("*.")):
            raise ValueError(
                f"--allowed-host {name!r}: a wildcard is * alone or *.DOMAIN (*.example.org)"
            )
    names = [name.lower() for name in extra]
    if host in WILDCARDS:
        return names or ["*"]
    names.append(f"[{host}]" if ":" in host else host.lower())
    if is_loopback(host):
        names += ["localhost", "127.0.0.1", "[::1]"]
    return list(dict.fromkeys(names))


def bind(host: str, port: int) -> socket.socket:
    """A listening TCP socket on ``host``:``port`` (0: a free port), or a ValueError naming
    the address and why it cannot be had (in use, not this machine's, not an address)."""
    if isinstance(port, bool) or not isinstance(port, int) or not 0 <= port <= 65535:
        raise ValueError(f"--port must be a whole number from 0 to 65535, got {port!r}")
    try:
        family, kind, proto, _, address = socket.getaddrinfo(
            host, port, type=socket.SOCK_STREAM, flags=socket.AI_PASSIVE
        )[0]
    except (socket.gaierror, UnicodeError) as exc:
        raise ValueError(f"--host {host!r} is not an address of this machine ({exc})") from None
    sock = socket.socket(family, kind, proto)
    try:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        sock.bind(address)
        sock.listen(2048)
    except OSError as exc:
        sock.close()
        reason = "is in use" if exc.errno == 98 else f"cannot be used ({exc.strerror})"
        raise ValueError(
            f"port {port} on {host} {reason}; choose another with --port (0: any free port)"
        ) from None
    return sock


def url(sock: socket.socket) -> str:
    """``http://HOST:PORT/`` of a bound socket (an IPv6 host in brackets)."""
    host, port = sock.getsockname()[:2]
    return f"http://[{host}]:{port}/" if ":" in host else f"http://{host}:{port}/"


def serve(
    host: str = "127.0.0.1",
    port: int = 8000,
    *,
    time_limit: float = DEFAULT_TIME_LIMIT,
    workers: int | None = None,
    allowed: Sequence[str] = (),
    announce: Callable[[str], None] = print,
    warn: Callable[[str], None] = print,
) -> None:
    """Serve :func:`coinflight.web.create_app` on ``host``:``port`` until interrupted.

    Requests naming another host than ``host`` (and ``allowed``) are answered 400
    (:func:`allowed_hosts`). ``announce`` receives the address once the socket is bound
    (requests wait until the workers have started); ``warn`` a warning when ``host`` is
    reachable from other machines.
    """
    import uvicorn

    from coinflight.web.app import create_app

    names = allowed_hosts(host, allowed)
    sock = bind(host, port)  # a port in use is refused before any worker starts
    app = create_app(time_limit=time_limit, workers=workers, allowed_hosts=names)
    if not is_loopback(host):
        warn(
            f"--host {host} serves coinflight to every machine that can reach this one "
            "(no login, no encryption); use it on a network you trust"
        )
    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="on")
    announce(f"coinflight serving on {url(sock)} (Ctrl-C to stop)")
    try:
        uvicorn.Server(config).run(sockets=[sock])
    finally:
        sock.close()


__all__ = ["allowed_hosts", "bind", "is_loopback", "serve", "url"]

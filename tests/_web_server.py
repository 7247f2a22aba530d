"""A real ``coinflight serve`` in a subprocess, for the tests that talk to it over HTTP."""

from __future__ import annotations

import os
import re
import select
import signal
import subprocess
import sys
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

ADDRESS = re.compile(r"^coinflight serving on (http://\S+/) \(Ctrl-C to stop\)$")


@dataclass
class Server:
    process: subprocess.Popen[str]
    url: str
    port: int


WAIT = 300.0
"""Seconds a wait on the server may take before the test gives up: a generous bound, not a
timing (each wait ends on its condition). Its workers start in the lifespan, importing the
library in a fork server: seconds when quiet, tens of seconds at load 10, and uvicorn does not
act on Ctrl-C until they have (`coinflight.web.runner.START_TIMEOUT` is 300 s)."""


def _ready(url: str, process: subprocess.Popen[str], timeout: float) -> None:
    """Wait until the server answers its page over HTTP: its lifespan (the workers) has
    started, so it serves, and stops on Ctrl-C, at once. A server on every address (0.0.0.0,
    ::) is asked on loopback."""
    local = url.replace("//0.0.0.0:", "//127.0.0.1:").replace("//[::]:", "//[::1]:")
    direct = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # no proxy
    with direct.open(local, timeout=timeout) as answer:  # waits in the listening backlog
        assert answer.status == 200, (answer.status, process.poll())


def _line(stream, timeout: float) -> str:
    ready, _, _ = select.select([stream], [], [], timeout)
    assert ready, f"no line from the server within {timeout} s"
    return stream.readline().rstrip("\n")


@contextmanager
def serving(*args: str, timeout: float = WAIT) -> Iterator[Server]:
    """``coinflight serve ARGS`` (default port 0: a free one), running until the block ends;
    yields its announced address once it answers over HTTP (:func:`_ready`). Stopped with
    SIGINT (Ctrl-C), as a user stops it."""
    command = [sys.executable, "-m", "coinflight", "serve", *(args or ("--port", "0"))]
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    proc = subprocess.Popen(
        command,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        # Ctrl-C acts as at a terminal even when pytest was started with SIGINT ignored (a
        # background job of a shell without job control; Python keeps it ignored).
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    try:
        line = _line(proc.stdout, timeout)
        match = ADDRESS.match(line)
        assert match, (line, proc.stderr.read() if proc.poll() is not None else "")
        url = match.group(1)
        _ready(url, proc, timeout)
        yield Server(proc, url, int(url.rstrip("/").rsplit(":", 1)[1]))
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            try:
                proc.wait(timeout=WAIT)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        proc.stdout.close()
        proc.stderr.close()

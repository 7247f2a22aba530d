"""A real ``coinflight serve`` in a subprocess, for the tests that talk to it over HTTP."""

from __future__ import annotations

import os
import re
import select
import signal
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

ADDRESS = re.compile(r"^coinflight serving on (http://\S+/) \(Ctrl-C to stop\)$")


@dataclass
class Server:
    process: subprocess.Popen[str]
    url: str
    port: int


def _line(stream, timeout: float) -> str:
    ready, _, _ = select.select([stream], [], [], timeout)
    assert ready, f"no line from the server within {timeout} s"
    return stream.readline().rstrip("\n")


@contextmanager
def serving(*args: str, timeout: float = 60.0) -> Iterator[Server]:
    """``coinflight serve ARGS`` (default port 0: a free one), running until the block ends;
    yields its announced address. Stopped with SIGINT (Ctrl-C), as a user stops it."""
    command = [sys.executable, "-m", "coinflight", "serve", *(args or ("--port", "0"))]
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    proc = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env
    )
    try:
        line = _line(proc.stdout, timeout)
        match = ADDRESS.match(line)
        assert match, (line, proc.stderr.read() if proc.poll() is not None else "")
        url = match.group(1)
        yield Server(proc, url, int(url.rstrip("/").rsplit(":", 1)[1]))
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            try:
                proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        proc.stdout.close()
        proc.stderr.close()

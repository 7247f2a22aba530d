"""Command-line checks shared by the tests: one error line, exit 2, no traceback."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

from typer.testing import CliRunner

from coinflight import __version__
from coinflight._provenance import command_line
from coinflight.cli import app

runner = CliRunner()


def answer(result: Any, argv: list[Any]) -> Any:
    """The JSON that ``coinflight ARGV`` printed (``result`` of the runner), to compare with
    another command line's: each object's ``"command"`` checked to be ARGV's command line and
    left out (the one field that differs), its ``coinflight_version`` checked and kept."""
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout)
    for obj in payload if isinstance(payload, list) else [payload]:
        assert obj.pop("command") == command_line([str(a) for a in argv])
        assert obj["coinflight_version"] == __version__
    return payload


def api_answer(response: Any) -> Any:
    """The web API's JSON, to compare with the command line's :func:`answer`: its
    ``"command"`` checked to be the request as sent and left out, its version checked."""
    assert response.status_code == 200, response.text
    payload = response.json()
    for obj in payload if isinstance(payload, list) else [payload]:
        assert obj.pop("command") == "GET " + response.request.url.raw_path.decode()
        assert obj["coinflight_version"] == __version__
    return payload


def one_line_error(*args: object) -> str:
    """Run the CLI; assert exit 2 and one error line on stderr, no traceback; the message."""
    result = runner.invoke(app, [str(a) for a in args])
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("coinflight: error: ")
    return lines[0].removeprefix("coinflight: error: ")


def script_error(script: Path, args: list[str], cwd: Path) -> str:
    """Run a benchmark script with ``args`` (in ``cwd``); assert exit 2, nothing on stdout,
    no traceback, and a last stderr line ``SCRIPT: error: ...`` (argparse's own errors print
    the usage first); the message after that prefix."""
    run = subprocess.run(
        [sys.executable, str(script), *args],
        capture_output=True,
        text=True,
        timeout=300,  # start-up and imports only: every input is checked before a toss
        cwd=cwd,
    )
    assert run.returncode == 2, run.stderr
    assert run.stdout == ""
    assert "Traceback" not in run.stderr
    last = run.stderr.strip().splitlines()[-1]
    assert last.startswith(f"{script.name}: error: "), run.stderr
    return last.removeprefix(f"{script.name}: error: ")

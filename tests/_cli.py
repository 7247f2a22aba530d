"""Command-line checks shared by the tests: one error line, exit 2, no traceback."""

from __future__ import annotations

from typer.testing import CliRunner

from coinflight.cli import app

runner = CliRunner()


def one_line_error(*args: object) -> str:
    """Run the CLI; assert exit 2 and one error line on stderr, no traceback; the message."""
    result = runner.invoke(app, [str(a) for a in args])
    assert result.exit_code == 2, result.output
    assert "Traceback" not in result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("coinflight: error: ")
    return lines[0].removeprefix("coinflight: error: ")

"""Standard streams and Ctrl-C, as command-line tools handle them (issue 10 items 2 and 5).

A closed pipe ends quietly with exit code 141 (128 + SIGPIPE); standard output on a full disk,
or closed, is one line ``coinflight: error: cannot write to standard output: REASON`` and exit
code 2; Ctrl-C is ``coinflight: interrupted`` and exit code 130, with no partial output. The
streams are real, so these run ``python -m coinflight`` in a subprocess (sources on PYTHONPATH,
as in CI); what CliRunner can show is tested through it.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from typer.testing import CliRunner

from coinflight.cli import app

SRC = Path(__file__).parents[1] / "src"
ENV = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
COUNTS = "person hsame hdiff tsame tdiff same flips\nA 30 20 28 22 58 100\nB 26 24 25 25 51 100\n"

# The cheapest command lines, one per kind of output: help, version, text, JSON, a data file.
COMMANDS = [
    ["--help"],
    ["--version"],
    ["toss", "--help"],
    ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7"],
    ["toss", "--omega", "80", "0", "0", "--flight-time", "0.7", "--json"],
    ["data", "--counts", "counts.txt"],
]
IDS = [" ".join(argv) for argv in COMMANDS]


def _coinflight(argv, cwd, **kwargs):
    return subprocess.Popen(
        [sys.executable, "-m", "coinflight", *argv],
        cwd=cwd,
        env=ENV,
        stderr=subprocess.PIPE,
        text=True,
        **kwargs,
    )


@pytest.fixture
def folder(tmp_path):
    (tmp_path / "counts.txt").write_text(COUNTS, encoding="utf-8")
    return tmp_path


@pytest.mark.parametrize("argv", COMMANDS, ids=IDS)
def test_a_closed_pipe_ends_quietly_with_141(folder, argv):
    """`coinflight … | head -c 0`: the reader is gone before the first write."""
    proc = _coinflight(argv, folder, stdout=subprocess.PIPE)
    assert proc.stdout is not None
    proc.stdout.close()  # as `head` does when it has what it wants
    _, err = proc.communicate(timeout=120)
    assert (proc.returncode, err) == (141, "")


def test_a_reader_that_stops_early_ends_the_command_quietly(folder):
    """`coinflight data … | head -c 10`, with the shell's pipe."""
    command = f'"{sys.executable}" -m coinflight data --counts counts.txt | head -c 10'
    result = subprocess.run(
        ["bash", "-o", "pipefail", "-c", command + "; echo ${PIPESTATUS[0]} >&2"],
        cwd=folder,
        env=ENV,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.stdout == "counts.txt"
    assert result.stderr in ("0\n", "141\n")  # 0 when all was written before head closed


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
@pytest.mark.parametrize("argv", COMMANDS, ids=IDS)
def test_a_full_disk_is_one_line_and_exit_2(folder, argv):
    with open("/dev/full", "w") as full:
        proc = _coinflight(argv, folder, stdout=full)
        _, err = proc.communicate(timeout=120)
    assert (proc.returncode, err) == (
        2,
        "coinflight: error: cannot write to standard output: No space left on device\n",
    )


@pytest.mark.parametrize("argv", [COMMANDS[0], COMMANDS[4]], ids=[IDS[0], IDS[4]])
def test_a_closed_stdout_is_one_line_and_exit_2(folder, argv):
    """`coinflight … >&-`: refused before anything runs."""
    proc = _coinflight(argv, folder, preexec_fn=lambda: os.close(1))
    _, err = proc.communicate(timeout=120)
    assert (proc.returncode, err) == (
        2,
        "coinflight: error: cannot write to standard output: Bad file descriptor\n",
    )


def test_a_closed_stdout_writes_no_output_file(folder):
    proc = _coinflight(
        ["plot", "toss", "--flight-time", "0.5", "--out", "toss.png"],
        folder,
        preexec_fn=lambda: os.close(1),
    )
    _, err = proc.communicate(timeout=120)
    assert proc.returncode == 2, err
    assert sorted(p.name for p in folder.iterdir()) == ["counts.txt"]


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
def test_bad_input_with_stderr_on_a_full_disk_still_exits_2(folder):
    with open("/dev/full", "w") as full:
        proc = subprocess.run(
            [sys.executable, "-m", "coinflight", "toss", "--flight-time", "nan"],
            cwd=folder,
            env=ENV,
            stdout=subprocess.PIPE,
            stderr=full,
            timeout=120,
        )
    assert (proc.returncode, proc.stdout) == (2, b"")


def _busy(pid: int, timeout: float = 60.0) -> None:
    """Wait until process ``pid`` has loaded numba: its command is computing (Linux /proc)."""
    maps = Path(f"/proc/{pid}/maps")
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            if "numba" in maps.read_text():
                time.sleep(0.5)
                return
        except OSError:
            pass
        time.sleep(0.05)
    raise AssertionError("the command did not start computing")


@pytest.mark.skipif(not Path("/proc/self/maps").exists(), reason="needs Linux /proc")
@pytest.mark.parametrize(
    "argv",
    [
        ["probability", "--method", "monte-carlo", "--n", "1000000000", "--threads", "1"],
        [
            "convergence",
            "--methods",
            "monte-carlo",
            "--event-sizes",
            "100,1000000000",
            "--threads",
            "2",
            "--out",
            "out/conv",
        ],
    ],
    ids=["probability", "convergence"],
)
def test_ctrl_c_is_one_line_exit_130_and_no_output(folder, argv):
    argv = [*argv, "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--seed", "1", "-q"]
    proc = _coinflight(argv, folder, stdout=subprocess.PIPE)
    _busy(proc.pid)
    started = time.monotonic()
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=60)
    assert (proc.returncode, out, err) == (130, "", "coinflight: interrupted\n")
    assert time.monotonic() - started < 20  # the chunk in hand, not the whole run
    assert sorted(p.name for p in folder.rglob("*")) == ["counts.txt"]  # nor staging


# What CliRunner can show: the exception that reaches the command line, wherever it is raised.


def _raise(exc):
    def boom(*_args, **_kwargs):
        raise exc

    return boom


@pytest.mark.parametrize(
    ("exc", "code", "stderr"),
    [
        (KeyboardInterrupt(), 130, "coinflight: interrupted\n"),
        (BrokenPipeError(32, "Broken pipe"), 141, ""),
    ],
)
def test_interrupt_and_broken_pipe_inside_a_command(monkeypatch, exc, code, stderr):
    import coinflight.cli.toss as toss_cli

    monkeypatch.setattr(toss_cli, "toss_query", _raise(exc))
    result = CliRunner().invoke(app, ["toss", "--flight-time", "0.7"])
    assert (result.exit_code, result.stderr) == (code, stderr)


def test_other_os_errors_are_not_taken_for_stdout(monkeypatch):
    """Only standard output's failures are 'cannot write to standard output'."""
    import coinflight.cli.toss as toss_cli

    monkeypatch.setattr(toss_cli, "toss_query", _raise(OSError(28, "No space left on device")))
    result = CliRunner().invoke(app, ["toss", "--flight-time", "0.7"])
    assert isinstance(result.exception, OSError)
    assert "standard output" not in result.stderr

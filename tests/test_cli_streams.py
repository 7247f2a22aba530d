"""Standard streams and Ctrl-C, as command-line tools handle them (issue 10 items 2 and 5).

A closed pipe ends quietly with exit code 141 (128 + SIGPIPE); standard output on a full disk,
or closed, is one line ``coinflight: error: cannot write to standard output: REASON`` and exit
code 2; Ctrl-C is ``coinflight: interrupted`` and exit code 130, with no partial output. The
streams are real, so these run ``python -m coinflight`` in a subprocess (sources on PYTHONPATH,
as in CI); what CliRunner can show is tested through it.
"""

from __future__ import annotations

import os
import shutil
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


_STARTED: list[subprocess.Popen[str]] = []


def _coinflight(argv, cwd, preexec_fn=None, **kwargs):
    def start():
        # Ctrl-C acts as at a terminal even when pytest itself was started with SIGINT
        # ignored (a background job of a shell without job control): Python keeps an
        # ignored SIGINT ignored, and these tests would wait for a Ctrl-C never acted on.
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        if preexec_fn is not None:
            preexec_fn()

    proc = subprocess.Popen(
        [sys.executable, "-m", "coinflight", *argv],
        cwd=cwd,
        env=ENV,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=start,
        **kwargs,
    )
    _STARTED.append(proc)
    return proc


@pytest.fixture(autouse=True)
def _no_command_left_running():
    """Each command a test started is ended and its pipes closed when the test ends, even
    when it failed (a timeout): one left running, or an open pipe, would be reported as a
    ResourceWarning (an error here) in whatever later test the garbage collector ran in."""
    yield
    while _STARTED:
        proc = _STARTED.pop()
        if proc.poll() is None:
            proc.kill()
        proc.communicate()  # reaps it and closes its pipes


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


WAIT = 600.0
"""Seconds any one wait below may take before the test gives up (a generous bound, not a
timing: on a loaded machine start-up alone took tens of seconds; each wait ends on its
condition)."""

AFTER_CTRL_C = 5.0
"""CPU seconds the command may spend after Ctrl-C: the chunk in hand (a million tosses, ~0.02 s)
and the way out, not the rest of the run. CPU time, not wall time, so a busy machine does not
stretch it; the runs below would take minutes of CPU (10^10 tosses: ~150 s at the 6.7e7 tosses
per CPU second measured with --threads 1, 2026-11-23)."""


def _cpu_seconds(pid: int) -> float:
    """User and system CPU time of process ``pid`` so far (Linux /proc/PID/stat)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _finished(proc: subprocess.Popen[str]) -> tuple[str, str, float]:
    """Wait for ``proc`` to end and reap it with ``os.wait4``, whose usage is that process's own
    CPU seconds (user + system, its threads' included; it starts no processes), not
    RUSAGE_CHILDREN's sum over every child this test process has reaped. Its standard output and
    error (small: they wait in the pipes, under a pipe's buffer), and those seconds."""
    deadline = time.monotonic() + WAIT
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid == proc.pid:
            break
        assert time.monotonic() < deadline, f"the command did not end within {WAIT:g} s"
        time.sleep(0.05)
    proc.returncode = os.waitstatus_to_exitcode(status)  # reaped here, so Popen cannot
    out, err = proc.communicate(timeout=WAIT)  # what it wrote; closes the pipes
    return out, err, usage.ru_utime + usage.ru_stime


def _start_up_cpu(argv: list[str], folder: Path) -> float:
    """CPU seconds the command takes from start to end at a tiny size, run twice: the first
    fills numba's cache (a fresh clone compiles), so that neither the second, measured, nor
    the interrupted run below compiles anything."""
    for _ in range(2):
        proc = _coinflight(argv, folder, stdout=subprocess.PIPE)
        _, err, cpu = _finished(proc)
        assert proc.returncode == 0, err
    return cpu


def _computing(proc: subprocess.Popen[str], start_up: float) -> float:
    """Wait until ``proc`` has spent more CPU than its whole tiny run (``start_up``, with a
    margin): it is past its start-up and computing. Its CPU seconds then."""
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        assert proc.poll() is None, "the command ended before it was interrupted"
        used = _cpu_seconds(proc.pid)
        if used > 1.25 * start_up + 0.5:
            return used
        time.sleep(0.05)
    raise AssertionError(f"the command did not start computing within {WAIT:g} s")


def _probability(n: int) -> list[str]:
    return ["probability", "--method", "monte-carlo", "--n", str(n), "--threads", "1"]


def _convergence(n: int) -> list[str]:
    return ["convergence", "--methods", "monte-carlo", "--event-sizes", f"100,{n}",
            "--threads", "2", "--out", "out/conv"]  # fmt: skip


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs Linux /proc")
@pytest.mark.parametrize(
    "command", [_probability, _convergence], ids=["probability", "convergence"]
)
def test_ctrl_c_is_one_line_exit_130_and_no_output(folder, command):
    """Ctrl-C while the command computes: one line, exit 130, nothing written, and only the
    chunk in hand finished (in CPU seconds), not the rest of the run."""
    common = ["--omega-x", "60:90", "--flight-time", "0.6:0.9", "--seed", "1", "-q"]
    start_up = _start_up_cpu([*command(1000), *common], folder)
    shutil.rmtree(folder / "out", ignore_errors=True)  # the tiny run's figure and table
    proc = _coinflight([*command(10**10), *common], folder, stdout=subprocess.PIPE)
    at_ctrl_c = _computing(proc, start_up)
    proc.send_signal(signal.SIGINT)
    out, err, at_end = _finished(proc)
    assert (proc.returncode, out, err) == (130, "", "coinflight: interrupted\n")
    assert at_end - at_ctrl_c < AFTER_CTRL_C  # the chunk in hand only
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
    """Only standard output's failures are 'cannot write to standard output'; another error of
    the system is its own one line (exit 2; tests/test_os_errors.py)."""
    import coinflight.cli.toss as toss_cli

    monkeypatch.setattr(toss_cli, "toss_query", _raise(OSError(28, "No space left on device")))
    result = CliRunner().invoke(app, ["toss", "--flight-time", "0.7"])
    assert (result.exit_code, result.stderr) == (
        2,
        "coinflight: error: No space left on device\n",
    )

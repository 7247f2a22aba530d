"""Errors of the operating system and of the environment are one line naming the value, exit 2.

Issue: a file name over the system's limit gave a traceback (exit 1) from plot, sweep, data
and paper; NUMBA_NUM_THREADS=0 gave numba's own words and =abc a traceback on stderr with
exit 0. The cause was the command line's handler letting every OSError but standard output's
through, and numba reading its environment with a warning; these tests cover the commands
that read or write files and every way a numba variable can be wrong.
"""

from __future__ import annotations

import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest
from tests._cli import one_line_error

LONG = "a" * 300  # over NAME_MAX (255) on every common file system

WRITERS = [
    ["plot", "toss", "--flight-time", "0.5", "--out", "{}.png"],
    ["plot", "toss", "--flight-time", "0.5", "--out", "{}/x.png"],
    ["sweep", "--omega-x", "60:90", "--flight-time", "0.7", "--out", "{}.csv"],
    ["sweep", "--omega-x", "60:90", "--flight-time", "0.7", "--out", "{}/x.parquet"],
    ["data", "--counts", "{}"],
    ["data", "--counts", "{}/x.txt"],
    ["paper", "--events", "1000", "--out", "{}"],
    ["convergence", "--flight-time", "0.6:0.9", "--grid-sizes", "5", "--out", "{}"],
    ["animate", "--flight-time", "0.5", "--out", "{}.gif"],
    ["landing-report", "--out", "{}"],
]


@pytest.mark.parametrize("argv", WRITERS, ids=lambda a: " ".join(a[:2]))
def test_a_file_name_over_the_systems_limit_is_one_line(tmp_path, monkeypatch, argv):
    monkeypatch.chdir(tmp_path)
    line = one_line_error(*[a.format(LONG) for a in argv])
    assert LONG[:100] in line and "File name too long" in line, line
    assert list(tmp_path.iterdir()) == []  # nothing written, nothing left


def test_a_counts_file_that_is_a_folder_is_one_line(tmp_path):
    line = one_line_error("data", "--counts", tmp_path)
    assert str(tmp_path) in line and "directory" in line.lower(), line


@pytest.mark.parametrize(
    "error",
    [
        OSError(errno.ENOSPC, "No space left on device"),
        PermissionError(errno.EACCES, "Permission denied"),
        OSError(errno.EROFS, "Read-only file system"),
    ],
    ids=["ENOSPC", "EACCES", "EROFS"],
)
def test_an_output_the_system_refuses_is_one_line_naming_it(tmp_path, monkeypatch, error):
    """The system refusing the last step (the rename into place), as a full disk or a folder
    turned read-only while the command ran would."""
    import coinflight._files as files

    def refuse(src, dst):
        error.filename = os.fspath(dst)
        raise error

    monkeypatch.setattr(files.os, "replace", refuse)
    out = tmp_path / "x.png"
    line = one_line_error("plot", "toss", "--flight-time", "0.5", "--out", out)
    assert line == f"cannot write {out}: {error.strerror}"
    assert list(tmp_path.iterdir()) == []


def test_any_other_os_error_is_one_line_naming_its_file(monkeypatch):
    """The handler's own rule, whatever raised it: ``PATH: reason`` (a rename's second path in
    brackets), exit 2, a long name shortened around an ellipsis."""
    from typer.testing import CliRunner

    import coinflight.cli.toss as toss_module
    from coinflight.cli import app
    from coinflight.cli.errors import os_error_line

    name = "/tmp/" + "b" * 5000

    def unreadable(*args, **kwargs):
        raise PermissionError(errno.EACCES, "Permission denied", name, None, "/tmp/x")

    monkeypatch.setattr(toss_module, "toss_query", unreadable, raising=True)
    result = CliRunner().invoke(app, ["toss", "--flight-time", "0.5"])
    assert result.exit_code == 2 and "Traceback" not in result.output
    line = result.stderr.strip()
    assert line == "coinflight: error: " + os_error_line(unreadable_error(name))
    assert line.startswith("coinflight: error: /tmp/bbb") and line.endswith(
        "bbb: Permission denied (/tmp/x)"
    )
    assert "…" in line and len(line) < 400


def unreadable_error(name):
    return PermissionError(errno.EACCES, "Permission denied", name, None, "/tmp/x")


def _run(env_extra, *argv):
    env = {k: x for k, x in os.environ.items() if not k.startswith("NUMBA_")}
    env.update(env_extra, PYTHONPATH=str(Path(__file__).parents[1] / "src"))
    return subprocess.run(
        [sys.executable, "-m", "coinflight", *argv],
        env=env,
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )


NUMBA_COMMAND = ["probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9",
                 "--method", "monte-carlo", "--n", "1000", "--seed", "1"]  # fmt: skip


@pytest.mark.parametrize(
    "name, value",
    [
        ("NUMBA_NUM_THREADS", "0"),
        ("NUMBA_NUM_THREADS", "abc"),
        ("NUMBA_NUM_THREADS", "-2"),
        ("NUMBA_NUM_THREADS", ""),
        ("NUMBA_NUM_THREADS", "99999999999999999999"),
        ("NUMBA_OPT", "fast please"),
        ("NUMBA_DISABLE_JIT", "maybe"),
    ],
)
def test_a_numba_variable_numba_cannot_use_is_one_line_naming_it(name, value):
    run = _run({name: value}, *NUMBA_COMMAND)
    assert run.returncode == 2, run.stderr
    assert run.stdout == "" and "Traceback" not in run.stderr
    assert run.stderr.splitlines() == [run.stderr.strip()], run.stderr
    assert run.stderr.startswith(f"coinflight: error: the environment variable {name}={value!r}")


def test_a_good_numba_variable_is_used():
    run = _run({"NUMBA_NUM_THREADS": "1"}, *NUMBA_COMMAND, "--json")
    assert run.returncode == 0, run.stderr
    # nothing on stderr but, on a cold numba cache, the one-time compile notice
    said = [
        line for line in run.stderr.splitlines() if not line.startswith("coinflight: compiling ")
    ]
    assert said == [], run.stderr


def test_serve_refuses_a_bad_numba_variable_before_it_starts():
    run = _run({"NUMBA_NUM_THREADS": "abc"}, "serve", "--port", "0")
    assert run.returncode == 2, run.stderr
    assert "NUMBA_NUM_THREADS='abc'" in run.stderr and run.stdout == ""


def test_a_matplotlib_backend_matplotlib_does_not_know_is_one_line_naming_it(tmp_path):
    run = _run({"MPLBACKEND": "nonsense"}, "plot", "toss", "--flight-time", "0.5", "--out",
               str(tmp_path / "x.png"))  # fmt: skip
    assert run.returncode == 2 and run.stdout == "", run.stderr
    assert run.stderr == (
        "coinflight: error: the environment variable MPLBACKEND='nonsense' is not a backend "
        "matplotlib knows (e.g. agg); correct it, or unset it\n"
    )
    assert not (tmp_path / "x.png").exists()

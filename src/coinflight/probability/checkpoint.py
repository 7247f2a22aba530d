"""A sweep's checkpoint: the finished rows of one run, in a file only coinflight writes.

The file is JSON lines. Its first line is a header naming the file a coinflight sweep
checkpoint and the run it belongs to (method, n, seed); every further line is one finished row
(its key, its result, and a checksum of both). A checkpoint is trusted only when all of this
holds:

- the path is a regular file, opened without following a symbolic link (``O_NOFOLLOW``): a
  link is refused, never read, appended to or removed through;
- the header is ours and names the same method, n and seed as the run reading it;
- every row parses, carries its checksum, and its result is a result of that run (method, n,
  probabilities in [0, 1] summing to 1, non-negative counts).

Anything else is refused with one line naming the file and the way on (remove it, or start
over with ``fresh=True``, the command line's ``--fresh``), before any row is reused. The one
exception is a last line cut short (no newline) by a run killed while writing it: it is
dropped, and its row computed again. The file is removed at the end of a run only if it is
still the file this run read or created (same device and inode).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import stat
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from coinflight.probability.result import ProbabilityResult

MAX_ROWS = 100_000
"""Most rows a sweep accepts (checked before any row is built), so most a checkpoint holds."""
MARKER = "coinflight sweep checkpoint"
"""The header's ``coinflight`` field: what makes a file a checkpoint."""
FORMAT = 1
"""The header's ``format`` field."""
MAX_LINE = 1 << 20
"""Longest line (bytes) a checkpoint row may have; a longer one is not ours."""

_FIELDS = {
    "p_heads", "p_tails", "p_edge", "p_same_side", "method", "n", "samples", "stderr", "ci95",
    "error_estimate", "counts", "seed", "elapsed", "details",
}  # fmt: skip
_WAY_ON = "remove it, or start over with --fresh"
_FOREIGN = "was not written by coinflight (a sweep keeps its finished rows there)"


class CheckpointError(ValueError):
    """A file in the place of a checkpoint that is not one this run can trust."""


def _refuse(path: Path, why: str, way_on: str = _WAY_ON) -> CheckpointError:
    return CheckpointError(f"the checkpoint {os.fspath(path)} {why}; {way_on}")


def _checksum(key: str, result: Mapping[str, Any]) -> str:
    text = json.dumps({"key": key, "result": result}, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _header(method: str, n: int | None, seed: int | None) -> dict[str, Any]:
    return {"coinflight": MARKER, "format": FORMAT, "method": method, "n": n, "seed": seed}


def _open_nofollow(path: Path, flags: int, mode: int = 0o666) -> int:
    """``os.open`` that never follows a symbolic link in the last component."""
    try:
        return os.open(path, flags | os.O_NOFOLLOW | getattr(os, "O_CLOEXEC", 0), mode)
    except OSError as exc:
        if os.path.islink(path):
            raise _refuse(
                path,
                "is a symbolic link, which coinflight never follows",
                "remove the link, or start over with --fresh",
            ) from None
        if isinstance(exc, FileNotFoundError | FileExistsError):
            raise
        raise _refuse(path, f"cannot be opened: {exc.strerror}", "check the path") from None


def _probability(value: Any) -> bool:
    return (
        isinstance(value, float | int)
        and not isinstance(value, bool)
        and math.isfinite(value)
        and 0.0 <= value <= 1.0
    )


def _result(data: Any, method: str, n: int | None) -> ProbabilityResult:
    """The result of a row, or ValueError saying what is wrong with it."""
    if not isinstance(data, dict) or not {"p_heads", "p_tails", "p_edge", "method"} <= set(data):
        raise ValueError("its result is not a result")
    if not set(data) <= _FIELDS:
        raise ValueError(f"its result has unknown fields {sorted(set(data) - _FIELDS)}")
    if data["method"] != method or data.get("n") != n:
        raise ValueError("its result is not of this run's method and n")
    p = [data[k] for k in ("p_heads", "p_tails", "p_edge", "p_same_side") if k in data]
    if not all(_probability(x) for x in p):
        raise ValueError("a probability is not a number in [0, 1]")
    if abs(data["p_heads"] + data["p_tails"] + data["p_edge"] - 1.0) > 1e-9:
        raise ValueError("P(heads), P(tails) and P(edge) do not sum to 1")
    for name in ("stderr", "error_estimate", "elapsed"):
        x = data.get(name)
        if x is not None and not (isinstance(x, float | int) and math.isfinite(x) and x >= 0):
            raise ValueError(f"{name} is not a non-negative number")
    ci = data.get("ci95")
    if ci is not None and not (
        isinstance(ci, list) and len(ci) == 2 and all(map(_probability, ci))
    ):
        raise ValueError("ci95 is not two numbers in [0, 1]")
    counts = data.get("counts")
    if counts is not None:
        if not isinstance(counts, dict) or set(counts) != {"tails", "heads", "edge"}:
            raise ValueError("counts are not tails, heads and edge")
        if not all(type(c) is int and c >= 0 for c in counts.values()):
            raise ValueError("counts are not non-negative integers")
    if not isinstance(data.get("details", {}), dict):
        raise ValueError("details are not a mapping")
    d = dict(data)
    d["ci95"] = None if ci is None else (float(ci[0]), float(ci[1]))
    d["counts"] = None if counts is None else (counts["tails"], counts["heads"], counts["edge"])
    return ProbabilityResult(**d)


class Checkpoint:
    """The checkpoint of one run (``method``, ``n``, ``seed``) at ``path``.

    :meth:`read` the rows (refusing anything not written by such a run), :meth:`append` each
    finished row, :meth:`close`, and :meth:`remove` it when the run's output is written.
    """

    def __init__(
        self, path: str | os.PathLike[str], method: str, n: int | None, seed: int | None
    ) -> None:
        self.path = Path(path)
        self.header = _header(method, n, seed)
        self._identity: tuple[int, int] | None = None  # of the file read or created
        self._good_end = 0  # bytes up to the end of the last whole line
        self._fd: int | None = None

    def read(self, fresh: bool = False) -> dict[str, ProbabilityResult]:
        """The finished rows by key ({} when there is no checkpoint yet).

        ``fresh``: ignore and replace a file in the checkpoint's place (a regular file or a
        symbolic link, the link itself, never what it points to). Raises
        :class:`CheckpointError` (a ValueError) for anything this run cannot trust.
        """
        if fresh:
            self._discard()
            return {}
        try:  # O_NONBLOCK: a pipe in its place must not hang the run
            fd = _open_nofollow(self.path, os.O_RDONLY | os.O_NONBLOCK)
        except FileNotFoundError:
            return {}
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            os.close(fd)
            raise _refuse(self.path, "is not a regular file", "give another --out")
        with os.fdopen(fd, "rb") as f:
            rows = self._rows(f)
        self._identity = (info.st_dev, info.st_ino)
        return rows

    def _rows(self, f: Any) -> dict[str, ProbabilityResult]:
        method, n = self.header["method"], self.header["n"]
        out: dict[str, ProbabilityResult] = {}
        first = f.readline(MAX_LINE)
        try:
            header = json.loads(first.decode("utf-8"))
            if not (isinstance(header, dict) and header.get("coinflight") == MARKER):
                raise ValueError
        except ValueError:
            raise _refuse(self.path, _FOREIGN) from None
        if not first.endswith(b"\n"):  # killed before the header was whole: nothing in it
            raise _refuse(self.path, _FOREIGN)
        if header != self.header:
            run = ", ".join(f"{k} {header.get(k)}" for k in ("method", "n", "seed"))
            raise _refuse(
                self.path,
                f"belongs to another run ({run})",
                "rerun with that method, n and seed to resume it, or start over with --fresh",
            )
        self._good_end = len(first)
        number = 1
        while line := f.readline(MAX_LINE):
            number += 1
            if number > MAX_ROWS + 1:
                raise _refuse(self.path, f"holds more rows than a sweep has ({MAX_ROWS:,})")
            if not line.endswith(b"\n"):
                if len(line) < MAX_LINE:
                    break  # the last line, cut short by a kill: its row is computed again
                raise _refuse(self.path, f"has a line longer than any coinflight writes ({number})")
            try:
                entry = json.loads(line.decode("utf-8"))
                if not isinstance(entry, dict) or set(entry) != {"key", "result", "check"}:
                    raise ValueError("it is not a row")
                key, data = entry["key"], entry["result"]
                if not isinstance(key, str) or entry["check"] != _checksum(key, data):
                    raise ValueError("its checksum does not match (edited by hand?)")
                out[key] = _result(data, method, n)
            except ValueError as exc:  # UnicodeDecodeError and JSONDecodeError included
                text = isinstance(exc, UnicodeDecodeError | json.JSONDecodeError)
                why = "it is not JSON text" if text else str(exc)
                raise _refuse(self.path, f"is damaged at line {number}: {why}") from None
            self._good_end += len(line)
        return out

    def _discard(self) -> None:
        try:
            info = os.lstat(self.path)
        except FileNotFoundError:
            return
        if not (stat.S_ISREG(info.st_mode) or stat.S_ISLNK(info.st_mode)):
            raise _refuse(self.path, "is not a regular file", "give another --out")
        try:
            os.unlink(self.path)
        except OSError as exc:
            why = f"cannot be removed: {exc.strerror}"
            raise _refuse(self.path, why, "check its folder") from None

    def append(self, key: str, result: ProbabilityResult) -> None:
        """Add one finished row (the file is created with its header on the first)."""
        if self._fd is None:
            self._fd = self._open_for_append()
        data = result.to_dict()
        line = json.dumps({"key": key, "result": data, "check": _checksum(key, data)}) + "\n"
        os.write(self._fd, line.encode("utf-8"))

    def _open_for_append(self) -> int:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        if self._identity is None:  # none was read: create it, never take over a file
            try:
                fd = _open_nofollow(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL)
            except FileExistsError:
                raise _refuse(self.path, "appeared while the sweep ran", _WAY_ON) from None
            os.write(fd, (json.dumps(self.header) + "\n").encode("utf-8"))
        else:
            fd = _open_nofollow(self.path, os.O_WRONLY)
            info = os.fstat(fd)
            if (info.st_dev, info.st_ino) != self._identity:
                os.close(fd)
                raise _refuse(self.path, "was replaced while the sweep ran", _WAY_ON)
            os.ftruncate(fd, self._good_end)  # drop a torn last line before appending
            os.lseek(fd, 0, os.SEEK_END)
        info = os.fstat(fd)
        self._identity = (info.st_dev, info.st_ino)
        return fd

    def close(self) -> None:
        """Close the file (the rows written stay)."""
        if self._fd is not None:
            os.close(self._fd)
            self._fd = None

    def remove(self) -> None:
        """Remove the checkpoint, if it is one of this run (its header) and a regular file;
        anything else in its place is left alone."""
        self.close()
        try:
            fd = _open_nofollow(self.path, os.O_RDONLY | os.O_NONBLOCK)
        except (FileNotFoundError, CheckpointError):
            return
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            os.close(fd)
            return
        with os.fdopen(fd, "rb") as f:
            try:
                ours = json.loads(f.readline(MAX_LINE).decode("utf-8")) == self.header
            except ValueError:
                ours = False
        if not ours:
            return
        now = os.lstat(self.path)
        if (now.st_dev, now.st_ino) == (info.st_dev, info.st_ino):
            os.unlink(self.path)


__all__ = ["FORMAT", "MARKER", "Checkpoint", "CheckpointError"]

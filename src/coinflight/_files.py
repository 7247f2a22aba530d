"""Writing output files whole or not at all: the one place that does it."""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def replacing(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary file beside ``path`` that becomes ``path`` when the block succeeds.

    The caller writes to the yielded path; on success it is renamed into place (an atomic
    ``os.replace``), on any error it is removed. An interrupted run therefore never leaves a
    half-written file, nor replaces a good one with it.
    """
    target = Path(path)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(
            prefix=f".{target.stem}-", suffix=target.suffix, dir=target.parent
        )
    except OSError as exc:
        check_writable(target)  # names a file in the way of a folder, if that is the cause
        raise cannot_write(target, exc) from None
    os.close(fd)
    try:
        yield Path(tmp)
        os.chmod(tmp, 0o644)  # mkstemp creates 0600; an output file is for everyone to read
        try:
            os.replace(tmp, target)
        except OSError as exc:
            raise cannot_write(target, exc) from None
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_text(path: str | os.PathLike[str], text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` whole or not at all."""
    with replacing(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(path)


@contextmanager
def staged_folder(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A hidden folder inside ``path`` whose files all move into ``path`` when the block succeeds.

    For outputs made of several files (a report and its figures): they appear together at the
    end, or, if the run fails or is interrupted, none of them does.
    """
    target = Path(path)
    try:
        target.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(prefix=".partial-", dir=target))
    except OSError as exc:
        check_writable(target, folder=True)
        raise cannot_write(target, exc) from None
    try:
        yield stage
        for item in sorted(stage.rglob("*")):
            if item.is_file():
                dest = target / item.relative_to(stage)
                dest.parent.mkdir(parents=True, exist_ok=True)
                os.replace(item, dest)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def cannot_write(path: str | os.PathLike[str], exc: OSError) -> ValueError:
    """The one wording of an output that cannot be written: ``cannot write PATH: reason``."""
    reason = exc.strerror or str(exc)
    name = None if exc.filename is None else os.fspath(exc.filename)
    if name is not None and name != os.fspath(path) and not Path(name).name.startswith("."):
        reason = f"{reason} ({name})"  # a folder on the way, not our temporary file
    return ValueError(f"cannot write {os.fspath(path)}: {reason}")


def check_writable(path: str | os.PathLike[str], folder: bool = False) -> None:
    """ValueError unless ``path`` (a file, or a folder if ``folder``) can be written.

    For commands that compute for a long time before they write: they call this first, so a
    bad output location fails at once. The check creates nothing that stays: it makes and
    removes one temporary file in the nearest folder that already exists.
    """
    target = Path(path)
    if target.exists():
        if folder and not target.is_dir():
            raise ValueError(f"cannot write {target}: it is a file, not a folder")
        if not folder and target.is_dir():
            raise ValueError(f"cannot write {target}: it is a folder")
    base = target if folder else target.parent
    while not base.exists() and base != base.parent:
        base = base.parent
    if not base.is_dir():
        raise ValueError(f"cannot write {target}: {base} is a file, not a folder")
    try:
        fd, tmp = tempfile.mkstemp(prefix=".coinflight-check-", dir=base)
    except OSError as exc:
        raise cannot_write(target, exc) from None
    os.close(fd)
    os.unlink(tmp)

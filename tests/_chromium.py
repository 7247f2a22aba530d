"""Debian's Chromium driven by Playwright, for the tests that open a page in a real browser
(``test_web_browser.py``, ``test_docs_offline.py``).

The browser is ``/usr/bin/chromium`` (``make chromium``; ``COINFLIGHT_CHROMIUM`` names another),
never Playwright's own download; each launch has a fresh profile in a temporary folder, deleted
afterwards. Without Chromium or Playwright the tests skip on a workstation and fail in CI
(``CI`` set), so a CI machine that lost the browser cannot pass silently.
"""

from __future__ import annotations

import os
import shutil
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

CHROMIUM = Path(os.environ.get("COINFLIGHT_CHROMIUM", "/usr/bin/chromium"))
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]
IN_CI = os.environ.get("CI", "").strip().lower() not in ("", "0", "false", "no")


def browser_or_skip() -> None:
    """Skip (workstation) or fail (CI) when the browser or its driver is missing."""
    problem = None
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        problem = "Playwright for Python is missing: pip install -e '.[dev]'"
    if problem is None and not (CHROMIUM.is_file() and os.access(CHROMIUM, os.X_OK)):
        problem = f"{CHROMIUM} is missing: `make chromium` installs Debian's chromium"
    if problem is not None:
        if IN_CI:
            pytest.fail(f"the browser tests cannot run in CI: {problem}")
        pytest.skip(problem)


@contextmanager
def chromium(**options: Any) -> Iterator[Any]:
    """A headless Chromium context with a fresh profile (Playwright's
    ``launch_persistent_context``; ``options`` such as ``viewport`` and ``base_url`` passed on),
    closed and its profile deleted on leaving."""
    from playwright.sync_api import sync_playwright

    profile = tempfile.mkdtemp(prefix="coinflight-chromium-")
    try:
        with sync_playwright() as pw:
            context = pw.chromium.launch_persistent_context(
                profile,
                executable_path=str(CHROMIUM),
                args=CHROMIUM_ARGS,
                headless=True,
                **options,
            )
            try:
                yield context
            finally:
                context.close()
    finally:
        shutil.rmtree(profile, ignore_errors=True)

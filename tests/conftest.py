"""Test-wide settings.

In CI (``CI`` set in the environment) hypothesis runs derandomized: the same examples on every
run, so that a CI result is reproducible. Locally it explores new examples each run, and prints
the seed of any failure (``--hypothesis-seed`` replays it).
"""

from __future__ import annotations

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")

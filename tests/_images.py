"""Checks on written images shared by the figure tests: size, not blank, colours present."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PIL import Image


def load_rgb(path: Path) -> np.ndarray:
    """The image as an (h, w, 3) uint8 array (first frame of an animation)."""
    with Image.open(path) as im:
        return np.asarray(im.convert("RGB"))


def assert_nontrivial(path: Path, min_side: int = 300) -> np.ndarray:
    """The file exists, is a real picture of reasonable size and is not a blank canvas."""
    assert path.is_file(), f"{path} was not written"
    rgb = load_rgb(path)
    h, w, _ = rgb.shape
    assert min(h, w) >= min_side, f"{path} is only {w}x{h} pixels"
    # A blank canvas has one colour; a figure has axes, text and drawings.
    non_white = np.any(rgb < 245, axis=-1).mean()
    assert non_white > 0.02, f"{path} is almost blank ({non_white:.1%} non-white pixels)"
    return rgb


def colour_fraction(rgb: np.ndarray, hex_colour: str, tol: int = 12) -> float:
    """Fraction of pixels within ``tol`` (per channel) of ``hex_colour``."""
    target = np.array([int(hex_colour[i : i + 2], 16) for i in (1, 3, 5)])
    close = np.all(np.abs(rgb.astype(int) - target) <= tol, axis=-1)
    return float(close.mean())

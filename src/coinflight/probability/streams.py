"""Random streams: one seed → one ``SeedSequence`` → an independent generator per block and per
parameter. Every Monte Carlo of the package draws through this module.

Scheme (NumPy's recommended ``SeedSequence`` spawning; NumPy docs, "Parallel random number
generation"): the root sequence of a seed has children ``key`` = (block, parameter), built as
``SeedSequence(entropy, spawn_key=root.spawn_key + key)``, exactly what nested
``SeedSequence.spawn`` calls give. A run of n tosses is cut into blocks of :data:`BLOCK` tosses;
toss j of block b takes the j-th uniform of the stream (b, r) for its parameter r. Hence

* the answer does not depend on how the blocks are grouped into tasks, threads or executors, nor
  on how many tosses are drawn at a time (:data:`DRAW`);
* a run of n tosses is the first n tosses of any longer run with the same seed.

Default-seed policy (all of coinflight): no seed means a fresh one from the operating system's
entropy; the integer that reproduces the run is always reported (:func:`reported_seed`).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Union

import numpy as np
from numpy.typing import NDArray

SeedLike = Union[int, np.integer, np.random.SeedSequence, None]  # noqa: UP007
"""What every random function of coinflight accepts as ``seed``."""

BLOCK = 1 << 20
"""Tosses per random stream. Part of the reproducibility contract: do not change lightly."""
DRAW = 1 << 16
"""Tosses drawn at a time from a stream (memory only: the tosses do not depend on it)."""


def check_seed(seed: object) -> None:
    """TypeError unless ``seed`` is None, a ``SeedSequence`` or a whole number; ValueError if
    negative. The one seed validation of the package."""
    if seed is None or isinstance(seed, np.random.SeedSequence):
        return
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer):
        raise TypeError(f"seed must be a non-negative integer, got {seed!r}")
    if seed < 0:
        raise ValueError(f"seed must be a non-negative integer, got {seed}")


def seed_sequence(seed: SeedLike) -> np.random.SeedSequence:
    """The root ``SeedSequence`` of ``seed`` (fresh OS entropy when ``seed`` is None)."""
    check_seed(seed)
    if isinstance(seed, np.random.SeedSequence):
        return seed
    return np.random.SeedSequence(None if seed is None else int(seed))


def reported_seed(root: np.random.SeedSequence) -> int:
    """The integer that reproduces ``root`` (its entropy)."""
    entropy = root.entropy
    if isinstance(entropy, int):
        return entropy
    raise ValueError("give the seed as one integer so that it can be reported")


def child(root: np.random.SeedSequence, *key: int) -> np.random.SeedSequence:
    """The descendant ``key`` of ``root``: what ``root.spawn`` (nested) gives at those indices,
    independent of how many children were spawned before."""
    return np.random.SeedSequence(
        root.entropy, spawn_key=(*root.spawn_key, *key), pool_size=root.pool_size
    )


def generator(
    root: np.random.SeedSequence, *key: int, bit_generator: type = np.random.SFC64
) -> np.random.Generator:
    """A generator (default SFC64) on the descendant ``key`` of ``root``."""
    return np.random.Generator(bit_generator(child(root, *key)))


def block_generators(root: np.random.SeedSequence, block: int, k: int) -> list[np.random.Generator]:
    """The k generators of block ``block``: SFC64 on the children ``(block, r)`` of ``root``."""
    return [generator(root, block, r) for r in range(k)]


def draw_block(
    rngs: list[np.random.Generator], size: int, cells: int = 0
) -> Iterator[NDArray[np.float64]]:
    """The unit-cube points of one block, :data:`DRAW` tosses at a time, shape (k, m).

    Row r comes from ``rngs[r]``. ``cells`` > 0 snaps each coordinate to the midpoint of its
    cell among ``cells`` equal cells (Stefan & Cheche's method B).
    """
    for start in range(0, size, DRAW):
        u = np.empty((len(rngs), min(DRAW, size - start)))
        for row, rng in zip(u, rngs, strict=True):
            rng.random(out=row)
        if cells > 0:
            u *= cells
            np.floor(u, out=u)
            u += 0.5
            u /= cells
        yield u


def unit_cube(
    root: np.random.SeedSequence,
    n: int,
    k: int,
    *,
    first_block: int = 0,
    last_block: int | None = None,
    cells: int = 0,
) -> Iterator[NDArray[np.float64]]:
    """The first ``n`` points of ``root``'s stream in the k-dimensional unit cube, in arrays of
    shape (k, m) (m ≤ :data:`DRAW`), blocks ``first_block`` to ``last_block`` (exclusive;
    default all) only."""
    n_blocks = -(-n // BLOCK)
    for b in range(first_block, n_blocks if last_block is None else last_block):
        yield from draw_block(block_generators(root, b, k), min(BLOCK, n - b * BLOCK), cells)


__all__ = [
    "BLOCK",
    "DRAW",
    "SeedLike",
    "block_generators",
    "check_seed",
    "child",
    "draw_block",
    "generator",
    "reported_seed",
    "seed_sequence",
    "unit_cube",
]

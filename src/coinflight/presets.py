"""Named distributions of tosses: ``--preset NAME`` wherever a distribution of tosses is asked.

``human``: a person's natural toss, caught in the hand
-------------------------------------------------------
Built from the published measurements (REFERENCES §2, Diaconis, Holmes & Montgomery 2007,
quoting Keller 1986 and their own filmed flips) and one modelling choice of ours:

=====================  =====================================  ==================================
quantity               value                                  source
=====================  =====================================  ==================================
launch speed v0        normal, mean 2.4 m/s, sd 10 %          mean: Diaconis via Keller (§2);
                       (flight time T = 2 v0 / g ≈ 0.49 s)    spread: our assumption
spin about a diameter  ωx normal, mean 38 rev/s = 238.8 rad/s, mean: Diaconis via Keller (§2);
                       sd 10 %; ωy = 0                        spread: our assumption
cone angle ψ           set by ωz: cot ψ = I3 ωz / (I1 ωx),    "near but below 90°"; per-flip
                       ωz normal with mean (I1/I3)·238.8·c    p(ψ) 0.500 to 0.545, mean 0.508
                       and sd half of it, c = 0.1396          (DHM's filmed flips, §2)
=====================  =====================================  ==================================

The constant c is the one number fitted: it makes the closed-form average of p(ψ)
(:func:`coinflight.bias.expected_same_side`) equal 0.508, the mean DHM report and the pooled
rate Bartoš et al. measured over 350,757 flips (0.5077, REFERENCES §6). It gives ψ with median
82.1° and 95 % of tosses between 74° and 89.8° (a few per cent just above 90°), and per-flip
p(ψ) from 0.500 to about 0.537 (99.5th percentile), as DHM describe. ωz scales with I1/I3 so that
the ψ distribution is the same for every coin. The 10 % spreads make ωp T vary by about 2.6
turns (sd), enough for the phase to be uniform, which is what the closed form assumes; the
spread values themselves are not published and barely matter (the bias depends on ψ alone).
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable
from types import MappingProxyType

from coinflight.coin import DEFAULT_COIN, Coin
from coinflight.distributions import Fixed, Normal
from coinflight.ensemble import TossDistribution
from coinflight.toss import STANDARD_GRAVITY, Start

HUMAN_LAUNCH_SPEED = 2.4
"""Upward launch speed of a natural toss, m/s (Diaconis via Keller; REFERENCES §2)."""

HUMAN_SPIN = 38.0 * 2.0 * math.pi
"""Spin of a natural toss, 38 rev/s in rad/s (Diaconis via Keller; REFERENCES §2)."""

HUMAN_RELATIVE_SPREAD = 0.10
"""Standard deviation of launch speed and spin relative to their means (our assumption)."""

HUMAN_COT_PSI = 0.1396
"""Typical cot ψ of a natural toss (ψ ≈ 82°), fitted so that the average p(ψ) is 0.508."""

HUMAN_COT_PSI_RELATIVE_SD = 0.5
"""Spread of cot ψ relative to its typical value (keeps ψ mostly below 90°)."""


def human(
    coin: Coin | None = None, start: Start = "heads", g: float = STANDARD_GRAVITY
) -> TossDistribution:
    """A person's natural toss caught in the hand; see the module notes for every number.

    Parameters
    ----------
    coin : Coin, optional
        Default the US quarter.
    start : {"heads", "tails"}
        Face up at launch.
    g : float
        Gravitational acceleration, m/s².

    Returns
    -------
    TossDistribution
        ωx ~ Normal(238.8, 23.9) rad/s, ωy = 0, ωz ~ Normal(μ, μ/2) with
        μ = (I1/I3)·238.8·0.1396 rad/s, T = 2 v0 / g with v0 ~ Normal(2.4, 0.24) m/s.
    """
    the_coin = coin if coin is not None else Coin.preset(DEFAULT_COIN)
    i1, i3 = the_coin.moments
    wz = i1 / i3 * HUMAN_SPIN * HUMAN_COT_PSI
    return TossDistribution.from_launch_speed(
        omega_x=Normal(HUMAN_SPIN, HUMAN_RELATIVE_SPREAD * HUMAN_SPIN),
        omega_y=Fixed(0.0),
        omega_z=Normal(wz, HUMAN_COT_PSI_RELATIVE_SD * wz),
        launch_speed=Normal(HUMAN_LAUNCH_SPEED, HUMAN_RELATIVE_SPREAD * HUMAN_LAUNCH_SPEED),
        coin=the_coin,
        start=start,
        g=g,
    )


PRESETS: MappingProxyType[str, Callable[..., TossDistribution]] = MappingProxyType({"human": human})
"""Toss presets by name: each a factory ``(coin=None, start="heads", g=9.81)``."""


def preset(
    name: str, coin: Coin | None = None, start: Start = "heads", g: float = STANDARD_GRAVITY
) -> TossDistribution:
    """The preset ``name`` for ``coin``; ValueError listing the presets if unknown."""
    try:
        factory = PRESETS[name]
    except KeyError:
        hint = difflib.get_close_matches(str(name), PRESETS, n=1)
        maybe = f" (did you mean {hint[0]}?)" if hint else ""
        raise ValueError(
            f"unknown preset {name!r}{maybe}; known presets: {', '.join(PRESETS)}"
        ) from None
    return factory(coin=coin, start=start, g=g)


__all__ = [
    "HUMAN_COT_PSI",
    "HUMAN_LAUNCH_SPEED",
    "HUMAN_SPIN",
    "PRESETS",
    "human",
    "preset",
]

"""coinflight: the physics of coin tossing.

A coin toss is deterministic: Newton's laws decide the face from the launch speed and spin.
coinflight models the coin as a thin uniform cylinder in torque-free flight (Stefan & Cheche,
"Coin toss modeling"), in closed form for every spin, and builds probabilities, biases and
pictures on top. Everything a user needs is importable from here:

>>> from coinflight import Coin, Flight, Toss
>>> flight = Flight(Coin.preset("us-quarter"), Toss(omega=(80, 0, 0), flight_time=0.7))
>>> flight.outcome.face_name
'heads'

P(heads) over a range of tosses (Stefan & Cheche Fig 2a, 0.497471 by the exact method):

>>> from coinflight import TossDistribution, Uniform, estimate
>>> tosses = TossDistribution(omega_x=Uniform(60, 90), flight_time=Uniform(0.6, 0.9))
>>> round(estimate(tosses, "exact").p_heads, 6)
0.497471

Beyond the one-toss objects, the names are loaded on first use (the figure functions import
matplotlib only then), so that ``import coinflight`` stays light.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING, Any

from coinflight._version import __version__
from coinflight.model.coin import PRESETS, Coin
from coinflight.model.toss import Flight, FlightState, Outcome, Toss
from coinflight.outcomes import outcome_model  # registers the surface kinds hand and table

if TYPE_CHECKING:
    from coinflight.model.distributions import Distribution, Fixed, Normal, Uniform
    from coinflight.model.ensemble import TossDistribution
    from coinflight.model.surface import Drag, Surface
    from coinflight.outcomes.table import Landing
    from coinflight.plotting.basin import plot_basin
    from coinflight.plotting.bias import plot_bias
    from coinflight.plotting.convergence import plot_convergence, plot_estimates
    from coinflight.plotting.edge import plot_edge
    from coinflight.plotting.forest import plot_forest
    from coinflight.plotting.toss import plot_toss
    from coinflight.probability import (
        ProbabilityResult,
        ProbabilityResults,
        estimate,
        estimate_many,
    )
    from coinflight.probability.convergence import convergence
    from coinflight.studies.basin import basin_map
    from coinflight.studies.bias import same_side_probability

# Names loaded on first access (PEP 562), so that `import coinflight` (and with it every
# `coinflight` command, `--help` included) loads only the one-toss objects above.
_LAZY = {
    "Distribution": "coinflight.model.distributions",
    "Drag": "coinflight.model.surface",
    "Fixed": "coinflight.model.distributions",
    "Landing": "coinflight.outcomes.table",
    "Normal": "coinflight.model.distributions",
    "ProbabilityResult": "coinflight.probability",
    "ProbabilityResults": "coinflight.probability",
    "Surface": "coinflight.model.surface",
    "TossDistribution": "coinflight.model.ensemble",
    "Uniform": "coinflight.model.distributions",
    "basin_map": "coinflight.studies.basin",
    "convergence": "coinflight.probability.convergence",
    "estimate": "coinflight.probability",
    "estimate_many": "coinflight.probability",
    "plot_basin": "coinflight.plotting.basin",
    "plot_bias": "coinflight.plotting.bias",
    "plot_convergence": "coinflight.plotting.convergence",
    "plot_estimates": "coinflight.plotting.convergence",
    "plot_edge": "coinflight.plotting.edge",
    "plot_forest": "coinflight.plotting.forest",
    "plot_toss": "coinflight.plotting.toss",
    "same_side_probability": "coinflight.studies.bias",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(import_module(_LAZY[name]), name)
        globals()[name] = value  # later look-ups find it directly
        return value
    raise AttributeError(f"module 'coinflight' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)


__all__ = [
    "PRESETS",
    "Coin",
    "Distribution",
    "Drag",
    "Fixed",
    "Flight",
    "FlightState",
    "Landing",
    "Normal",
    "Outcome",
    "ProbabilityResult",
    "ProbabilityResults",
    "Surface",
    "Toss",
    "TossDistribution",
    "Uniform",
    "__version__",
    "basin_map",
    "convergence",
    "estimate",
    "estimate_many",
    "outcome_model",
    "plot_basin",
    "plot_bias",
    "plot_convergence",
    "plot_edge",
    "plot_estimates",
    "plot_forest",
    "plot_toss",
    "same_side_probability",
]

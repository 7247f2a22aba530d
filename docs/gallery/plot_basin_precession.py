"""
Basin map of a precessing coin
==============================

A coin whose normal makes ψ = 60° with its angular momentum, over flight times and precession
rates ωp: it lands on the side it started on far more often than not, p(60°) = 0.608
(Diaconis, Holmes & Montgomery 2007). (``coinflight plot basin --psi 60 --precession-rate
100:200``)
"""

import math

from coinflight import Coin, basin_map, plot_basin

basin = basin_map(
    Coin.preset("us-quarter"),
    flight_time=(0.6, 0.9),
    spin=(100.0, 200.0),
    psi=math.radians(60.0),
    resolution=(300, 300),
)
print(f"same-side fraction on the grid: {basin.heads_fraction:.4f}")
fig = plot_basin(basin)

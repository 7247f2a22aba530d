"""
Basin map with Keller's hyperbolas
==================================

Heads and tails over a box of flight times T and spins ωx0 (the founding paper's Fig 2a
range), caught at launch height. The curves are Keller's hyperbolas ωT = (2k ± ½)π; the
fraction of heads cells is the grid method's probability on the same grid.
(``coinflight plot basin --omega-x 60:90 --flight-time 0.6:0.9``)
"""

from coinflight import Coin, basin_map, plot_basin

basin = basin_map(Coin.preset("us-quarter"), flight_time=(0.6, 0.9), spin=(60.0, 90.0))
print(f"heads fraction on the grid: {basin.heads_fraction:.6f}")
fig = plot_basin(basin)

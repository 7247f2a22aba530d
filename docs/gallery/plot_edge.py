"""
P(edge) of a thick coin
=======================

Yong & Mahadevan's geometric and dynamic models of P(edge) against thickness / diameter, the
ratios that give 1/3 marked, and simulated dead landings (±2 s.e.).
(``coinflight plot edge --simulate 4000 --seed 1``)
"""

from coinflight import plot_edge
from coinflight.studies.edge import simulate_edge

fig = plot_edge(simulate_edge([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0], n=300, seed=1))

"""
Thick coins and edges
=====================

A real coin has a rim. How thick must a cylinder be to land on its edge one time in three?
Yong & Mahadevan (2011) give two answers from two models; coinflight computes both
(:mod:`coinflight.studies.edge`) and simulates the landing they describe.
"""

# %%
# Two models
# ----------
# *Geometric*: the cylinder comes to rest in a uniformly random orientation; it stands on its
# edge when its centre of mass lies above the rim band. *Dynamic*: a vigorously spinning
# cylinder lands dead at a random angle in its plane of spin and falls towards the side of the
# contact point where its centre of mass lies, P(edge) = (2/π) arctan(h/d).
import numpy as np

from coinflight.studies.edge import edge_probability, ratio_for

for model in ("geometric", "dynamic"):
    print(f"{model:9s}: P(edge) = 1/3 at h/d = {ratio_for(1 / 3, model):.4f}")
ratios = np.array([0.05, 0.1, 0.354, 0.577, 1.0])
print("h/d      ", ratios)
print("geometric", edge_probability(ratios, "geometric").round(4))
print("dynamic  ", edge_probability(ratios, "dynamic").round(4))

# %%
# The exact ratios are 1/(2√2) ≈ 0.354 and 1/√3 ≈ 0.577. Real coins are far thinner: a US
# nickel has h/d = 1.95/21.21 ≈ 0.092.
from coinflight import Coin

nickel = Coin.preset("us-nickel")
print(f"US nickel h/d = {nickel.thickness / nickel.diameter:.3f}")

# %%
# Simulated landings beside the models
# ------------------------------------
# :func:`~coinflight.studies.edge.simulate_edge` tosses cylinders of each ratio with the full flight
# and lands them dead (restitution 0) on a table: the dynamic model's setting. A few hundred
# tosses per ratio keep this page quick; the error bars are ±2 standard errors.
from coinflight import plot_edge
from coinflight.studies.edge import simulate_edge

simulated = simulate_edge([0.1, 0.2, 0.3, 0.4, 0.6, 0.8], n=300, seed=1)
for ratio, s in simulated:
    print(f"h/d = {ratio:.1f}: {s.successes} of {s.n} on edge = {s.p:.3f} ± {s.stderr:.3f}")
fig = plot_edge(simulated)

# %%
# On a hard table a coin also bounces, and bouncing changes the answer (see
# :doc:`plot_06_table_landing`): Murray & Teare's extrapolation from their model for a US
# nickel is about one edge in 6,000 tosses; coinflight's answer depends on the unmeasured
# restitution and friction, so it is a band over them (``coinflight landing-report``).

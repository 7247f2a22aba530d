"""
Same-side probability p(ψ)
==========================

p(ψ) = ½ + (1/π) arcsin(cot²ψ) for a coin caught in the hand (Diaconis, Holmes & Montgomery
2007), with Monte Carlo simulations of the full torque-free flight at a few ψ (±2 s.e.) and
the rate measured over 350,757 flips. (``coinflight plot bias --monte-carlo 20000
--measured 0.5077``)
"""

from coinflight import plot_bias
from coinflight.studies.bias import psi_for_probability, simulate_same_side

measured = 0.5077  # Bartoš et al. 2025: 178,078 of 350,757 flips
psi = float(psi_for_probability(measured, degrees=True))
simulated = [(p, simulate_same_side(p, n=5000, seed=1, degrees=True)) for p in (50, 60, 70, 80)]
fig = plot_bias(simulated, measured=measured, psi_measured=psi)

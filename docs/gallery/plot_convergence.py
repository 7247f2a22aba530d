"""
Convergence of methods A and B
==============================

The founding paper's Fig 3b (ωx0 ∈ [60, 90] rad/s, ωy0 = 60 rad/s, T ∈ [0.6, 0.9] s): the
error ``|P(heads) − exact|`` of method A's grid and method B's random events against their size,
log–log, with method B's 95 % interval half-width shaded, its expected slope −1/2 and the grid's
observed slope.
Sizes are kept small so that this page builds quickly. (``coinflight convergence
--omega-x 60:90 --omega-y 60 --flight-time 0.6:0.9 --out fig3b``)
"""

from coinflight import TossDistribution, Uniform, convergence, plot_convergence

fig3b = TossDistribution(
    omega_x=Uniform(60.0, 90.0), omega_y=60.0, omega_z=0.0, flight_time=Uniform(0.6, 0.9)
)
result = convergence(
    fig3b,
    ["grid", "monte-carlo"],
    grid_sizes=[10, 30, 100, 300, 1000],
    event_sizes=[100, 1_000, 10_000, 100_000],
    seed=1,
)
fig = plot_convergence(result)

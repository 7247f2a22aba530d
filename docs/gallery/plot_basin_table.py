"""
Basins on a table, bounce by bounce
===================================

The face a coin would settle on, over launch speed and spin, when it falls onto a table
0.3 m below the hand, at its first contact and after one and two bounces (restitution 0.5,
friction 0.3). The boundaries stay smooth but grow more intricate with each bounce (Strzałko
et al. 2008). (``coinflight plot basin --surface table --drop-height 0.3 --bounces K``)
"""

from coinflight import Coin, Surface, basin_map, plot_basin
from coinflight.outcomes import outcome_model

coin = Coin.preset("us-quarter")
surface = Surface("table", drop_height=0.3, restitution=0.5, friction=0.3)
figures = []
for bounces in (0, 1, 2):
    basin = basin_map(
        coin,
        flight_time=(2 * 1.0 / 9.81, 2 * 2.5 / 9.81),  # launch speed 1-2.5 m/s
        spin=(20.0, 60.0),
        resolution=(150, 120),
        outcome=outcome_model(surface, max_bounces=bounces),
    )
    ending = f"on a table 0.3 m below, after {bounces} bounces"
    figures.append(plot_basin(basin, boundaries=False, ending=ending))

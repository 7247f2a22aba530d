"""coinflight: the physics of coin tossing.

A coin toss is deterministic: Newton's laws decide the face from the launch speed and spin.
coinflight models the coin as a thin uniform cylinder in torque-free flight (Stefan & Cheche,
"Coin toss modeling"), in closed form for every spin, and builds probabilities, biases and
pictures on top.

>>> from coinflight import Coin, Flight, Toss
>>> flight = Flight(Coin.preset("us-quarter"), Toss(omega=(80, 0, 0), flight_time=0.7))
>>> flight.outcome.face_name
'heads'
"""

from coinflight._version import __version__
from coinflight.coin import PRESETS, Coin
from coinflight.toss import Flight, FlightState, Outcome, Toss

__all__ = ["PRESETS", "Coin", "Flight", "FlightState", "Outcome", "Toss", "__version__"]

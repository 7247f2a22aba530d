"""The help texts of the table's options (:mod:`coinflight.cli.landing_groups`, and the
sweep's and the edge command's groups that repeat them): what each option is, its unit, range,
default and source."""

from __future__ import annotations

from typing import Any

from coinflight.cli.options import CONTACT_PANEL, option

TABLE_PREFIX = "table: "
SPREAD = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal "
    "one truncated to the physical range)."
)
ENDING_HELP = (
    "how a landing ends once its bounces die out. rocking (default): a planar rocking hand-off, "
    "fast, but it discards the spin and precession. rigid: the rigid, event-driven 3-D ending "
    "(rolling without slip, exact Coulomb sliding, hops flown in closed form, rim impacts, "
    "rest on the edge band); about 200 times slower than rocking."
)
"""--ending's help (command line and sweep)."""


def _resistance_tail(ell: str, against: str) -> str:
    return (
        f"m, 0 to 0.01 (torque {ell} F_n against {against}; default 1e-4). Not measured for "
        "coins: quote a band over 1e-5 to 1e-3, not a value."
    )


ROLLING_TAIL = _resistance_tail("ℓ_r", "the coin's rolling")
"""--rolling-resistance's help after the name of the length: unit, range, default, unmeasured."""
PIVOTING_TAIL = _resistance_tail("ℓ_p", "the coin's spin about the vertical")
"""--pivoting-resistance's help after the name of the length, as :data:`ROLLING_TAIL`."""
ROLLING_HELP = "rolling resistance length ℓ_r, " + ROLLING_TAIL
"""--rolling-resistance's help."""
PIVOTING_HELP = "pivoting (drilling) resistance length ℓ_p, " + PIVOTING_TAIL
"""--pivoting-resistance's help."""


def resistance_option(which: str, metavar: str, help: str) -> Any:
    """The --rolling-resistance or --pivoting-resistance option (``which``: rolling or
    pivoting), read as text (a number, a distribution or a list: the command parses it); the
    one definition of the table group's and the sweep's."""
    return option(f"--{which}-resistance", metavar=metavar, panel=CONTACT_PANEL, help=help)


CORNER_HELP = (
    "radius of the coin's rounded rim corners, m, 0 to half the thickness (or the radius if "
    "smaller; default 0: sharp). "
    "Used by the flight's contacts, the impacts, both endings (the rocking section rolls on "
    "its round corners) and every ending's face/edge wells. Not measured for coins (worn coins "
    "are rounder): quote a band, not a value."
)
"""--corner-radius's help."""
SPREAD_RESISTANCE = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal one"
    " truncated to 0 to 0.01 m), drawn toss by toss."
)
DURATION_LIST_HELP = (
    "1e-6 to 0.01 (default 1e-4): rim points meeting the table less than t_c apart strike as "
    "one. Hertz's contact time: 5e-5 to 3e-4 on wood, 2e-5 to 4e-5 on stone or glass; not "
    "measured for coins: sweep a band."
)
"""The sweep's --contact-duration help after what it lists."""
DURATION_HELP = (
    "contact duration t_c of one impact of the coin's rim on the table, s, 1e-6 to 0.01 "
    "(default 1e-4): two rim points meeting the table less than t_c apart strike as one "
    "(a coin landing nearly flat or upright). Hertz's contact time: 5e-5 to 3e-4 on wood, "
    "2e-5 to 4e-5 on stone or glass; not measured for coins: quote a band, not a value."
)
"""--contact-duration's help."""
SPREAD_DURATION = (
    " probability: also a distribution over the tosses, LOW:HIGH or normal:MEAN,SD (a normal one"
    " truncated to 1e-6 to 0.01 s), drawn toss by toss."
)

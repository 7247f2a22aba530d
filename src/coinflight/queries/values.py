"""Turning parsed options into the library's values (coin, toss, tosses), checking the
combinations the command line allows (one of --flight-time and --launch-speed, …)."""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

from coinflight.model.coin import PRESETS

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.ensemble import TossDistribution
    from coinflight.model.toss import Toss

COIN_NAMES = ", ".join(PRESETS)
"""The coins a --coin (``coin=``) names: the presets of :mod:`coinflight.model.coin`."""


def flag(name: str) -> str:
    """The command-line option of a parameter (or API parameter): ``omega_x`` → ``--omega-x``."""
    return "--" + name.replace("_", "-")


def resolve_coin(
    coin: str | None, radius: float | None, thickness: float | None, mass: float | None
) -> Coin:
    """The coin the user asked for: a preset by name, or custom dimensions (all three)."""
    from coinflight.model.coin import DEFAULT_COIN, Coin

    custom = {"--radius": radius, "--thickness": thickness, "--mass": mass}
    given = [k for k, val in custom.items() if val is not None]
    if given and coin is not None:
        raise ValueError(f"give either --coin or custom dimensions ({', '.join(given)}), not both")
    if given:
        missing = [k for k, val in custom.items() if val is None]
        if missing:
            raise ValueError(
                "a custom coin needs --radius, --thickness and --mass; "
                f"missing {', '.join(missing)}"
            )
        assert radius is not None and thickness is not None and mass is not None
        return Coin(radius=radius, thickness=thickness, mass=mass)
    return Coin.preset(coin if coin is not None else DEFAULT_COIN)


class CoinArgs(NamedTuple):
    """The coin, as typed: --coin or the custom dimensions --radius, --thickness, --mass (SI;
    None: not given); :meth:`resolve` makes the coin."""

    coin: str | None = None
    radius: float | None = None
    thickness: float | None = None
    mass: float | None = None

    def resolve(self) -> Coin:
        """The coin (:func:`resolve_coin`)."""
        return resolve_coin(*self)


class TossArgs(NamedTuple):
    """The options of one toss: spin, one of flight time and launch speed, start face, g."""

    omega: tuple[float, float, float]
    flight_time: float | None
    launch_speed: float | None
    start: str
    g: float


def build_toss(args: TossArgs) -> Toss:
    """The :class:`~coinflight.model.toss.Toss` for the toss options (one of T and V0 required)."""
    from coinflight.model.toss import Toss

    omega, flight_time, launch_speed, start, g = args
    if (flight_time is None) == (launch_speed is None):
        raise ValueError("give exactly one of --flight-time and --launch-speed")
    if flight_time is not None:
        return Toss(omega=omega, flight_time=flight_time, start=start, g=g)  # type: ignore[arg-type]
    return Toss.from_launch_speed(omega, launch_speed, start=start, g=g)  # type: ignore[arg-type]


class DistArgs(NamedTuple):
    """The options of a range of tosses, as typed: each spin and T or v0 a distribution."""

    omega_x: str
    omega_y: str
    omega_z: str
    flight_time: str | None
    launch_speed: str | None
    start: str
    g: float

    def build(self, coin: Coin) -> TossDistribution:
        """The :class:`~coinflight.model.ensemble.TossDistribution` these options describe."""
        from coinflight.model.distributions import parse_distribution
        from coinflight.model.ensemble import TossDistribution, check_launch_speed

        wx = parse_distribution(self.omega_x, "--omega-x", "rad/s")
        wy = parse_distribution(self.omega_y, "--omega-y", "rad/s")
        wz = parse_distribution(self.omega_z, "--omega-z", "rad/s")
        where = {"coin": coin, "start": self.start, "g": self.g}
        if (self.flight_time is None) == (self.launch_speed is None):
            raise ValueError("give exactly one of --flight-time and --launch-speed")
        if self.flight_time is not None:
            t = parse_distribution(self.flight_time, "--flight-time", "s")
            return TossDistribution(wx, wy, wz, t, **where)  # type: ignore[arg-type]
        assert self.launch_speed is not None
        v0 = check_launch_speed(
            parse_distribution(self.launch_speed, "--launch-speed", "m/s"), "--launch-speed"
        )
        return TossDistribution.from_launch_speed(wx, wy, wz, v0, **where)  # type: ignore[arg-type]


class TableArgs(NamedTuple):
    """Where the toss ends, as typed: --surface and the table's options (None: not given),
    --surface-preset, then the rigid ending's options: --rolling-resistance,
    --pivoting-resistance (texts: a distribution where a probability takes one), the coin's
    --corner-radius (m) and the impact's --contact-duration (s; a text, as the resistances)."""

    surface: str
    drop_height: float | None
    restitution: str | None
    friction: str | None
    surface_preset: str | None
    rolling_resistance: str | None = None
    pivoting_resistance: str | None = None
    corner_radius: float | None = None
    contact_duration: str | None = None


class AirArgs(NamedTuple):
    """The air, as typed: --drag and --spin-damping (None: not given)."""

    drag: float | None
    spin_damping: float | None


def simulation_seed(
    runs: int | None,
    seed: int | None,
    *others: tuple[str, object],
    run_flag: str = "--monte-carlo",
) -> int | None:
    """--seed, passed through (None: the library draws one and reports it); ValueError if --seed
    or another simulation option is given without ``run_flag``, which alone runs the simulation
    they set."""
    if runs is None:
        for flag, value in (("--seed", seed), *others):
            if value is not None:
                raise ValueError(f"{flag} needs {run_flag} N (it sets the simulation)")
    return seed


def parse_range(text: str, name: str, unit: str = "") -> tuple[float, float]:
    """ "LO:HI" as two numbers (the range syntax of :func:`parse_distribution`).

    A map needs a box, so a fixed value or a normal distribution is refused with a ValueError
    naming the option and the text.
    """
    from coinflight.model.distributions import Uniform, parse_distribution

    dist = parse_distribution(text, name, unit)
    if not isinstance(dist, Uniform):
        raise ValueError(
            f"{name} must be a range LO:HI such as 60:90 for a map; got {text!r} "
            f"({dist.describe(unit)})"
        )
    return dist.low, dist.high


def parse_resolution(text: str) -> tuple[int, int]:
    """ "N" (N×N cells) or "NTxNW" (cells along T, along the spin)."""
    parts = text.lower().split("x")
    try:
        if len(parts) not in (1, 2):
            raise ValueError
        sizes = [int(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"--resolution must be N or NTxNW with whole numbers, such as 500 or 600x400; "
            f"got {text!r}"
        ) from None
    return (sizes[0], sizes[-1])


def parse_numbers(text: str, name: str, example: str = "0.6,0.65,0.7") -> list[float]:
    """Comma-separated numbers, or a ValueError naming the option, an ``example`` of what it
    takes and the bad text."""
    parts = [p.strip() for p in text.split(",")]
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise ValueError(
            f"{name} must be comma-separated numbers such as {example}; got {text!r}"
        ) from None
    return values


def parse_sizes(text: str, option: str) -> list[int]:
    """Comma-separated whole numbers (at least one), or a ValueError naming the option."""
    try:
        values = [int(part) for part in text.split(",") if part.strip()]
    except ValueError:
        raise ValueError(f"{option} {text!r}: give comma-separated whole numbers") from None
    if not values:
        raise ValueError(f"{option} {text!r}: give at least one size")
    return values


MAX_COUNT = 10_000
"""Largest COUNT of a FROM:TO:COUNT item of :func:`parse_numbers_list`."""


def parse_numbers_list(text: str, option_name: str) -> list[float]:
    """Comma-separated numbers and FROM:TO:COUNT items (COUNT evenly spaced values, ends
    included), or a ValueError naming the option and the item (the lists of a sweep)."""
    import numpy as np

    from coinflight.model.distributions import parse_distribution

    out: list[float] = []
    for raw in str(text).split(","):
        item = raw.strip()
        parts = item.split(":")
        try:
            if len(parts) == 3:
                count = int(parts[2])
                if not 1 <= count <= MAX_COUNT:
                    raise ValueError
                ends = [parse_distribution(p, option_name).mean for p in parts[:2]]
                out.extend(float(x) for x in np.linspace(ends[0], ends[1], count))
            elif len(parts) == 1 and item:
                out.append(float(parse_distribution(item, option_name).mean))
            else:
                raise ValueError
        except ValueError:
            raise ValueError(
                f"{option_name} {text!r}: {item!r} is not a number nor FROM:TO:COUNT "
                f"(COUNT a whole number 1–{MAX_COUNT}); e.g. 150,200,250 or 150:250:5"
            ) from None
    return out


def names(text: str, option_name: str) -> list[str]:
    """Comma-separated names, or a ValueError naming the option when one is empty."""
    items = [x.strip() for x in str(text).split(",")]
    if not all(items):
        raise ValueError(f"{option_name} {text!r}: give comma-separated names, none empty")
    return items

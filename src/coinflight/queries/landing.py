"""The landing surface and the air, from the options as typed: built, checked, described
(the command line's and the web application's one reading of --surface, --drop-height,
--restitution, --friction, --rolling-resistance, --pivoting-resistance,
--contact-duration, --corner-radius, --drag, --spin-damping and --bounces)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from coinflight.queries.values import AirArgs, TableArgs

if TYPE_CHECKING:
    from collections.abc import Iterable

    from coinflight.model.coin import Coin
    from coinflight.model.distributions import Distribution
    from coinflight.model.ensemble import TossDistribution
    from coinflight.model.surface import Drag, Surface, SurfaceKind
    from coinflight.outcomes.base import OutcomeModel

CONTACT_FLAGS = {
    "restitution": "--restitution",
    "friction": "--friction",
    "rolling_resistance": "--rolling-resistance",
    "pivoting_resistance": "--pivoting-resistance",
    "contact_duration": "--contact-duration",
}
"""The contact parameters a command line may spread, and their options."""

TAKES = {
    "--drop-height": ("drop_height",),
    "--restitution": ("restitution",),
    "--friction": ("friction",),
    "--surface-preset": ("restitution", "friction", "contact_duration"),
    "--rolling-resistance": ("rolling_resistance",),
    "--pivoting-resistance": ("pivoting_resistance",),
    "--corner-radius": ("corner_radius",),
    "--contact-duration": ("contact_duration",),
}
"""The table's options and what each sets (:data:`coinflight.model.surface.TABLE_PARAMETERS`):
a surface kind that does not take it refuses the option given."""


def contact_spread(
    restitution: str | float | None,
    friction: str | float | None,
    surface_preset: str | None = None,
    rolling_resistance: str | float | None = None,
    pivoting_resistance: str | float | None = None,
    contact_duration: str | float | None = None,
) -> dict[str, Distribution]:
    """The --restitution, --friction, --rolling-resistance, --pivoting-resistance and
    --contact-duration texts (or
    numbers, a sweep's values: fixed) as distributions (only those given), each checked against
    its physical range (:func:`coinflight.model.surface.contact_distribution`: a normal one
    truncated to it, the rest refused outside it); ValueError naming the option. With
    --surface-preset, the preset's ranges (:data:`coinflight.studies.presets.SURFACE_PRESETS`)
    for those not given."""
    from coinflight.model.distributions import Fixed, parse_distribution
    from coinflight.model.surface import CONTACT_UNITS, contact_distribution

    out: dict[str, Distribution] = {}
    if surface_preset is not None:
        from coinflight.studies.presets import surface_preset as lookup

        out.update(lookup(surface_preset).contact)
    texts = (restitution, friction, rolling_resistance, pivoting_resistance, contact_duration)
    for name, text in zip(CONTACT_FLAGS, texts, strict=True):
        if text is None:
            continue
        flag = CONTACT_FLAGS[name]
        try:
            dist = (
                Fixed(text)
                if isinstance(text, float)
                else parse_distribution(text, flag, CONTACT_UNITS.get(name, ""))
            )
            out[name] = contact_distribution(name, dist)
        except ValueError as exc:
            message = str(exc)
            raise ValueError(
                message if message.startswith(flag) else f"{flag}: {message}"
            ) from None
    return out


def single_values(
    spread: dict[str, Distribution], command: str = "this command"
) -> dict[str, float]:
    """The contact parameters of ``spread`` as single numbers; ValueError (one line) for a
    distribution, which only a probability integrates over."""
    ranged = [
        f"{CONTACT_FLAGS[name]} {d.describe()}" for name, d in spread.items() if not d.is_fixed
    ]
    if ranged:
        raise ValueError(
            f"{', '.join(ranged)}: {command} takes a single value; a distribution of a contact "
            "parameter is for coinflight probability --method monte-carlo, qmc or grid, which "
            "integrate over it"
        )
    return {name: d.mean for name, d in spread.items()}


def build_surface(
    kind: str,
    drop_height: float | None,
    restitution: str | float | None,
    friction: str | float | None,
    surface_preset: str | None = None,
    ranged: bool = False,
    *,
    rolling_resistance: str | float | None = None,
    pivoting_resistance: str | float | None = None,
    corner_radius: float | None = None,
    contact_duration: str | float | None = None,
) -> Surface:
    """The :class:`~coinflight.model.surface.Surface` for the options (table options: a table;
    the contact parameters as typed, or a sweep's numbers).

    --restitution, --friction, --rolling-resistance, --pivoting-resistance and
    --contact-duration must be single numbers, and --surface-preset (ranges) is refused,
    unless ``ranged`` (the command then reads their distributions with :func:`contact_spread`
    and passes them with the tosses; the surface keeps its defaults for them).
    ``corner_radius`` (the coin's, applied by :func:`landing_coin`) is only checked here to
    belong to a table.
    """
    from coinflight.model.surface import Surface, surface_kind

    the_kind = surface_kind(kind)
    given = {
        "--drop-height": drop_height,
        "--restitution": restitution,
        "--friction": friction,
        "--surface-preset": surface_preset,
        "--rolling-resistance": rolling_resistance,
        "--pivoting-resistance": pivoting_resistance,
        "--corner-radius": corner_radius,
        "--contact-duration": contact_duration,
    }
    extra = [
        flag
        for flag, value in given.items()
        if value is not None and not set(TAKES[flag]) <= set(the_kind.takes)
    ]
    if extra:
        raise ValueError(f"{', '.join(extra)} {the_kind.refusal}")
    if surface_preset is not None and not ranged:
        contact_spread(None, None, surface_preset)  # an unknown name first
        raise ValueError(
            f"--surface-preset {surface_preset} spreads restitution, friction and contact "
            "duration over the literature's ranges: this command takes single values "
            "(--restitution, --friction, --contact-duration); "
            "coinflight probability --method monte-carlo, qmc or grid integrates over a preset"
        )
    spread = contact_spread(
        restitution,
        friction,
        surface_preset,
        rolling_resistance,
        pivoting_resistance,
        contact_duration,
    )
    fixed = (
        {name: d.mean for name, d in spread.items() if d.is_fixed}
        if ranged
        else single_values(spread)
    )
    from coinflight.outcomes.table import PER_TOSS

    # only the contact parameters given: the surface keeps its defaults marked as not given
    # (a catch in the hand refuses a given one)
    given_values = {name: fixed[name] for name in PER_TOSS if name in fixed}
    if drop_height is not None:  # else the default, marked as not given (0 m below launch)
        given_values["drop_height"] = drop_height
    return Surface(kind, **given_values)


def surface_from(table: TableArgs, ranged: bool = False) -> Surface:
    """:func:`build_surface` for the table options as typed (every one of them)."""
    return build_surface(
        table.surface,
        table.drop_height,
        table.restitution,
        table.friction,
        table.surface_preset,
        ranged,
        rolling_resistance=table.rolling_resistance,
        pivoting_resistance=table.pivoting_resistance,
        corner_radius=table.corner_radius,
        contact_duration=table.contact_duration,
    )


def table_spread(table: TableArgs) -> dict[str, Distribution]:
    """The contact parameters the table options spread over the tosses (distributions only;
    single values are in the surface): :func:`contact_spread` of every one of them. The
    landing draws them toss by toss (:data:`coinflight.outcomes.table.PER_TOSS`)."""
    given = contact_spread(
        table.restitution,
        table.friction,
        table.surface_preset,
        table.rolling_resistance,
        table.pivoting_resistance,
        table.contact_duration,
    )
    return {name: d for name, d in given.items() if not d.is_fixed}


def landing_coin(coin: Coin, table: TableArgs) -> Coin:
    """``coin`` with the rim corner radius of --corner-radius (m), if given; ValueError naming
    the option when it lies outside 0 to h/2 (the coin's own check and wording)."""
    if table.corner_radius is None:
        return coin
    try:
        return coin.with_corner_radius(table.corner_radius)
    except ValueError as exc:
        raise ValueError(f"--corner-radius: {exc}") from None


def build_drag(coefficient: float | None, spin_damping: float | None) -> Drag | None:
    """The :class:`~coinflight.model.surface.Drag` for the options, None when there is no air."""
    from coinflight.model.surface import Drag

    if coefficient is None and spin_damping is None:
        return None
    drag = Drag(
        coefficient=0.0 if coefficient is None else coefficient,
        spin_damping=0.0 if spin_damping is None else spin_damping,
    )
    return None if drag.is_zero else drag


def check_bounces(surface: Surface, bounces: int | None) -> None:
    """--bounces needs a surface kind that takes it (a table) and a count between 0 and
    landing.MAX_BOUNCES."""
    if bounces is None:
        return
    from coinflight.model.surface import surface_kind

    kind = surface_kind(surface.kind)
    if "max_bounces" not in kind.takes:
        raise ValueError(f"--bounces {kind.refusal}")
    from coinflight.outcomes.table import check_max_bounces

    check_max_bounces(bounces, "--bounces")


def surfaces_payload(
    kinds: Iterable[SurfaceKind] | None = None, seconds: float | None = None
) -> dict[str, Any]:
    """``GET /api/surfaces``: the surface ``kinds`` (default: every registered one,
    :func:`coinflight.outcomes.register`) in order, each its ``name``, ``summary``, the table's
    parameters it ``takes`` and its model's declarations the page asks: ``can_end_on_edge``
    (P(edge) is printed) and ``closed_form_bands`` (the exact method applies). With
    ``seconds``, the work a request may take, each kind also has ``suggested_n``, the number of
    random tosses the page proposes on it (:func:`suggested_tosses`)."""
    from coinflight.model.surface import surface_kinds
    from coinflight.outcomes import outcome_model

    listed = []
    for k in surface_kinds().values() if kinds is None else kinds:
        entry: dict[str, Any] = {
            "name": k.name,
            "summary": k.summary,
            "takes": list(k.takes),
            "can_end_on_edge": bool(k.model.can_end_on_edge),
            "closed_form_bands": bool(k.model.closed_form_bands),
        }
        if seconds is not None:
            entry["suggested_n"] = suggested_tosses(outcome_model(k.name).rate, seconds)
        listed.append(entry)
    return {"surfaces": listed}


SUGGESTED_MOST = 100_000
"""The most tosses :func:`suggested_tosses` proposes (the page's default n in the hand)."""


def suggested_tosses(rate: float, seconds: float) -> int:
    """The number of random tosses to propose for a request that may take ``seconds`` of work,
    on a surface whose tosses run at ``rate`` a second (its model's work-bound rate): the
    largest 1, 2 or 5 times a power of ten, from 10 to :data:`SUGGESTED_MOST`, whose tosses
    take at most half of ``seconds`` (a table landing carried to rest takes thousands of times
    as long as a catch in the hand).

    >>> suggested_tosses(70.0, 7.5), suggested_tosses(1e8, 7.5)
    (200, 100000)
    """
    fits = 0.5 * rate * seconds
    best = 10
    for n in (10 * 10**k * f for k in range(5) for f in (1, 2, 5)):
        if n <= min(fits, SUGGESTED_MOST):
            best = max(best, n)
    return best


def surface_payload(surface: Surface, drag: Drag | None) -> dict[str, object]:
    """JSON description of the landing surface and the air (:func:`settings_for` its model)."""
    from coinflight.outcomes import outcome_model

    return settings_for(outcome_model(surface, drag))


def describe_landing(surface: Surface, drag: Drag | None) -> str:
    """One line for the text output: where the toss ends, the air drag and the spin damping."""
    from coinflight.outcomes import outcome_model

    return outcome_model(surface, drag).describe()


def describe_for(model: OutcomeModel, dist: TossDistribution | None = None) -> str:
    """One line for the text output: how the tosses ``dist`` end under ``model``. A table
    landing names the tosses' own contact distributions in place of its surface's values and
    their coin's rounded rim (:meth:`coinflight.outcomes.table.TableLanding.describe`); any
    other model says what its ``describe`` says."""
    from coinflight.outcomes.table import TableLanding

    if isinstance(model, TableLanding) and dist is not None:
        return model.describe(dist.contact, dist.coin.corner_radius)
    return model.describe()


def settings_for(model: OutcomeModel, dist: TossDistribution | None = None) -> dict[str, Any]:
    """JSON settings of ``model`` for the tosses ``dist``, as :func:`describe_for` (a table
    landing's contact distributions as objects, ``{"kind": "uniform", ...}``). A table landing
    reports its impact's ``contact_duration`` (s) always, as its restitution and friction: its
    model's own settings leave the default out (a sweep row's random stream is keyed on them)."""
    from coinflight.outcomes.table import TableLanding

    if not isinstance(model, TableLanding):
        return model.to_dict()
    out = model.to_dict() if dist is None else model.to_dict(dist.contact, dist.coin.corner_radius)
    out.setdefault("contact_duration", float(model.surface.contact_duration))
    return out


@dataclass(frozen=True)
class LandingChoice:
    """The landing the options ask for, and the outcome model that evaluates it."""

    surface: Surface
    drag: Drag | None
    model: OutcomeModel

    def describe(self) -> str:
        """One line for the text output (the model's ``describe``)."""
        return self.model.describe()


def outcome_model(
    table: TableArgs, air: AirArgs, bounces: int | None = None, ranged: bool = False
) -> LandingChoice | None:
    """None for the plain hand catch; else the surface, drag and outcome model to use
    (``ranged``: the contact parameters may be distributions, read apart with
    :func:`table_spread`)."""
    from coinflight import outcomes

    the_surface = surface_from(table, ranged)
    the_drag = build_drag(*air)
    check_bounces(the_surface, bounces)
    if the_surface.kind == "hand" and the_drag is None:
        return None
    return LandingChoice(
        the_surface, the_drag, outcomes.outcome_model(the_surface, the_drag, bounces)
    )


def table_outcome(table: TableArgs, bounces: int | None) -> dict[str, Any]:
    """``outcome=`` for :func:`coinflight.studies.basin.basin_map` (empty for the hand: the
    closed form; the outcome model of any other surface kind)."""
    from coinflight.outcomes import outcome_model

    the_surface = surface_from(table)
    check_bounces(the_surface, bounces)
    if the_surface.kind == "hand":
        return {}
    return {"outcome": outcome_model(the_surface, None, bounces)}

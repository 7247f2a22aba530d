"""The landing surface and the air, from the options as typed: built, checked, described
(the command line's and the web application's one reading of --surface, --drop-height,
--restitution, --friction, --drag, --spin-damping and --bounces)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from coinflight.model.distributions import Distribution
    from coinflight.model.surface import Drag, Surface
    from coinflight.outcomes.base import OutcomeModel

CONTACT_FLAGS = {"restitution": "--restitution", "friction": "--friction"}
"""The contact parameters a command line may spread, and their options."""


def contact_spread(
    restitution: str | None, friction: str | None, surface_preset: str | None = None
) -> dict[str, Distribution]:
    """The --restitution and --friction texts as distributions (only those given), each checked
    against its physical range (:func:`coinflight.model.surface.contact_distribution`: a normal
    one truncated to it, the rest refused outside it); ValueError naming the option. With
    --surface-preset, the preset's ranges (:data:`coinflight.studies.presets.SURFACE_PRESETS`)
    for those not given."""
    from coinflight.model.distributions import parse_distribution
    from coinflight.model.surface import contact_distribution

    out: dict[str, Distribution] = {}
    if surface_preset is not None:
        from coinflight.studies.presets import surface_preset as lookup

        out.update(lookup(surface_preset).contact)
    for name, text in (("restitution", restitution), ("friction", friction)):
        if text is None:
            continue
        flag = CONTACT_FLAGS[name]
        try:
            out[name] = contact_distribution(name, parse_distribution(text, flag))
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
            f"{', '.join(ranged)}: {command} takes a single value; a distribution of restitution "
            "or friction is for coinflight probability --method monte-carlo, qmc or grid, which "
            "integrate over it"
        )
    return {name: d.mean for name, d in spread.items()}


def build_surface(
    kind: str,
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    surface_preset: str | None = None,
    ranged: bool = False,
) -> Surface:
    """The :class:`~coinflight.model.surface.Surface` for the options (table options: a table).

    --restitution and --friction must be single numbers, and --surface-preset (ranges) is
    refused, unless ``ranged`` (the command then reads their distributions with
    :func:`contact_spread` and passes them with the tosses; the surface keeps its defaults
    for them).
    """
    from coinflight.model.surface import DEFAULT_FRICTION, DEFAULT_RESTITUTION, Surface

    given = {
        "--drop-height": drop_height,
        "--restitution": restitution,
        "--friction": friction,
        "--surface-preset": surface_preset,
    }
    if kind == "hand":
        extra = [flag for flag, value in given.items() if value is not None]
        if extra:
            raise ValueError(f"{', '.join(extra)} applies to --surface table only")
    if surface_preset is not None and not ranged:
        contact_spread(None, None, surface_preset)  # an unknown name first
        raise ValueError(
            f"--surface-preset {surface_preset} spreads restitution and friction over the "
            "literature's ranges: this command takes single values (--restitution, --friction); "
            "coinflight probability --method monte-carlo, qmc or grid integrates over a preset"
        )
    spread = contact_spread(restitution, friction, surface_preset)
    fixed = (
        {name: d.mean for name, d in spread.items() if d.is_fixed}
        if ranged
        else single_values(spread)
    )
    return Surface(
        kind,  # type: ignore[arg-type]
        drop_height=0.0 if drop_height is None else drop_height,
        restitution=fixed.get("restitution", DEFAULT_RESTITUTION),
        friction=fixed.get("friction", DEFAULT_FRICTION),
    )


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
    """--bounces needs a table and a count between 0 and landing.MAX_BOUNCES."""
    if bounces is None:
        return
    if surface.kind != "table":
        raise ValueError("--bounces applies to --surface table only")
    from coinflight.outcomes.table import check_max_bounces

    check_max_bounces(bounces, "--bounces")


def surface_payload(surface: Surface, drag: Drag | None) -> dict[str, object]:
    """JSON description of the landing surface and the air (the model's ``to_dict``)."""
    from coinflight.outcomes import outcome_model

    return outcome_model(surface, drag).to_dict()


def describe_landing(surface: Surface, drag: Drag | None) -> str:
    """One line for the text output: where the toss ends, the air drag and the spin damping."""
    from coinflight.outcomes import outcome_model

    return outcome_model(surface, drag).describe()


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
    kind: str,
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    surface_preset: str | None,
    drag: float | None,
    spin_damping: float | None,
    bounces: int | None = None,
    ranged: bool = False,
) -> LandingChoice | None:
    """None for the plain hand catch; else the surface, drag and outcome model to use
    (``ranged``: --restitution and --friction may be distributions, read apart with
    :func:`contact_spread`)."""
    from coinflight import outcomes

    the_surface = build_surface(kind, drop_height, restitution, friction, surface_preset, ranged)
    the_drag = build_drag(drag, spin_damping)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces and the_drag is None:
        return None
    return LandingChoice(
        the_surface, the_drag, outcomes.outcome_model(the_surface, the_drag, bounces)
    )


def table_outcome(
    kind: str,
    drop_height: float | None,
    restitution: str | None,
    friction: str | None,
    surface_preset: str | None,
    bounces: int | None,
) -> dict[str, Any]:
    """``outcome=`` for :func:`coinflight.studies.basin.basin_map` (empty for the hand)."""
    from coinflight.outcomes import outcome_model

    the_surface = build_surface(kind, drop_height, restitution, friction, surface_preset)
    check_bounces(the_surface, bounces)
    if not the_surface.bounces:
        return {}
    return {"outcome": outcome_model(the_surface, None, bounces)}

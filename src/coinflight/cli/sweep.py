"""``coinflight sweep``: P(heads), P(same side), P(edge) over the product of option lists.

The option grammar (also in the command's help and docs/user_guide/sweeps.md):

- a toss parameter (``--omega-x``, ``--omega-y``, ``--omega-z``, ``--flight-time``,
  ``--launch-speed``) takes a list of distributions: comma-separated items, each a number
  (fixed) or LOW:HIGH (uniform), as in ``coinflight probability``; ``normal:MEAN,SD`` is one
  normal distribution (its comma is its own). Repeat the option to add more values:
  ``--omega-x 60:90 --omega-x normal:240,24``;
- ``--P-mean`` and ``--P-sd`` (P one of the parameters) sweep normal distributions over the
  product of their lists of numbers; an sd of 0 is a fixed value. A list of numbers is
  comma-separated numbers and FROM:TO:COUNT items (COUNT evenly spaced values from FROM to TO);
- ``--coin``, ``--start``, ``--surface`` take comma-separated names; ``--drop-height``,
  ``--restitution`` and ``--friction`` lists of numbers, swept for the table rows only;
  ``--ending`` comma-separated endings (rocking, contact), and ``--rolling-resistance`` and
  ``--pivoting-resistance`` lists of numbers swept for the contact ending's rows only;
  ``--corner-radius`` a list of numbers (m) swept over the coins (--surface table only).
"""

from __future__ import annotations

import itertools
import time
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from coinflight import _validation as v
from coinflight.cli.cluster import ClusterOptions
from coinflight.cli.command import command
from coinflight.cli.landing_groups import (
    CORNER_HELP,
    ENDING_HELP,
    PIVOTING_TAIL,
    ROLLING_TAIL,
    resistance_option,
)
from coinflight.cli.options import (
    COIN_PANEL,
    CONTACT_PANEL,
    METHOD_PANEL,
    OUTPUT_HELP,
    OUTPUT_PANEL,
    SURFACE_PANEL,
    TOSS_PANEL,
    Gravity,
    JsonFlag,
    Quiet,
    Seed,
    Threads,
    option,
    print_json,
)
from coinflight.cli.progress import progress_bar
from coinflight.probability import registry

if TYPE_CHECKING:
    from coinflight.model.coin import Coin
    from coinflight.model.distributions import Distribution
    from coinflight.outcomes.base import OutcomeModel

MAX_COUNT = 10_000
"""Largest COUNT of a FROM:TO:COUNT item."""

_UNITS = {
    "omega_x": "rad/s",
    "omega_y": "rad/s",
    "omega_z": "rad/s",
    "flight_time": "s",
    "launch_speed": "m/s",
}
_WHAT = {
    "omega_x": "Spin about the x diameter",
    "omega_y": "Spin about the y diameter",
    "omega_z": "Spin about the normal",
    "flight_time": "Flight time",
    "launch_speed": "Launch speed v0 (T = 2 v0 / g), instead of --flight-time",
}
_DEFAULTS = {"omega_y": "0", "omega_z": "0"}


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def _dists_option(name: str) -> Any:
    unit = _UNITS[name]
    default = f" Default {_DEFAULTS[name]}." if name in _DEFAULTS else ""
    return option(
        _flag(name),
        metavar="DISTS",
        panel=TOSS_PANEL,
        help=f"{_WHAT[name]}, {unit}: comma-separated values, each a number or LOW:HIGH "
        f"(uniform), or one normal:MEAN,SD; repeat the option for more.{default}",
    )


def _numbers_option(name: str, stat: str) -> Any:
    what = "means" if stat == "mean" else "standard deviations (0: fixed at the mean)"
    return option(
        f"{_flag(name)}-{stat}",
        metavar="LIST",
        panel=TOSS_PANEL,
        help=f"Normal {_flag(name)[2:]}: {what}, {_UNITS[name]}; numbers and FROM:TO:COUNT, "
        f"comma-separated (with {_flag(name)}-{'sd' if stat == 'mean' else 'mean'}).",
    )


Dists = list[str] | None


def parse_numbers_list(text: str, option_name: str) -> list[float]:
    """Comma-separated numbers and FROM:TO:COUNT items (COUNT evenly spaced values, ends
    included), or a ValueError naming the option and the item."""
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


def parse_dists(texts: list[str], option_name: str, unit: str) -> list[Distribution]:
    """The distributions of a repeated option: each text a comma-separated list of numbers and
    LOW:HIGH ranges, or one normal:MEAN,SD."""
    from coinflight.model.distributions import parse_distribution

    out = []
    for text in texts:
        raw = str(text).strip()
        if raw.lower().startswith("normal:"):
            if raw.count(",") != 1:
                raise ValueError(
                    f"{option_name} {raw!r}: a normal is normal:MEAN,SD; for several, repeat "
                    f"the option or use {option_name}-mean and {option_name}-sd"
                )
            out.append(parse_distribution(raw, option_name, unit))
            continue
        for item in raw.split(","):
            out.append(parse_distribution(item, option_name, unit))
    return out


def _normals(means: str, sds: str, name: str) -> list[Distribution]:
    from coinflight.model.distributions import Fixed, Normal
    from coinflight.probability.sweep import MAX_ROWS

    flag = _flag(name)
    mean_list = parse_numbers_list(means, f"{flag}-mean")
    sd_list = parse_numbers_list(sds, f"{flag}-sd")
    rows = len(mean_list) * len(sd_list)
    if rows > MAX_ROWS:  # before building them
        shown, most = v.over_limit(rows, MAX_ROWS)
        raise ValueError(
            f"{flag}-mean × {flag}-sd is {v.quantity(len(mean_list))} × "
            f"{v.quantity(len(sd_list))} = {shown} distributions, more than the {most} rows a "
            "sweep accepts; use fewer"
        )
    out: list[Distribution] = []
    for mean in mean_list:
        for sd in sd_list:
            if sd < 0:
                raise ValueError(f"{flag}-sd {sds!r}: a standard deviation must be ≥ 0")
            out.append(Fixed(mean) if sd == 0 else Normal(mean, sd))
    return out


def parameter_values(
    name: str, dists: list[str] | None, means: str | None, sds: str | None
) -> list[Distribution] | None:
    """The values of one toss parameter from its options (None when none is given)."""
    flag = _flag(name)
    if (means is None) != (sds is None):
        given, missing = (f"{flag}-mean", f"{flag}-sd")[:: 1 if sds is None else -1]
        raise ValueError(f"{given} needs {missing} (normal distributions: both lists)")
    if dists and means is not None:
        raise ValueError(f"give either {flag} or {flag}-mean/{flag}-sd, not both")
    if dists:
        return parse_dists(dists, flag, _UNITS[name])
    if means is not None and sds is not None:
        return _normals(means, sds, name)
    return None


def _names(text: str, option_name: str) -> list[str]:
    items = [x.strip() for x in str(text).split(",")]
    if not all(items):
        raise ValueError(f"{option_name} {text!r}: give comma-separated names, none empty")
    return items


def outcome_models(
    surfaces: str,
    drop_height: str | None,
    restitution: str | None,
    friction: str | None,
    bounces: int | None,
    ending: str | None = None,
    rolling_resistance: str | None = None,
    pivoting_resistance: str | None = None,
) -> list[OutcomeModel]:
    """The outcome models of --surface and the table's lists (swept for the table only; the
    rolling and pivoting resistances for the contact ending's rows only)."""
    from coinflight.outcomes import SURFACE_KINDS
    from coinflight.outcomes import outcome_model as build_model
    from coinflight.queries.landing import build_surface, check_bounces

    kinds = _names(surfaces, "--surface")
    for kind in kinds:
        if kind not in SURFACE_KINDS:
            raise ValueError(f"--surface {kind!r}: choose among {', '.join(SURFACE_KINDS)}")
    table = {
        "--drop-height": drop_height,
        "--restitution": restitution,
        "--friction": friction,
    }
    contact = {
        "--rolling-resistance": rolling_resistance,
        "--pivoting-resistance": pivoting_resistance,
    }
    given = [flag for flag, text in {**table, "--ending": ending, **contact}.items()
             if text is not None]  # fmt: skip
    if given and "table" not in kinds:
        from coinflight.model.surface import TABLE_ONLY

        raise ValueError(f"{', '.join(given)} {TABLE_ONLY}")
    endings = ["rocking"] if ending is None else _names(ending, "--ending")
    resistances = [
        [None] if text is None else parse_numbers_list(text, flag) for flag, text in contact.items()
    ]
    models: list[OutcomeModel] = []
    for kind in dict.fromkeys(kinds):
        if kind != "table":
            check_bounces(build_surface(kind, None, None, None), bounces)
            models.append(build_model(kind))
            continue
        lists = [
            [None] if text is None else parse_numbers_list(text, flag)
            for flag, text in table.items()
        ]
        for the_ending in dict.fromkeys(endings):
            # the resistances are swept over the contact ending's rows only; without such rows
            # the rocking rows get them, and the surface refuses them in its words
            swept = the_ending == "contact" or "contact" not in endings
            ells = resistances if swept else [[None], [None]]
            for d, e, mu, rolling, pivoting in itertools.product(*lists, *ells):
                # build_surface reads the options as typed; repr round-trips a float exactly
                surface = build_surface(
                    "table", d, _text(e), _text(mu), ending=the_ending,
                    rolling_resistance=_text(rolling), pivoting_resistance=_text(pivoting),
                )  # fmt: skip
                check_bounces(surface, bounces)
                models.append(build_model(surface, None, bounces))
    return models


def _text(value: float | None) -> str | None:
    """A swept number as build_surface reads an option (repr round-trips a float exactly)."""
    return None if value is None else repr(value)


def corner_coins(coins: list[Coin], corner_radius: str | None, surfaces: str) -> list[Coin]:
    """Each coin with each --corner-radius of the list (m; --surface table only), or the coins
    as they are."""
    if corner_radius is None:
        return coins
    if _names(surfaces, "--surface") != ["table"]:
        raise ValueError(
            "--corner-radius applies to --surface table only (a catch in the hand does not read "
            "it: sweep the table alone)"
        )
    radii = parse_numbers_list(corner_radius, "--corner-radius")
    out = []
    for coin in coins:
        for a in dict.fromkeys(radii):
            try:
                out.append(coin.with_corner_radius(a))
            except ValueError as exc:
                raise ValueError(f"--corner-radius: {coin.name}: {exc}") from None
    return out


Method = Annotated[
    str,
    option(
        "--method",
        "-m",
        metavar="|".join(registry.names()),
        panel=METHOD_PANEL,
        help="The method of every row: "
        + "; ".join(f"{e.name}: {e.description}" for e in registry.estimators())
        + ". exact handles the hand only.",
    ),
]
Size = Annotated[
    int | None,
    option(
        "--n",
        "-n",
        metavar="N",
        panel=METHOD_PANEL,
        help="The method's size for every row (as coinflight probability --n).",
        min=1,
    ),
]
Out = Annotated[
    Path,
    option(
        "--out",
        "-o",
        metavar="FILE",
        panel=OUTPUT_PANEL,
        help='The table: FILE.parquet (pip install "coinflight[parquet]"; the inputs, method, '
        "n, seed and version in its metadata) or FILE.csv (with FILE.csv.json). Resumable: "
        "finished rows are kept in FILE.partial.jsonl until FILE is written; run the same "
        "command again after a stop (Ctrl-C, a failure, a killed job) and only the missing rows "
        f"are computed (same options, method, n and seed; --fresh to start over). {OUTPUT_HELP}",
    ),
]


@command
def sweep(
    ctx: typer.Context,
    *,
    omega_x: Annotated[Dists, _dists_option("omega_x")] = None,
    omega_x_mean: Annotated[str | None, _numbers_option("omega_x", "mean")] = None,
    omega_x_sd: Annotated[str | None, _numbers_option("omega_x", "sd")] = None,
    omega_y: Annotated[Dists, _dists_option("omega_y")] = None,
    omega_y_mean: Annotated[str | None, _numbers_option("omega_y", "mean")] = None,
    omega_y_sd: Annotated[str | None, _numbers_option("omega_y", "sd")] = None,
    omega_z: Annotated[Dists, _dists_option("omega_z")] = None,
    omega_z_mean: Annotated[str | None, _numbers_option("omega_z", "mean")] = None,
    omega_z_sd: Annotated[str | None, _numbers_option("omega_z", "sd")] = None,
    flight_time: Annotated[Dists, _dists_option("flight_time")] = None,
    flight_time_mean: Annotated[str | None, _numbers_option("flight_time", "mean")] = None,
    flight_time_sd: Annotated[str | None, _numbers_option("flight_time", "sd")] = None,
    launch_speed: Annotated[Dists, _dists_option("launch_speed")] = None,
    launch_speed_mean: Annotated[str | None, _numbers_option("launch_speed", "mean")] = None,
    launch_speed_sd: Annotated[str | None, _numbers_option("launch_speed", "sd")] = None,
    coin: Annotated[
        str,
        option(
            "--coin",
            metavar="NAMES",
            panel=COIN_PANEL,
            help="Comma-separated coins: us-cent, us-nickel, us-dime, us-quarter, "
            "us-half-dollar, eur-1, eur-2, eur-50c, gbp-1.",
        ),
    ] = "us-quarter",
    start: Annotated[
        str,
        option("--start", metavar="FACES", panel=TOSS_PANEL, help="heads, tails or heads,tails."),
    ] = "heads",
    g: Gravity = 9.81,
    surface: Annotated[
        str,
        option(
            "--surface",
            metavar="hand,table",
            panel=SURFACE_PANEL,
            help="Comma-separated: hand (caught, P(edge) empty) and/or table (lands, bounces; "
            "P(edge)). A table's result depends on its unmeasured restitution and friction: "
            "sweep them over their plausible range (e.g. --restitution 0.3,0.5,0.7 --friction "
            "0.1,0.3,0.5) and quote the band.",
        ),
    ] = "hand",
    drop_height: Annotated[
        str | None,
        option("--drop-height", metavar="LIST", panel=SURFACE_PANEL, help="table: m (default 0)."),
    ] = None,
    restitution: Annotated[
        str | None,
        option(
            "--restitution",
            metavar="LIST",
            panel=SURFACE_PANEL,
            help="table: coefficients of restitution in [0, 1] (default 0.5).",
        ),
    ] = None,
    friction: Annotated[
        str | None,
        option(
            "--friction",
            metavar="LIST",
            panel=SURFACE_PANEL,
            help="table: Coulomb friction coefficients, 0 to 3 (default 0.3).",
        ),
    ] = None,
    bounces: Annotated[
        int | None,
        option(
            "--bounces",
            metavar="K",
            panel=SURFACE_PANEL,
            help="table: the face at the contact after K bounces (default: at rest).",
        ),
    ] = None,
    ending: Annotated[
        str | None,
        option(
            "--ending",
            metavar="rocking,contact",
            panel=CONTACT_PANEL,
            help="table, comma-separated endings: " + ENDING_HELP,
        ),
    ] = None,
    rolling_resistance: Annotated[
        str | None,
        resistance_option(
            "rolling", "LIST", "table, contact ending rows: lengths ℓ_r, " + ROLLING_TAIL
        ),
    ] = None,
    pivoting_resistance: Annotated[
        str | None,
        resistance_option(
            "pivoting", "LIST", "table, contact ending rows: lengths ℓ_p, " + PIVOTING_TAIL
        ),
    ] = None,
    corner_radius: Annotated[
        str | None,
        option(
            "--corner-radius",
            metavar="LIST",
            panel=CONTACT_PANEL,
            help="--surface table only, swept over every coin: " + CORNER_HELP,
        ),
    ] = None,
    method: Method = "exact",
    n: Size = None,
    seed: Seed = None,
    threads: Threads = None,
    cluster: ClusterOptions,
    out: Out,
    fresh: Annotated[
        bool,
        option(
            "--fresh",
            metavar=None,
            panel=OUTPUT_PANEL,
            help="Start over: replace FILE.partial.jsonl (the rows of an earlier run of this "
            "table) instead of resuming from it.",
        ),
    ] = False,
    quiet: Quiet = False,
    json_output: JsonFlag = False,
) -> None:
    """P(heads), P(same side), P(edge) for every combination of the given values, as one table.

    Each toss parameter takes a list of distributions: numbers (fixed), LOW:HIGH (uniform),
    normal:MEAN,SD; or --P-mean and --P-sd lists for normals over their product (a list of
    numbers also takes FROM:TO:COUNT). --coin, --start, --surface take comma-separated names,
    the table's options lists of numbers. One row per combination; one seed for the sweep,
    each row drawing its own stream from it and its inputs (a row does not depend on the
    others, their order or the workers).

    Example: coinflight sweep --omega-x-mean 150,200,250 --omega-x-sd 10,20 --launch-speed
    1.5:3 --coin us-quarter,eur-1 --method monte-carlo --n 100000 --seed 1 --out sweep.parquet
    """
    from coinflight.probability.sweep import product_cases, run_sweep, table_files
    from coinflight.queries.values import resolve_coin

    t0 = time.perf_counter()
    estimator = registry.get(method)
    table_files(out)  # the suffix, before any work
    if seed is not None and not estimator.seeded:
        seeded = " and ".join(registry.names(seeded=True))
        raise ValueError(f"--seed applies to {seeded}, not {method}")
    if n is not None and estimator.default_n is None:
        raise ValueError(f"--n does not apply to the {method} method")
    options = {
        "omega_x": (omega_x, omega_x_mean, omega_x_sd),
        "omega_y": (omega_y, omega_y_mean, omega_y_sd),
        "omega_z": (omega_z, omega_z_mean, omega_z_sd),
        "flight_time": (flight_time, flight_time_mean, flight_time_sd),
        "launch_speed": (launch_speed, launch_speed_mean, launch_speed_sd),
    }
    values = {name: parameter_values(name, *texts) for name, texts in options.items()}
    if values["omega_x"] is None:
        raise ValueError("give --omega-x (or --omega-x-mean and --omega-x-sd)")
    if (values["flight_time"] is None) == (values["launch_speed"] is None):
        raise ValueError(
            "give one of --flight-time and --launch-speed (or their -mean and -sd lists)"
        )
    coins = [resolve_coin(name, None, None, None) for name in _names(coin, "--coin")]
    coins = corner_coins(coins, corner_radius, surface)
    starts = _names(start, "--start")
    for face in starts:
        if face not in ("heads", "tails"):
            raise ValueError(f"--start {start!r}: each face is heads or tails")
    models = outcome_models(
        surface, drop_height, restitution, friction, bounces, ending, rolling_resistance,
        pivoting_resistance,
    )  # fmt: skip
    from coinflight.outcomes.table import CONTACT_TOSSES_PER_SECOND

    # rows that reach the 3-D contact phase (a dead or bounce-limited row never does)
    slow = [m for m in models if m.rate <= CONTACT_TOSSES_PER_SECOND]
    if slow and n is None and estimator.default_n is not None:
        raise ValueError(
            f"with --ending contact each landing is carried through the 3-D contact phase "
            f"(about {min(m.rate for m in slow):,.0f} tosses per second), so the default size of "
            f"--method {method} would run for about an hour a row; give --n explicitly "
            "(e.g. --n 1000)"
        )
    if method == "exact" and any(not m.closed_form_bands for m in models):
        others = " or ".join(registry.names(seeded=True)) + " or grid"
        raise ValueError(f"--method exact handles --surface hand only; for a table use {others}")
    cases = product_cases(
        omega_x=values["omega_x"],
        omega_y=values["omega_y"] or [0.0],
        omega_z=values["omega_z"] or [0.0],
        flight_time=values["flight_time"],
        launch_speed=values["launch_speed"],
        coins=coins,
        starts=starts,
        models=models,
        g=g,
    )
    inputs = {
        _flag(k): x
        for k, x in ctx.params.items()
        if x not in (None, [])
        and k not in ("quiet", "json_output", "out", "fresh", "scheduler", "workers")
    }
    with cluster.executor(threads) as executor, progress_bar(len(cases), "sweep", quiet) as bar:
        results, files = run_sweep(
            cases,
            out,
            method,
            n,
            seed,
            inputs=inputs,
            fresh=fresh,
            executor=executor,
            threads=threads,
            progress=bar,
        )
    summary = {
        "rows": len(results),
        "reused": results.reused,
        "computed": len(results) - results.reused,
        "method": method,
        "n": results.n,
        "seed": results.seed,
        "files": [str(f) for f in files],
        "elapsed": time.perf_counter() - t0,
    }
    if json_output:
        print_json(summary)
        return
    heads = [r.p_heads for r in results]
    reused = f" ({results.reused} reused from a previous run)" if results.reused else ""
    seed_text = "" if results.seed is None else f", seed {results.seed}"
    typer.echo(f"{len(results)} rows by {method}{reused}{seed_text}")
    typer.echo(f"P(heads) from {min(heads):.6f} to {max(heads):.6f}")
    typer.echo(f"wrote {', '.join(map(str, files))}")

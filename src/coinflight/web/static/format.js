// Numbers written as the command line writes them (Python's format specifications), so that the
// page and `coinflight toss` / `coinflight probability` print the same characters.

/** Python's `format(x, ".{p}g")`: p significant digits, trailing zeros dropped. */
export function fmtG(x, p = 6) {
  if (!Number.isFinite(x)) return String(x).replace("Infinity", "inf");
  if (x === 0) return "0";
  const [mant, expText] = x.toExponential(Math.max(p - 1, 0)).split("e");
  const exp = Number(expText);
  if (exp < -4 || exp >= p) {
    const m = mant.includes(".") ? mant.replace(/\.?0+$/, "") : mant;
    const sign = exp < 0 ? "-" : "+";
    return `${m}e${sign}${String(Math.abs(exp)).padStart(2, "0")}`;
  }
  const fixed = x.toFixed(Math.max(p - 1 - exp, 0));
  return fixed.includes(".") ? fixed.replace(/\.?0+$/, "") : fixed;
}

/** Python's `format(n, ",")` for an integer: 350,757. */
export function thousands(n) {
  return Math.round(n)
    .toString()
    .replace(/\B(?=(\d{3})+(?!\d))/g, ",");
}

/** What the coin did, in words (cli/toss.py `_turns`). */
export function turns(rotations, psi) {
  const psiDeg = (psi * 180) / Math.PI;
  if (Math.abs(psiDeg - 90) < 1e-9) {
    return `${rotations.toFixed(4)} rotations about a diameter (ψ = 90°: S ⟂ n)`;
  }
  const wobble =
    Math.abs(psiDeg - 90) > 45
      ? "; it only wobbles and never turns over (ψ < 45° or > 135°)"
      : "";
  return (
    `${rotations.toFixed(4)} turns of its normal about the angular momentum, on a cone of ` +
    `half-angle ψ = ${psiDeg.toFixed(1)}°${wobble}`
  );
}

/** The first line of `coinflight toss` and `coinflight probability` (`Coin.describe`, the start). */
function coinLine(c, start) {
  return (
    `${c.name} (d = ${(2000 * c.radius).toFixed(2)} mm, h = ${(1000 * c.thickness).toFixed(2)} mm, ` +
    `m = ${(1000 * c.mass).toFixed(3)} g), started ${start} up`
  );
}

/** The text `coinflight toss` prints, from the object `coinflight toss --json` prints. */
export function tossLines(r) {
  const [wx, wy, wz] = r.omega;
  return [
    coinLine(r.coin, r.start),
    `spin ω0 = (${fmtG(wx)}, ${fmtG(wy)}, ${fmtG(wz)}) rad/s, flight time T = ${fmtG(r.flight_time, 4)} s ` +
      `(launch speed ${fmtG(r.launch_speed, 3)} m/s, apex ${fmtG(r.apex, 3)} m)`,
    `lands ${r.outcome.toUpperCase()} up after ${turns(r.rotations, r.psi)}`,
  ];
}

const UNITS = { omega_x: "rad/s", omega_y: "rad/s", omega_z: "rad/s", flight_time: "s" };

/** A distribution as `TossDistribution.describe` writes it (fixed and uniform). */
export function describeDistribution(name, d) {
  const unit = UNITS[name] ? ` ${UNITS[name]}` : "";
  if (d.kind === "fixed") return `${name} = ${fmtG(d.value)}${unit}`;
  if (d.kind === "uniform") return `${name} = ${fmtG(d.low)}–${fmtG(d.high)}${unit}`;
  if (d.kind === "normal") return `${name} = normal(${fmtG(d.mean)}, sd ${fmtG(d.sd)})${unit}`;
  return `${name} = ${JSON.stringify(d)}`;
}

/** `ProbabilityResult.describe()`: the probability with its uncertainty. */
export function describeResult(r) {
  let unc = "";
  if (r.stderr != null && r.ci95 != null) {
    unc = ` ± ${fmtG(r.stderr, 2)} s.e. (95 % CI ${r.ci95[0].toFixed(4)} – ${r.ci95[1].toFixed(4)})`;
  } else if (r.error_estimate != null && r.error_estimate > 0) {
    unc = ` ± ${fmtG(r.error_estimate, 1)} (quadrature error bound)`;
  } else if (r.method === "exact") {
    unc = " (closed form)";
  }
  return `P(heads) = ${r.p_heads.toFixed(6)}${unc}`;
}

/** The estimator's one-line summary (each estimator's `summary` in coinflight.probability). */
function methodSummary(r) {
  const d = r.details || {};
  if (r.method === "exact") {
    return String(d.how) + (d.warning ? `; quadrature warning: ${d.warning}` : "");
  }
  if (r.method === "monte-carlo") {
    const cells = d.grid_cells;
    return (
      `${thousands(r.n)} tosses` +
      (cells ? ` drawn from ${cells} cells (method B)` : "") +
      `, seed ${r.seed}`
    );
  }
  return `${thousands(r.samples ?? r.n ?? 0)} tosses`;
}

/**
 * The text `coinflight probability` prints, from its --json object: for the hand catch all of
 * it; on another surface (`edge`: its kind can end a toss on edge, /api/surfaces) all but the
 * line that describes the surface, which the object does not carry.
 */
export function probabilityLines(r, edge = false) {
  const lines = [coinLine({ name: r.coin, ...r.coin_dimensions }, r.start)];
  for (const name of ["omega_x", "omega_y", "omega_z", "flight_time"]) {
    if (r.distribution && r.distribution[name]) {
      lines.push(describeDistribution(name, r.distribution[name]));
    }
  }
  lines.push(`g = ${fmtG(r.g)} m/s²`);
  lines.push(describeResult(r));
  lines.push(
    `P(tails) = ${r.p_tails.toFixed(6)}, P(same side) = ${r.p_same_side.toFixed(6)}` +
      (edge ? `, P(edge) = ${fmtG(r.p_edge)}` : ""),
  );
  for (const w of r.warnings || []) lines.push(`warning: ${w}`);
  lines.push(`method ${r.method}: ${methodSummary(r)}; ${fmtG(r.elapsed, 3)} s`);
  return lines;
}

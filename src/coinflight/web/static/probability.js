// Probability: P(heads) over ranges of spin and flight time (/api/probability), printed as
// `coinflight probability` prints it.
import { ApiError, getJSON, latest, showError, unlessSuperseded } from "./api.js";
import { fmtG, probabilityLines, thousands } from "./format.js";
import { fitCanvas, Axes } from "./plot2d.js";
import { COLORS } from "./explorer.js";

const HALVINGS = 8; // the build-up's points: n, n/2, …, n/2^8 tosses (at least 100)

/** A parameter as the command line takes it: one number (fixed) or LOW:HIGH (uniform). */
function spec(lo, hi) {
  lo = lo.trim();
  hi = hi.trim();
  return hi === "" || hi === lo ? lo : `${lo}:${hi}`;
}

export class Probability {
  constructor(root, settings) {
    this.root = root;
    this.settings = settings;
    this.el = (id) => root.querySelector(`#${id}`);
    this.request = latest((signal) => this.fetchProbability(signal));
    this.el("prob-form").addEventListener("submit", (e) => {
      e.preventDefault();
      this.update();
    });
    this.el("prob-method").addEventListener("change", () => this.syncMethod());
    this.el("prob-surface").addEventListener("change", () => {
      this.proposeTosses();
      this.update();
    });
    this.surfaces = this.loadSurfaces();
    new ResizeObserver(() => this.drawBuildUp()).observe(this.el("buildup-canvas"));
    this.syncMethod();
  }

  /**
   * The surface menu, filled from the server's registered surface kinds (/api/surfaces): its
   * name, and its one line as the option's title. The catch in the hand is chosen (and the
   * only one asked while the menu is empty).
   */
  async loadSurfaces() {
    const select = this.el("prob-surface");
    let surfaces;
    try {
      ({ surfaces } = await getJSON("api/surfaces"));
    } catch (err) {
      showError(this.el("prob-error"), err); // the hand's answers still come
      return;
    }
    this.kinds = new Map(surfaces.map((kind) => [kind.name, kind]));
    for (const kind of surfaces) {
      const option = document.createElement("option");
      option.value = kind.name;
      option.textContent = kind.name;
      option.title = kind.summary;
      select.append(option);
    }
    select.value = "hand";
    select.title = this.kind().summary ?? "";
    this.proposeTosses();
    select.addEventListener("change", () => {
      select.title = this.kind().summary ?? "";
    });
  }

  /**
   * The number of random tosses the server answers on the chosen surface within its time
   * limit (its suggested_n: a landing on a table, carried to rest, takes thousands of times as
   * long as a catch), put in the tosses field unless a number of one's own was typed there.
   */
  proposeTosses() {
    const field = this.el("prob-n");
    const n = this.kind().suggested_n;
    if (n == null) return;
    if (this.proposed === undefined || field.value.trim() === String(this.proposed)) {
      field.value = String(n);
    }
    this.proposed = n;
  }

  /** The chosen surface kind's declarations (the hand's while the menu is not yet filled). */
  kind() {
    const chosen = this.kinds?.get(this.el("prob-surface").value || "hand");
    return chosen ?? { name: "hand", can_end_on_edge: false, closed_form_bands: true };
  }

  syncMethod() {
    const mc = this.el("prob-method").value === "monte-carlo";
    this.el("prob-mc").hidden = !mc;
  }

  query() {
    const v = (id) => this.el(id).value;
    const q = {
      omega_x: spec(v("p-wx-lo"), v("p-wx-hi")),
      omega_y: spec(v("p-wy-lo"), v("p-wy-hi")),
      omega_z: spec(v("p-wz-lo"), v("p-wz-hi")),
      flight_time: spec(v("p-T-lo"), v("p-T-hi")),
      method: v("prob-method"),
      surface: v("prob-surface") === "hand" ? "" : v("prob-surface"), // hand: the default
      coin: this.settings.coin(),
      start: this.settings.start(),
    };
    if (q.method === "monte-carlo") {
      q.n = v("prob-n").trim();
      q.seed = v("prob-seed").trim();
    }
    return q;
  }

  hideBuildUp() {
    this.el("buildup").hidden = true;
    this.points = null;
  }

  /**
   * The estimate as the tosses add up: the same run (same seed) cut after n/2^k tosses; a
   * shorter run is the start of a longer one (coinflight's seeded streams), so each point is
   * where this very answer stood after that many tosses. With the exact value for reference.
   */
  async buildUp(r, signal) {
    const box = this.el("buildup");
    if (typeof r.seed === "number" && !Number.isSafeInteger(r.seed)) {
      // This browser rounded the seed (no JSON source access): it cannot ask for the same run.
      this.hideBuildUp();
      return;
    }
    box.hidden = false;
    box.dataset.state = "loading";
    const q = { ...this.query(), seed: r.seed };
    const sizes = [];
    for (let k = HALVINGS; k >= 1; k--) {
      const n = Math.floor(r.n / 2 ** k);
      if (n >= 100 && !sizes.includes(n)) sizes.push(n);
    }
    this.points = [[r.n, r.p_heads, r.ci95]];
    this.exact = null;
    this.drawBuildUp();
    try {
      if (!this.kind().closed_form_bands) throw new Error("no closed form on this surface");
      const exact = await getJSON("api/probability", { ...q, method: "exact", n: "", seed: "" }, { signal });
      this.exact = exact.p_heads;
    } catch (err) {
      if (err.name === "AbortError") throw err;
      this.exact = null; // no closed form for these tosses: the curve alone
    }
    for (const n of sizes) {
      const part = await getJSON("api/probability", { ...q, n }, { signal });
      this.points.push([part.n, part.p_heads, part.ci95]);
      this.drawBuildUp();
    }
    this.el("buildup-text").textContent =
      `the same ${thousands(r.n)} tosses (seed ${r.seed}) cut after ` +
      `${sizes.map(thousands).join(", ")} tosses` +
      (this.exact != null ? `; exact value ${this.exact.toFixed(6)}` : "");
    box.dataset.state = "ready";
  }

  drawBuildUp() {
    const fit = fitCanvas(this.el("buildup-canvas"));
    if (!this.points) return;
    const pts = [...this.points].sort((a, b) => a[0] - b[0]);
    const xs = pts.map((p) => Math.log10(p[0]));
    const lo = Math.min(...pts.map((p) => p[2][0]), this.exact ?? 1);
    const hi = Math.max(...pts.map((p) => p[2][1]), this.exact ?? 0);
    const pad = 0.08 * (hi - lo || 0.01);
    const x0 = Math.min(...xs) - 0.15;
    const x1 = Math.max(Math.max(...xs) + 0.15, x0 + 1);
    const ax = new Axes(fit, [x0, x1], [lo - pad, hi + pad], { right: 3 * fit.fontPx });
    const { ctx } = fit;
    ctx.save();
    ax.clip();
    if (this.exact != null) {
      ctx.strokeStyle = "#000";
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(ax.left, ax.y(this.exact));
      ctx.lineTo(ax.left + ax.pw, ax.y(this.exact));
      ctx.stroke();
    }
    ctx.strokeStyle = COLORS.heads;
    ctx.fillStyle = COLORS.heads;
    ctx.lineWidth = 2;
    pts.forEach(([n, p, ci]) => {
      const x = ax.x(Math.log10(n));
      ctx.beginPath();
      ctx.moveTo(x, ax.y(ci[0]));
      ctx.lineTo(x, ax.y(ci[1]));
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(x, ax.y(p), 4.5, 0, 2 * Math.PI);
      ctx.fill();
    });
    ctx.restore();
    const ticks = [];
    for (let e = Math.ceil(ax.xlim[0]); e <= ax.xlim[1]; e++) ticks.push(e);
    ax.draw("tosses (log scale)", "P(heads)", { xticks: ticks, xformat: (e) => thousands(10 ** e) });
  }

  update() {
    return unlessSuperseded(this.request);
  }

  async fetchProbability(signal) {
    this.root.dataset.state = "loading";
    this.el("prob-run").disabled = true;
    try {
      const r = await getJSON("api/probability", this.query(), { signal });
      const out = this.el("prob-result");
      out.dataset.pHeads = String(r.p_heads);
      this.el("prob-p").textContent = r.p_heads.toFixed(6);
      this.el("prob-unc").textContent =
        r.stderr != null
          ? `± ${fmtG(r.stderr, 2)} (standard error), 95 % interval ${r.ci95[0].toFixed(4)} – ${r.ci95[1].toFixed(4)}`
          : r.method === "exact"
            ? "exact (closed form: no sampling error)"
            : "";
      this.el("prob-bar").style.setProperty("--p", String(r.p_heads));
      this.el("prob-text").textContent = probabilityLines(r, this.kind().can_end_on_edge).join("\n");
      showError(this.el("prob-error"), null);
      this.root.dataset.state = "ready";
      if (r.method === "monte-carlo") await this.buildUp(r, signal);
      else this.hideBuildUp();
    } catch (err) {
      if (err.name === "AbortError") throw err;
      if (!(err instanceof ApiError)) console.warn(err);
      showError(this.el("prob-error"), err);
      this.root.dataset.state = "error";
    } finally {
      this.el("prob-run").disabled = false;
    }
  }
}

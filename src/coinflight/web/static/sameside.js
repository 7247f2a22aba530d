// Same side: p(ψ), the chance a precessing coin lands the side it started (/api/bias, Diaconis,
// Holmes & Montgomery 2007), and the ψ that explains 350,757 real flips (/api/data).
import { ApiError, getJSON, latest, linkSlider, showError, showing, unlessSuperseded } from "./api.js";
import { fitCanvas, Axes } from "./plot2d.js";
import { COLORS } from "./explorer.js";
import { fmtG, thousands } from "./format.js";

/** The curve's ψ, degrees: every 5°, closer near 45° and 135° where p(ψ) leaves 1 steeply. */
function curvePsis() {
  const near = [0.1, 0.3, 0.6, 1, 1.5, 2.2, 3.2];
  const psis = new Set();
  for (let d = 0; d <= 180; d += 5) psis.add(d);
  for (const e of near) {
    psis.add(45 + e);
    psis.add(135 - e);
  }
  return [...psis].sort((a, b) => a - b);
}

/** p(ψ) at each of `psis`, in one request (/api/bias?psis=…: the answer for each ψ, in order). */
async function curveAt(psis) {
  return psis.length ? getJSON("api/bias", { psis: psis.join(",") }) : [];
}

const VIEWS = {
  all: { x: [0, 180], y: [0.5, 1.0], ticks: [0, 30, 60, 90, 120, 150, 180] },
  near: { x: [60, 100], y: [0.49, 0.62], ticks: [60, 70, 80, 90, 100], psis: range(60, 100, 1) },
};

function range(lo, hi, step) {
  const out = [];
  for (let v = lo; v <= hi; v += step) out.push(v);
  return out;
}

export class SameSide {
  constructor(root) {
    this.root = root;
    this.el = (id) => root.querySelector(`#${id}`);
    this.curve = null;
    this.data = null;
    this.current = null;
    this.request = latest((signal) => this.fetchPsi(signal));
    const range = this.el("psi-range");
    const box = this.el("psi");
    linkSlider(range, box, () => this.changed());
    this.el("psi-data").addEventListener("click", () => {
      if (!this.data) return;
      const psi = this.data.psi_deg.toFixed(1);
      box.value = psi;
      range.value = psi;
      this.changed();
    });
    for (const radio of root.querySelectorAll("input[name=psi-view]")) {
      radio.addEventListener("change", () => this.setView(radio.value));
    }
    this.view = "all";
    new ResizeObserver(() => this.draw()).observe(this.el("psi-canvas"));
  }

  changed() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.update(), 80);
  }

  async load() {
    this.root.dataset.state = "loading";
    try {
      const psis = curvePsis();
      const [curve, data] = await Promise.all([
        curveAt(psis),
        getJSON("api/data"),
      ]);
      this.curve = new Map(curve.map((r) => [r.psi_deg, r.p_same_side]));
      this.data = data;
      this.el("data-text").textContent =
        `${thousands(data.flips)} flips by ${data.people} people (Bartoš et al.): ` +
        `${(100 * data.p_same_side).toFixed(2)} % landed on the side they started ` +
        `(95 % interval ${(100 * data.ci95[0]).toFixed(2)} – ${(100 * data.ci95[1]).toFixed(2)} %), ` +
        `heads ${(100 * data.p_heads).toFixed(2)} %. ` +
        `A coin whose normal makes ψ = ${data.psi_deg.toFixed(1)}° ` +
        `(${data.psi_ci95_deg[0].toFixed(1)}° – ${data.psi_ci95_deg[1].toFixed(1)}°) ` +
        `with its angular momentum explains that rate.`;
      this.el("data-text").title = `${data.citation}. doi:${data.doi}`;
      showError(this.el("psi-error"), null);
      await this.update();
    } catch (err) {
      if (!(err instanceof ApiError)) console.warn(err);
      showError(this.el("psi-error"), err);
      this.root.dataset.state = "error";
    }
  }

  /** The whole range of ψ, or close to 90° (the curve sampled every degree there, once). */
  async setView(view) {
    this.view = view;
    const missing = (VIEWS[view].psis || []).filter((psi) => !this.curve.has(psi));
    try {
      const answers = await curveAt(missing);
      for (const r of answers) this.curve.set(r.psi_deg, r.p_same_side);
      showError(this.el("psi-error"), null);
    } catch (err) {
      if (!(err instanceof ApiError)) console.warn(err);
      showError(this.el("psi-error"), err);
    }
    this.draw();
  }

  update() {
    return unlessSuperseded(this.request);
  }

  async fetchPsi(signal) {
    await showing(this.root, this.el("psi-error"), async () => {
      const r = await getJSON("api/bias", { psi: this.el("psi").value.trim() }, { signal });
      this.current = r;
      this.el("psi-p").textContent = r.p_same_side.toFixed(6);
      this.el("psi-p").dataset.value = String(r.p_same_side);
      this.el("psi-text").textContent =
        `ψ = ${fmtG(r.psi_deg)}° (${r.psi_model}): P(same side) = ${r.p_same_side.toFixed(6)}  ` +
        `(closed form, ${r.source})`;
      this.draw();
    });
  }

  draw() {
    const fit = fitCanvas(this.el("psi-canvas"));
    if (!this.curve) return;
    const view = VIEWS[this.view];
    const ax = new Axes(fit, view.x, view.y);
    const { ctx } = fit;
    ctx.save();
    ax.clip();
    if (this.data) {
      const d = this.data;
      // The flips' same-side rate (band: its 95 % interval) and the ψ that explains it.
      ctx.fillStyle = "rgba(0, 158, 115, 0.18)";
      ctx.fillRect(ax.left, ax.y(d.ci95[1]), ax.pw, Math.max(2, ax.y(d.ci95[0]) - ax.y(d.ci95[1])));
      ctx.fillRect(ax.x(d.psi_ci95_deg[0]), ax.top, ax.x(d.psi_ci95_deg[1]) - ax.x(d.psi_ci95_deg[0]), ax.ph);
      ctx.strokeStyle = COLORS.edge;
      ctx.lineWidth = 1.5;
      ctx.setLineDash([6, 4]);
      ctx.beginPath();
      ctx.moveTo(ax.left, ax.y(d.p_same_side));
      ctx.lineTo(ax.left + ax.pw, ax.y(d.p_same_side));
      ctx.moveTo(ax.x(d.psi_deg), ax.top);
      ctx.lineTo(ax.x(d.psi_deg), ax.top + ax.ph);
      ctx.stroke();
      ctx.setLineDash([]);
    }
    ctx.strokeStyle = COLORS.heads;
    ctx.lineWidth = 2.5;
    ctx.beginPath();
    const points = [...this.curve].sort((a, b) => a[0] - b[0]);
    points.forEach(([psi, p], k) => (k ? ctx.lineTo(ax.x(psi), ax.y(p)) : ctx.moveTo(ax.x(psi), ax.y(p))));
    ctx.stroke();
    if (this.current) {
      const x = ax.x(this.current.psi_deg);
      const y = ax.y(this.current.p_same_side);
      ctx.fillStyle = COLORS.momentum;
      ctx.strokeStyle = "#fff";
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(x, y, 7, 0, 2 * Math.PI);
      ctx.fill();
      ctx.stroke();
    }
    ctx.restore();
    ax.draw("ψ, degrees (angle between the normal n and the angular momentum S)", "P(same side)", {
      xticks: view.ticks,
    });
  }
}

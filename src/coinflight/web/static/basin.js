// Basin map: which face each toss of a (T, ω) box shows (/api/basin), drawn cell by cell;
// a click tosses that (T, ω) in the explorer.
import { getJSON, latest, showing, unlessSuperseded } from "./api.js";
import { fitCanvas, Axes } from "./plot2d.js";
import { COLORS } from "./explorer.js";
import { thousands } from "./format.js";

const HEADS = 1; // coinflight.core.outcome.Face (the answer's "faces" names them)
const TAILS = 0;

function rgb(hex) {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
}

/** The map of the answer: cell centres along T and ω, faces by row (spin) and column (T). */
function readBasin(r) {
  const T = r.flight_time ?? r.flight_times ?? r.T;
  const W = r.spin ?? r.omega ?? r.omega_x;
  let face = r.face ?? r.faces ?? r.grid;
  const code = (v) => (v === "heads" || v === "H" ? HEADS : v === "tails" || v === "T" ? TAILS : Number(v));
  if (typeof face[0] === "string") face = face.map((row) => Array.from(row, code));
  else face = face.map((row) => row.map(code));
  const Tr = r.flight_time_range ?? [T[0] - (T[1] - T[0]) / 2, T.at(-1) + (T[1] - T[0]) / 2];
  const Wr = r.spin_range ?? [W[0] - (W[1] - W[0]) / 2, W.at(-1) + (W[1] - W[0]) / 2];
  return { T, W, face, Tr, Wr, boundaries: r.boundaries || [], headsFraction: r.heads_fraction };
}

export class Basin {
  constructor(root, settings, explorer) {
    this.root = root;
    this.settings = settings;
    this.explorer = explorer;
    this.el = (id) => root.querySelector(`#${id}`);
    this.map = null;
    this.mark = null;
    this.request = latest((signal) => this.fetchMap(signal));
    this.el("basin-form").addEventListener("submit", (e) => {
      e.preventDefault();
      this.update();
    });
    this.el("basin-boundaries").addEventListener("change", () => this.update());
    const canvas = this.el("basin-canvas");
    canvas.addEventListener("click", (e) => this.click(e));
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  query() {
    const v = (id) => this.el(id).value.trim();
    return {
      flight_time: `${v("basin-T-lo")}:${v("basin-T-hi")}`,
      omega_x: `${v("basin-w-lo")}:${v("basin-w-hi")}`,
      omega_y: this.settings.wy(),
      omega_z: this.settings.wz(),
      resolution: v("basin-res"),
      boundaries: this.el("basin-boundaries").checked,
      coin: this.settings.coin(),
      start: this.settings.start(),
    };
  }

  update() {
    return unlessSuperseded(this.request);
  }

  async fetchMap(signal) {
    const q = this.query();
    await showing(this.root, this.el("basin-error"), async () => {
      const r = await getJSON("api/basin", q, { signal });
      this.map = readBasin(r);
      this.query_ = q;
      const cells = this.map.T.length * this.map.W.length;
      this.el("basin-summary").textContent =
        `${thousands(cells)} tosses (${this.map.T.length} flight times × ${this.map.W.length} spins, ` +
        `ωy = ${q.omega_y}, ωz = ${q.omega_z} rad/s): heads ${(100 * this.map.headsFraction).toFixed(1)} %`;
      this.draw();
    });
  }

  /** The map's axes on the canvas as it is now laid out. */
  axes() {
    const canvas = this.el("basin-canvas");
    const rect = canvas.getBoundingClientRect();
    const fontPx = parseFloat(getComputedStyle(canvas).fontSize) || 14;
    return new Axes({ w: rect.width, h: rect.height, fontPx }, this.map.Tr, this.map.Wr);
  }

  /** Where the point (T, ω) lies on the canvas, CSS pixels from its top left corner. */
  pixelOf(T, w) {
    const ax = this.axes();
    return [ax.x(T), ax.y(w)];
  }

  draw() {
    const canvas = this.el("basin-canvas");
    const fit = fitCanvas(canvas);
    if (!this.map) return;
    const { T, W, face } = this.map;
    const ax = new Axes(fit, this.map.Tr, this.map.Wr);
    // One image pixel per cell, scaled into the plotting box without smoothing.
    const image = new ImageData(T.length, W.length);
    const h = rgb(COLORS.heads);
    const t = rgb(COLORS.tails);
    const e = rgb(COLORS.edge);
    for (let j = 0; j < W.length; j++) {
      const row = W.length - 1 - j; // spin grows upwards
      for (let i = 0; i < T.length; i++) {
        const f = face[j][i];
        const c = f === HEADS ? h : f === TAILS ? t : e;
        const k = 4 * (row * T.length + i);
        image.data.set([c[0], c[1], c[2], 255], k);
      }
    }
    const off = document.createElement("canvas");
    off.width = T.length;
    off.height = W.length;
    off.getContext("2d").putImageData(image, 0, 0);
    const { ctx } = fit;
    ctx.save();
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(off, ax.left, ax.top, ax.pw, ax.ph);
    ctx.restore();
    // Keller's boundaries between heads and tails (null where a curve leaves the box).
    ctx.save();
    ax.clip();
    ctx.strokeStyle = "rgba(0, 0, 0, 0.55)";
    ctx.lineWidth = 1;
    for (const curve of this.map.boundaries) {
      ctx.beginPath();
      let pen = false;
      curve.flight_time.forEach((t, k) => {
        const w = curve.spin[k];
        if (t === null || w === null) {
          pen = false;
        } else if (pen) {
          ctx.lineTo(ax.x(t), ax.y(w));
        } else {
          ctx.moveTo(ax.x(t), ax.y(w));
          pen = true;
        }
      });
      ctx.stroke();
    }
    ctx.restore();
    ax.draw("flight time T, s", "spin ωx, rad/s");
    if (this.mark) {
      const x = ax.x(this.mark[0]);
      const y = ax.y(this.mark[1]);
      ctx.save();
      ctx.lineWidth = 3;
      ctx.strokeStyle = "#fff";
      ctx.beginPath();
      ctx.arc(x, y, 9, 0, 2 * Math.PI);
      ctx.stroke();
      ctx.lineWidth = 1.5;
      ctx.strokeStyle = "#000";
      ctx.beginPath();
      ctx.arc(x, y, 9, 0, 2 * Math.PI);
      ctx.moveTo(x - 14, y);
      ctx.lineTo(x + 14, y);
      ctx.moveTo(x, y - 14);
      ctx.lineTo(x, y + 14);
      ctx.stroke();
      ctx.restore();
    }
  }

  /** A click on the map: toss that (T, ω) in the explorer. */
  click(event) {
    if (!this.map) return;
    const rect = this.el("basin-canvas").getBoundingClientRect();
    const point = this.axes().invert(event.clientX - rect.left, event.clientY - rect.top);
    if (!point) return;
    // Round to the map's resolution: a click cannot be finer than a cell.
    const T = Number(point[0].toFixed(4));
    const w = Number(point[1].toFixed(2));
    this.mark = [T, w];
    this.draw();
    const q = this.query_;
    this.el("basin-picked").textContent = `tossed T = ${T} s, ωx = ${w} rad/s in the explorer ↑`;
    this.root.dataset.picked = JSON.stringify({ flight_time: T, omega_x: w });
    return this.explorer.tossAt({ wx: w, wy: q.omega_y, wz: q.omega_z, T });
  }
}

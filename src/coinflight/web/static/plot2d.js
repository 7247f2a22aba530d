// Plain 2-D axes on a <canvas>: scales, ticks and labels for the basin map and the p(ψ) curve.

/** Size the canvas to its CSS box at the screen's pixel density; the 2-D context in CSS pixels. */
export function fitCanvas(canvas) {
  const dpr = window.devicePixelRatio || 1;
  const rect = canvas.getBoundingClientRect();
  const w = Math.max(1, Math.round(rect.width));
  const h = Math.max(1, Math.round(rect.height));
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  const ctx = canvas.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  const style = getComputedStyle(canvas);
  return { ctx, w, h, fontPx: parseFloat(style.fontSize) || 14, family: style.fontFamily };
}

/** About `n` round tick values (1, 2 or 5 × 10^k apart) covering [lo, hi]. */
export function niceTicks(lo, hi, n = 5) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / n;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) || 10 * mag;
  const ticks = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
    ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  }
  return ticks;
}

function tickText(v, ticks) {
  const step = ticks.length > 1 ? Math.abs(ticks[1] - ticks[0]) : 1;
  const digits = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return v.toFixed(digits);
}

/** A tick mark from `from` to `to` ([x, y] pixels) and its text at `at`. */
function tick(ctx, from, to, text, at) {
  ctx.beginPath();
  ctx.moveTo(...from);
  ctx.lineTo(...to);
  ctx.stroke();
  ctx.fillText(text, ...at);
}

/** Axes in a box of the canvas: data → pixel maps, the inverse for clicks, and drawing. */
export class Axes {
  constructor(fit, xlim, ylim, { left, bottom, right = 12, top = 10 } = {}) {
    const f = fit.fontPx;
    this.fit = fit;
    this.left = left ?? Math.round(4.2 * f);
    this.bottom = bottom ?? Math.round(3.0 * f);
    this.right = right;
    this.top = top;
    this.xlim = xlim;
    this.ylim = ylim;
    this.pw = Math.max(10, fit.w - this.left - this.right);
    this.ph = Math.max(10, fit.h - this.top - this.bottom);
  }

  x(v) {
    return this.left + ((v - this.xlim[0]) / (this.xlim[1] - this.xlim[0])) * this.pw;
  }

  y(v) {
    return this.top + (1 - (v - this.ylim[0]) / (this.ylim[1] - this.ylim[0])) * this.ph;
  }

  /** Data coordinates of a pixel, or null outside the plotting box. */
  invert(px, py) {
    const u = (px - this.left) / this.pw;
    const w = 1 - (py - this.top) / this.ph;
    if (u < 0 || u > 1 || w < 0 || w > 1) return null;
    return [
      this.xlim[0] + u * (this.xlim[1] - this.xlim[0]),
      this.ylim[0] + w * (this.ylim[1] - this.ylim[0]),
    ];
  }

  /** The frame, ticks and axis labels. */
  draw(xlabel, ylabel, { xticks, yticks, xformat } = {}) {
    const { ctx, fontPx, family } = this.fit;
    const ink = "#222";
    ctx.save();
    ctx.strokeStyle = ink;
    ctx.fillStyle = ink;
    ctx.lineWidth = 1;
    ctx.strokeRect(this.left + 0.5, this.top + 0.5, this.pw, this.ph);
    ctx.font = `${Math.round(0.85 * fontPx)}px ${family}`;
    const xt = xticks || niceTicks(this.xlim[0], this.xlim[1], Math.max(3, Math.floor(this.pw / (5 * fontPx))));
    ctx.textAlign = "center";
    ctx.textBaseline = "top";
    const bottom = this.top + this.ph;
    for (const v of xt) {
      const px = this.x(v);
      tick(ctx, [px, bottom], [px, bottom + 5], xformat ? xformat(v) : tickText(v, xt), [px, bottom + 7]);
    }
    const yt = yticks || niceTicks(this.ylim[0], this.ylim[1], Math.max(3, Math.floor(this.ph / (3 * fontPx))));
    ctx.textAlign = "right";
    ctx.textBaseline = "middle";
    for (const v of yt) {
      const py = this.y(v);
      tick(ctx, [this.left, py], [this.left - 5, py], tickText(v, yt), [this.left - 7, py]);
    }
    ctx.font = `${Math.round(0.95 * fontPx)}px ${family}`;
    ctx.textAlign = "center";
    ctx.textBaseline = "bottom";
    ctx.fillText(xlabel, this.left + this.pw / 2, this.fit.h - 2);
    ctx.save();
    ctx.translate(Math.round(0.2 * fontPx), this.top + this.ph / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textBaseline = "top";
    ctx.fillText(ylabel, 0, 0);
    ctx.restore();
    ctx.restore();
  }

  /** Clip later drawing to the plotting box. */
  clip() {
    const { ctx } = this.fit;
    ctx.beginPath();
    ctx.rect(this.left, this.top, this.pw, this.ph);
    ctx.clip();
  }
}

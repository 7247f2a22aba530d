// Probability: P(heads) over ranges of spin and flight time (/api/probability), printed as
// `coinflight probability` prints it.
import { ApiError, getJSON, latest, showError } from "./api.js";
import { fmtG, probabilityLines } from "./format.js";

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
    this.syncMethod();
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
      coin: this.settings.coin(),
      start: this.settings.start(),
    };
    if (q.method === "monte-carlo") {
      q.n = v("prob-n").trim();
      q.seed = v("prob-seed").trim();
    }
    return q;
  }

  async update() {
    try {
      await this.request();
    } catch (err) {
      if (err.name !== "AbortError") throw err;
    }
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
      this.el("prob-text").textContent = probabilityLines(r).join("\n");
      showError(this.el("prob-error"), null);
      this.root.dataset.state = "ready";
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

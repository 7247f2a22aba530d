// Toss explorer: one toss from /api/toss drawn in 3-D along the closed-form attitude the server
// computes (n(t), the angular momentum S and the precession cone), with a time slider.
import * as THREE from "three";
import { OrbitControls } from "./vendor/three/addons/controls/OrbitControls.js";
import { getJSON, latest, linkSlider, showing, unlessSuperseded } from "./api.js";
import { fitCanvas, Axes } from "./plot2d.js";
import { tossLines } from "./format.js";

export const COLORS = {
  heads: "#0072B2", // Okabe & Ito blue: plotting/style.py HEADS_COLOR
  tails: "#E69F00", // orange: TAILS_COLOR
  edge: "#009E73", // bluish green: EDGE_COLOR
  normal: "#000000", // n: black
  momentum: "#D55E00", // S: vermillion
  cone: "#CC79A7", // the precession cone: reddish purple
};

const N_LENGTH = 1.9; // the arrow n and the cone's slant, in coin radii
const S_LENGTH = 2.5;

/** Samples of the attitude over [0, T]: at least 24 a turn, within the server's bound. */
function sampleCount(rotations, maxSamples) {
  const want = Math.ceil(24 * Math.max(rotations, 1)) + 1;
  return Math.max(101, Math.min(maxSamples, want));
}

/**
 * The flight of the answer (`trajectory=K` of /api/toss, coinflight.queries.toss.trajectory):
 * times t, the heads normal n(t), the attitude quaternions [x, y, z, w] (body → lab, the body z
 * axis is n), heights, and the unit angular momentum S ("axis"), all in the lab frame, z up.
 */
function readTrajectory(r) {
  const tr = r.trajectory;
  if (!tr) throw new Error("the server sent no trajectory");
  return { time: tr.t, normal: tr.normal, quaternion: tr.quaternion, height: tr.height, S: tr.axis };
}

/** A text label that always faces the camera (the arrows' n and S). */
function makeLabel(text, color) {
  const canvas = document.createElement("canvas");
  canvas.width = 128;
  canvas.height = 128;
  const ctx = canvas.getContext("2d");
  ctx.font = "italic bold 96px serif";
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.lineWidth = 10;
  ctx.strokeStyle = "rgba(255, 255, 255, 0.9)";
  ctx.strokeText(text, 64, 64);
  ctx.fillStyle = color;
  ctx.fillText(text, 64, 64);
  const map = new THREE.CanvasTexture(canvas);
  map.colorSpace = THREE.SRGBColorSpace;
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map, depthTest: false }));
  sprite.scale.set(0.55, 0.55, 1);
  sprite.renderOrder = 10;
  return sprite;
}

function makeArrow(color, length, radius) {
  const group = new THREE.Group();
  const material = new THREE.MeshLambertMaterial({ color });
  const head = 0.28 * length > 0.45 ? 0.45 : 0.28 * length;
  const shaft = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length - head, 16), material);
  shaft.position.y = (length - head) / 2;
  const tip = new THREE.Mesh(new THREE.ConeGeometry(2.6 * radius, head, 24), material);
  tip.position.y = length - head / 2;
  group.add(shaft, tip);
  return group;
}

const Y = new THREE.Vector3(0, 1, 0);

/** A face of the coin: its colour and its letter, so the face reads without colour too, and
 * the letter turning shows the spin about the normal. */
function faceTexture(color, letter) {
  const size = 256;
  const canvas = document.createElement("canvas");
  canvas.width = size;
  canvas.height = size;
  const ctx = canvas.getContext("2d");
  ctx.fillStyle = color;
  ctx.fillRect(0, 0, size, size);
  ctx.strokeStyle = "rgba(255, 255, 255, 0.7)";
  ctx.lineWidth = 8;
  ctx.beginPath();
  ctx.arc(size / 2, size / 2, size * 0.42, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.fillStyle = "#ffffff";
  ctx.font = `bold ${Math.round(size * 0.5)}px sans-serif`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.fillText(letter, size / 2, size / 2 + size * 0.02);
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  return texture;
}

export class Explorer {
  constructor(root, settings) {
    this.root = root;
    this.settings = settings;
    this.el = (id) => root.querySelector(`#${id}`);
    this.result = null;
    this.traj = null;
    this.t = 0;
    this.playing = false;
    this.maxSamples = 2000; // MAX_TRAJECTORY of coinflight.queries.toss
    this.sceneOK = this.buildScene();
    this.bindControls();
    this.request = latest((signal) => this.fetchToss(signal));
  }

  // ---------------------------------------------------------------- the 3-D scene
  buildScene() {
    const canvas = this.el("scene-canvas");
    try {
      this.renderer = new THREE.WebGLRenderer({
        canvas,
        antialias: true,
        preserveDrawingBuffer: true,
      });
    } catch {
      this.el("scene-fallback").hidden = false;
      return false;
    }
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color("#f8f8f5");
    this.scene = scene;
    const camera = new THREE.PerspectiveCamera(32, 1, 0.1, 100);
    camera.up.set(0, 0, 1);
    camera.position.set(4.0, -7.2, 5.4); // from above: a coin tilted up shows its top face
    camera.lookAt(0, 0, 0);
    this.camera = camera;
    this.controls = new OrbitControls(camera, canvas);
    this.controls.enablePan = false;
    this.controls.minDistance = 4;
    this.controls.maxDistance = 30;
    this.controls.addEventListener("change", () => this.render());

    scene.add(new THREE.AmbientLight(0xffffff, 1.4));
    const sun = new THREE.DirectionalLight(0xffffff, 2.0);
    sun.position.set(3, -4, 8);
    scene.add(sun);

    // The horizontal: a grid below the coin (the hand's plane), z up.
    const grid = new THREE.GridHelper(6, 12, 0xb0b0b0, 0xd8d8d8);
    grid.rotation.x = Math.PI / 2;
    grid.position.z = -1.6;
    scene.add(grid);

    // The coin: a cylinder of radius 1 (thickness to scale); its +z face heads (blue, H), as the
    // body frame of the quaternions.
    this.coin = new THREE.Group();
    this.coinMesh = new THREE.Mesh(new THREE.CylinderGeometry(1, 1, 0.144, 96).rotateX(Math.PI / 2), [
      new THREE.MeshLambertMaterial({ color: "#9a9a9a" }),
      new THREE.MeshLambertMaterial({ map: faceTexture(COLORS.heads, "H") }),
      new THREE.MeshLambertMaterial({ map: faceTexture(COLORS.tails, "T") }),
    ]);
    this.coin.add(this.coinMesh);
    scene.add(this.coin);

    this.nArrow = makeArrow(COLORS.normal, N_LENGTH, 0.035);
    this.sArrow = makeArrow(COLORS.momentum, S_LENGTH, 0.045);
    this.nLabel = makeLabel("n", COLORS.normal);
    this.sLabel = makeLabel("S", COLORS.momentum);
    scene.add(this.nArrow, this.sArrow, this.nLabel, this.sLabel);

    this.cone = new THREE.Mesh(
      new THREE.BufferGeometry(),
      new THREE.MeshBasicMaterial({
        color: COLORS.cone,
        transparent: true,
        opacity: 0.22,
        side: THREE.DoubleSide,
        depthWrite: false,
      }),
    );
    this.rim = new THREE.LineLoop(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: COLORS.cone }),
    );
    scene.add(this.cone, this.rim);

    this.trail = new THREE.Line(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: COLORS.normal, transparent: true, opacity: 0.55 }),
    );
    scene.add(this.trail);

    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
    return true;
  }

  resize() {
    if (!this.renderer) return;
    const canvas = this.renderer.domElement;
    const w = canvas.clientWidth || 1;
    const h = canvas.clientHeight || 1;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
    this.drawHeight();
  }

  /** The cone n sweeps about S: apex at the coin's centre, half-angle ψ, slant N_LENGTH. */
  setCone(S, psi) {
    const s = new THREE.Vector3(...S);
    const u = new THREE.Vector3(1, 0, 0).cross(s);
    if (u.lengthSq() < 1e-6) u.set(0, 1, 0).cross(s);
    u.normalize();
    const v = new THREE.Vector3().crossVectors(s, u);
    const centre = s.clone().multiplyScalar(N_LENGTH * Math.cos(psi));
    const radius = N_LENGTH * Math.sin(psi);
    const segments = 96;
    const fan = [0, 0, 0];
    const ring = [];
    for (let k = 0; k <= segments; k++) {
      const a = (2 * Math.PI * k) / segments;
      const p = centre
        .clone()
        .addScaledVector(u, radius * Math.cos(a))
        .addScaledVector(v, radius * Math.sin(a));
      fan.push(p.x, p.y, p.z);
      if (k < segments) ring.push(p.x, p.y, p.z);
    }
    const index = [];
    for (let k = 1; k <= segments; k++) index.push(0, k, k + 1);
    const cone = new THREE.BufferGeometry();
    cone.setAttribute("position", new THREE.Float32BufferAttribute(fan, 3));
    cone.setIndex(index);
    this.cone.geometry.dispose();
    this.cone.geometry = cone;
    const rim = new THREE.BufferGeometry();
    rim.setAttribute("position", new THREE.Float32BufferAttribute(ring, 3));
    this.rim.geometry.dispose();
    this.rim.geometry = rim;
    this.sArrow.quaternion.setFromUnitVectors(Y, s);
    this.sLabel.position.copy(s).multiplyScalar(S_LENGTH + 0.3);
  }

  setTrail(normals) {
    const pts = [];
    for (const n of normals) pts.push(N_LENGTH * n[0], N_LENGTH * n[1], N_LENGTH * n[2]);
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(pts, 3));
    this.trail.geometry.dispose();
    this.trail.geometry = g;
  }

  /** n at time t: the sample, or the normalised blend of the two samples around t. */
  normalAt(t) {
    const { time, normal } = this.traj;
    const last = time.length - 1;
    if (t <= time[0]) return [...normal[0]];
    if (t >= time[last]) return [...normal[last]];
    let lo = 0;
    let hi = last;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (time[mid] <= t) lo = mid;
      else hi = mid;
    }
    const w = (t - time[lo]) / (time[hi] - time[lo]);
    const n = normal[lo].map((a, i) => (1 - w) * a + w * normal[hi][i]);
    const len = Math.hypot(...n);
    return n.map((a) => a / len);
  }

  /** The attitude at time t: the sample, or the spherical blend of the two around t. */
  attitudeAt(t, out) {
    const { time, quaternion } = this.traj;
    const last = time.length - 1;
    const k = Math.min(last - 1, Math.max(0, Math.floor((t / time[last]) * last)));
    const w = Math.min(1, Math.max(0, (t - time[k]) / (time[k + 1] - time[k])));
    const a = new THREE.Quaternion(...quaternion[k]);
    const b = new THREE.Quaternion(...quaternion[k + 1]);
    return out.slerpQuaternions(a, b, w);
  }

  heightAt(t) {
    const { time, height } = this.traj;
    const last = time.length - 1;
    if (t <= time[0]) return height[0];
    if (t >= time[last]) return height[last];
    const k = Math.min(last - 1, Math.floor((t / time[last]) * last));
    const w = (t - time[k]) / (time[k + 1] - time[k]);
    return (1 - w) * height[k] + w * height[k + 1];
  }

  render() {
    if (!this.renderer) return;
    this.renderer.render(this.scene, this.camera);
  }

  /** Put the coin at time t: attitude, arrows, trail, read-outs. */
  show(t) {
    if (!this.traj) return;
    const T = this.result.flight_time;
    this.t = Math.min(Math.max(t, 0), T);
    const n = this.normalAt(this.t);
    const up = n[2] > 0 ? "heads" : n[2] < 0 ? "tails" : "edge";
    const nv = new THREE.Vector3(...n);
    if (this.renderer) {
      this.attitudeAt(this.t, this.coin.quaternion);
      this.nArrow.quaternion.setFromUnitVectors(Y, nv);
      this.nLabel.position.copy(nv).multiplyScalar(N_LENGTH + 0.3);
      const { time } = this.traj;
      const k = Math.round((this.t / T) * (time.length - 1));
      this.trail.geometry.setDrawRange(0, k + 1);
      this.render();
    }
    const slider = this.el("time");
    slider.value = String(Math.round((this.t / T) * Number(slider.max)));
    this.el("time-readout").textContent = `t = ${this.t.toFixed(3)} s of T = ${T.toFixed(3)} s`;
    this.el("height-readout").textContent = `height ${this.heightAt(this.t).toFixed(3)} m`;
    const faceNow = this.el("face-now");
    faceNow.textContent = up.toUpperCase();
    faceNow.dataset.face = up;
    this.el("scene").dataset.faceUp = up;
    this.drawHeight();
  }

  /** Height against time, with the face up at each instant as a coloured strip. */
  drawHeight() {
    const canvas = this.el("height-canvas");
    const fit = fitCanvas(canvas);
    if (!this.traj) return;
    const { time, height, normal } = this.traj;
    const T = this.result.flight_time;
    const top = Math.max(...height) * 1.08 || 1;
    const f = fit.fontPx;
    const ax = new Axes(fit, [0, T], [0, top], { left: Math.round(3.4 * f), bottom: Math.round(2.8 * f), top: 8 });
    const { ctx } = fit;
    // The face up along the flight, as a strip under the curve.
    const strip = Math.max(6, Math.round(0.45 * f));
    for (let k = 0; k < time.length - 1; k++) {
      const nz = 0.5 * (normal[k][2] + normal[k + 1][2]);
      ctx.fillStyle = nz >= 0 ? COLORS.heads : COLORS.tails;
      const x0 = ax.x(time[k]);
      ctx.fillRect(x0, ax.y(0) - strip, ax.x(time[k + 1]) - x0 + 0.5, strip);
    }
    ctx.strokeStyle = "#222";
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    time.forEach((t, k) => (k ? ctx.lineTo(ax.x(t), ax.y(height[k])) : ctx.moveTo(ax.x(t), ax.y(height[k]))));
    ctx.stroke();
    ax.draw("time t, s", "height, m");
    const x = ax.x(this.t);
    ctx.strokeStyle = COLORS.momentum;
    ctx.setLineDash([4, 3]);
    ctx.beginPath();
    ctx.moveTo(x, ax.y(top));
    ctx.lineTo(x, ax.y(0));
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = "#222";
    ctx.beginPath();
    ctx.arc(x, ax.y(this.heightAt(this.t)), 5, 0, 2 * Math.PI);
    ctx.fill();
  }

  // ---------------------------------------------------------------- the controls
  bindControls() {
    // Each slider has a number box: either one sets the other, then the toss is asked again.
    for (const name of ["wx", "wy", "wz", "T", "v0"]) {
      linkSlider(this.el(`${name}-range`), this.el(name), () => this.changed());
    }
    for (const radio of this.root.querySelectorAll("input[name=by]")) {
      radio.addEventListener("change", () => {
        this.syncBy();
        this.changed();
      });
    }
    this.syncBy();
    this.el("time").addEventListener("input", (e) => {
      this.pause();
      if (this.result) this.show((Number(e.target.value) / Number(e.target.max)) * this.result.flight_time);
    });
    this.el("play").addEventListener("click", () => (this.playing ? this.pause() : this.play()));
  }

  syncBy() {
    const byT = this.root.querySelector("input[name=by]:checked").value === "T";
    this.el("by-T").hidden = !byT;
    this.el("by-v0").hidden = byT;
  }

  changed() {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.update(), 120);
  }

  /** The query of the current controls, as /api/toss takes it. */
  query() {
    const byT = this.root.querySelector("input[name=by]:checked").value === "T";
    const q = {
      omega: [this.el("wx").value, this.el("wy").value, this.el("wz").value].map((s) => s.trim()).join(","),
      coin: this.settings.coin(),
      start: this.settings.start(),
    };
    if (byT) q.flight_time = this.el("T").value.trim();
    else q.launch_speed = this.el("v0").value.trim();
    return q;
  }

  /** Set the spin and flight time (from a basin click) and toss. */
  tossAt({ wx, wy, wz, T }) {
    const set = (name, value) => {
      this.el(name).value = value;
      this.el(`${name}-range`).value = value;
    };
    set("wx", wx);
    set("wy", wy);
    set("wz", wz);
    set("T", T);
    this.root.querySelector("input[name=by][value=T]").checked = true;
    this.syncBy();
    return this.update();
  }

  update() {
    return unlessSuperseded(this.request);
  }

  async fetchToss(signal) {
    const q = this.query();
    await showing(this.root, this.el("toss-error"), async () => {
      // First the answer itself (as `coinflight toss --json`), then its attitude finely enough.
      let r = await getJSON("api/toss", { ...q, trajectory: 101 }, { signal });
      const k = sampleCount(r.rotations, this.maxSamples);
      if (k > 101) r = await getJSON("api/toss", { ...q, trajectory: k }, { signal });
      this.setResult(r);
    });
  }

  setResult(r) {
    this.pause();
    this.result = r;
    this.traj = readTrajectory(r);
    const out = this.el("toss-result");
    out.dataset.outcome = r.outcome;
    out.dataset.rotations = String(r.rotations);
    out.dataset.flightTime = String(r.flight_time);
    const face = this.el("toss-face");
    face.textContent = r.outcome.toUpperCase();
    face.dataset.face = r.outcome;
    this.el("toss-rotations").textContent = r.rotations.toFixed(4);
    // As `coinflight toss` says it: rotations about a diameter, or turns of n about S.
    const flip = Math.abs(r.psi_deg - 90) < 1e-9;
    this.el("toss-turns").textContent = flip ? "rotations" : "turns of n about S";
    this.el("toss-psi").textContent = `${r.psi_deg.toFixed(1)}°`;
    this.el("toss-text").textContent = tossLines(r).join("\n");
    // Too fast to draw: fewer than 8 samples a turn and the blend between samples would turn
    // the coin the short way round (a stroboscope). Say so; the face and the numbers stay exact.
    const samples = this.traj.time.length;
    const perTurn = (samples - 1) / Math.max(r.rotations, 1e-12);
    const note = this.el("sample-note");
    note.hidden = perTurn >= 8;
    note.textContent =
      `${r.rotations.toFixed(1)} turns drawn from ${samples} instants: too fast to follow every ` +
      "turn (the motion shown between instants is not the coin's); the face and counts are exact.";
    if (this.renderer) {
      this.coinMesh.scale.z = r.coin.thickness / r.coin.radius / 0.144;
      this.setCone(this.traj.S, r.psi);
      this.setTrail(this.traj.normal);
    }
    this.show(r.flight_time);
  }

  play() {
    if (!this.result) return;
    const T = this.result.flight_time;
    if (this.t >= T) this.t = 0;
    this.playing = true;
    const button = this.el("play");
    button.textContent = "❚❚ pause";
    button.setAttribute("aria-pressed", "true");
    let last = performance.now();
    const step = (now) => {
      if (!this.playing) return;
      const speed = Number(this.el("speed").value);
      const t = this.t + ((now - last) / 1000) * speed;
      last = now;
      if (t >= T) {
        this.show(T);
        this.pause();
        return;
      }
      this.show(t);
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }

  pause() {
    this.playing = false;
    const button = this.el("play");
    button.textContent = "▶ play";
    button.setAttribute("aria-pressed", "false");
  }
}

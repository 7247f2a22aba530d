// The page: shared settings (coin, start face) and the four panels.
import { Explorer } from "./explorer.js";
import { Basin } from "./basin.js";
import { Probability } from "./probability.js";
import { SameSide } from "./sameside.js";

const $ = (id) => document.getElementById(id);

const settings = {
  coin: () => $("coin").value,
  start: () => $("start").value,
  wy: () => $("wy").value.trim(),
  wz: () => $("wz").value.trim(),
};

const explorer = new Explorer($("explorer"), settings);
const basin = new Basin($("basin"), settings, explorer);
const probability = new Probability($("probability"), settings);
const sameSide = new SameSide($("same-side"));

for (const id of ["coin", "start"]) {
  $(id).addEventListener("change", () => {
    explorer.update();
    basin.update();
    probability.update();
  });
}

// The map is drawn for the explorer's ωy and ωz: redraw it when they settle.
let redraw = null;
for (const id of ["wy", "wz", "wy-range", "wz-range"]) {
  $(id).addEventListener("input", () => {
    clearTimeout(redraw);
    redraw = setTimeout(() => basin.update(), 400);
  });
}

// The tests and curious students can reach the panels from the console.
window.coinflight = { explorer, basin, probability, sameSide };

await Promise.all([
  explorer.update(),
  basin.update(),
  probability.update(),
  probability.surfaces, // the surface menu, from the server's registry
  sameSide.load(),
]);
document.body.dataset.ready = "true";

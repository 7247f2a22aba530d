// The JSON API behind the page: one GET per question, the same answers as `coinflight … --json`.

/** An answer the server refused (HTTP 4xx/5xx): `message` is its one line. */
export class ApiError extends Error {
  constructor(message, status) {
    super(message);
    this.name = "ApiError";
    this.status = status;
  }
}

/** The one line a refusal carries, whatever the envelope (`detail` as text or FastAPI's list). */
function refusal(body, status) {
  if (body && typeof body === "object") {
    const d = body.detail ?? body.error ?? body.message;
    if (typeof d === "string") return d;
    if (Array.isArray(d) && d.length) {
      return d.map((e) => (typeof e === "string" ? e : e.msg || JSON.stringify(e))).join("; ");
    }
  }
  return `the server answered HTTP ${status}`;
}

/**
 * Integers beyond 2^53 (a seed drawn by the server is up to 128 bits) kept as their exact digits:
 * a JavaScript number would round them, and the seed sent back would be another one.
 */
function exactIntegers(key, value, context) {
  if (typeof value === "number" && !Number.isSafeInteger(value) && context?.source) {
    if (/^-?\d+$/.test(context.source)) return context.source;
  }
  return value;
}

/** GET `path` with query `params` (null and "" left out); the decoded JSON or an ApiError. */
export async function getJSON(path, params = {}, { signal } = {}) {
  const query = new URLSearchParams();
  for (const [key, value] of Object.entries(params)) {
    if (value !== null && value !== undefined && value !== "") query.set(key, String(value));
  }
  const url = query.toString() ? `${path}?${query}` : path;
  let response;
  try {
    response = await fetch(url, { signal, headers: { Accept: "application/json" } });
  } catch (err) {
    if (err.name === "AbortError") throw err;
    throw new ApiError("the coinflight server does not answer (is `coinflight serve` running?)", 0);
  }
  let body = null;
  try {
    body = JSON.parse(await response.text(), exactIntegers);
  } catch (err) {
    if (err.name === "AbortError") throw err;
    body = null;
  }
  if (!response.ok) throw new ApiError(refusal(body, response.status), response.status);
  return body;
}

/**
 * Run `task` (given an AbortSignal) at most once at a time: a newer call cancels the older one,
 * so a slider dragged fast shows the answer for where it stopped, never an older one.
 */
export function latest(task) {
  let controller = null;
  return async (...args) => {
    if (controller) controller.abort();
    const mine = new AbortController();
    controller = mine;
    try {
      return await task(mine.signal, ...args);
    } finally {
      if (controller === mine) controller = null;
    }
  };
}

/**
 * Await `request()`, a `latest` task: its cancellation by a newer call (an AbortError) is not an
 * error, any other failure is. Each panel's `update()`.
 */
export async function unlessSuperseded(request) {
  try {
    await request();
  } catch (err) {
    if (err.name !== "AbortError") throw err;
  }
}

/** Show `err` in the panel's error line (or clear it when `err` is null). */
export function showError(element, err) {
  if (!err) {
    element.textContent = "";
    element.hidden = true;
    return;
  }
  element.textContent = err instanceof ApiError ? err.message : `error: ${err.message || err}`;
  element.hidden = false;
}

/** Call `fn` once `ms` milliseconds have passed without another call. */
export function debounce(fn, ms) {
  let timer = null;
  return (...args) => {
    clearTimeout(timer);
    timer = setTimeout(() => fn(...args), ms);
  };
}

/** A slider and its number box kept together: moving either sets the other, then `changed()`
 * (a box's text that is not a finite number leaves the slider where it is). */
export function linkSlider(range, box, changed) {
  range.addEventListener("input", () => {
    box.value = range.value;
    changed();
  });
  box.addEventListener("input", () => {
    if (box.value !== "" && Number.isFinite(Number(box.value))) range.value = box.value;
    changed();
  });
}

/** Run `work()` (a panel's requests and drawing) with the panel's `data-state` "loading", then
 * "ready", or "error" with the message shown in `errorElement`; an abort (a newer request) is
 * passed on. */
export async function showing(root, errorElement, work) {
  root.dataset.state = "loading";
  try {
    await work();
    showError(errorElement, null);
    root.dataset.state = "ready";
  } catch (err) {
    if (err.name === "AbortError") throw err;
    if (!(err instanceof ApiError)) console.warn(err);
    showError(errorElement, err);
    root.dataset.state = "error";
  }
}

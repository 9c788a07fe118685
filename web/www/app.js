// gjk2d in the browser. Plain JS, no build step: loads gjk2d.wasm (the web
// crate, a plain C ABI), writes the scene into wasm memory, runs the queries
// and draws what they return.
//
// World coordinates: y up, a view of about 18 x 10 units centered on the
// origin. Shapes are placed as in the crate: world = R(angle) local + position.

const KIND = {
  circle: 1, polygon: 2, rectangle: 3, triangle: 4, segment: 5,
  capsule: 6, ellipse: 7, halfEllipse: 8, slice: 9, rounded: 10,
};
const KIND_LABEL = {
  1: "circle", 2: "polygon", 3: "rectangle", 4: "triangle", 5: "segment",
  6: "capsule", 7: "ellipse", 8: "half-ellipse", 9: "slice", 10: "rounded",
};
const STATUS = ["converged", "iteration limit", "capacity limit"];

// ---------------------------------------------------------------- the scene

function hexagon() {
  const pts = [];
  const radii = [1.05, 0.9, 1.1, 0.95, 1.0, 0.85];
  for (let i = 0; i < 6; i++) {
    const t = (i / 6) * Math.PI * 2 + 0.2;
    pts.push([radii[i] * Math.cos(t), radii[i] * Math.sin(t)]);
  }
  return pts;
}

function pentagon(r) {
  const pts = [];
  for (let i = 0; i < 5; i++) {
    const t = (i / 5) * Math.PI * 2 + Math.PI / 2;
    pts.push([r * Math.cos(t), r * Math.sin(t)]);
  }
  return pts;
}

function initialShapes() {
  return [
    { kind: KIND.circle, x: -6.9, y: 2.3, angle: 0, radius: 0.95 },
    { kind: KIND.polygon, x: -3.3, y: 2.1, angle: 0.1, vertices: hexagon() },
    { kind: KIND.rectangle, x: 0.1, y: 2.5, angle: 0.35, width: 2.2, height: 1.2 },
    { kind: KIND.triangle, x: 3.5, y: 2.2, angle: -0.2, vertices: [[-1.1, -0.8], [1.2, -0.6], [-0.1, 1.1]] },
    { kind: KIND.segment, x: 7.0, y: 2.3, angle: 0.9, a: [-1.2, 0], b: [1.2, 0] },
    { kind: KIND.capsule, x: -6.9, y: -1.8, angle: -0.5, width: 2.6, height: 1.0 },
    { kind: KIND.ellipse, x: -3.3, y: -1.7, angle: 0.3, width: 2.4, height: 1.4 },
    { kind: KIND.halfEllipse, x: 0.1, y: -2.3, angle: 0, width: 2.4, height: 1.3 },
    { kind: KIND.slice, x: 3.0, y: -1.7, angle: 0.15, radius: 1.5, theta: 1.7 },
    { kind: KIND.rounded, x: 7.0, y: -1.8, angle: 0.2, vertices: pentagon(0.8), rounding: 0.3 },
  ];
}

// A's motion for the shape cast, relative to its position.
function initialMotion() {
  return [2.4, -1.3];
}

function initialRay() {
  return { o: [-8.6, -4.6], e: [-5.6, -3.3] };
}

const state = {
  shapes: initialShapes(),
  ray: initialRay(),
  motion: initialMotion(),
  prec: "f32",
  a: 1,          // index of shape A
  b: -1,         // index of shape B; -1: the nearest shape to A
  bNow: 0,       // B actually queried
  results: null,
  timing: null,
  dirty: true,
};

// The 24-f64 record of the web crate (web/src/lib.rs).
const STRIDE = 24;
function record(s) {
  const r = new Array(STRIDE).fill(0);
  r[0] = s.kind; r[1] = s.x; r[2] = s.y; r[3] = s.angle;
  const p = (k, v) => { r[4 + k] = v; };
  switch (s.kind) {
    case KIND.circle: p(0, s.radius); break;
    case KIND.polygon:
    case KIND.rounded:
      p(0, s.vertices.length);
      s.vertices.forEach(([x, y], k) => { p(1 + 2 * k, x); p(2 + 2 * k, y); });
      if (s.kind === KIND.rounded) p(17, s.rounding);
      break;
    case KIND.rectangle: case KIND.capsule: case KIND.ellipse: case KIND.halfEllipse:
      p(0, s.width); p(1, s.height); break;
    case KIND.triangle: s.vertices.forEach(([x, y], k) => { p(2 * k, x); p(2 * k + 1, y); }); break;
    case KIND.segment: p(0, s.a[0]); p(1, s.a[1]); p(2, s.b[0]); p(3, s.b[1]); break;
    case KIND.slice: p(0, s.radius); p(1, s.theta); break;
  }
  return r;
}

// Outline in local coordinates, for drawing and picking (the queries use
// the crate's exact shapes, not these samples).
function arc(out, cx, cy, rx, ry, t0, t1, n) {
  for (let i = 0; i <= n; i++) {
    const t = t0 + ((t1 - t0) * i) / n;
    out.push([cx + rx * Math.cos(t), cy + ry * Math.sin(t)]);
  }
  return out;
}

function ccw(pts) {
  let a = 0;
  for (let i = 0; i < pts.length; i++) {
    const [x0, y0] = pts[i], [x1, y1] = pts[(i + 1) % pts.length];
    a += x0 * y1 - x1 * y0;
  }
  return a >= 0 ? pts : pts.slice().reverse();
}

function outline(s) {
  const N = 96;
  switch (s.kind) {
    case KIND.circle: return arc([], 0, 0, s.radius, s.radius, 0, 2 * Math.PI, N).slice(0, -1);
    case KIND.polygon: case KIND.triangle: return ccw(s.vertices);
    case KIND.rectangle: {
      const w = s.width / 2, h = s.height / 2;
      return [[-w, -h], [w, -h], [w, h], [-w, h]];
    }
    case KIND.segment: return [s.a, s.b];
    case KIND.capsule: {
      const along = s.width >= s.height;
      const r = Math.min(s.width, s.height) / 2;
      const c = Math.max((Math.max(s.width, s.height) - Math.min(s.width, s.height)) / 2, 0);
      const out = [];
      if (along) {
        arc(out, c, 0, r, r, -Math.PI / 2, Math.PI / 2, N / 2);
        arc(out, -c, 0, r, r, Math.PI / 2, 1.5 * Math.PI, N / 2);
      } else {
        arc(out, 0, c, r, r, 0, Math.PI, N / 2);
        arc(out, 0, -c, r, r, Math.PI, 2 * Math.PI, N / 2);
      }
      return out;
    }
    case KIND.ellipse: return arc([], 0, 0, s.width / 2, s.height / 2, 0, 2 * Math.PI, N).slice(0, -1);
    case KIND.halfEllipse: return arc([], 0, 0, s.width / 2, s.height, 0, Math.PI, N);
    case KIND.slice: return [[0, 0], ...arc([], 0, 0, s.radius, s.radius, -s.theta / 2, s.theta / 2, N / 2)];
    case KIND.rounded: {
      const v = ccw(s.vertices), n = v.length, r = s.rounding, out = [];
      const normal = (p, q) => {
        const dx = q[0] - p[0], dy = q[1] - p[1], l = Math.hypot(dx, dy);
        return Math.atan2(-dx / l, dy / l);
      };
      for (let i = 0; i < n; i++) {
        const prev = v[(i + n - 1) % n], cur = v[i], next = v[(i + 1) % n];
        let t0 = normal(prev, cur), t1 = normal(cur, next);
        while (t1 < t0) t1 += 2 * Math.PI;
        arc(out, cur[0], cur[1], r, r, t0, t1, 12);
      }
      return out;
    }
  }
  return [];
}

function toWorld(s, p) {
  const c = Math.cos(s.angle), sn = Math.sin(s.angle);
  return [c * p[0] - sn * p[1] + s.x, sn * p[0] + c * p[1] + s.y];
}

function worldOutline(s) { return outline(s).map((p) => toWorld(s, p)); }

function boundingRadius(s) {
  let r = 0;
  for (const [x, y] of outline(s)) r = Math.max(r, Math.hypot(x, y));
  return r;
}

// ----------------------------------------------------------------- the wasm

let wasm = null;
let mem = null;
let moduleBytes = 0;

async function loadWasm() {
  const resp = await fetch("gjk2d.wasm");
  if (!resp.ok) throw new Error(`gjk2d.wasm: HTTP ${resp.status} (run web/build.sh)`);
  const bytes = await resp.arrayBuffer();
  moduleBytes = bytes.byteLength;
  const { instance } = await WebAssembly.instantiate(bytes, {});
  wasm = instance.exports;
}

function f64view(ptr, len) { return new Float64Array(wasm.memory.buffer, ptr, len); }

function build() {
  const scene = f64view(wasm.scene_ptr(), wasm.max_shapes() * STRIDE);
  state.shapes.forEach((s, i) => scene.set(record(s), i * STRIDE));
  const failed = wasm.build(state.shapes.length);
  if (failed) console.warn("shapes rejected by the crate:", failed.toString(2));
  mem = f64view(wasm.out_ptr(), 16);
}

function q(name) { return wasm[name + (state.prec === "f32" ? "32" : "64")]; }
function out(n) { return Array.from(mem.subarray(0, n)); }

// Ray cast at every shape: the first shape the ray starts inside, else the
// nearest hit (ties to the lower index). examples/web_expected.rs does the same.
function castRay() {
  const [ox, oy] = state.ray.o;
  const dx = state.ray.e[0] - ox, dy = state.ray.e[1] - oy;
  const cast = q("raycast");
  let best = null;
  for (let i = 0; i < state.shapes.length; i++) {
    const code = cast(i, ox, oy, dx, dy, 0);
    if (code === 2) { best = { shape: i, code, v: out(7) }; break; }
    if (code === 1) {
      const v = out(7);
      if (!best || v[0] < best.v[0]) best = { shape: i, code, v };
    }
  }
  return best;
}

// A moving by its motion, cast against every other shape: the first shape
// A touches or overlaps at the start (lowest index), else the earliest hit
// (ties to the lower index). examples/web_expected.rs does the same.
function castMotion() {
  const [mx, my] = state.motion;
  const cast = q("cast");
  let best = null;
  for (let k = 0; k < state.shapes.length; k++) {
    if (k === state.a) continue;
    const code = cast(k, state.a, mx, my);
    if (code === 2) { best = { shape: k, code, v: out(6) }; break; }
    if (code === 1) {
      const v = out(11);
      if (!best || v[0] < best.v[0]) best = { shape: k, code, v };
    }
  }
  return best;
}

// The contact manifold's speculative margin (examples/web_expected.rs has it too).
const MANIFOLD_MARGIN = 0.25;

function pairQueries(i, j) {
  const count = q("manifold")(i, j, MANIFOLD_MARGIN);
  const manifold = count >= 0 ? out(4 + 5 * count) : null;
  const hit = q("intersects")(i, j);
  const det = out(3);
  const pen = q("penetration")(i, j) === 1 ? out(6) : null;
  const dist = q("distance")(i, j) === 1 ? out(10) : null;
  return { hit: hit === 1, det, pen, dist, manifold };
}

function nearestTo(a) {
  let best = -1, score = Infinity;
  for (let j = 0; j < state.shapes.length; j++) {
    if (j === a) continue;
    let s;
    if (q("penetration")(a, j) === 1) s = -mem[2];
    else if (q("distance")(a, j) === 1) s = mem[0];
    else s = 0;
    if (s < score) { score = s; best = j; }
  }
  return best;
}

function update() {
  if (!wasm) return;
  build();
  state.bNow = state.b >= 0 && state.b !== state.a ? state.b : nearestTo(state.a);
  const pair = pairQueries(state.a, state.bNow);
  const overlaps = new Set();
  for (let i = 0; i < state.shapes.length; i++) {
    for (let j = i + 1; j < state.shapes.length; j++) {
      if (q("intersects")(i, j) === 1) { overlaps.add(i); overlaps.add(j); }
    }
  }
  state.results = { ...pair, ray: castRay(), cast: castMotion(), overlaps };
  state.dirty = false;
  renderReadouts();
  exportScene();
  scheduleTiming();
}

// One query's time: the median of three runs, each a loop of calls that
// lasts at least 3 ms (performance.now() may tick in 0.1 ms steps).
function timeIt(fn) {
  const runs = [];
  for (let r = 0; r < 3; r++) {
    let n = 0, dt = 0;
    const t0 = performance.now();
    do {
      for (let k = 0; k < 32; k++) fn();
      n += 32;
      dt = performance.now() - t0;
    } while (dt < 3);
    runs.push(dt / n);
  }
  runs.sort((x, y) => x - y);
  return runs[1] * 1e6; // ns
}

let timingTimer = 0;
let lastTiming = 0;
function scheduleTiming() {
  clearTimeout(timingTimer);
  const since = performance.now() - lastTiming;
  timingTimer = setTimeout(runTiming, since > 600 ? 60 : 250);
}

let warmedUp = false;
function runTiming() {
  if (!wasm) return;
  build();
  if (!warmedUp) {
    // Let the engine tier the module up before the first measurement.
    const t0 = performance.now();
    while (performance.now() - t0 < 150) {
      for (let i = 0; i < state.shapes.length; i++) {
        q("intersects")(i, (i + 1) % state.shapes.length);
        q("penetration")(i, (i + 3) % state.shapes.length);
        q("distance")(i, (i + 5) % state.shapes.length);
        q("raycast")(i, -9, -5, 1, 0.6, 0);
      }
    }
    warmedUp = true;
  }
  const a = state.a, b = state.bNow;
  const [ox, oy] = state.ray.o;
  const dx = state.ray.e[0] - ox, dy = state.ray.e[1] - oy;
  const target = state.results.ray ? state.results.ray.shape : a;
  const fi = q("intersects"), fp = q("penetration"), fd = q("distance"), fr = q("raycast");
  state.timing = {
    intersects: timeIt(() => fi(a, b)),
    penetration: timeIt(() => fp(a, b)),
    distance: timeIt(() => fd(a, b)),
    raycast: timeIt(() => fr(target, ox, oy, dx, dy, 0)),
  };
  lastTiming = performance.now();
  renderTiming();
}

// --------------------------------------------------------------- the readout

const $ = (id) => document.getElementById(id);

function fmt(x) {
  if (x === 0) return "0";
  const digits = state.prec === "f32" ? 7 : 13;
  const a = Math.abs(x);
  if (a < 1e-4 || a >= 1e6) return x.toExponential(digits - 1).replace("-", "−");
  return Number(x.toPrecision(digits)).toString().replace("-", "−");
}

function setNum(id, v) {
  const el = $(id);
  if (v === null || v === undefined) { el.dataset.value = ""; el.textContent = "—"; return; }
  el.dataset.value = String(v);
  el.textContent = fmt(v);
}

function setVec(id, x, y) {
  const el = $(id);
  if (x === null || x === undefined) { el.dataset.x = ""; el.dataset.y = ""; el.textContent = "—"; return; }
  el.dataset.x = String(x);
  el.dataset.y = String(y);
  el.textContent = `(${fmt(x)}, ${fmt(y)})`;
}

function iterText(n, status) {
  return `${n}${status ? " · " + STATUS[status] : ""}`;
}

function renderReadouts() {
  const r = state.results;
  const name = (i) => `${KIND_LABEL[state.shapes[i].kind]}`;
  const card = $("card-intersects");
  card.dataset.state = r.hit ? "hit" : "apart";
  $("intersects").dataset.value = String(r.hit);
  $("intersects").textContent = r.hit ? "overlapping" : "apart";
  $("intersects-iter").dataset.value = String(r.det[1]);
  $("intersects-iter").textContent = `${r.det[1]} GJK iterations`;
  $("pair-names").textContent = `${name(state.a)} × ${name(state.bNow)}`;

  $("card-penetration").dataset.state = r.pen ? "some" : "none";
  if (r.pen) {
    setNum("pen-depth", r.pen[2]);
    setVec("pen-normal", r.pen[0], r.pen[1]);
    setNum("pen-err", r.pen[3]);
    setNum("pen-iter", r.pen[4]);
    $("pen-iter").textContent = iterText(r.pen[4], r.pen[5]);
  } else {
    ["pen-depth", "pen-err", "pen-iter"].forEach((id) => setNum(id, null));
    setVec("pen-normal", null);
  }

  $("card-distance").dataset.state = r.dist ? "some" : "none";
  if (r.dist) {
    setNum("dist", r.dist[0]);
    setVec("dist-normal", r.dist[1], r.dist[2]);
    setVec("dist-a", r.dist[3], r.dist[4]);
    setVec("dist-b", r.dist[5], r.dist[6]);
    setNum("dist-err", r.dist[7]);
    setNum("dist-iter", r.dist[8]);
    $("dist-iter").textContent = iterText(r.dist[8], r.dist[9]);
  } else {
    ["dist", "dist-err", "dist-iter"].forEach((id) => setNum(id, null));
    ["dist-normal", "dist-a", "dist-b"].forEach((id) => setVec(id, null));
  }

  const ray = r.ray;
  const oc = $("ray-outcome");
  $("card-ray").dataset.state = ray && ray.code === 1 ? "some" : "none";
  oc.dataset.shape = ray ? String(ray.shape) : "-1";
  oc.dataset.code = ray ? String(ray.code) : "0";
  oc.textContent = !ray ? "miss" : ray.code === 2 ? `starts inside ${name(ray.shape)}` : `hits ${name(ray.shape)}`;
  if (ray && ray.code === 1) {
    setNum("ray-dist", ray.v[0]);
    setVec("ray-point", ray.v[1], ray.v[2]);
    setVec("ray-normal", ray.v[3], ray.v[4]);
  } else {
    setNum("ray-dist", null);
    setVec("ray-point", null);
    setVec("ray-normal", null);
  }
  if (ray) {
    setNum("ray-iter", ray.v[5]);
    $("ray-iter").textContent = ray.v[5] === 0 ? "0 · closed form" : iterText(ray.v[5], ray.v[6]);
  } else setNum("ray-iter", null);

  const man = r.manifold;
  const count = man ? (man.length - 4) / 5 : 0;
  $("card-manifold").dataset.state = count > 0 ? "some" : "none";
  setNum("man-count", man ? count : null);
  if (man) $("man-count").textContent = `${count} · ${iterText(man[2], man[3])}`;
  setVec("man-normal", count > 0 ? man[0] : null, count > 0 ? man[1] : null);
  const featureName = (f) => (f < 0 ? "curve" : f >= 65536 ? `edge ${f - 65536}` : `vertex ${f}`);
  for (let k = 0; k < 2; k++) {
    const el = $(`man-p${k}`);
    if (k < count) {
      const p = man.slice(4 + 5 * k, 9 + 5 * k);
      el.dataset.values = p.map(String).join(" ");
      el.textContent = `(${fmt(p[0])}, ${fmt(p[1])}) sep ${fmt(p[2])} · A ${featureName(p[3])}, B ${featureName(p[4])}`;
    } else {
      el.dataset.values = "";
      el.textContent = "—";
    }
  }

  const cast = r.cast;
  const co = $("cast-outcome");
  $("card-cast").dataset.state = cast ? "some" : "none";
  co.dataset.shape = cast ? String(cast.shape) : "-1";
  co.dataset.code = cast ? String(cast.code) : "0";
  co.textContent = !cast ? "no contact" : cast.code === 2
    ? `${cast.v[3] ? "leaving" : "in contact:"} ${name(cast.shape)}`
    : `first touches ${name(cast.shape)}`;
  const hit = cast && cast.code === 1 ? cast.v : null;
  setNum("cast-fraction", hit ? hit[0] : null);
  setNum("cast-dist", hit ? hit[1] : null);
  setVec("cast-normal", hit ? hit[2] : cast ? cast.v[0] : null, hit ? hit[3] : cast ? cast.v[1] : null);
  setVec("cast-point-a", hit ? hit[4] : null, hit ? hit[5] : null);
  setVec("cast-point-b", hit ? hit[6] : null, hit ? hit[7] : null);
  setNum("cast-err", hit ? hit[8] : null);
  if (cast) {
    const [n, st] = hit ? [hit[9], hit[10]] : [cast.v[4], cast.v[5]];
    setNum("cast-iter", n);
    $("cast-iter").textContent = iterText(n, st);
  } else setNum("cast-iter", null);

  $("sel-a").value = String(state.a);
  $("sel-b").value = String(state.b);
}

function fmtTime(ns) {
  if (ns < 1000) return `${ns.toFixed(ns < 100 ? 1 : 0)} ns`;
  return `${(ns / 1000).toFixed(2)} µs`;
}

function renderTiming() {
  const t = state.timing;
  const max = Math.max(t.intersects, t.penetration, t.distance, t.raycast);
  for (const k of ["intersects", "penetration", "distance", "raycast"]) {
    const el = $("t-" + k);
    el.dataset.ns = String(t[k]);
    el.textContent = fmtTime(t[k]);
    $("tb-" + k).style.width = `${Math.max(2, (100 * t[k]) / max)}%`;
  }
  $("timing-note").textContent = `${state.prec}, wasm, this device`;
}

// For the browser test: the scene exactly as the crate got it.
function exportScene() {
  const [ox, oy] = state.ray.o;
  canvas.dataset.scene = JSON.stringify({
    prec: state.prec,
    a: state.a,
    b: state.bNow,
    ray: [ox, oy, state.ray.e[0] - ox, state.ray.e[1] - oy],
    motion: state.motion.slice(),
    records: state.shapes.map(record),
  });
}

// ------------------------------------------------------------------ drawing

const canvas = $("stage");
const ctx = canvas.getContext("2d");
const view = { w: 0, h: 0, dpr: 1, scale: 50, cx: 0, cy: 0 };
let colors = {};

function readColors() {
  const cs = getComputedStyle(document.documentElement);
  const v = (n) => cs.getPropertyValue(n).trim();
  colors = {
    bg: v("--bg"), grid: v("--grid"), gridStrong: v("--grid-strong"), text: v("--text"),
    muted: v("--muted"), faint: v("--faint"), shape: v("--shape"), a: v("--a"), b: v("--b"),
    hit: v("--hit"), pen: v("--pen"), dist: v("--dist"), ray: v("--ray"), panel: v("--panel"),
    mono: v("--mono"), sans: v("--sans"),
  };
}

function resize() {
  const rect = canvas.getBoundingClientRect();
  view.dpr = window.devicePixelRatio || 1;
  view.w = rect.width;
  view.h = rect.height;
  canvas.width = Math.round(rect.width * view.dpr);
  canvas.height = Math.round(rect.height * view.dpr);
  // Fit an 18 x 10.6 unit world.
  view.scale = Math.min(view.w / 18.4, view.h / 10.8);
  view.cx = view.w / 2;
  view.cy = view.h / 2;
  requestDraw();
}

const S = (p) => [view.cx + p[0] * view.scale, view.cy - p[1] * view.scale];
const W = (x, y) => [(x - view.cx) / view.scale, (view.cy - y) / view.scale];

function alpha(color, a) {
  return `color-mix(in srgb, ${color} ${Math.round(a * 100)}%, transparent)`;
}

function pathOf(points, closed) {
  ctx.beginPath();
  points.forEach((p, i) => {
    const [x, y] = S(p);
    if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
  });
  if (closed) ctx.closePath();
}

function drawGrid() {
  const { w, h, scale } = view;
  const [x0, y1] = W(0, 0), [x1, y0] = W(w, h);
  ctx.lineWidth = 1;
  for (let x = Math.ceil(x0); x <= x1; x++) {
    ctx.strokeStyle = x === 0 ? colors.gridStrong : colors.grid;
    const sx = Math.round(view.cx + x * scale) + 0.5;
    ctx.beginPath(); ctx.moveTo(sx, 0); ctx.lineTo(sx, h); ctx.stroke();
  }
  for (let y = Math.ceil(y0); y <= y1; y++) {
    ctx.strokeStyle = y === 0 ? colors.gridStrong : colors.grid;
    const sy = Math.round(view.cy - y * scale) + 0.5;
    ctx.beginPath(); ctx.moveTo(0, sy); ctx.lineTo(w, sy); ctx.stroke();
  }
}

function drawShape(i, role) {
  const s = state.shapes[i];
  const r = state.results;
  const pts = worldOutline(s);
  const pairHit = r && r.hit && (role === "a" || role === "b");
  const base = role === "a" ? colors.a : role === "b" ? colors.b : colors.shape;
  const stroke = base;
  const otherHit = r && !pairHit && r.overlaps.has(i);
  ctx.lineJoin = "round";
  ctx.lineCap = "round";
  if (s.kind === KIND.segment) {
    pathOf(pts, false);
    ctx.strokeStyle = stroke;
    ctx.lineWidth = role ? 3 : 2.2;
    ctx.stroke();
    for (const p of pts) {
      const [x, y] = S(p);
      ctx.beginPath(); ctx.arc(x, y, 3.2, 0, 2 * Math.PI); ctx.fillStyle = stroke; ctx.fill();
    }
  } else {
    pathOf(pts, true);
    ctx.fillStyle = alpha(base, role ? (pairHit ? 0.12 : 0.17) : 0.08);
    ctx.fill();
    ctx.strokeStyle = otherHit ? alpha(colors.hit, 0.8) : role ? stroke : alpha(stroke, 0.85);
    ctx.lineWidth = role ? 2 : 1.4;
    ctx.stroke();
  }
  // Origin of the shape's frame and its local x axis.
  const [ox, oy] = S([s.x, s.y]);
  const ax = S(toWorld(s, [0.35, 0]));
  ctx.strokeStyle = alpha(role ? stroke : colors.shape, 0.7);
  ctx.lineWidth = 1.2;
  ctx.beginPath(); ctx.moveTo(ox, oy); ctx.lineTo(ax[0], ax[1]); ctx.stroke();
  ctx.beginPath(); ctx.arc(ox, oy, 2.4, 0, 2 * Math.PI); ctx.fillStyle = alpha(role ? stroke : colors.shape, 0.9); ctx.fill();

}

// Labels go on top of every shape, with a halo in the background colour.
function drawLabel(i, role) {
  const s = state.shapes[i];
  const pts = worldOutline(s);
  let sumX = 0, maxY = -Infinity;
  for (const p of pts) {
    const [x, y] = S(p);
    sumX += x;
    maxY = Math.max(maxY, y);
  }
  const label = KIND_LABEL[s.kind] + (role === "a" ? "  A" : role === "b" ? "  B" : "");
  ctx.font = `${role ? 600 : 500} 12px ${colors.sans}`;
  ctx.textAlign = "center";
  ctx.textBaseline = "top";
  ctx.lineJoin = "round";
  ctx.lineWidth = 4;
  ctx.strokeStyle = alpha(colors.bg, 0.85);
  ctx.strokeText(label, sumX / pts.length, maxY + 8);
  ctx.fillStyle = role === "a" ? colors.a : role === "b" ? colors.b : colors.muted;
  ctx.fillText(label, sumX / pts.length, maxY + 8);
}

function arrow(from, to, color, width = 2, head = 9) {
  const [x0, y0] = S(from), [x1, y1] = S(to);
  const len = Math.hypot(x1 - x0, y1 - y0);
  if (len < 1) return;
  const ux = (x1 - x0) / len, uy = (y1 - y0) / len;
  const h = Math.min(head, len * 0.6);
  ctx.strokeStyle = color;
  ctx.fillStyle = color;
  ctx.lineWidth = width;
  ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1 - ux * h * 0.8, y1 - uy * h * 0.8); ctx.stroke();
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x1 - ux * h - uy * h * 0.45, y1 - uy * h + ux * h * 0.45);
  ctx.lineTo(x1 - ux * h + uy * h * 0.45, y1 - uy * h - ux * h * 0.45);
  ctx.closePath();
  ctx.fill();
}

function pill(text, at, color, dx = 0, dy = 0) {
  const [x, y] = S(at);
  ctx.font = `600 12px ${colors.mono}`;
  const w = ctx.measureText(text).width + 14;
  const px = x + dx - w / 2, py = y + dy - 11;
  ctx.fillStyle = alpha(colors.panel, 0.92);
  ctx.strokeStyle = alpha(color, 0.7);
  ctx.lineWidth = 1;
  ctx.beginPath();
  ctx.roundRect(px, py, w, 22, 11);
  ctx.fill();
  ctx.stroke();
  ctx.fillStyle = color;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.fillText(text, x + dx, y + dy + 0.5);
}

function short(x) { return Math.abs(x) >= 100 ? x.toFixed(1) : x.toFixed(3); }

// The overlap of A and B (Sutherland-Hodgman on the drawn outlines, both
// convex and counter-clockwise): only a picture; the numbers are the crate's.
function clipConvex(subject, clip) {
  let out = subject;
  for (let i = 0; i < clip.length && out.length; i++) {
    const a = clip[i], b = clip[(i + 1) % clip.length];
    const side = (p) => (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    const input = out;
    out = [];
    for (let k = 0; k < input.length; k++) {
      const p = input[k], q = input[(k + 1) % input.length];
      const sp = side(p), sq = side(q);
      if (sp >= 0) out.push(p);
      if ((sp >= 0) !== (sq >= 0)) {
        const t = sp / (sp - sq);
        out.push([p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t]);
      }
    }
  }
  return out;
}

function drawOverlap() {
  const r = state.results;
  if (!r || !r.hit) return;
  const a = state.shapes[state.a], b = state.shapes[state.bNow];
  if (a.kind === KIND.segment || b.kind === KIND.segment) return;
  const region = clipConvex(worldOutline(a), worldOutline(b));
  if (region.length < 3) return;
  pathOf(region, true);
  ctx.fillStyle = alpha(colors.hit, 0.42);
  ctx.fill();
  ctx.strokeStyle = colors.hit;
  ctx.lineWidth = 1.6;
  ctx.stroke();
}

function drawPenetration() {
  const r = state.results;
  if (!r.pen) return;
  const [nx, ny, depth] = r.pen;
  const b = state.shapes[state.bNow];
  const moved = { ...b, x: b.x + nx * depth, y: b.y + ny * depth };
  ctx.setLineDash([5, 4]);
  pathOf(worldOutline(moved), b.kind !== KIND.segment);
  ctx.strokeStyle = alpha(colors.pen, 0.9);
  ctx.lineWidth = 1.5;
  ctx.stroke();
  ctx.setLineDash([]);
  const from = [b.x, b.y], to = [moved.x, moved.y];
  const lenPx = depth * view.scale;
  if (lenPx > 3) arrow(from, to, colors.pen, 2.2);
  // The normal itself, as a unit direction from B's origin.
  const tip = [b.x + nx * Math.max(depth, 0.9), b.y + ny * Math.max(depth, 0.9)];
  if (lenPx <= 3) arrow(from, tip, alpha(colors.pen, 0.8), 1.6, 8);
  pill(`depth ${short(depth)}`, tip, colors.pen, 0, -20);
}

function drawDistance() {
  const r = state.results;
  if (!r.dist) return;
  const pa = [r.dist[3], r.dist[4]], pb = [r.dist[5], r.dist[6]];
  const [x0, y0] = S(pa), [x1, y1] = S(pb);
  ctx.setLineDash([6, 5]);
  ctx.strokeStyle = colors.dist;
  ctx.lineWidth = 1.8;
  ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
  ctx.setLineDash([]);
  for (const [x, y, c] of [[x0, y0, colors.a], [x1, y1, colors.b]]) {
    ctx.beginPath(); ctx.arc(x, y, 5, 0, 2 * Math.PI);
    ctx.fillStyle = colors.dist; ctx.fill();
    ctx.lineWidth = 2; ctx.strokeStyle = c; ctx.stroke();
  }
  const mid = [(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2];
  // Offset the label perpendicular to the line, in screen space.
  const len = Math.hypot(x1 - x0, y1 - y0) || 1;
  const off = Math.max(20, 46 - len / 2); // clear of short segments' end dots
  pill(`d = ${short(r.dist[0])}`, mid, colors.dist, (-(y1 - y0) / len) * off, ((x1 - x0) / len) * off);
}

function drawRay() {
  const { o, e } = state.ray;
  const r = state.results;
  const dx = e[0] - o[0], dy = e[1] - o[1];
  const l = Math.hypot(dx, dy) || 1;
  const far = [o[0] + (dx / l) * 60, o[1] + (dy / l) * 60];
  const hit = r && r.ray && r.ray.code === 1 ? r.ray : null;
  const stop = hit ? [hit.v[1], hit.v[2]] : far;
  const [ox, oy] = S(o), [sx, sy] = S(stop), [fx, fy] = S(far);
  ctx.lineCap = "round";
  // Beyond the hit: faint.
  if (hit) {
    ctx.setLineDash([2, 6]);
    ctx.strokeStyle = alpha(colors.ray, 0.35);
    ctx.lineWidth = 1.4;
    ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(fx, fy); ctx.stroke();
    ctx.setLineDash([]);
  }
  ctx.strokeStyle = alpha(colors.ray, hit ? 1 : 0.7);
  ctx.lineWidth = 2;
  ctx.beginPath(); ctx.moveTo(ox, oy); ctx.lineTo(sx, sy); ctx.stroke();
  if (hit) {
    arrow([hit.v[1], hit.v[2]], [hit.v[1] + hit.v[3] * 0.8, hit.v[2] + hit.v[4] * 0.8], colors.ray, 2, 8);
    ctx.beginPath(); ctx.arc(sx, sy, 5, 0, 2 * Math.PI);
    ctx.fillStyle = colors.ray; ctx.fill();
    ctx.lineWidth = 2; ctx.strokeStyle = colors.bg; ctx.stroke();
  }
  // Handles: origin (filled), aim (ring with the direction).
  ctx.beginPath(); ctx.arc(ox, oy, 7, 0, 2 * Math.PI);
  ctx.fillStyle = colors.ray; ctx.fill();
  ctx.lineWidth = 2; ctx.strokeStyle = colors.bg; ctx.stroke();
  const [ex, ey] = S(e);
  ctx.beginPath(); ctx.arc(ex, ey, 8, 0, 2 * Math.PI);
  ctx.fillStyle = alpha(colors.panel, 0.9); ctx.fill();
  ctx.lineWidth = 2.2; ctx.strokeStyle = colors.ray; ctx.stroke();
  ctx.beginPath(); ctx.arc(ex, ey, 2.5, 0, 2 * Math.PI); ctx.fillStyle = colors.ray; ctx.fill();
  if (r && r.ray && r.ray.code === 2) pill("starts inside", o, colors.ray, 0, -22);
}

// The manifold's points on A, each with a tick along the normal to where B is.
function drawManifold() {
  const man = state.results && state.results.manifold;
  if (!man) return;
  const count = (man.length - 4) / 5;
  for (let k = 0; k < count; k++) {
    const [px, py, sep] = man.slice(4 + 5 * k, 7 + 5 * k);
    const onB = [px + man[0] * sep, py + man[1] * sep];
    const [sx, sy] = S([px, py]), [bx, by] = S(onB);
    ctx.strokeStyle = colors.hit; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(bx, by); ctx.stroke();
    ctx.beginPath(); ctx.arc(sx, sy, 4, 0, 2 * Math.PI);
    ctx.fillStyle = colors.hit; ctx.fill();
    ctx.lineWidth = 1.5; ctx.strokeStyle = colors.bg; ctx.stroke();
  }
}

// The tip of A's motion arrow: where the cast would take A's position.
function motionHandle() {
  const s = state.shapes[state.a];
  return [s.x + state.motion[0], s.y + state.motion[1]];
}

// A's motion as a dashed arrow, and A drawn where the cast first touches.
function drawCast() {
  const s = state.shapes[state.a];
  const tip = motionHandle();
  ctx.setLineDash([5, 5]);
  arrow([s.x, s.y], tip, alpha(colors.a, 0.75), 1.6, 8);
  ctx.setLineDash([]);
  const [hx, hy] = S(tip);
  ctx.beginPath(); ctx.arc(hx, hy, hover === "motion" ? 8 : 6.5, 0, 2 * Math.PI);
  ctx.fillStyle = colors.panel; ctx.fill();
  ctx.lineWidth = 2; ctx.strokeStyle = colors.a; ctx.stroke();
  const cast = state.results && state.results.cast;
  if (!cast) return;
  if (cast.code === 2) { pill("in contact at the start", tip, colors.a, 0, -22); return; }
  const v = cast.v;
  const shift = [v[0] * state.motion[0], v[0] * state.motion[1]];
  const ghost = worldOutline(s).map(([x, y]) => [x + shift[0], y + shift[1]]);
  ctx.setLineDash([3, 4]);
  ctx.strokeStyle = colors.a;
  ctx.lineWidth = 1.6;
  pathOf(ghost, s.kind !== KIND.segment);
  ctx.stroke();
  ctx.setLineDash([]);
  arrow([v[4], v[5]], [v[4] + v[2] * 0.8, v[5] + v[3] * 0.8], colors.a, 2, 8);
  const [px, py] = S([v[4], v[5]]);
  ctx.beginPath(); ctx.arc(px, py, 4.5, 0, 2 * Math.PI);
  ctx.fillStyle = colors.a; ctx.fill();
  pill(`t = ${short(v[0])}`, [s.x + shift[0], s.y + shift[1]], colors.a, 0, -24);
}

function rotationHandle() {
  const s = state.shapes[state.a];
  const reach = boundingRadius(s) + 22 / view.scale;
  return toWorld(s, [0, reach]);
}

function drawRotationHandle() {
  const s = state.shapes[state.a];
  const h = rotationHandle();
  const [ox, oy] = S([s.x, s.y]), [hx, hy] = S(h);
  const c = colors.a;
  ctx.setLineDash([2, 4]);
  ctx.strokeStyle = alpha(c, 0.6);
  ctx.lineWidth = 1.2;
  ctx.beginPath(); ctx.moveTo(ox, oy); ctx.lineTo(hx, hy); ctx.stroke();
  ctx.setLineDash([]);
  ctx.beginPath(); ctx.arc(hx, hy, hover === "rotate" ? 9 : 7.5, 0, 2 * Math.PI);
  ctx.fillStyle = colors.panel; ctx.fill();
  ctx.lineWidth = 2; ctx.strokeStyle = c; ctx.stroke();
  // A small circular arrow inside.
  ctx.beginPath(); ctx.arc(hx, hy, 3.4, -0.4, 3.9); ctx.lineWidth = 1.4; ctx.stroke();
}

function draw() {
  drawPending = false;
  if (state.dirty) update();
  ctx.setTransform(view.dpr, 0, 0, view.dpr, 0, 0);
  ctx.clearRect(0, 0, view.w, view.h);
  drawGrid();
  if (!state.results) return;
  state.shapes.forEach((_, i) => { if (i !== state.a && i !== state.bNow) drawShape(i, null); });
  drawShape(state.bNow, "b");
  drawShape(state.a, "a");
  drawOverlap();
  state.shapes.forEach((_, i) => drawLabel(i, i === state.a ? "a" : i === state.bNow ? "b" : null));
  drawPenetration();
  drawDistance();
  drawManifold();
  drawRay();
  drawCast();
  drawRotationHandle();
}

let drawPending = false;
function requestDraw() {
  if (drawPending) return;
  drawPending = true;
  requestAnimationFrame(draw);
}

function changed() { state.dirty = true; requestDraw(); }

// ------------------------------------------------------------- interaction

function inside(pts, p) {
  let sign = 0;
  for (let i = 0; i < pts.length; i++) {
    const a = pts[i], b = pts[(i + 1) % pts.length];
    const c = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    if (c !== 0) {
      if (sign === 0) sign = Math.sign(c);
      else if (Math.sign(c) !== sign) return false;
    }
  }
  return true;
}

function segDist(p, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

function pick(p, touch = false) {
  const reach = touch ? 24 : 14; // a fingertip is bigger than a cursor
  const near = (q, px) => Math.hypot(q[0] - p[0], q[1] - p[1]) * view.scale <= px;
  if (near(state.ray.e, reach)) return { what: "ray-e" };
  if (near(state.ray.o, reach)) return { what: "ray-o" };
  if (near(rotationHandle(), reach)) return { what: "rotate", i: state.a };
  if (near(motionHandle(), reach)) return { what: "motion" };
  const order = [state.a, state.bNow, ...state.shapes.map((_, i) => i).filter((i) => i !== state.a && i !== state.bNow)];
  for (const i of order) {
    const s = state.shapes[i];
    const pts = worldOutline(s);
    if (s.kind === KIND.segment ? segDist(p, pts[0], pts[1]) * view.scale <= reach - 4 : inside(pts, p)) return { what: "shape", i };
  }
  return null;
}

let drag = null;
let hover = null;

function pointerWorld(ev) {
  const rect = canvas.getBoundingClientRect();
  return W(ev.clientX - rect.left, ev.clientY - rect.top);
}

function select(i) {
  if (i === state.a) return;
  if (i === state.b) state.b = state.a; // an explicit B picked as A: swap
  state.a = i;
}

canvas.addEventListener("pointerdown", (ev) => {
  if (!wasm || (ev.pointerType === "mouse" && ev.button !== 0)) return;
  const p = pointerWorld(ev);
  const hit = pick(p, ev.pointerType === "touch");
  if (!hit) return;
  ev.preventDefault();
  canvas.setPointerCapture(ev.pointerId);
  if (hit.what === "shape") {
    select(hit.i);
    const s = state.shapes[hit.i];
    drag = ev.shiftKey
      ? { what: "rotate", i: hit.i, start: Math.atan2(p[1] - s.y, p[0] - s.x), angle: s.angle }
      : { what: "move", i: hit.i, dx: s.x - p[0], dy: s.y - p[1] };
  } else if (hit.what === "rotate") {
    const s = state.shapes[hit.i];
    drag = { what: "rotate", i: hit.i, start: Math.atan2(p[1] - s.y, p[0] - s.x), angle: s.angle };
  } else if (hit.what === "motion") {
    const h = motionHandle();
    drag = { what: "motion", dx: h[0] - p[0], dy: h[1] - p[1] };
  } else {
    const h = hit.what === "ray-o" ? state.ray.o : state.ray.e;
    drag = { what: hit.what, dx: h[0] - p[0], dy: h[1] - p[1] };
  }
  canvas.style.cursor = "grabbing";
  changed();
});

canvas.addEventListener("pointermove", (ev) => {
  const p = pointerWorld(ev);
  if (!drag) {
    const h = wasm ? pick(p) : null;
    const next = h ? h.what : null;
    canvas.style.cursor = !h ? "default" : h.what === "shape" ? (ev.shiftKey ? "alias" : "grab") : h.what === "rotate" ? "alias" : "crosshair";
    if (next !== hover) { hover = next; requestDraw(); }
    return;
  }
  const clampX = (x) => Math.max(-9.5, Math.min(9.5, x));
  const clampY = (y) => Math.max(-6, Math.min(6, y));
  if (drag.what === "move") {
    const s = state.shapes[drag.i];
    s.x = clampX(p[0] + drag.dx);
    s.y = clampY(p[1] + drag.dy);
  } else if (drag.what === "rotate") {
    const s = state.shapes[drag.i];
    const now = Math.atan2(p[1] - s.y, p[0] - s.x);
    s.angle = wrap(drag.angle + now - drag.start);
  } else if (drag.what === "motion") {
    const s = state.shapes[state.a];
    state.motion = [clampX(p[0] + drag.dx) - s.x, clampY(p[1] + drag.dy) - s.y];
  } else {
    const h = drag.what === "ray-o" ? state.ray.o : state.ray.e;
    const other = drag.what === "ray-o" ? state.ray.e : state.ray.o;
    const nx = clampX(p[0] + drag.dx), ny = clampY(p[1] + drag.dy);
    if (Math.hypot(nx - other[0], ny - other[1]) > 0.2) { h[0] = nx; h[1] = ny; }
  }
  changed();
});

function endDrag(ev) {
  if (!drag) return;
  drag = null;
  if (canvas.hasPointerCapture(ev.pointerId)) canvas.releasePointerCapture(ev.pointerId);
  canvas.style.cursor = "grab";
  scheduleTiming();
}
canvas.addEventListener("pointerup", endDrag);
canvas.addEventListener("pointercancel", endDrag);

function wrap(a) {
  while (a > Math.PI) a -= 2 * Math.PI;
  while (a <= -Math.PI) a += 2 * Math.PI;
  return a;
}

canvas.addEventListener("wheel", (ev) => {
  if (!wasm) return;
  const hit = pick(pointerWorld(ev));
  if (!hit || (hit.what !== "shape" && hit.what !== "rotate")) return;
  ev.preventDefault();
  const s = state.shapes[hit.i];
  const unit = ev.deltaMode === 1 ? 16 : ev.deltaMode === 2 ? 400 : 1;
  s.angle = wrap(s.angle - ev.deltaY * unit * 0.0025);
  changed();
}, { passive: false });

// Keyboard, for the canvas when focused: arrows move A (Shift: faster),
// Q/E rotate it, [ and ] pick the previous or next shape as A.
canvas.tabIndex = 0;
canvas.addEventListener("keydown", (ev) => {
  if (!wasm) return;
  const s = state.shapes[state.a];
  const step = ev.shiftKey ? 0.5 : 0.1;
  const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] };
  if (moves[ev.key]) {
    s.x = Math.max(-9.5, Math.min(9.5, s.x + moves[ev.key][0]));
    s.y = Math.max(-6, Math.min(6, s.y + moves[ev.key][1]));
  } else if (ev.key === "q" || ev.key === "e") {
    s.angle = wrap(s.angle + (ev.key === "q" ? 1 : -1) * (ev.shiftKey ? 0.4 : 0.08));
  } else if (ev.key === "[" || ev.key === "]") {
    const n = state.shapes.length;
    select((state.a + (ev.key === "]" ? 1 : n - 1)) % n);
  } else return;
  ev.preventDefault();
  changed();
});

// ----------------------------------------------------------------- controls

function fillSelects() {
  const a = $("sel-a"), b = $("sel-b");
  a.innerHTML = "";
  b.innerHTML = "";
  const nearest = new Option("nearest", "-1");
  b.add(nearest);
  state.shapes.forEach((s, i) => {
    a.add(new Option(KIND_LABEL[s.kind], String(i)));
    b.add(new Option(KIND_LABEL[s.kind], String(i)));
  });
}

$("sel-a").addEventListener("change", (ev) => { select(Number(ev.target.value)); changed(); });
$("sel-b").addEventListener("change", (ev) => {
  const v = Number(ev.target.value);
  if (v === state.a) { state.a = state.bNow; }
  state.b = v;
  changed();
});

for (const btn of document.querySelectorAll("#precision button")) {
  btn.addEventListener("click", () => {
    state.prec = btn.dataset.prec;
    for (const other of document.querySelectorAll("#precision button")) {
      other.setAttribute("aria-pressed", String(other === btn));
    }
    changed();
  });
}

$("reset").addEventListener("click", () => {
  state.shapes = initialShapes();
  state.ray = initialRay();
  state.motion = initialMotion();
  state.a = 1;
  state.b = -1;
  changed();
});

window.matchMedia("(prefers-color-scheme: light)").addEventListener("change", () => { readColors(); requestDraw(); });
new ResizeObserver(resize).observe(canvas);
// A window dragged to a screen of another pixel density: re-render sharp.
(function watchDpr() {
  matchMedia(`(resolution: ${window.devicePixelRatio || 1}dppx)`).addEventListener("change", () => { resize(); watchDpr(); }, { once: true });
})();

// A handle for tests and the curious: the state, a synchronous update, and
// where a world point is on screen (CSS pixels, relative to the viewport).
window.gjk = {
  state,
  KIND,
  update() { update(); draw(); },
  // The cast card as numbers: [shape, 1, fraction, distance, nx, ny, ax, ay,
  // bx, by, error bound, iterations], [shape, 2, nx, ny, iterations] for a
  // start in contact, [-1, 0] for none.
  readCast() {
    const get = (id) => document.getElementById(id);
    const num = (id) => Number(get(id).dataset.value);
    const vec = (id) => [Number(get(id).dataset.x), Number(get(id).dataset.y)];
    const oc = get("cast-outcome").dataset, code = Number(oc.code), k = Number(oc.shape);
    if (k < 0) return [-1, 0];
    if (code === 1) {
      return [k, 1, num("cast-fraction"), num("cast-dist"), ...vec("cast-normal"), ...vec("cast-point-a"),
        ...vec("cast-point-b"), num("cast-err"), num("cast-iter")];
    }
    return [k, 2, ...vec("cast-normal"), num("cast-iter")];
  },
  // The manifold card as numbers: [count, nx, ny, iterations, (px, py,
  // separation, id_a, id_b) per point], as examples/web_expected.rs prints it.
  readManifold() {
    const get = (id) => document.getElementById(id);
    const c = get("man-count").dataset.value;
    if (c === "") return null;
    const count = Number(c);
    const n = get("man-normal").dataset;
    const head = count > 0 ? [Number(n.x), Number(n.y)] : [];
    const points = [];
    for (let k = 0; k < count; k++) points.push(...get(`man-p${k}`).dataset.values.split(" ").map(Number));
    return [count, ...head, ...points];
  },
  toScreen(p) {
    const rect = canvas.getBoundingClientRect();
    const [x, y] = S(p);
    return [rect.left + x, rect.top + y];
  },
};

// ------------------------------------------------------------------- start

readColors();
fillSelects();
try {
  await loadWasm();
  const info = $("wasm-info");
  info.dataset.bytes = String(moduleBytes);
  info.innerHTML = `gjk2d.wasm · <b>${(moduleBytes / 1024).toFixed(1)} KB</b><span class="long"> · every shape, every query, f32 + f64</span>`;
  resize();
  update();
  draw();
  document.body.dataset.ready = "1";
} catch (err) {
  const info = $("wasm-info");
  info.classList.add("error");
  info.textContent = String(err.message || err);
  console.error(err);
}

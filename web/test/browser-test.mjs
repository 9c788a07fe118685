// Headless-browser test of the demo page (web/www) against the crate run
// natively (examples/web_expected.rs).
//
// Drives Debian's /usr/bin/chromium through playwright-core: loads the page,
// drags shapes, the rotation handle and the ray with simulated pointer input,
// rotates with the wheel, switches precision, then reads the numbers the page
// shows (data attributes of the readout elements, full precision) together
// with the scene the crate got (the canvas's data-scene), runs every scene
// through the native example, and compares.
//
// Tolerance: none. The wasm module and the native build run the same code on
// IEEE floats with the same libm, so every number must be bit-identical:
// f32 against f32, f64 against f64, iteration counts and statuses equal.
//
//   GJK_URL=http://127.0.0.1:8000/ node browser-test.mjs   (web/test/run.sh does it all)
import { chromium } from "playwright-core";
import { spawnSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import path from "node:path";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "../..");
const URL = process.env.GJK_URL || "http://127.0.0.1:8000/";
const SCREENSHOT = process.env.GJK_SCREENSHOT || path.join(here, "screenshot.png");

const failures = [];
function check(ok, what) {
  if (!ok) failures.push(what);
  return ok;
}
const log = (...a) => console.log(...a);

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic",
  ],
});

let exitCode = 1;
try {
  // A high-DPI screen: the canvas must render at device resolution.
  const context = await browser.newContext({ viewport: { width: 1400, height: 860 }, deviceScaleFactor: 2, colorScheme: "dark" });
  const page = await context.newPage();
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error" || m.type() === "warning") problems.push(`console ${m.type()}: ${m.text()}`); });
  page.on("pageerror", (e) => problems.push(`page error: ${e.message}`));
  page.on("requestfailed", (r) => problems.push(`request failed: ${r.url()}`));
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  page.on("request", (r) => { if (!r.url().startsWith(new globalThis.URL(URL).origin) && !r.url().startsWith("data:")) problems.push(`external request: ${r.url()}`); });

  await page.goto(URL);
  await page.waitForSelector("body[data-ready='1']", { timeout: 15000 });
  const bytes = Number(await page.getAttribute("#wasm-info", "data-bytes"));
  log(`page loaded, gjk2d.wasm ${bytes} bytes`);
  check(bytes > 0, "module size shown");

  const dpi = await page.evaluate(() => {
    const c = document.getElementById("stage");
    const r = c.getBoundingClientRect();
    return { w: c.width, h: c.height, cw: r.width, ch: r.height, dpr: devicePixelRatio };
  });
  check(dpi.dpr === 2 && Math.abs(dpi.w - dpi.cw * 2) <= 1 && Math.abs(dpi.h - dpi.ch * 2) <= 1,
    `canvas backing store at device pixels: ${JSON.stringify(dpi)}`);

  // ------------------------------------------------------------ helpers
  const screenOf = (p) => page.evaluate((p) => window.gjk.toScreen(p), p);
  const shapePos = (i) => page.evaluate((i) => { const s = window.gjk.state.shapes[i]; return [s.x, s.y, s.angle]; }, i);
  const settle = () => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

  async function dragScreen(from, to, { steps = 12, shift = false } = {}) {
    await page.mouse.move(from[0], from[1]);
    if (shift) await page.keyboard.down("Shift");
    await page.mouse.down();
    await page.mouse.move(to[0], to[1], { steps });
    await page.mouse.up();
    if (shift) await page.keyboard.up("Shift");
    await settle();
  }

  // What the page shows, and the scene it ran.
  const readPage = () => page.evaluate(() => {
    const g = (id) => document.getElementById(id);
    const num = (id) => (g(id).dataset.value === "" ? null : Number(g(id).dataset.value));
    const vec = (id) => (g(id).dataset.x === "" ? null : [Number(g(id).dataset.x), Number(g(id).dataset.y)]);
    const pen = num("pen-depth") === null ? null
      : [...vec("pen-normal"), num("pen-depth"), num("pen-err"), num("pen-iter")];
    const dist = num("dist") === null ? null
      : [num("dist"), ...vec("dist-normal"), ...vec("dist-a"), ...vec("dist-b"), num("dist-err"), num("dist-iter")];
    const oc = g("ray-outcome").dataset;
    const code = Number(oc.code);
    let ray;
    if (Number(oc.shape) < 0) ray = [-1, 0];
    else if (code === 1) ray = [Number(oc.shape), 1, num("ray-dist"), ...vec("ray-point"), ...vec("ray-normal"), num("ray-iter")];
    else ray = [Number(oc.shape), code, num("ray-iter")];
    return {
      scene: JSON.parse(g("stage").dataset.scene),
      shown: {
        intersects: [g("intersects").dataset.value === "true" ? 1 : 0, Number(g("intersects-iter").dataset.value)],
        penetration: pen,
        distance: dist,
        ray,
        cast: window.gjk.readCast(),
        manifold: window.gjk.readManifold(),
      },
    };
  });

  const cases = [];
  async function record(label) {
    await settle();
    const c = await readPage();
    c.label = label;
    cases.push(c);
    return c;
  }

  // ------------------------------------------------ pointer-driven scenarios
  // A starts as the polygon (1); drag it onto the rectangle (2).
  let s1 = await shapePos(1), s2 = await shapePos(2);
  await dragScreen(await screenOf([s1[0], s1[1]]), await screenOf([s2[0] - 1.2, s2[1] - 0.4]));
  let c = await record("drag polygon onto rectangle (f32)");
  const moved = await shapePos(1);
  check(Math.abs(moved[0] - (s2[0] - 1.2)) < 0.05 && Math.abs(moved[1] - (s2[1] - 0.4)) < 0.05,
    `the drag moved the polygon to where the pointer went: ${moved}`);
  check(c.shown.intersects[0] === 1 && c.shown.penetration !== null && c.scene.b === 2,
    `dragged polygon overlaps the rectangle: ${JSON.stringify(c.shown)}`);
  log(`overlap: depth ${c.shown.penetration?.[2]}, normal (${c.shown.penetration?.[0]}, ${c.shown.penetration?.[1]})`);

  // Rotate it with the wheel, then with the rotation handle, then shift-drag.
  s1 = await shapePos(1);
  await page.mouse.move(...(await screenOf([s1[0], s1[1]])));
  await page.mouse.wheel(0, 120);
  const afterWheel = await shapePos(1);
  check(Math.abs(afterWheel[2] - s1[2]) > 0.1, `wheel rotated A: ${s1[2]} -> ${afterWheel[2]}`);
  await record("wheel-rotated polygon (f32)");

  const handle = await page.evaluate(() => {
    const s = window.gjk.state.shapes[window.gjk.state.a];
    return { x: s.x, y: s.y, angle: s.angle };
  });
  // The handle sits on A's local +y axis; find it by hovering outward until the cursor says "alias".
  let handleScreen = null;
  for (let reach = 0.8; reach < 3.5 && !handleScreen; reach += 0.05) {
    const p = [handle.x - Math.sin(handle.angle) * reach, handle.y + Math.cos(handle.angle) * reach];
    const sp = await screenOf(p);
    await page.mouse.move(sp[0], sp[1]);
    const cursor = await page.evaluate(() => document.getElementById("stage").style.cursor);
    if (cursor === "alias") handleScreen = sp;
  }
  if (check(handleScreen !== null, "found the rotation handle")) {
    const center = await screenOf([handle.x, handle.y]);
    // Swing the handle a quarter turn around the shape's origin.
    const dx = handleScreen[0] - center[0], dy = handleScreen[1] - center[1];
    await dragScreen(handleScreen, [center[0] - dy, center[1] + dx], { steps: 16 });
    const afterHandle = await shapePos(1);
    const turned = Math.atan2(Math.sin(afterHandle[2] - handle.angle), Math.cos(afterHandle[2] - handle.angle));
    check(Math.abs(Math.abs(turned) - Math.PI / 2) < 0.05, `rotation handle turned A a quarter turn: ${turned}`);
    await record("handle-rotated polygon (f32)");
  }

  s1 = await shapePos(1);
  const sc = await screenOf([s1[0], s1[1]]);
  await dragScreen([sc[0] + 20, sc[1]], [sc[0], sc[1] - 20], { shift: true });
  const afterShift = await shapePos(1);
  check(Math.abs(afterShift[2] - s1[2]) > 0.5 && Math.abs(afterShift[0] - s1[0]) < 1e-9,
    `shift-drag rotated A in place: ${s1} -> ${afterShift}`);
  await record("shift-drag-rotated polygon (f32)");

  // Pull it away: the pair is apart and the distance has closest points.
  s1 = await shapePos(1);
  await dragScreen(await screenOf([s1[0], s1[1]]), await screenOf([s1[0] - 1.4, s1[1] - 0.3]));
  c = await record("polygon pulled apart (f32)");
  check(c.shown.intersects[0] === 0 && c.shown.distance !== null && c.shown.distance[0] > 0,
    `apart: distance shown: ${JSON.stringify(c.shown.distance)}`);

  // Aim the ray: drag its end handle onto the circle (0), its origin elsewhere.
  const ray0 = await page.evaluate(() => window.gjk.state.ray);
  const circle = await shapePos(0);
  await dragScreen(await screenOf(ray0.e), await screenOf([circle[0] + 0.2, circle[1] - 0.1]));
  await dragScreen(await screenOf(ray0.o), await screenOf([-8.8, -0.2]));
  c = await record("ray aimed at the circle (f32)");
  check(c.shown.ray[0] === 0 && c.shown.ray[1] === 1, `the ray hits the circle: ${JSON.stringify(c.shown.ray)}`);

  // Drag A's motion arrow towards the rectangle (2): the cast touches it.
  {
    const a = await shapePos(1), rect = await shapePos(2);
    const m0 = await page.evaluate(() => window.gjk.state.motion);
    await dragScreen(await screenOf([a[0] + m0[0], a[1] + m0[1]]), await screenOf([rect[0] + 0.2, rect[1]]));
    const m1 = await page.evaluate(() => window.gjk.state.motion);
    check(Math.abs(a[0] + m1[0] - rect[0] - 0.2) < 0.05 && Math.abs(a[1] + m1[1] - rect[1]) < 0.05,
      `the drag moved the motion arrow's tip: ${m0} -> ${m1}`);
    c = await record("motion dragged onto the rectangle (f32)");
    check(c.shown.cast[0] === 2 && c.shown.cast[1] === 1 && c.shown.cast[2] > 0 && c.shown.cast[2] < 1,
      `the cast touches the rectangle on the way: ${JSON.stringify(c.shown.cast)}`);
  }

  // Tap the ellipse: it becomes A.
  const ell = await shapePos(6);
  await page.mouse.click(...(await screenOf([ell[0], ell[1]])));
  c = await record("ellipse tapped (f32)");
  check(c.scene.a === 6, `tapping made the ellipse A: a = ${c.scene.a}`);
  // Drag the ellipse onto the capsule.
  const cap = await shapePos(5);
  await dragScreen(await screenOf([ell[0], ell[1]]), await screenOf([cap[0] + 1.3, cap[1] + 0.2]));
  c = await record("ellipse onto capsule (f32)");
  check(c.shown.intersects[0] === 1 && c.scene.b === 5, `ellipse overlaps capsule: ${JSON.stringify(c.shown.intersects)}, b = ${c.scene.b}`);

  // f64.
  await page.click("#precision button[data-prec='f64']");
  c = await record("ellipse onto capsule (f64)");
  check(c.scene.prec === "f64", "precision switched to f64");
  await dragScreen(await screenOf([cap[0] + 1.3, cap[1] + 0.2]), await screenOf([cap[0] + 2.2, cap[1] + 0.5]));
  await record("ellipse off the capsule (f64)");

  // The keyboard: focus the canvas, move A right and rotate it.
  await page.focus("#stage");
  const beforeKeys = await page.evaluate(() => { const s = window.gjk.state.shapes[window.gjk.state.a]; return [s.x, s.y, s.angle]; });
  await page.keyboard.press("ArrowRight");
  await page.keyboard.press("Shift+ArrowUp");
  await page.keyboard.press("q");
  const afterKeys = await page.evaluate(() => { const s = window.gjk.state.shapes[window.gjk.state.a]; return [s.x, s.y, s.angle]; });
  check(Math.abs(afterKeys[0] - beforeKeys[0] - 0.1) < 1e-9 && Math.abs(afterKeys[1] - beforeKeys[1] - 0.5) < 1e-9 && afterKeys[2] !== beforeKeys[2],
    `keyboard moved and rotated A: ${beforeKeys} -> ${afterKeys}`);
  await record("keyboard-moved ellipse (f64)");

  // Timing is shown for every query.
  await page.waitForFunction(() => document.getElementById("t-raycast").dataset.ns !== "", null, { timeout: 5000 });
  const times = await page.evaluate(() => Object.fromEntries(
    ["intersects", "penetration", "distance", "raycast"].map((k) => [k, Number(document.getElementById("t-" + k).dataset.ns)])));
  check(Object.values(times).every((t) => Number.isFinite(t) && t > 0), `times shown: ${JSON.stringify(times)}`);
  log(`time per query (ns, f64, headless): ${JSON.stringify(Object.fromEntries(Object.entries(times).map(([k, v]) => [k, Math.round(v)])))}`);

  // A picture of an overlap, for web/README.md: the polygon pushed into the
  // rectangle, the ray aimed at the ellipse.
  await page.click("#reset");
  await page.click("#precision button[data-prec='f32']");
  await settle();
  {
    const r = await page.evaluate(() => window.gjk.state.ray);
    await dragScreen(await screenOf(r.e), await screenOf([-6.5, -3.4]));
    const a = await shapePos(1), b = await shapePos(2);
    await dragScreen(await screenOf([a[0], a[1]]), await screenOf([b[0] - 1.3, b[1] - 0.6]));
    await page.mouse.move(5, 5);
    await page.waitForTimeout(700);
    c = await record("screenshot scene (f32)");
    check(c.shown.intersects[0] === 1 && c.shown.ray[1] === 1, "screenshot scene: an overlap and a ray hit");
    await page.screenshot({ path: SCREENSHOT, scale: "css" });
    log(`screenshot: ${path.relative(root, SCREENSHOT)}`);
  }

  // ------------------------------ coverage: every pair of kinds, both ways
  // Placed by the page's own update (no pointer needed): B on A, then apart.
  const covered = await page.evaluate(() => {
    const g = window.gjk, st = g.state, out = [];
    const snapshot = () => {
      const get = (id) => document.getElementById(id);
      const num = (id) => (get(id).dataset.value === "" ? null : Number(get(id).dataset.value));
      const vec = (id) => (get(id).dataset.x === "" ? null : [Number(get(id).dataset.x), Number(get(id).dataset.y)]);
      const pen = num("pen-depth") === null ? null : [...vec("pen-normal"), num("pen-depth"), num("pen-err"), num("pen-iter")];
      const dist = num("dist") === null ? null
        : [num("dist"), ...vec("dist-normal"), ...vec("dist-a"), ...vec("dist-b"), num("dist-err"), num("dist-iter")];
      const oc = get("ray-outcome").dataset, code = Number(oc.code);
      const ray = Number(oc.shape) < 0 ? [-1, 0]
        : code === 1 ? [Number(oc.shape), 1, num("ray-dist"), ...vec("ray-point"), ...vec("ray-normal"), num("ray-iter")]
        : [Number(oc.shape), code, num("ray-iter")];
      return {
        scene: JSON.parse(get("stage").dataset.scene),
        shown: {
          intersects: [get("intersects").dataset.value === "true" ? 1 : 0, Number(get("intersects-iter").dataset.value)],
          penetration: pen, distance: dist, ray, cast: g.readCast(), manifold: g.readManifold(),
        },
      };
    };
    const n = st.shapes.length;
    // B on A, B barely off-center on A, B apart; with a ray that starts
    // inside A, one aimed at A from afar, one aimed away from everything.
    const offsets = [[0.45, 0.3, 0.7], [0.05, -0.02, 2.1], [2.3, 1.1, -0.4]];
    for (const prec of ["f32", "f64"]) {
      st.prec = prec;
      for (let i = 0; i < n; i++) {
        for (let j = 0; j < n; j++) {
          if (i === j) continue;
          offsets.forEach(([dx, dy, da], k) => {
            const home = st.shapes.map((s) => ({ ...s }));
            const A = st.shapes[i];
            st.a = i; st.b = j;
            st.shapes[j].x = A.x + dx;
            st.shapes[j].y = A.y + dy;
            st.shapes[j].angle = da;
            st.ray = k === 0 ? { o: [A.x + 0.01, A.y + 0.02], e: [A.x + 2, A.y + 1] }
              : k === 1 ? { o: [A.x - 3, A.y - 2.5], e: [A.x, A.y] }
              : { o: [-9.4, 5.6], e: [-12, 7] };
            g.update();
            const c = snapshot();
            c.label = `coverage ${prec} ${i}-${j} offset ${dx},${dy}`;
            out.push(c);
            st.shapes = home;
          });
        }
      }
    }
    st.prec = "f32"; st.b = -1;
    g.update();
    return out;
  });
  cases.push(...covered);

  // ------------------------------------------------------ the native side
  const lines = [];
  for (const c of cases) {
    lines.push(`prec ${c.scene.prec}`);
    for (const r of c.scene.records) lines.push(`shape ${r.join(" ")}`);
    lines.push(`pair ${c.scene.a} ${c.scene.b}`);
    lines.push(`ray ${c.scene.ray.join(" ")}`);
    lines.push(`motion ${c.scene.motion.join(" ")}`);
    lines.push("end");
  }
  const native = spawnSync("cargo", ["run", "--quiet", "--release", "--example", "web_expected"], {
    cwd: root, input: lines.join("\n") + "\n", encoding: "utf8", maxBuffer: 64 << 20,
  });
  if (native.status !== 0) throw new Error(`web_expected failed:\n${native.stderr}`);
  const expected = native.stdout.trim().split("\n").map((l) => JSON.parse(l));
  check(expected.length === cases.length, `native answered ${expected.length} of ${cases.length} scenes`);

  // Compare: the page shows (hit, iterations), penetration without status,
  // distance without status, ray without status; the rest must be equal.
  const pick = (e) => ({
    intersects: e.intersects.slice(0, 2),
    penetration: e.penetration && e.penetration.slice(0, 5),
    distance: e.distance && e.distance.slice(0, 9),
    ray: e.ray.length <= 2 ? e.ray : e.ray[1] === 1 ? e.ray.slice(0, 8) : [e.ray[0], e.ray[1], e.ray[7]],
    cast: e.cast.length <= 2 ? e.cast : e.cast[1] === 1 ? e.cast.slice(0, 12) : [...e.cast.slice(0, 4), e.cast[6]],
    // The page shows the normal only with points, and no status.
    manifold: e.manifold[0] > 0 ? [e.manifold[0], e.manifold[1], e.manifold[2], ...e.manifold.slice(5)] : [0],
  });
  let compared = 0, numbers = 0, mismatched = 0;
  const kinds = new Set(), queries = { overlap: 0, apart: 0, hit: 0, inside: 0, miss: 0 };
  const casts = { hit: 0, start: 0, miss: 0 };
  const manifolds = [0, 0, 0];
  cases.forEach((c, k) => {
    const want = pick(expected[k]);
    for (const key of Object.keys(want)) {
      const a = c.shown[key], b = want[key];
      const same = (a === null && b === null) || (Array.isArray(a) && Array.isArray(b) && a.length === b.length && a.every((x, i) => Object.is(x, b[i])));
      if (Array.isArray(b)) numbers += b.length;
      if (!same) {
        mismatched++;
        if (mismatched <= 12) failures.push(`${c.label}: ${key}: page ${JSON.stringify(a)} native ${JSON.stringify(b)}`);
      }
    }
    compared++;
    c.scene.records.forEach((r) => kinds.add(r[0]));
    queries[c.shown.intersects[0] ? "overlap" : "apart"]++;
    queries[c.shown.ray[1] === 1 ? "hit" : c.shown.ray[1] === 2 ? "inside" : "miss"]++;
    casts[c.shown.cast[1] === 1 ? "hit" : c.shown.cast[1] === 2 ? "start" : "miss"]++;
    manifolds[c.shown.manifold ? c.shown.manifold[0] : 0]++;
  });
  log(`compared ${compared} scenes (${cases.length - covered.length} interactive, ${covered.length} coverage), ${numbers} numbers, ${mismatched} mismatches; ` +
    `${kinds.size} shape kinds; pairs overlapping ${queries.overlap}, apart ${queries.apart}; rays hit ${queries.hit}, inside ${queries.inside}, miss ${queries.miss}; ` +
    `casts hit ${casts.hit}, start in contact ${casts.start}, miss ${casts.miss}; manifolds of 0, 1, 2 points ${manifolds.join(", ")}`);
  check(manifolds[1] > 0 && manifolds[2] > 0, "manifolds of one and of two points covered");
  check(casts.hit > 0 && casts.start > 0 && casts.miss > 0, "cast hits, starts in contact and misses covered");
  check(kinds.size === 10, "every shape kind covered");
  check(queries.overlap > 0 && queries.apart > 0 && queries.hit > 0, "overlaps, separations and ray hits covered");

  for (const p of problems) failures.push(p);
  await context.close();
  exitCode = failures.length ? 1 : 0;
} catch (err) {
  failures.push(`exception: ${err.stack || err}`);
} finally {
  await browser.close();
}

if (failures.length) {
  console.log(`FAIL (${failures.length}):`);
  for (const f of failures) console.log("  - " + f);
} else {
  console.log("PASS: the page's numbers equal the native crate's, bit for bit");
}
process.exit(exitCode);

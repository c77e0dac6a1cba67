// The editor in space, in real headless Chromium (Debian's /usr/bin/chromium
// driven by playwright-core, WebGL through SwiftShader): a spatial task
// started from an example of tasks/spatial/ is shown in the 3-D view; a
// base box is edited by its numbers and dragged along an axis; the task is
// synthesized with live progress and the arm moves in the view; then a
// primitive moved out of reach is proved infeasible, its explanation shown
// and the proof drawn; last, a drawing dropped "on a plane" becomes a
// spatial task. No script error on the page throughout. Every wait is for
// a condition, bounded.
//
// usage: node editor3d.test.mjs MODSYNTH_BINARY SOURCE_DIR OUTPUT_DIR
// Exit: 0 all passed, 1 a check failed, 77 skipped (Chromium or
// playwright-core missing: ./scripts/test installs both).

import { spawn } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import readline from "node:readline";

const [bin, root, outDir] = process.argv.slice(2);
const SKIP = 77;
const CHROMIUM = "/usr/bin/chromium";
// WebGL without a GPU: ANGLE on SwiftShader. Without the networking flags
// Chromium keeps calling home, and this machine's closed network refuses.
const CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-gl=angle", "--use-angle=swiftshader",
                        "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                        "--disable-background-networking", "--disable-component-update",
                        "--disable-sync", "--no-first-run"];
const WHOLE_RUN_MS = 360_000;
const SOLVE_MS = 60_000;
const EXPLAIN_MS = 90_000;
// Any other wait: long enough for a machine busy with other work, where
// the view is drawn in software (SwiftShader).
const WAIT_MS = 30_000;
const EXAMPLE = "helix-pipe";
// The helix's start this far out makes it a helix of radius 10 m round the
// pipe: far beyond the longest chain the example allows (4 joints, links
// of at most 1 m: 8 m from the base).
const OUT_OF_REACH_X = 10;

const failures = [];
let checks = 0;
const figures = {};
const pageErrors = [];
let server = null;
let browser = null;

function check(cond, what) {
  ++checks;
  if (!cond) {
    failures.push(what);
    console.log("FAIL: " + what);
  }
}

async function cleanup() {
  if (browser) await browser.close().catch(() => {});
  if (server && server.exitCode === null) server.kill("SIGTERM");
}

// ------------------------------------------------------------------ setup

async function loadPlaywright() {
  if (!fs.existsSync(CHROMIUM)) {
    console.log(`e2e: skipped: ${CHROMIUM} is missing (Debian packages chromium, chromium-driver)`);
    process.exit(SKIP);
  }
  try {
    return (await import("playwright-core")).chromium;
  } catch (e) {
    console.log("e2e: skipped: playwright-core is not installed (npm ci in tests/e2e): " + e.message);
    process.exit(SKIP);
  }
}

/// Starts `modsynth serve --port 0` and reads the URL it prints.
function startServer() {
  return new Promise((resolve, reject) => {
    server = spawn(bin, ["serve", "--port", "0", "--max-solves", "2"], { stdio: ["ignore", "pipe", "inherit"] });
    server.on("error", reject);
    server.on("exit", (code) => reject(new Error("serve exited early with code " + code)));
    readline.createInterface({ input: server.stdout }).once("line", (line) => {
      const m = /http:\/\/[^ ]+\//.exec(line);
      if (m) resolve(m[0]); else reject(new Error("serve printed no URL: " + line));
    });
  });
}

async function openEditor(url) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 900 } });
  const page = await context.newPage();
  page.on("pageerror", (e) => pageErrors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") pageErrors.push(m.text()); });
  await page.goto(url);
  await page.waitForSelector("body[data-ready=true]");
  return page;
}

const text = (page, selector) => page.$eval(selector, (e) => e.textContent);
const doc = (page) => page.evaluate(() => window.modsynth.model.doc);
const view = (page) => page.evaluate(() => {
  const s = window.modsynth.view3d.state;
  return { ...s, q: s.q && [...s.q], ee: s.ee && [...s.ee] };
});
const valid = (page) => page.waitForSelector('body[data-validity="valid"]', { timeout: WAIT_MS });

/// How many pixels of the 3-D view differ from its white background.
const drawnPixels = (page) => page.evaluate(() => {
  const c = document.querySelector("#view3d canvas");
  const copy = document.createElement("canvas");
  copy.width = c.width; copy.height = c.height;
  const g = copy.getContext("2d");
  g.drawImage(c, 0, 0);
  const d = g.getImageData(0, 0, copy.width, copy.height).data;
  let drawn = 0;
  for (let i = 0; i < d.length; i += 4) if (d[i] < 250 || d[i + 1] < 250 || d[i + 2] < 250) ++drawn;
  return { drawn, total: d.length / 4 };
});

/// Types a number into the selection form's field (key, axis) and commits it.
async function setField(page, key, axis, value) {
  const field = page.locator(`#selection-form input[data-key="${key}"][data-axis="${axis}"]`);
  await field.fill(String(value));
  await field.press("Tab");
}

// ----------------------------------------------------------- the example

async function buildFromExample(page) {
  await page.selectOption("#example3d", EXAMPLE);
  await page.waitForFunction(() => document.body.dataset.space === "3d" && window.modsynth.view3d && window.modsynth.view3d.state.parts > 0,
                             null, { timeout: WAIT_MS });
  const example = JSON.parse(fs.readFileSync(path.join(root, "tasks/spatial", EXAMPLE + ".json"), "utf8"));
  check(JSON.stringify(await doc(page)) === JSON.stringify(example), `the example ${EXAMPLE} is the task being edited`);
  await valid(page);
  check(/valid: 1 primitives, 2 obstacles, 1 base regions/.test(await text(page, "#validity")),
        "the server calls the example valid: " + await text(page, "#validity"));
  check(await page.isVisible("#view3d canvas") && !(await page.isVisible("#canvas")), "the 3-D view replaces the plane's canvas");
  const s = await view(page);
  check(s.ready && s.error === "", "the 3-D view draws (error: " + s.error + ")");
  check(s.parts === 1 + 2 + 1, `every part is in the view (${s.parts})`);
  const pixels = await drawnPixels(page);
  check(pixels.drawn > pixels.total * 0.02, `the view shows the task (${pixels.drawn} of ${pixels.total} pixels drawn)`);
  check((await page.locator("#parts li[data-part]").count()) === 4, "the part list lists the 4 parts");
  check(/helix ccw, 1\.5\d\d m/.test(await text(page, '#parts li[data-part="trajectory[0]"]')),
        "the helix is listed with its length: " + await text(page, '#parts li[data-part="trajectory[0]"]'));
  check(/capsule 300\.0 mm long, r 30\.0 mm/.test(await text(page, '#parts li[data-part="obstacles[0]"]')),
        "the pipe is listed with its sizes: " + await text(page, '#parts li[data-part="obstacles[0]"]'));
  check(await page.isVisible("#dof-4") && !(await page.isVisible("#dof-2")), "joint counts of space (3 to 6) are offered");

  // Orbiting redraws.
  const frames = (await view(page)).frames;
  const box = await page.locator("#view3d canvas").boundingBox();
  await page.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.3);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.3 + 80, box.y + box.height * 0.3 + 30, { steps: 5 });
  await page.mouse.up();
  check(await page.waitForFunction((f) => window.modsynth.view3d.state.frames > f, frames, { timeout: WAIT_MS }).then(() => true, () => false),
        "dragging the background orbits the view");
  await page.click("#fit");
}

async function editByNumber(page) {
  await page.click('#parts li[data-part="base_regions[0]"]');
  check((await text(page, "#selection-title")) === "Selection: base_regions[0]", "the base box is selected from the list");
  await setField(page, "min", 0, -0.06);
  const b = (await doc(page)).base_regions[0];
  check(JSON.stringify(b) === JSON.stringify({ min: [-0.06, -0.05, 0.9], max: [0.05, 0.05, 0.9] }),
        "its min x is typed in: " + JSON.stringify(b));
  await valid(page);
}

/// Drags the active handle's arrow along `axis` by `pixels` on the screen.
async function dragArrow(page, axis, pixels) {
  const [x0, y0] = await page.evaluate((a) => window.modsynth.view3d.axisClientPoint(a), axis);
  // Along the arrow as the screen shows it: from the handle to the grip.
  const h = (await view(page)).handle;
  const [hx, hy] = await page.evaluate((p) => window.modsynth.view3d.clientPoint(p), h.point);
  const len = Math.hypot(x0 - hx, y0 - hy);
  const [dx, dy] = [(x0 - hx) / len, (y0 - hy) / len];
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x0 + dx * pixels, y0 + dy * pixels, { steps: 8 });
  await page.mouse.up();
}

async function editByDrag(page) {
  // The box's middle handle moves it whole.
  const before = (await doc(page)).base_regions[0];
  const middle = [(before.min[0] + before.max[0]) / 2, (before.min[1] + before.max[1]) / 2, (before.min[2] + before.max[2]) / 2];
  const [mx, my] = await page.evaluate((p) => window.modsynth.view3d.clientPoint(p), middle);
  await page.mouse.click(mx, my);
  const h = (await view(page)).handle;
  check(h && h.key === "middle", "clicking the box's middle handle makes it the one with arrows: " + JSON.stringify(h));
  const undoSteps = await page.evaluate(() => window.modsynth.model.undoStack.length);
  await dragArrow(page, "y", 40);
  const after = (await doc(page)).base_regions[0];
  const dy = after.min[1] - before.min[1];
  check(Math.abs(dy) > 0.005 && Math.abs((after.max[1] - before.max[1]) - dy) < 1e-9,
        `dragging the y arrow moves the box along y (by ${dy.toFixed(3)} m)`);
  check(after.min[0] === before.min[0] && after.min[2] === before.min[2] && after.max[0] === before.max[0] &&
        after.max[2] === before.max[2], "and only along y: " + JSON.stringify(after));
  check(Math.abs(dy * 1000 - Math.round(dy * 1000)) < 1e-6, "snapped to whole millimetres: " + dy);
  check((await page.evaluate(() => window.modsynth.model.undoStack.length)) === undoSteps + 1, "the drag is one undo step");
  figures.dragged = dy;
  await valid(page);
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-edit.png") });
}

// ------------------------------------------------------------- synthesis

async function synthesize(page) {
  const started = Date.now();
  await page.click("#synthesize");
  await page.waitForSelector("#run-box:not([hidden])", { timeout: WAIT_MS });
  // Live progress: a stage other than "starting" while it runs (or the end).
  await page.waitForFunction(() => {
    const s = document.getElementById("run-stage").textContent;
    return s && s !== "starting";
  }, null, { timeout: WAIT_MS });
  await page.waitForFunction(() => !["starting", "running"].includes(document.body.dataset.synthesis), null, { timeout: SOLVE_MS });
  figures.solveSeconds = (Date.now() - started) / 1000;
  check((await page.evaluate(() => document.body.dataset.synthesis)) === "solved", "the example is solved: " + await text(page, "#run-stage"));
  await page.waitForSelector("#summary-links", { timeout: WAIT_MS });
  check(/DH/.test(await text(page, "#result-summary")), "the summary gives the DH rows: " + await text(page, "#result-summary"));
  await page.waitForFunction(() => window.modsynth.view3d.state.duration > 0, null, { timeout: WAIT_MS });
  check(await page.isVisible("#motion-bar"), "the play / scrub bar shows");
  check(await page.isVisible("#view3d canvas"), "the editor's 3-D view stays in front");

  // The arm moves: its pose changes from frame to frame while it plays.
  await page.waitForFunction(() => window.modsynth.view3d.state.playing, null, { timeout: WAIT_MS });
  // From the pose shown now, the frames that follow take the joints and
  // the tool elsewhere (by a millimetre at least; a frame on a busy machine
  // may come a whole loop of the motion later, so moments are not compared
  // at fixed frame counts).
  const first = await view(page);
  const moved = await page.waitForFunction((f) => {
    const s = window.modsynth.view3d.state;
    const far = Math.hypot(s.ee[0] - f.ee[0], s.ee[1] - f.ee[1], s.ee[2] - f.ee[2]);
    return s.frames > f.frames && far > 1e-3 && s.q.some((v, k) => Math.abs(v - f.q[k]) > 1e-4);
  }, first, { timeout: WAIT_MS }).then(() => true, () => false);
  const later = await view(page);
  const shown = [first, later].map((p) => `t ${p.time.toFixed(2)} q [${p.q.map((v) => v.toFixed(3))}] ee [${p.ee.map((v) => v.toFixed(4))}]`).join(" -> ");
  check(moved, "the arm's joints and its tool move over frames: " + shown);
  figures.frames = later.frames - first.frames;
  // Scrubbing shows another moment.
  await page.click("#play3d");
  await page.evaluate(() => window.modsynth.view3d.setTime(window.modsynth.view3d.state.duration * 0.6));
  const c = await view(page);
  check(!c.playing && Math.abs(c.time - c.duration * 0.6) < 1e-6, "scrubbing holds the arm at the time asked");
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-solved.png") });
}

// ---------------------------------------------------------- infeasibility

async function outOfReach(page) {
  await page.click('#parts li[data-part="trajectory[0]"]');
  await setField(page, "start", 0, OUT_OF_REACH_X);
  const t = (await doc(page)).trajectory;
  check(t[0].start[0] === OUT_OF_REACH_X && t[0].center[0] === 0, "the helix's start moves out, round the same axis: " + JSON.stringify(t[0]));
  check((await view(page)).duration === 0, "an edit takes the solved arm away");
  await valid(page);
  await page.click("#synthesize");
  await page.waitForFunction(() => document.getElementById("explanation-message"), null, { timeout: SOLVE_MS });
  const message = await text(page, "#explanation-message");
  check(/out of reach from every base region/.test(message), "the explanation says what is out of reach: " + message);
  const core = await page.$$eval("#core-list li", (items) => items.map((e) => e.dataset.part));
  check(core.includes("base_regions") && core.includes("robot.max_link_length") && core.includes("trajectory[0]"),
        "the core names the base regions, the link length and the primitive out of reach: " + core.join(", "));
  const far = core.find((p) => /^trajectory\[/.test(p));
  await page.waitForSelector(`#parts li[data-part="${far}"] .core-badge`, { timeout: WAIT_MS });
  check(await page.isVisible(`#parts li[data-part="${far}"] .core-badge`), `${far} is marked in conflict in the list`);
  await page.waitForSelector("#proof-note", { timeout: WAIT_MS });
  check(/out of reach is drawn/.test(await text(page, "#proof-note")), "the page says where the proof is drawn");
  const lines = await page.evaluate(() => window.modsynth.proofLines());
  const b = (await doc(page)).base_regions[0];
  const middle = b.min.map((v, i) => (v + b.max[i]) / 2);
  check(lines.length >= 1 && lines[0].length > 8 && Math.hypot(...lines[0].from.map((v, i) => v - middle[i])) < 1e-9,
        "the proof's line runs from the base box past the reach of 8 m: " + JSON.stringify(lines[0]));
  check((await page.locator("#max-link.core-field").count()) === 1, "the link length field is marked");
  await page.click("#fit");
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-infeasible.png") });
  // The changes that remove the conflict, each re-checked by modsynth explain.
  await page.waitForSelector("#suggestions", { timeout: EXPLAIN_MS });
  const suggestions = await text(page, "#suggestions");
  check(/max_link_length|base_regions/.test(suggestions), "the suggested changes are shown: " + suggestions.slice(0, 200));
  figures.suggestions = await page.locator("#suggestions li").count();
}

// ------------------------------------------------------------- a drawing

async function dropOnPlane(page) {
  const file = path.join(root, "tasks/drawings/bracket.dxf");
  const base = (await doc(page)).base_regions;
  await page.selectOption("#import-place", "plane");
  await page.fill("#import-width", "0.1");
  check(await page.isVisible("#import-plane") && !(await page.isVisible("#import-at")), "on a plane: its numbers are asked, not a centre");
  const bytes = fs.readFileSync(file).toString("base64");
  const transfer = await page.evaluateHandle(([b64, name]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], name, { type: "application/dxf" }));
    return dt;
  }, [bytes, path.basename(file)]);
  await page.dispatchEvent("#editor-view", "dragover", { dataTransfer: transfer });
  await page.dispatchEvent("#editor-view", "drop", { dataTransfer: transfer });
  await page.waitForFunction(() => /on a plane/.test(document.getElementById("import-status").textContent), null, { timeout: WAIT_MS });
  const d = await doc(page);
  const prims = (d.strokes || [d.trajectory]).flat();
  check(d.space === "3d" && prims.length > 0 && prims.every((p) => p.start[0] === 0.4),
        `the dropped drawing lies on the wall x = 0.4 (${prims.length} primitives)`);
  check(JSON.stringify(d.base_regions) === JSON.stringify(base), "the base box of the task before stays");
  await valid(page);
  check((await view(page)).parts > 0, "and the view shows it");
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-drop.png") });
}

// ------------------------------------------------------ views and proofs

/// A drawing on a plane tilted by 30 degrees is seen face-on when opened.
async function tiltedFaceOn(page) {
  await page.selectOption("#example3d", "tilted-plane-drawing");
  await page.waitForFunction(() => window.modsynth.model.doc.name === "tilted-plane-drawing", null, { timeout: WAIT_MS });
  await page.click("#fit");
  const frame = await page.evaluate(() => window.modsynth.view3d.state.frame);
  const n = [-0.5, 0, Math.sqrt(0.75)];
  const cos = frame.direction.reduce((s, v, i) => s + v * n[i], 0);
  check(cos > Math.cos(25 * Math.PI / 180), `the tilted drawing is seen within 25 degrees of face-on (${(Math.acos(cos) * 180 / Math.PI).toFixed(1)})`);
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-tilted.png") });
}

/// A base in a closed box: the wall's proof drawn as its cells, said once,
/// in the words of a wall (not of a reach proof).
async function wallExplained(page) {
  const walled = JSON.parse(fs.readFileSync(path.join(root, "tasks/spatial/infeasible/walled.task.json"), "utf8"));
  await page.evaluate((d) => window.modsynth.loadDocument(d), walled);
  await valid(page);
  await page.click("#synthesize");
  await page.waitForSelector("#proof-note", { timeout: SOLVE_MS });
  const note = await text(page, "#proof-note");
  check(/cells it closes in/.test(note) && !/out of reach|dashed/.test(note), "the note speaks of the wall: " + note);
  check((await page.$$("#proof-note")).length === 1, "one proof note");
  check((await page.evaluate(() => window.modsynth.proofLines())).length === 0, "no reach line is drawn for a wall");
  await page.waitForFunction(() => window.modsynth.view3d.state.enclosureCells > 0, null, { timeout: WAIT_MS });
  const cells = (await view(page)).enclosureCells;
  check(cells > 100, `the wall's cells are drawn (${cells})`);
  await page.waitForSelector('body[data-synthesis="infeasible"]', { timeout: EXPLAIN_MS });
  await page.screenshot({ path: path.join(outDir, "e2e-editor3d-wall.png") });
}

// ------------------------------------------------------------------- main

async function main() {
  const chromium = await loadPlaywright();
  const watchdog = setTimeout(async () => {
    console.log(`e2e: FAILED: still running after ${WHOLE_RUN_MS / 1000} s`);
    await cleanup();
    process.exit(1);
  }, WHOLE_RUN_MS);
  fs.mkdirSync(outDir, { recursive: true });
  try {
    const url = await startServer();
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_FLAGS });
    const page = await openEditor(url);
    for (const [name, run] of [["a task in space from the example", buildFromExample], ["edit by number", editByNumber],
                               ["edit by drag", editByDrag], ["synthesize and animate", synthesize],
                               ["out of reach, explained", outOfReach], ["a drawing seen face-on", tiltedFaceOn],
                               ["a wall, explained", wallExplained], ["a drawing on a plane", dropOnPlane]]) {
      const started = Date.now();
      try {
        await run(page);
      } catch (e) {
        check(false, `${name}: ${e.message.split("\n")[0]}`);
      }
      console.log(`${name}: ${((Date.now() - started) / 1000).toFixed(1)} s`);
    }
    check(pageErrors.length === 0, "no script or console error on the page: " + pageErrors.join("; "));
  } catch (e) {
    check(false, "setup: " + e.message);
  } finally {
    clearTimeout(watchdog);
    await cleanup();
  }
  const about = figures.solveSeconds !== undefined
    ? `; solved in ${figures.solveSeconds.toFixed(1)} s, arm moved within ${figures.frames} frames, ${figures.suggestions} suggestions` : "";
  if (failures.length) {
    console.log(`e2e: FAILED: ${failures.length} of ${checks} checks${about}`);
    process.exit(1);
  }
  console.log(`e2e: all ${checks} checks passed${about}; screenshots in ${outDir}`);
}

await main();

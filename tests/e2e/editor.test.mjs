// `modsynth serve` as a new user meets it, in real headless Chromium (Debian's
// /usr/bin/chromium driven by playwright-core): draw a small task by clicking,
// synthesize, watch the robot move along the path; load an infeasible task
// and see its core outlined; edit numbers, drag, undo, and cancel a long
// solve; drop a drawing, see it fitted over the original, and synthesize.
// Every wait is for a condition, bounded.
//
// usage: node editor.test.mjs MODSYNTH_BINARY SOURCE_DIR OUTPUT_DIR
// Exit: 0 all passed, 1 a check failed, 77 skipped (Chromium or
// playwright-core missing: ./scripts/test installs both).

import { spawn, spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import readline from "node:readline";

const [bin, root, outDir] = process.argv.slice(2);
const SKIP = 77;
const CHROMIUM = "/usr/bin/chromium";
// Without the networking flags Chromium keeps calling home, and this
// machine's closed network refuses every call.
const CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                        "--disable-component-update", "--disable-sync", "--no-first-run"];
const WHOLE_RUN_MS = 240_000;
const SOLVE_MS = 60_000;
const EXPLAIN_MS = 90_000;

const failures = [];
let checks = 0;
const figures = {};
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
  page.on("pageerror", (e) => check(false, "no script error on the page: " + e.message));
  await page.goto(url);
  await page.waitForSelector("body[data-ready=true]");
  return page;
}

/// A click on the canvas at a task point (metres), where the page draws it.
async function clickAt(page, p, modifiers = []) {
  const [x, y] = await page.evaluate((q) => window.modsynth.clientPoint(q), p);
  for (const m of modifiers) await page.keyboard.down(m);
  await page.mouse.move(x, y);
  await page.mouse.click(x, y);
  for (const m of modifiers) await page.keyboard.up(m);
}

const text = (page, selector) => page.$eval(selector, (e) => e.textContent);
const hasClass = (page, selector, cls) => page.$eval(selector, (e, c) => e.classList.contains(c), cls).catch(() => false);

// ------------------------------------------------------------ first user

const DRAWN = {
  trajectory: [
    { type: "line", start: [0.4, 0.1], end: [0.6, 0.1] },
    { type: "arc", start: [0.6, 0.1], end: [0.6, 0.3], center: [0.6, 0.2], direction: "ccw" },
    { type: "circle", start: [0.6, 0.3], center: [0.6, 0.4], direction: "ccw" },
  ],
  obstacles: [{ center: [0.2, 0.6], radius: 0.1 }],
  base_regions: [{ min: [-0.1, -0.1], max: [0.1, 0.1] }],
};

async function drawTask(page) {
  await page.click('button[data-tool="line"]');
  await clickAt(page, [0.4, 0.1]);
  await clickAt(page, [0.6, 0.1]);
  await page.click('button[data-tool="arc"]');
  await clickAt(page, [0.6, 0.3]);   // its end
  await clickAt(page, [0.7, 0.2]);   // a point on it
  await page.click('button[data-tool="circle"]');
  await clickAt(page, [0.6, 0.4]);   // its centre
  await page.click('button[data-tool="obstacle"]');
  await clickAt(page, [0.2, 0.6]);
  await clickAt(page, [0.3, 0.6]);
  await page.click('button[data-tool="region"]');
  await clickAt(page, [-0.1, -0.1]);
  await clickAt(page, [0.1, 0.1]);
}

async function firstUser(url) {
  const opened = Date.now();
  const page = await openEditor(url);
  await drawTask(page);
  const doc = await page.evaluate(() => window.modsynth.model.doc);
  for (const key of ["trajectory", "obstacles", "base_regions"]) {
    check(JSON.stringify(doc[key]) === JSON.stringify(DRAWN[key]),
          `clicks drew the ${key}: ${JSON.stringify(doc[key])}`);
  }
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  check((await text(page, "#validity")).includes("3 primitives"), "the server calls the drawn task valid");

  await page.keyboard.press("Control+z");
  check((await page.evaluate(() => window.modsynth.model.regions.length)) === 0, "undo removes the base region");
  await page.keyboard.press("Control+y");
  check((await page.evaluate(() => window.modsynth.model.regions.length)) === 1, "redo brings it back");
  await page.screenshot({ path: path.join(outDir, "e2e-editor-drawn.png") });

  await page.click("#synthesize");
  await page.waitForFunction(() => document.getElementById("run-stage").textContent.length > 0);
  await page.waitForSelector('body[data-synthesis="solved"]', { timeout: SOLVE_MS });
  await watchRobotMove(page, opened);
  await checkFigures(page);
  await checkSteps(page);
  await page.screenshot({ path: path.join(outDir, "e2e-editor-solved.png") });
  await page.context().close();
}

/// A finished solve shows every step done and a full bar, however little
/// of its time limit it used.
async function checkSteps(page) {
  const steps = await page.$$eval("#run-steps li", (items) => items.map((e) => [e.dataset.step, e.className]));
  check(steps.length >= 5 && steps.every(([, c]) => c === "done"), "every step is done: " + JSON.stringify(steps));
  const share = await page.$eval("#run-meter", (e) => +e.dataset.share);
  const bar = await page.$eval("#run-bar", (e) => e.getBoundingClientRect().width / e.parentElement.getBoundingClientRect().width);
  check(share === 1 && bar > 0.99, `the bar is full when the solve is done (${bar.toFixed(2)})`);
}

/// The example solved, as the README shows it; then another example loaded
/// takes the result away (its figures, downloads and report), so that no
/// download is about a task no longer on the page.
async function resultFollowsTheTask(url) {
  const page = await openEditor(url);
  await page.click("#example");
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  await page.click("#synthesize");
  await page.waitForSelector('body[data-synthesis="solved"]', { timeout: SOLVE_MS });
  await page.waitForSelector("#summary-links", { timeout: 10_000 });
  const frame = await (await page.waitForSelector("#report")).contentFrame();
  await frame.waitForSelector("#robot .link", { state: "attached", timeout: 10_000 });
  await page.waitForTimeout(1500);  // the arm a little way along the path
  await page.screenshot({ path: path.join(outDir, "editor-result.png") });
  check((await page.$$("#downloads a")).length >= 4, "the result offers its downloads");

  await loadFile(page, path.join(root, "tasks/infeasible/ring-around-path.task.json"));
  await page.waitForFunction(() => document.getElementById("downloads").children.length === 0, null, { timeout: 5_000 })
    .catch(() => {});
  check((await page.$$("#downloads a")).length === 0, "another task takes the downloads away");
  check((await text(page, "#result-summary")).trim() === "", "... and the figures");
  check(await page.$eval("#tab-result", (e) => e.disabled), "... and the Result tab");
  check(!(await page.isVisible("#run-box")), "... and the finished run");
  check((await page.evaluate(() => window.modsynth.store.solution)) === null, "... and the solution");
  await page.screenshot({ path: path.join(outDir, "editor-after-load.png") });
  // An edit does the same.
  await page.click("#example");
  await page.click("#synthesize");
  await page.waitForSelector('body[data-synthesis="solved"]', { timeout: SOLVE_MS });
  await page.evaluate(() => { const m = window.modsynth.model; m.load({ ...m.doc, name: "renamed" }); });
  check((await page.$$("#downloads a")).length === 0, "an edit takes the result away too");
  await page.context().close();
}

/// The report opens in the Result tab and plays: the arm's last link moves.
async function watchRobotMove(page, opened) {
  await page.waitForSelector("#result-view:not([hidden])", { timeout: 10_000 });
  const frame = await (await page.waitForSelector("#report")).contentFrame();
  await frame.waitForSelector("#robot .link", { state: "attached", timeout: 10_000 });
  const tip = () => frame.$eval("#robot .link:last-of-type", (e) => e.getAttribute("x2") + "," + e.getAttribute("y2"));
  const before = await tip();
  await frame.waitForFunction((b) => {
    const l = document.querySelector("#robot .link:last-of-type");
    return l.getAttribute("x2") + "," + l.getAttribute("y2") !== b;
  }, before, { timeout: 10_000 });
  figures.animatedAfter = (Date.now() - opened) / 1000;
  check(figures.animatedAfter < 60, `an animated robot within a minute of opening the page (${figures.animatedAfter} s)`);
  check(/^(Pause)$/.test(await frame.$eval("#play", (e) => e.textContent)), "the report is playing");
}

async function checkFigures(page) {
  const frame = await (await page.$("#report")).contentFrame();
  const cell = (id) => frame.$eval(`#${id} td`, (e) => e.textContent);
  check(/^[23]$/.test(await cell("fig-dof")), "figures: joint count");
  check((await cell("fig-links")).includes("mm"), "figures: link lengths");
  check((await cell("fig-clearance")).includes("mm"), "figures: certified clearance");
  check((await frame.$$("#reachable path")).length > 0, "the reachable space is drawn");
  check((await frame.$$("#swept path")).length >= 3, "a swept region per primitive");
  check((await text(page, "#summary-table")).includes("solved"), "the panel says solved");
  await page.waitForSelector("#summary-links", { timeout: 10_000 });
  check(/mm/.test(await text(page, "#summary-links")), "the panel shows the link lengths");
  const links = await page.$$eval("#downloads a", (as) => as.map((a) => [a.dataset.file, a.href]));
  const names = links.map(([name]) => name);
  for (const name of ["solution.json", "robot.urdf", "trajectory.csv", "report.html"]) {
    check(names.includes(name), "download offered: " + name);
  }
  for (const [name, href] of links) {
    const status = await page.evaluate(async (u) => (await fetch(u)).status, href);
    check(status === 200, `download ${name} answers 200 (${status})`);
  }
}

// ------------------------------------------------------------- infeasible

async function loadFile(page, file) {
  const [chooser] = await Promise.all([page.waitForEvent("filechooser"), page.click("#open")]);
  await chooser.setFiles(file);
  // The page reads the file asynchronously: wait until it holds that task,
  // so that the verdicts waited for next are about it.
  const trajectory = JSON.stringify(JSON.parse(fs.readFileSync(file, "utf8")).trajectory);
  await page.waitForFunction((t) => JSON.stringify(window.modsynth.model.doc.trajectory) === t, trajectory,
                             { timeout: 10_000 });
}

async function infeasibleTask(url) {
  const page = await openEditor(url);
  await loadFile(page, path.join(root, "tests/fixtures/invalid/disconnected.json"));
  await page.waitForSelector('body[data-validity="invalid"]', { timeout: 10_000 });
  const row = '#parts li[data-part="trajectory[1]"]';
  check((await text(page, row + " .part-error").catch(() => "")).includes("connect"),
        "the validation error sits next to trajectory[1] in the list");
  check(await hasClass(page, '#canvas polyline.primitive[data-part="trajectory[1]"]', "error"),
        "trajectory[1] is marked on the canvas");
  check((await page.$$('#canvas .error-label[data-part="trajectory[1]"]')).length === 1,
        "the message is written next to it on the canvas");

  await loadFile(page, path.join(root, "tasks/infeasible/out-of-reach.task.json"));
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  await page.click("#synthesize");
  await page.waitForSelector("#core-list li", { timeout: SOLVE_MS });
  check(await hasClass(page, '#canvas polyline.primitive[data-part="trajectory[0]"]', "core"),
        "the core's primitive is outlined on the canvas");
  check(await hasClass(page, '#canvas rect.region[data-part="base_regions[0]"]', "core"),
        "the core's base region is outlined on the canvas");
  check(await hasClass(page, "#max-link", "core-field"), "robot.max_link_length is marked in the panel");
  check(/infeasible/i.test(await text(page, "#explanation-message")), "the explanation is shown");
  await page.waitForSelector('body[data-synthesis="infeasible"]', { timeout: EXPLAIN_MS });
  await page.waitForSelector("#suggestions", { timeout: 5_000 });
  const suggestions = await text(page, "#suggestions");
  check(suggestions.length > 10, "suggested changes (or why there are none): " + suggestions);
  figures.suggestions = (await page.$$("#suggestions li")).length;
  await page.screenshot({ path: path.join(outDir, "e2e-editor-infeasible.png") });
  await page.context().close();
}

// ------------------------------------------------------------ the proof

/// A task walled in by a ring: the wall drawn over the task from the
/// solution's witness, each overlap of neighbours marked; a long wall: the
/// detour and its length. Loading another task takes the drawing away.
async function proofDrawn(url) {
  const page = await openEditor(url);
  const ringFile = path.join(root, "tasks/infeasible/ring-around-path.task.json");
  await loadFile(page, ringFile);
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  await page.click("#synthesize");
  await page.waitForSelector("#canvas .wall-overlap", { timeout: SOLVE_MS });
  const core = await page.evaluate(() => window.modsynth.store ? window.modsynth.store.core : null);
  const overlaps = (await page.$$("#canvas .wall-overlap")).length;
  const discs = (await page.$$("#canvas .wall-disc")).length;
  check(overlaps === discs && overlaps >= 3, `the wall's ${discs} discs and ${overlaps} overlaps are drawn`);
  if (core) check(core.filter((p) => p.startsWith("obstacles[")).length === discs, "one disc per obstacle of the core");
  check((await page.$$("#canvas .wall-cycle")).length === 1, "the polygon through the wall's centres is drawn");
  check((await page.$$("#canvas .proof-point")).length >= 1, "the path point behind the wall is marked");
  check(/wall/.test(await text(page, "#proof-note")), "the panel says what the red drawing is");
  check((await page.$$("#proof-note")).length === 1, "one proof note");
  // The message is said once, in the explanation (not again in the figures).
  const message = await text(page, "#explanation-message");
  const said = await page.evaluate((m) => [...document.querySelectorAll("#run-box *")]
    .filter((e) => e.children.length === 0 && e.textContent.includes(m.slice(0, 40))).length, message);
  check(said === 1, `the explanation is printed once (${said} times)`);
  // The parts in conflict are named round the ring, no two labels overlapping.
  const labels = await page.$$eval("#canvas .core-label", (ts) => ts.map((t) => {
    const b = t.getBBox();
    return { part: t.dataset.part, x: b.x, y: b.y, w: b.width, h: b.height };
  }));
  check(labels.length >= 12, `a label per part in conflict (${labels.length})`);
  const overlapping = [];
  for (let i = 0; i < labels.length; ++i) {
    for (let j = i + 1; j < labels.length; ++j) {
      const a = labels[i], b = labels[j];
      if (a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h) overlapping.push(a.part + "/" + b.part);
    }
  }
  check(overlapping.length === 0, "no two conflict labels overlap: " + overlapping.join(", "));
  await page.screenshot({ path: path.join(outDir, "e2e-editor-wall.png") });

  await loadFile(page, path.join(root, "tasks/infeasible/long-wall.task.json"));
  check((await page.$$("#canvas .wall")).length === 0, "another task takes the wall away");
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  await page.click("#synthesize");
  await page.waitForSelector("#canvas path.detour", { timeout: SOLVE_MS });
  const label = await text(page, "#canvas .detour-length");
  check(/^at least \d+\.\d\d m; reach \d+\.\d\d m$/.test(label), "the detour's length is written beside it: " + label);
  const [bound, reach] = label.match(/\d+\.\d\d/g).map(Number);
  check(bound > reach, "the detour is longer than the reach");
  await page.screenshot({ path: path.join(outDir, "e2e-editor-detour.png") });
  await page.context().close();
}

// ------------------------------------------------------- edit and cancel

/// Exact numbers in the panel, a drag on the canvas, undo; then a long solve
/// with live progress, stopped with the Cancel button.
async function editAndCancel(url) {
  const page = await openEditor(url);
  await loadFile(page, path.join(root, "tests/fixtures/serve/slow.task.json"));
  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  const radius = () => page.evaluate(() => window.modsynth.model.doc.obstacles[0].radius);
  await page.click('#parts li[data-part="obstacles[0]"]');
  await page.fill('#selection-form input[data-key="radius"]', "0.025");
  await page.press('#selection-form input[data-key="radius"]', "Tab");
  check((await radius()) === 0.025, "the panel sets an obstacle's radius exactly");
  await page.click("#undo");
  check((await radius()) === 0.03, "undo restores it");
  const center = await page.evaluate(() => window.modsynth.model.doc.obstacles[0].center);
  const [hx, hy] = await page.evaluate((c) => window.modsynth.clientPoint([c[0] + 0.03, c[1]]), center);
  await page.mouse.move(hx, hy);
  await page.mouse.down();
  await page.mouse.move(hx + 40, hy, { steps: 4 });
  await page.mouse.up();
  check((await radius()) > 0.03, "dragging the rim handle resizes the obstacle");
  await page.click("#undo");
  check((await radius()) === 0.03, "undo restores the size");

  await page.click("#synthesize");
  // The first progress line replaces "starting" once the solver has begun.
  await page.waitForFunction(() => !/^(|starting)$/.test(document.getElementById("run-stage").textContent),
                             null, { timeout: 20_000 });
  const stage = await text(page, "#run-stage");
  const log = await page.evaluate(() => window.modsynth.synthesis.job.log);
  check(log.some((line) => line.endsWith(stage)), "live progress shows the solver's latest stage: " + stage);
  check((await page.evaluate(() => document.body.dataset.synthesis)) === "running", "the solve runs on");
  // The clock shows the elapsed time and advances while the solve runs.
  const clock = async () => {
    const m = /^([0-9.]+) s \(time limit [0-9.]+ s\)$/.exec(await text(page, "#run-clock"));
    return m ? parseFloat(m[1]) : null;
  };
  const first = await clock();
  check(first !== null, "live progress shows the elapsed time: " + (await text(page, "#run-clock")));
  const advanced = await page.waitForFunction((t0) => {
    const m = /^([0-9.]+) s/.exec(document.getElementById("run-clock").textContent);
    return m && parseFloat(m[1]) >= t0 + 0.5;
  }, first ?? 0, { timeout: 5_000 }).then(() => true, () => false);
  check(advanced, "the elapsed time advances while the solve runs");
  // Progress is the pipeline's steps, not the time used: one under way.
  const steps = await page.$$eval("#run-steps li", (items) => items.map((e) => e.className));
  check(steps.filter((c) => c === "current").length === 1 && steps.length >= 5,
        "one step is under way: " + steps.join(" "));
  const id = await page.evaluate(() => document.body.dataset.jobId);
  await page.click("#cancel");
  await page.waitForSelector('body[data-synthesis="cancelled"]', { timeout: 5_000 });
  const job = await page.evaluate(async (j) => (await fetch("/api/jobs/" + j)).json(), id);
  check(job.status === "cancelled" && /client/.test(job.cancel_reason), "Cancel stops the solve on the server");
  await page.context().close();
}

// ---------------------------------------------------------- drawing import

const IMPORT_AT = [0.3, 0.1];
const IMPORT_TOLERANCE = 0.001;
const SVG_MM_PER_PX = 25.4 / 96;

/// Drops a file on the canvas as a file manager does: a DataTransfer made in
/// the page holding the file's bytes.
async function dropFile(page, file, type) {
  const bytes = fs.readFileSync(file).toString("base64");
  const transfer = await page.evaluateHandle(([b64, name, t]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], name, { type: t }));
    return dt;
  }, [bytes, path.basename(file), type]);
  await page.dispatchEvent("#editor-view", "dragover", { dataTransfer: transfer });
  await page.dispatchEvent("#editor-view", "drop", { dataTransfer: transfer });
}

/// What `modsynth import` makes of the drawing with the same options.
function importedByCli(file) {
  const out = path.join(outDir, "e2e-import-cli.json");
  const r = spawnSync(bin, ["import", file, "-o", out, "--at", IMPORT_AT.join(","), "--tolerance", String(IMPORT_TOLERANCE)],
                      { encoding: "utf8" });
  if (r.status !== 0) throw new Error("modsynth import failed: " + r.stderr);
  return JSON.parse(fs.readFileSync(out, "utf8"));
}

async function drawingImport(url) {
  const page = await openEditor(url);
  const sketch = path.join(root, "tasks/drawings/sketch.svg");
  const cli = importedByCli(sketch);
  const primitives = (cli.strokes || [cli.trajectory]).flat();
  // The example's base region and robot stay when a drawing replaces the path.
  await page.click("#example");
  await page.fill("#import-at", IMPORT_AT.join(","));
  await page.fill("#import-tolerance", String(IMPORT_TOLERANCE));
  await dropFile(page, sketch, "image/svg+xml");
  await page.waitForFunction(() => /deviation/.test(document.getElementById("import-status").textContent), null,
                             { timeout: 10_000 });
  const doc = await page.evaluate(() => window.modsynth.model.doc);
  check(JSON.stringify(doc.strokes) === JSON.stringify(cli.strokes) &&
        JSON.stringify(doc.trajectory) === JSON.stringify(cli.trajectory),
        "the dropped drawing gives the task `modsynth import` writes with the same options");
  const drawn = (await page.$$("#canvas #layer-trajectory polyline.primitive")).length;
  check(drawn === primitives.length && drawn > 10,
        `the fitted primitives are drawn: ${drawn} on the canvas, ${primitives.length} from modsynth import`);
  check(JSON.stringify(doc.base_regions) === JSON.stringify([{ min: [-0.1, -0.1], max: [0.1, 0.1] }]),
        "the base region of the task before stays");
  figures.importStatus = await text(page, "#import-status");
  const deviation = /deviation ([0-9.]+) mm \(tolerance 1.0 mm\)/.exec(figures.importStatus);
  check(deviation && parseFloat(deviation[1]) <= 1.0, "the deviation reached is shown: " + figures.importStatus);

  // The underlay: the dropped file as an image, placed so that the wave's
  // first point (20, 40 in the file's millimetres, y down) lands on a
  // vertex of the fitted primitives.
  const image = await page.$("#layer-underlay image.underlay");
  check(image !== null && /^blob:/.test((await image.getAttribute("href")) || ""), "the drawing is shown under the task");
  const underlay = await page.evaluate(() => window.modsynth.store.underlay);
  const [a, b, c, d, e, f] = underlay.transform;
  const px = [20 / SVG_MM_PER_PX, 40 / SVG_MM_PER_PX];
  const wave = [a * px[0] + c * px[1] + e, b * px[0] + d * px[1] + f];
  const near = (p) => Math.hypot(p[0] - wave[0], p[1] - wave[1]) < 1e-6;
  check(primitives.some((p) => near(p.start) || (p.end && near(p.end))),
        `the underlay's placement puts the wave's start on the fitted path: ${wave}`);
  // Both boxes in one evaluation: a verdict arriving in between redraws the
  // canvas and would leave a handle taken earlier pointing at a detached node.
  const [box, pathBox] = await page.evaluate(() =>
    ["#layer-underlay image.underlay", "#canvas #layer-trajectory"].map((selector) => {
      const node = document.querySelector(selector);
      if (!node) return null;
      const r = node.getBoundingClientRect();
      return { x: r.x, y: r.y, width: r.width, height: r.height };
    }));
  check(box && pathBox && pathBox.x >= box.x - 1 && pathBox.y >= box.y - 1 &&
        pathBox.x + pathBox.width <= box.x + box.width + 1 && pathBox.y + pathBox.height <= box.y + box.height + 1 &&
        pathBox.width > 0.9 * box.width,
        `the drawing's frame lines up with the image: ${JSON.stringify(pathBox)} in ${JSON.stringify(box)}`);
  await page.screenshot({ path: path.join(outDir, "e2e-editor-import.png") });

  // Drawing goes on from the last stroke's end; undo takes it back.
  const last = doc.strokes[doc.strokes.length - 1];
  const from = last[last.length - 1].end || last[last.length - 1].start;
  await page.click('button[data-tool="line"]');
  await clickAt(page, [from[0] + 0.02, from[1]]);
  const strokes = await page.evaluate(() => window.modsynth.model.doc.strokes);
  const added = strokes[strokes.length - 1].at(-1);
  check(added && added.type === "line" && JSON.stringify(added.start) === JSON.stringify(from) && !("trajectory" in
        (await page.evaluate(() => window.modsynth.model.doc))), "a line drawn after the import extends the last stroke");
  await page.click("#undo");
  check(JSON.stringify(await page.evaluate(() => window.modsynth.model.doc.strokes)) === JSON.stringify(doc.strokes),
        "undo takes the line back");
  await page.click('button[data-tool="select"]');

  // A broken file through the file picker: the error names the element.
  const bad = path.join(outDir, "broken.svg");
  fs.writeFileSync(bad, '<svg xmlns="http://www.w3.org/2000/svg" width="100mm" height="100mm" viewBox="0 0 100 100">\n' +
                        '  <path id="p3" d="M 10,10 L 20"/>\n</svg>\n');
  const [chooser] = await Promise.all([page.waitForEvent("filechooser"), page.click("#import")]);
  await chooser.setFiles(bad);
  await page.waitForFunction(() => document.getElementById("import-error").textContent !== "", null, { timeout: 10_000 });
  const error = await text(page, "#import-error");
  check(/path#p3/.test(error) && /broken\.svg/.test(error), "a bad drawing's error names the file and the element: " + error);
  check((await page.$$("#canvas #layer-trajectory polyline.primitive")).length === drawn, "the task before stays");

  await page.waitForSelector('body[data-validity="valid"]', { timeout: 10_000 });
  await page.fill("#time-limit", "40");
  await page.click("#synthesize");
  await page.waitForSelector('body[data-synthesis="solved"], body[data-synthesis="infeasible"]', { timeout: SOLVE_MS });
  figures.importSynthesis = await page.evaluate(() => document.body.dataset.synthesis);
  console.log(`drawing import: ${drawn} primitives, ${figures.importStatus}; synthesis ${figures.importSynthesis}`);
  await page.context().close();
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
    for (const [name, run] of [["draw, synthesize, animate", firstUser], ["the result follows the task", resultFollowsTheTask],
                               ["infeasible core", infeasibleTask],
                               ["the proof drawn", proofDrawn],
                               ["edit and cancel", editAndCancel], ["drawing import", drawingImport]]) {
      const started = Date.now();
      try {
        await run(url);
      } catch (e) {
        check(false, `${name}: ${e.message.split("\n")[0]}`);
      }
      console.log(`${name}: ${((Date.now() - started) / 1000).toFixed(1)} s`);
    }
  } catch (e) {
    check(false, "setup: " + e.message);
  } finally {
    clearTimeout(watchdog);
    await cleanup();
  }
  const timing = figures.animatedAfter !== undefined ? `; page open to animated robot ${figures.animatedAfter.toFixed(1)} s` : "";
  if (failures.length) {
    console.log(`e2e: FAILED: ${failures.length} of ${checks} checks${timing}`);
    process.exit(1);
  }
  console.log(`e2e: all ${checks} checks passed${timing}; screenshots in ${outDir}`);
}

await main();

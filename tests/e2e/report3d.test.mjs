// The 3-D report of a spatial solution in real headless Chromium (Debian's
// /usr/bin/chromium driven by playwright-core, WebGL through SwiftShader):
// `modsynth export --report` on a planted spatial solution, opened from a
// file with every request that is not the file itself refused; the view
// draws without a script error, the canvas shows more than the background,
// scrubbing moves the arm, and `#t=` opens at that time. The view frames
// the work (a part on a large table: the part and the arm, not the table),
// sees a drawing on a tilted plane face-on, and draws a wall's cells as
// green cubes. Screenshots land in OUTPUT_DIR (report3d.png is
// docs/report3d.png).
//
// usage: node report3d.test.mjs MODSYNTH_BINARY SOURCE_DIR OUTPUT_DIR
// Exit: 0 all passed, 1 a check failed, 77 skipped (Chromium or
// playwright-core missing: ./scripts/test installs both).

import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

import { Checks, CHROMIUM, WEBGL_FLAGS, chromiumOrSkip } from "./harness.mjs";

const [bin, root, outDir] = process.argv.slice(2);
const WAIT_MS = 150_000;
const checks = new Checks("report3d");
const check = (cond, what) => checks.check(cond, what);
const chromium = await chromiumOrSkip("report3d");

fs.mkdirSync(outDir, { recursive: true });
const fixture = (name) => path.join(root, "tests/fixtures/spatial", name);
const report = path.join(outDir, "s4-0010.report.html");
const exported = spawnSync(bin, ["export", fixture("s4-0010.task.json"), fixture("s4-0010.planted.json"),
                                 "--report", report], { encoding: "utf8" });
check(exported.status === 0, "export --report exits 0 (got " + exported.status + ": " + exported.stderr + ")");

const browser = await chromium.launch({ executablePath: CHROMIUM, args: WEBGL_FLAGS });
const timer = setTimeout(() => {
  console.log("FAIL: the whole run took longer than " + WAIT_MS + " ms");
  process.exit(1);
}, WAIT_MS);
try {
  const page = await (await browser.newContext({ viewport: { width: 1500, height: 1000 } })).newPage();
  const errors = [];
  const requests = [];
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  // The file may load nothing but itself.
  const url = pathToFileURL(report).href;
  await page.route("**/*", (route) => {
    const u = route.request().url();
    if (u.split("#")[0] === url) return route.continue();
    requests.push(u);
    return route.abort();
  });
  await page.goto(url + "#t=2");
  await page.waitForFunction(() => window.modsynthView && (window.modsynthView.ready || window.modsynthView.error),
                             null, { timeout: 30_000 });
  const view = await page.evaluate(() => ({ ...window.modsynthView }));
  check(view.error === "", "the view starts (error: " + view.error + ")");
  check(view.ready, "the view is ready");
  check(errors.length === 0, "no script error: " + errors.join("; "));
  check(requests.length === 0, "nothing fetched from elsewhere: " + requests.join(", "));
  check(Math.abs(view.time - 2) < 1e-6, "#t=2 opens at t = 2 s (got " + view.time + ")");
  check(view.duration > 2, "the motion lasts more than 2 s (" + view.duration + ")");
  check(await page.locator("#view canvas").count() === 1, "one canvas in #view");

  // The picture: how many distinct colours the canvas shows, and how many
  // pixels differ from the white background.
  const pixels = () => viewPixels(page);
  const first = await pixels();
  check(first.drawn > first.total * 0.02, `the scene covers the canvas (${first.drawn} of ${first.total} pixels drawn)`);
  check(first.colours > 50, `the scene is shaded (${first.colours} colours)`);
  await page.screenshot({ path: path.join(outDir, "report3d-page.png"), fullPage: false });
  await page.locator("#view").screenshot({ path: path.join(outDir, "report3d.png") });

  // Scrubbing moves the arm: another time, another picture, another readout.
  const readout = await page.locator("#readout").textContent();
  await page.evaluate(() => window.modsynthView.setTime(window.modsynthView.duration * 0.8));
  const later = await pixels();
  check(later.url !== first.url, "the picture changes when the time does");
  check((await page.locator("#readout").textContent()) !== readout, "the readout follows the time");
  check(/tracing (trajectory|strokes)\[/.test(await page.locator("#readout").textContent()),
        "the readout names the primitive being traced");

  // Play runs the clock.
  await page.evaluate(() => window.modsynthView.setTime(0));
  await page.click("#play");
  await page.waitForFunction(() => window.modsynthView.time > 0.3, null, { timeout: 10_000 });
  check((await page.locator("#play").textContent()) === "Pause", "Play turns into Pause");
  await page.click("#play");

  // Orbiting redraws.
  const frames = await page.evaluate(() => window.modsynthView.frames);
  const box = await page.locator("#view canvas").boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2 + 40, { steps: 5 });
  await page.mouse.up();
  check(await page.evaluate(() => window.modsynthView.frames) > frames, "dragging orbits the view");

  await framedOnTheWork(browser);
} finally {
  clearTimeout(timer);
  await browser.close();
}

// ------------------------------------------------------ what the view shows

/// Writes a report with modsynth (solve or export) and opens it.
async function openReport(browser, name, args) {
  const file = path.join(outDir, name + ".report.html");
  const run = spawnSync(bin, [...args, "--report", file], { encoding: "utf8" });
  check([0, 3].includes(run.status) && fs.existsSync(file), `${name}: the report is written (exit ${run.status}: ${run.stderr.slice(-300)})`);
  const page = await (await browser.newContext({ viewport: { width: 1500, height: 1000 } })).newPage();
  await page.goto(pathToFileURL(file).href + "#t=0.5");
  await page.waitForFunction(() => window.modsynthView && (window.modsynthView.ready || window.modsynthView.error),
                             null, { timeout: 30_000 });
  return page;
}

/// The path's points on the canvas: their box's share of the canvas's
/// width and height.
async function pathOnScreen(page) {
  return page.evaluate(() => {
    const data = JSON.parse(document.getElementById("scene-data").textContent);
    const c = document.querySelector("#view canvas").getBoundingClientRect();
    const pts = data.task.prims.flatMap((p) => p.pts).map((p) => window.modsynthView.project(p));
    const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
    return { w: (Math.max(...xs) - Math.min(...xs)) / c.width, h: (Math.max(...ys) - Math.min(...ys)) / c.height };
  });
}

/// The view's picture: pixels drawn (not the white background), distinct
/// colours, shades of green (a wall's cells) and olive (green seen through
/// red), the total, and the picture itself.
function viewPixels(page) {
  return page.evaluate(() => {
    const c = document.querySelector("#view canvas");
    const copy = document.createElement("canvas");
    copy.width = c.width; copy.height = c.height;
    const g = copy.getContext("2d");
    g.drawImage(c, 0, 0);
    const d = g.getImageData(0, 0, copy.width, copy.height).data;
    const colours = new Set();
    let drawn = 0, green = 0, olive = 0;
    for (let i = 0; i < d.length; i += 4) {
      const [r, gr, b] = [d[i], d[i + 1], d[i + 2]];
      if (r < 250 || gr < 250 || b < 250) ++drawn;
      colours.add((r << 16) | (gr << 8) | b);
      if (gr > r + 40 && gr > b + 15) ++green;
      else if (r > 60 && gr > 60 && Math.abs(r - gr) < 30 && b < Math.min(r, gr) - 30) ++olive;
    }
    return { drawn, colours: colours.size, green, olive, total: d.length / 4, url: c.toDataURL() };
  });
}

async function framedOnTheWork(browser) {
  // A part on a 2 m table: the view frames the arm and the part, with the
  // table round them, not the whole table.
  const glue = await openReport(browser, "glue-box-edges", ["solve", path.join(root, "tasks/spatial/glue-box-edges.json"),
                                                            "-o", path.join(outDir, "glue.solution.json"), "--quiet"]);
  const frame = await glue.evaluate(() => window.modsynthView.frame);
  check(frame && frame.radius < 0.6, `glue-box-edges: the view frames the work, not the table (radius ${frame && frame.radius.toFixed(3)} m)`);
  const shown = await pathOnScreen(glue);
  check(shown.w > 0.2, `glue-box-edges: the path spans ${Math.round(shown.w * 100)}% of the view's width (was about 5%)`);
  await glue.locator("#view").screenshot({ path: path.join(outDir, "glue-box-edges-report3d.png") });

  // A drawing on an easel leaning back by 45 degrees: seen face-on from the
  // arm's side, its outline open on the screen rather than a line.
  const easelTask = path.join(outDir, "easel45.task.json");
  const imported = spawnSync(bin, ["import", path.join(root, "tasks/drawings/bracket.dxf"), "--layers", "outline", "-o", easelTask,
                                   "--plane", "0.4,0,0.3,0,-1,0,0.7071,0,0.7071", "--base", "-0.05,-0.05,0.02,0.05,0.05,0.02"],
                             { encoding: "utf8" });
  check(imported.status === 0, "the easel's drawing is imported: " + imported.stderr);
  const easel = await openReport(browser, "easel45", ["solve", easelTask, "-o", path.join(outDir, "easel45.solution.json"), "--quiet"]);
  const dir = (await easel.evaluate(() => window.modsynthView.frame)).direction;
  const face = [-Math.SQRT1_2, 0, Math.SQRT1_2];
  const cos = dir[0] * face[0] + dir[1] * face[1] + dir[2] * face[2];
  check(cos > Math.cos(25 * Math.PI / 180), `the easel is seen within 25 degrees of face-on (${(Math.acos(cos) * 180 / Math.PI).toFixed(1)} degrees)`);
  // Face-on keeps the drawing's own proportions on the screen; edge-on
  // (the view before) flattened it to a line.
  const drawing = await pathOnScreen(easel);
  const own = await easel.evaluate(() => {
    const data = JSON.parse(document.getElementById("scene-data").textContent);
    const pts = data.task.prims.flatMap((p) => p.pts);
    const u = pts.map((p) => -p[1]), v = pts.map((p) => (p[0] + p[2]) * Math.SQRT1_2);
    return (Math.max(...v) - Math.min(...v)) / (Math.max(...u) - Math.min(...u));
  });
  const canvas = await easel.evaluate(() => { const c = document.querySelector("#view canvas").getBoundingClientRect(); return c.height / c.width; });
  const onScreen = (drawing.h * canvas) / drawing.w;
  check(Math.abs(onScreen / own - 1) < 0.3, `the drawing keeps its proportions on the screen: ${onScreen.toFixed(2)} against its own ${own.toFixed(2)}`);
  await easel.locator("#view").screenshot({ path: path.join(outDir, "easel45-report3d.png") });

  // A wall's witness: the enclosed cells as green cubes one tells apart,
  // not an olive blob behind red walls.
  const walled = await openReport(browser, "walled", ["solve", path.join(root, "tasks/spatial/infeasible/walled.task.json"),
                                                      "-o", path.join(outDir, "walled.solution.json"), "--quiet"]);
  const cells = await walled.evaluate(() => window.modsynthView.enclosureCells);
  check(cells > 100, `the wall's cells are drawn one by one (${cells} facing the wall)`);
  const colours = await viewPixels(walled);
  check(colours.green > colours.total * 0.05, `the cells show green (${colours.green} of ${colours.total} pixels)`);
  check(colours.olive < colours.green / 4, `hardly any olive: ${colours.olive} olive pixels against ${colours.green} green`);
  await walled.locator("#view").screenshot({ path: path.join(outDir, "walled-report3d.png") });
}

checks.finish();

// The 3-D report of a spatial solution in real headless Chromium (Debian's
// /usr/bin/chromium driven by playwright-core, WebGL through SwiftShader):
// `modsynth export --report` on a planted spatial solution, opened from a
// file with every request that is not the file itself refused; the view
// draws without a script error, the canvas shows more than the background,
// scrubbing moves the arm, and `#t=` opens at that time. Screenshots land in
// OUTPUT_DIR (report3d-page.png is the README's picture, docs/report3d.png).
//
// usage: node report3d.test.mjs MODSYNTH_BINARY SOURCE_DIR OUTPUT_DIR
// Exit: 0 all passed, 1 a check failed, 77 skipped (Chromium or
// playwright-core missing: ./scripts/test installs both).

import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

const [bin, root, outDir] = process.argv.slice(2);
const SKIP = 77;
const CHROMIUM = "/usr/bin/chromium";
// WebGL without a GPU: ANGLE on SwiftShader. Without the networking flags
// Chromium keeps calling home, and this machine's closed network refuses.
const CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-gl=angle", "--use-angle=swiftshader",
                        "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist",
                        "--disable-background-networking", "--disable-component-update",
                        "--disable-sync", "--no-first-run"];
const WAIT_MS = 60_000;

let checks = 0;
const failures = [];
function check(cond, what) {
  ++checks;
  if (!cond) {
    failures.push(what);
    console.log("FAIL: " + what);
  }
}

if (!fs.existsSync(CHROMIUM)) {
  console.log(`report3d: skipped: ${CHROMIUM} is missing (Debian packages chromium, chromium-driver)`);
  process.exit(SKIP);
}
let chromium;
try {
  chromium = (await import("playwright-core")).chromium;
} catch (e) {
  console.log("report3d: skipped: playwright-core is not installed (npm ci in tests/e2e): " + e.message);
  process.exit(SKIP);
}

fs.mkdirSync(outDir, { recursive: true });
const fixture = (name) => path.join(root, "tests/fixtures/spatial", name);
const report = path.join(outDir, "s4-0010.report.html");
const exported = spawnSync(bin, ["export", fixture("s4-0010.task.json"), fixture("s4-0010.planted.json"),
                                 "--report", report], { encoding: "utf8" });
check(exported.status === 0, "export --report exits 0 (got " + exported.status + ": " + exported.stderr + ")");

const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_FLAGS });
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
  const pixels = () => page.evaluate(() => {
    const c = document.querySelector("#view canvas");
    const copy = document.createElement("canvas");
    copy.width = c.width; copy.height = c.height;
    const g = copy.getContext("2d");
    g.drawImage(c, 0, 0);
    const d = g.getImageData(0, 0, copy.width, copy.height).data;
    const colours = new Set();
    let drawn = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 250 || d[i + 1] < 250 || d[i + 2] < 250) ++drawn;
      colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
    }
    return { drawn, colours: colours.size, total: d.length / 4, url: c.toDataURL() };
  });
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
} finally {
  clearTimeout(timer);
  await browser.close();
}

console.log(`report3d: ${checks - failures.length} passed, ${failures.length} failed`);
process.exit(failures.length ? 1 : 0);

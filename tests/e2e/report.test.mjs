// The planar report as a person sees it, in real headless Chromium: the
// timing charts draw each joint's curve in its legend's colour and never
// fill it, the limit lines show, and the robot's joints stay white circles.
// Screenshots land in OUTPUT_DIR (report-page.png: the whole page).
//
// usage: node report.test.mjs MODSYNTH_BINARY SOURCE_DIR OUTPUT_DIR
// Exit: 0 all passed, 1 a check failed, 77 skipped (Chromium or
// playwright-core missing: ./scripts/test installs both).

import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

import { Checks, CHROMIUM, PLAIN_FLAGS, chromiumOrSkip } from "./harness.mjs";

const [bin, root, outDir] = process.argv.slice(2);
const checks = new Checks("report");
const check = (cond, what) => checks.check(cond, what);
const chromium = await chromiumOrSkip("report");

fs.mkdirSync(outDir, { recursive: true });
const report = path.join(outDir, "rose.report.html");
const solved = spawnSync(bin, ["solve", path.join(root, "tasks/rose.json"), "-o", path.join(outDir, "rose.solution.json"),
                               "--report", report, "--quiet"], { encoding: "utf8" });
check(solved.status === 0, "solve --report exits 0 (got " + solved.status + ": " + solved.stderr + ")");

/// "rgb(31, 119, 180)" or "#1f77b4" as [r, g, b].
function rgb(text) {
  const m = /^#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})$/i.exec(text.trim());
  if (m) return [1, 2, 3].map((i) => parseInt(m[i], 16));
  const n = /rgba?\(([0-9]+), *([0-9]+), *([0-9]+)/.exec(text);
  return n ? [1, 2, 3].map((i) => +n[i]) : null;
}

const browser = await chromium.launch({ executablePath: CHROMIUM, args: PLAIN_FLAGS });
const timer = setTimeout(() => {
  console.log("FAIL: the whole run took longer than 60 s");
  process.exit(1);
}, 60_000);
try {
  const page = await (await browser.newContext({ viewport: { width: 1400, height: 900 } })).newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(pathToFileURL(report).href + "#t=1");
  await page.waitForSelector("#timing .chart polyline.joint-curve");
  check(errors.length === 0, "no script error: " + errors.join("; "));

  // Each curve as the browser paints it: the legend's colour, no fill.
  const curves = await page.$$eval("#timing .chart polyline.joint-curve", (ps) => ps.map((p) => {
    const s = getComputedStyle(p);
    const swatch = document.querySelector(`#timing .legend li[data-joint="${p.dataset.joint}"] .swatch`);
    return { joint: p.dataset.joint, stroke: s.stroke, fill: s.fill, legend: swatch ? getComputedStyle(swatch).backgroundColor : null };
  }));
  // Four charts of both joints, and the tool's speed.
  check(curves.length === 9, `every chart draws a curve per joint (${curves.length} curves)`);
  for (const c of curves) {
    check(c.legend !== null, `joint ${c.joint} is in the legend`);
    check(JSON.stringify(rgb(c.stroke)) === JSON.stringify(rgb(c.legend || "")),
          `joint ${c.joint}'s curve is painted ${c.stroke}, its legend ${c.legend}`);
    check(c.fill === "none", `joint ${c.joint}'s curve is not filled (${c.fill})`);
  }
  const colours = new Set(curves.map((c) => c.stroke));
  check(colours.size >= 2, "two joints, two colours: " + [...colours].join(", "));
  // The robot's joints are still white circles with a black rim.
  const joint = await page.$eval("#robot .joint", (e) => ({ fill: getComputedStyle(e).fill, stroke: getComputedStyle(e).stroke }));
  check(joint.fill === "rgb(255, 255, 255)" && joint.stroke === "rgb(0, 0, 0)", "the robot's joints are white circles: " + JSON.stringify(joint));

  // In the picture: the velocity chart shows both legend colours and its
  // dashed limit lines, and hardly any black (the curves were black).
  const chart = page.locator("#chart-qd");
  await chart.scrollIntoViewIfNeeded();
  const png = await chart.screenshot({ path: path.join(outDir, "report-chart-qd.png") });
  const counts = await page.evaluate(async ({ data, legend }) => {
    const img = new Image();
    img.src = "data:image/png;base64," + data;
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.width;
    c.height = img.height;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const near = (i, col) => Math.abs(d[i] - col[0]) + Math.abs(d[i + 1] - col[1]) + Math.abs(d[i + 2] - col[2]) < 60;
    const out = { black: 0, legend: legend.map(() => 0) };
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] < 40 && d[i + 1] < 40 && d[i + 2] < 40) out.black += 1;
      legend.forEach((col, k) => { if (near(i, col)) out.legend[k] += 1; });
    }
    return out;
  }, { data: png.toString("base64"), legend: [...colours].map(rgb) });
  counts.legend.forEach((n, k) => check(n > 300, `the chart shows joint ${k + 1}'s colour (${n} pixels)`));
  check(counts.black < 600, `the chart's curves are not black (${counts.black} black pixels, the axis text among them)`);
  await page.screenshot({ path: path.join(outDir, "report-page.png"), fullPage: true });
} finally {
  clearTimeout(timer);
  await browser.close();
}

checks.finish();

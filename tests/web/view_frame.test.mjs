// Where the 3-D views look from (web/report3d/view_frame.js): the work framed
// without the table it stands on, a drawing on a plane seen face-on from
// the base's side.

import assert from "node:assert/strict";
import fs from "node:fs";
import { test } from "node:test";

import { namedPrimitives, samplePrimitive3, spatialBounds } from "../../web/space_geometry.js";
import { drawingNormal, frameDistance, framedPoints, symmetricEigen, viewFrame } from "../../web/report3d/view_frame.js";

const example = (name) => JSON.parse(fs.readFileSync(new URL(`../../tasks/spatial/${name}.json`, import.meta.url), "utf8"));
const pathOf = (doc) => namedPrimitives(doc).flatMap(({ primitive }) => samplePrimitive3(primitive));
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const degrees = (a, b) => (Math.acos(Math.min(1, Math.abs(dot(a, b)))) * 180) / Math.PI;

/// A square of side 0.2 m centred at `c` in the plane spanned by u and v.
function square(c, u, v) {
  const pts = [];
  for (const [a, b] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
    for (let t = 0; t < 10; ++t) pts.push([0, 1, 2].map((i) => c[i] + 0.1 * (a * u[i] + b * v[i]) * (1 - t / 10) + 0.1 * (t / 10) * (-b * u[i] + a * v[i])));
  }
  return pts;
}

test("the eigenvectors of a symmetric matrix come out with their values, largest first", () => {
  const [a, b, c] = symmetricEigen([[2, 1, 0], [1, 2, 0], [0, 0, 5]]);
  assert.ok(Math.abs(a.value - 5) < 1e-12 && Math.abs(b.value - 3) < 1e-12 && Math.abs(c.value - 1) < 1e-12);
  assert.ok(degrees(a.vector, [0, 0, 1]) < 1e-6 && degrees(b.vector, [Math.SQRT1_2, Math.SQRT1_2, 0]) < 1e-6);
});

test("a drawing on an easel tilted by 45 degrees is seen face-on from the base's side", () => {
  // import --plane 0.4,0,0.3,0,-1,0,0.7071,0,0.7071: U = -y, V up and away.
  const u = [0, -1, 0], v = [Math.SQRT1_2, 0, Math.SQRT1_2];
  const path = square([0.4, 0, 0.3], u, v);
  const n = drawingNormal(path);
  assert.ok(n && degrees(n, [-Math.SQRT1_2, 0, Math.SQRT1_2]) < 1e-6, JSON.stringify(n));
  const base = [0, 0, 0.02];
  const f = viewFrame(path, [...path, base], base);
  const face = [-Math.SQRT1_2, 0, Math.SQRT1_2];  // the side the base is on
  assert.ok(dot(f.direction, face) > Math.cos((25 * Math.PI) / 180), `within 25 degrees of face-on: ${JSON.stringify(f.direction)}`);
  // The default view (0.9, -1.6, 0.9) would see it edge-on.
  const d = [0.9, -1.6, 0.9].map((x) => x / Math.hypot(0.9, 1.6, 0.9));
  assert.ok(Math.abs(dot(d, face)) < 0.01);
});

test("a drawing on a wall is seen from the base's side, whichever way its normal was written", () => {
  const path = square([0.4, 0, 0.25], [0, 1, 0], [0, 0, 1]);
  const f = viewFrame(path, path, [0, 0, 0]);
  assert.ok(f.direction[0] < -0.8, JSON.stringify(f.direction));
  const g = viewFrame(path, path, [0.8, 0, 0]);
  assert.ok(g.direction[0] > 0.8, JSON.stringify(g.direction));
});

test("the tilted-plane example and a level drawing are seen face-on, a helix from the front right", () => {
  const tilted = example("tilted-plane-drawing");
  const n = drawingNormal(pathOf(tilted));
  assert.ok(n && degrees(n, [-0.5, 0, Math.sqrt(0.75)]) < 1e-3, JSON.stringify(n));
  const level = square([0.4, 0, 0.1], [1, 0, 0], [0, 1, 0]);
  assert.ok(viewFrame(level, level, [0, 0, 0]).direction[2] > 0.85, "a level drawing from high above");
  const helix = pathOf(example("helix-pipe"));
  assert.equal(drawingNormal(helix), null);
  const f = viewFrame(helix, helix, null);
  assert.ok(Math.abs(dot(f.direction, [0.9, -1.6, 0.9].map((x) => x / Math.hypot(0.9, 1.6, 0.9))) - 1) < 1e-12);
  // A straight line spreads over no area.
  assert.equal(drawingNormal([[0, 0, 0], [0.1, 0, 0], [0.2, 0, 0], [0.3, 0, 0]]), null);
});

test("the table top is not framed: the work is, with the small part beside it", () => {
  const doc = example("glue-box-edges");
  const work = pathOf(doc).concat(doc.base_regions.flatMap((r) => [r.min, r.max]));
  const boxes = doc.obstacles.map((o) => ({ min: o.min, max: o.max }));
  const pts = framedPoints(work, boxes);
  const xs = pts.map((p) => p[0]);
  assert.ok(Math.max(...xs) - Math.min(...xs) < 1, "the 2 m table is left out");
  const f = viewFrame(pathOf(doc), pts, null);
  assert.ok(f.radius < 0.5, `the frame's radius ${f.radius}`);
  // The editor's bounds leave it out the same way.
  const b = spatialBounds(doc);
  assert.ok(b.max[0] - b.min[0] < 1);
  // The camera keeps the framed sphere in a 40-degree view.
  const dist = frameDistance(f.radius, 40, 1.5);
  assert.ok(dist * Math.sin((20 * Math.PI) / 180) >= f.radius);
});

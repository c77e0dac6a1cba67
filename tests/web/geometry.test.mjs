// The editor's plane geometry (web/geometry.js) and what is built on it:
// the shapes the drawing tools make, snapping, hit tests and the view
// transform.

import assert from "node:assert/strict";
import { test } from "node:test";

import {
  arcSweep, circumcenter, dist, distToPolyline, distToSegment, niceStep, primitiveEnd, primitiveLength,
  round9, samplePrimitive, taskBounds, turn,
} from "../../web/geometry.js";
import { handleAt, partAt } from "../../web/hit.js";
import { dragEdit, handlesOf } from "../../web/handles.js";
import { shapeOf } from "../../web/shapes.js";
import { keyPoints, snapPoint } from "../../web/snap.js";
import { exampleTask } from "../../web/task_model.js";
import { ViewTransform } from "../../web/view_transform.js";

const near = (a, b, tol = 1e-9) => assert.ok(Math.abs(a - b) <= tol, `${a} is not ${b} (within ${tol})`);
const nearPoint = (p, q, tol = 1e-9) => { near(p[0], q[0], tol); near(p[1], q[1], tol); };

test("the circle through three points has its centre equidistant from them", () => {
  const a = [1, 0], b = [0, 1], c = [-1, 0];
  nearPoint(circumcenter(a, b, c), [0, 0]);
  const p = [0.3, -0.2], q = [1.7, 0.4], r = [0.9, 2.2];
  const o = circumcenter(p, q, r);
  near(dist(o, p), dist(o, q), 1e-12);
  near(dist(o, q), dist(o, r), 1e-12);
});

test("three points on a line have no circle", () => {
  assert.equal(circumcenter([0, 0], [1, 1], [2, 2]), null);
  assert.equal(circumcenter([0, 0], [1, 1e-13], [2, 0]), null);
});

test("turn is positive counter-clockwise", () => {
  assert.ok(turn([0, 0], [1, 0], [1, 1]) > 0);
  assert.ok(turn([0, 0], [1, 0], [1, -1]) < 0);
  assert.equal(turn([0, 0], [1, 0], [2, 0]), 0);
});

test("an arc's sweep follows its direction, a closed one is a full turn", () => {
  near(arcSweep([1, 0], [0, 1], [0, 0], "ccw"), Math.PI / 2);
  near(arcSweep([1, 0], [0, 1], [0, 0], "cw"), -3 * Math.PI / 2);
  near(arcSweep([1, 0], [1, 0], [0, 0], "ccw"), 2 * Math.PI);
  near(arcSweep([1, 0], [1, 0], [0, 0], "cw"), -2 * Math.PI);
});

test("the arc tool draws the arc through its three clicks", () => {
  // start, end, then a point on the arc: the quarter above the chord.
  const start = [1, 0], end = [-1, 0], through = [0, 1];
  const shape = shapeOf("arc", [start, end, through]);
  assert.equal(shape.kind, "primitive");
  assert.deepEqual(shape.value, { type: "arc", start, end, center: [0, 0], direction: "ccw" });
  // The same chord through a point below turns the other way.
  assert.equal(shapeOf("arc", [start, end, [0, -1]]).value.direction, "cw");
  // Every sample lies on the circle, from the start to the end exactly.
  const pts = samplePrimitive(shape.value);
  for (const p of pts) near(dist(p, [0, 0]), 1, 1e-12);
  assert.deepEqual(pts[0], start);
  assert.deepEqual(pts[pts.length - 1], end);
  // ... and it passes through the point clicked on it.
  assert.ok(distToPolyline(through, pts) < 1e-3);
  near(primitiveLength(shape.value), Math.PI, 1e-12);
});

test("the drawing tools make nothing of degenerate clicks", () => {
  assert.deepEqual(shapeOf("arc", [[0, 0], [2, 0]]), { kind: "chord", a: [0, 0], b: [2, 0] });
  assert.equal(shapeOf("arc", [[0, 0], [2, 0], [1, 0]]), null);   // a point on the chord
  assert.equal(shapeOf("line", [[1, 1], [1, 1]]), null);
  assert.equal(shapeOf("obstacle", [[1, 1], [1, 1]]), null);
  assert.equal(shapeOf("region", [[0, 0], [0, 1]]), null);        // no area
  assert.deepEqual(shapeOf("obstacle", [[0, 0], [0.3, 0.4]]), { kind: "obstacle", center: [0, 0], radius: 0.5 });
  assert.equal(shapeOf("circle", [[0, 0], [1, 0]], true).value.direction, "cw");
});

test("primitives end where the format says, and measure their length", () => {
  assert.deepEqual(primitiveEnd({ type: "line", start: [0, 0], end: [1, 2] }), [1, 2]);
  assert.deepEqual(primitiveEnd({ type: "circle", start: [0, 0], center: [1, 0] }), [0, 0]);
  assert.equal(primitiveEnd({ type: "line", start: [0, 0] }), null);
  near(primitiveLength({ type: "line", start: [0, 0], end: [3, 4] }), 5);
  near(primitiveLength({ type: "circle", start: [0, 0], center: [0.5, 0] }), Math.PI, 1e-12);
  assert.deepEqual(samplePrimitive({ type: "arc", start: [0, 0] }), []);
});

test("hit distances: to a segment, its ends, a polyline", () => {
  near(distToSegment([1, 1], [0, 0], [2, 0]), 1);
  near(distToSegment([-3, 4], [0, 0], [2, 0]), 5);    // beyond an end: to the end
  near(distToSegment([5, 5], [1, 1], [1, 1]), Math.hypot(4, 4));
  near(distToPolyline([1, 3], [[0, 0], [2, 0], [2, 2]]), Math.hypot(1, 1));
  assert.equal(distToPolyline([0, 0], [[1, 1]]), Infinity);
});

test("a click hits the path before obstacles before base regions", () => {
  const doc = {
    trajectory: [{ type: "line", start: [0, 0], end: [1, 0] }],
    obstacles: [{ center: [0.5, 0], radius: 0.2 }],
    base_regions: [{ min: [-1, -1], max: [1, 1] }],
  };
  assert.equal(partAt(doc, [0.5, 0.01], 0.02), "trajectory[0]");
  assert.equal(partAt(doc, [0.5, 0.1], 0.02), "obstacles[0]");
  assert.equal(partAt(doc, [-0.5, 0.5], 0.02), "base_regions[0]");
  assert.equal(partAt(doc, [2, 2], 0.02), null);
  // The last drawn primitive is on top.
  doc.trajectory.push({ type: "line", start: [1, 0], end: [0, 0] });
  assert.equal(partAt(doc, [0.5, 0], 0.02), "trajectory[1]");
});

test("handles: region corners, an obstacle's rim, line-only vertices", () => {
  const doc = exampleTask();
  const corners = handlesOf(doc, "base_regions[0]");
  assert.deepEqual(corners.map((h) => h.handle), ["corner-0", "corner-1", "corner-2", "corner-3"]);
  assert.deepEqual(corners[2].point, [0.1, 0.1]);
  assert.deepEqual(handlesOf(doc, "obstacles[0]"), [{ handle: "radius", point: [0.35, 0.4], shape: "circle" }]);
  // The line's start is its own; its end meets an arc and stays exact.
  assert.deepEqual(handlesOf(doc, "trajectory[0]").map((h) => h.handle), ["vertex-0"]);
  assert.deepEqual(handlesOf(doc, "trajectory[1]"), []);
  assert.equal(handleAt(corners, [0.102, 0.097], 0.005).handle, "corner-2");
  assert.equal(handleAt(corners, [0.2, 0.2], 0.005), null);
});

test("dragging a corner keeps the opposite one, a rim sets the radius", () => {
  const doc = exampleTask();
  const region = JSON.parse(JSON.stringify(doc.base_regions[0]));
  dragEdit({ part: "base_regions[0]", handle: "corner-2", item: region }, [0.1, 0.1], [0.3, -0.2])(doc);
  assert.deepEqual(doc.base_regions[0], { min: [-0.1, -0.2], max: [0.3, -0.1] });
  dragEdit({ part: "obstacles[0]", handle: "radius", item: {} }, [0.35, 0.4], [0.3, 0.5])(doc);
  assert.equal(doc.obstacles[0].radius, 0.1);
  const obstacle = JSON.parse(JSON.stringify(doc.obstacles[0]));
  dragEdit({ part: "obstacles[0]", item: obstacle }, [0, 0], [0.05, -0.1])(doc);
  assert.deepEqual(doc.obstacles[0].center, [0.35, 0.3]);
});

test("snapping: key points attract within a few pixels, else the grid", () => {
  const view = new ViewTransform(() => [800, 600]);
  view.cx = 0; view.cy = 0; view.s = 1000;   // 1 mm a pixel, a 2 cm grid
  assert.equal(view.gridStep(), 0.02);
  const doc = exampleTask();
  const points = keyPoints(doc);
  assert.ok(points.some((p) => p[0] === 0.55 && p[1] === 0.25), "a circle's centre is a key point");
  const at = (w) => snapPoint(w, view.toScreen(w), { points, view, toGrid: true });
  assert.deepEqual(at([0.405, 0.104]), [0.4, 0.1]);       // 6 px from the path's start
  assert.deepEqual(at([0.425, 0.104]), [0.42, 0.1]);      // far from it: the grid
  assert.deepEqual(snapPoint([0.4251234567891, 0.1], view.toScreen([0.4251234567891, 0.1]),
                             { points, view, toGrid: false }), [0.425123457, 0.1]);
});

test("the view maps task points to the screen and back, zooms about the cursor", () => {
  const view = new ViewTransform(() => [800, 600]);
  view.fit({ min: [0, 0], max: [1, 0.5] });
  nearPoint(view.toScreen([0.5, 0.25]), [400, 300]);
  nearPoint(view.toWorld(view.toScreen([0.123, -0.4])), [0.123, -0.4], 1e-12);
  const q = [100, 50], before = view.toWorld(q);
  view.zoomAt(q, 3);
  nearPoint(view.toWorld(q), before, 1e-12);
  // y goes up in the task and down on the screen.
  assert.ok(view.toScreen([0, 1])[1] < view.toScreen([0, 0])[1]);
});

test("numbers for people: grid steps, rounding, bounds", () => {
  assert.equal(niceStep(0.013), 0.02);
  assert.equal(niceStep(0.3), 0.5);
  assert.equal(niceStep(1), 1);
  assert.equal(round9(0.1 + 0.2), 0.3);
  assert.equal(taskBounds({ trajectory: [], obstacles: [], base_regions: [] }), null);
  assert.deepEqual(taskBounds({ obstacles: [{ center: [1, 1], radius: 0.5 }], base_regions: [{ min: [-1, 0], max: [0, 2] }] }),
                   { min: [-1, 0], max: [1.5, 2] });
});

// Spatial tasks in the editor: their geometry (web/space_geometry.js) and
// their edits (web/space_edit.js), on the examples of tasks/spatial/.

import assert from "node:assert/strict";
import fs from "node:fs";
import { test } from "node:test";

import { TaskModel } from "../../web/task_model.js";
import {
  arcSweep3, handles3, helixPoint, isSpatial, namedPrimitives, primitiveEnd3, primitiveLength3, reachLine,
  samplePrimitive3, spatialBounds,
} from "../../web/space_geometry.js";
import { SPATIAL_EXAMPLES, addSpatialPart, emptySpatialTask, setObstacleKind, setPoint3 } from "../../web/space_edit.js";

const example = (name) => JSON.parse(fs.readFileSync(new URL(`../../tasks/spatial/${name}.json`, import.meta.url), "utf8"));
const close = (a, b, tol = 1e-9) => a.every((v, i) => Math.abs(v - b[i]) <= tol);

function modelWith(doc) {
  const model = new TaskModel();
  model.reset(doc);
  return model;
}

test("the examples served to the page are the spatial tasks of tasks/spatial/", () => {
  const names = fs.readdirSync(new URL("../../tasks/spatial/", import.meta.url)).filter((f) => f.endsWith(".json"));
  assert.deepEqual([...SPATIAL_EXAMPLES].sort(), names.map((f) => f.replace(/\.json$/, "")).sort());
  for (const name of SPATIAL_EXAMPLES) assert.ok(isSpatial(example(name)), name);
  assert.ok(!isSpatial({ trajectory: [] }));
  assert.ok(isSpatial(emptySpatialTask()));
});

test("an arc turns about its normal as formats.md says: ccw right-handed", () => {
  const arc = { type: "arc", start: [0.35, -0.1, 0.05], end: [0.35, 0.1, 0.05], center: [0.35, 0, 0.05], normal: [1, 0, 0], direction: "cw" };
  assert.ok(Math.abs(arcSweep3(arc) + Math.PI) < 1e-12);
  // Half-way round clockwise about +x from -y to +y passes below? Rot(x, -pi/2)(0, -0.1, 0) = (0, 0, 0.1): above.
  const pts = samplePrimitive3(arc);
  assert.ok(close(pts[0], arc.start) && close(pts[pts.length - 1], arc.end));
  assert.ok(close(pts[pts.length >> 1], [0.35, 0, 0.15], 1e-9));
  assert.ok(Math.abs(primitiveLength3(arc) - Math.PI * 0.1) < 1e-12);
  assert.ok(Math.abs(arcSweep3({ ...arc, direction: "ccw" }) - Math.PI) < 1e-12);
});

test("a helix climbs pitch per turn and ends where its turns take it", () => {
  const h = example("helix-pipe").trajectory[0];
  assert.ok(close(helixPoint(h, 0), h.start));
  assert.ok(close(primitiveEnd3(h), [0.12, 0, 0.2], 1e-12));
  // Two turns: an eighth of a turn at u = 1/16, a sixteenth of the climb.
  assert.ok(close(helixPoint(h, 1 / 16), [0.12 * Math.SQRT1_2, 0.12 * Math.SQRT1_2, 0.1 + 0.1 / 16], 1e-12));
  assert.ok(Math.abs(primitiveLength3(h) - 2 * Math.hypot(2 * Math.PI * 0.12, 0.05)) < 1e-12);
  assert.ok(close(samplePrimitive3(h).at(-1), [0.12, 0, 0.2], 1e-12));
  assert.deepEqual(samplePrimitive3({ ...h, turns: -1 }), []);
});

test("the view frames the work, not the table it stands on", () => {
  const b = spatialBounds(example("glue-box-edges"));
  assert.ok(close(b.min, [-0.1, -0.11, 0]) && close(b.max, [0.56, 0.11, 0.105]), JSON.stringify(b));
  assert.equal(spatialBounds({ space: "3d", trajectory: [], obstacles: [], base_regions: [] }), null);
});

test("handles: points of primitives, a sphere's centre, a box's corners and middle", () => {
  const doc = example("glue-box-edges");
  assert.deepEqual(handles3("trajectory", doc.trajectory[0]).map((h) => h.key), ["start", "end"]);
  assert.deepEqual(handles3("obstacles", doc.obstacles[0]).map((h) => h.key), ["min", "max", "middle"]);
  assert.deepEqual(handles3("base_regions", doc.base_regions[0]).find((h) => h.key === "middle").point, [0, 0, 0.02]);
  assert.deepEqual(handles3("trajectory", example("helix-pipe").trajectory[0]).map((h) => h.key), ["start", "center"]);
  assert.deepEqual(namedPrimitives({ strokes: [[{}], [{}, {}]] }).map((p) => p.part), ["strokes[0][0]", "strokes[1][0]", "strokes[1][1]"]);
});

test("moving a vertex moves the neighbour that shares it; a middle moves a box whole", () => {
  const model = modelWith(example("glue-box-edges"));
  setPoint3(model, "trajectory[1]", "start", [0.6, -0.11, 0.105]);
  assert.deepEqual(model.doc.trajectory[1].start, [0.6, -0.11, 0.105]);
  assert.deepEqual(model.doc.trajectory[0].end, [0.6, -0.11, 0.105]);
  model.undo();
  assert.deepEqual(model.doc.trajectory[0].end, [0.56, -0.11, 0.105]);
  // The path's start is its own: the loop's last line still ends where it did.
  setPoint3(model, "trajectory[0]", "start", [10, -0.11, 0.105]);
  assert.deepEqual(model.doc.trajectory[3].end, [0.34, -0.11, 0.105]);
  setPoint3(model, "base_regions[0]", "middle", [0.01, 0.02, 0.03]);
  assert.deepEqual(model.doc.base_regions[0], { min: [-0.09, -0.08, 0.03], max: [0.11, 0.12, 0.03] });
  setPoint3(model, "obstacles[0]", "max", [0.6, 0.1, 0.1]);
  assert.deepEqual(model.doc.obstacles[0].max, [0.6, 0.1, 0.1]);
});

test("a drag is one undo step", () => {
  const model = modelWith(example("glue-box-edges"));
  const steps = model.undoStack.length;
  model.beginGesture();
  for (const y of [0.01, 0.02, 0.03]) setPoint3(model, "base_regions[0]", "middle", [0, y, 0.02], true);
  assert.equal(model.undoStack.length, steps + 1);
  model.undo();
  assert.deepEqual(model.doc.base_regions[0].min, [-0.1, -0.1, 0.02]);
});

test("a line after a helix starts where the helix ends, and moving it leaves the helix whole", () => {
  const model = modelWith(example("helix-pipe"));
  assert.equal(addSpatialPart(model, "line"), "trajectory[1]");
  assert.ok(close(model.doc.trajectory[1].start, [0.12, 0, 0.2], 1e-9));
  setPoint3(model, "trajectory[1]", "start", [0.2, 0, 0.2]);
  assert.equal(model.doc.trajectory[0].end, undefined);
  assert.equal(addSpatialPart(model, "capsule"), "obstacles[2]");
  assert.equal(addSpatialPart(model, "base"), "base_regions[1]");
  assert.throws(() => addSpatialPart(model, "cone"));
});

test("an obstacle turns into another kind about the same place", () => {
  const model = modelWith(example("helix-pipe"));
  setObstacleKind(model, "obstacles[0]", "sphere");
  assert.deepEqual(model.doc.obstacles[0], { type: "sphere", center: [0, 0, 0.15], radius: 0.03 });
  setObstacleKind(model, "obstacles[0]", "box");
  assert.deepEqual(model.doc.obstacles[0], { type: "box", min: [-0.03, -0.03, 0.12], max: [0.03, 0.03, 0.18] });
});

test("a proof of reach is drawn from the nearest base box to the primitive's farthest point", () => {
  const doc = example("glue-box-edges");
  doc.trajectory[0].start = [10, -0.11, 0.105];
  const line = reachLine(doc, doc.trajectory[0]);
  assert.deepEqual(line.from, [0, 0, 0.02]);
  assert.deepEqual(line.to, [10, -0.11, 0.105]);
  assert.equal(reachLine({ ...doc, base_regions: [] }, doc.trajectory[0]), null);
});

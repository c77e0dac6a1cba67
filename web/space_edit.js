// Edits of spatial tasks (formats.md "Spatial tasks"), each one undoable
// step of the task model (or one update inside a drag): moving a point of
// a part, a capsule or a box whole, adding parts in space and turning an
// obstacle into another kind. A spatial task is started from an example
// of tasks/spatial/ (served beside the page) or empty.

import { moveVertex } from "./task_model.js";
import { round9 } from "./geometry.js";
import { splitPart, partName } from "./parts.js";
import { add, isPoint3, middlePair, mid, obstacleKind, primitiveEnd3, sub } from "./space_geometry.js";

/// The examples of tasks/spatial/, served as /NAME.json.
export const SPATIAL_EXAMPLES = ["glue-box-edges", "helix-pipe", "over-fixture", "scara-dispense", "tilted-plane-drawing"];

/// The robot a spatial task leaves to its defaults (formats.md).
export const SPATIAL_ROBOT_DEFAULTS = { dof: [3, 4], link_diameter: 0.03175, min_link_length: 0.05, max_link_length: 1.0, tool_length: 0 };

/// A base box standing on a 2 cm plate at the origin, as the examples'.
export const DEFAULT_BASE_BOX = { min: [-0.05, -0.05, 0.02], max: [0.05, 0.05, 0.02] };

export function emptySpatialTask() {
  return {
    format: "modsynth-task/1", name: "untitled", space: "3d",
    trajectory: [], obstacles: [], base_regions: [JSON.parse(JSON.stringify(DEFAULT_BASE_BOX))],
    robot: { dof: [3, 4], link_diameter: 0.03175, min_link_length: 0.05, max_link_length: 1.0 },
  };
}

export async function fetchSpatialExample(name) {
  const res = await fetch("/" + name + ".json");
  if (!res.ok) throw new Error(`${name}: HTTP ${res.status}`);
  return res.json();
}

const round3 = (p) => p.map(round9);

/// Sets the point `key` of a part; "middle" moves a capsule's ends or a
/// box's corners together. A primitive's start or end is shared with its
/// neighbours, which move with it.
export function setPoint3(model, part, key, point, inGesture = false) {
  const s = splitPart(part);
  if (!s || !isPoint3(point)) return;
  const edit = (d) => {
    const [list, i] = s;
    const item = d[list][i];
    if (!item) return;
    const p = round3(point);
    if (list === "trajectory" && (key === "start" || key === "end")) {
      moveVertex(d, key === "start" || item.type === "circle" ? i : i + 1, p);
    } else if (key === "middle") {
      const [a, b] = middlePair(list, item);
      if (!isPoint3(item[a]) || !isPoint3(item[b])) return;
      const shift = sub(p, mid(item[a], item[b]));
      item[a] = round3(add(item[a], shift));
      item[b] = round3(add(item[b], shift));
    } else {
      item[key] = p;
    }
  };
  if (inGesture) model.updateInGesture(edit); else model.change(edit);
}

/// Adds a part near the work; primitives start where the path ends. Returns
/// its name.
export function addSpatialPart(model, kind) {
  const t = model.trajectory;
  const end = (t.length && primitiveEnd3(t[t.length - 1])) || [0.4, 0, 0.2];
  const at = (v) => round3(add(end, v));
  const primitives = {
    line: () => ({ type: "line", start: [...end], end: at([0, 0.1, 0]) }),
    arc: () => ({ type: "arc", start: [...end], end: at([0.1, 0, 0]), center: at([0.05, 0, 0]), normal: [0, 0, 1], direction: "ccw" }),
    circle: () => ({ type: "circle", start: [...end], center: at([0.05, 0, 0]), normal: [0, 0, 1], direction: "ccw" }),
    helix: () => ({ type: "helix", start: [...end], center: at([0.05, 0, 0]), axis: [0, 0, 1], direction: "ccw", pitch: 0.02, turns: 1 }),
  };
  if (primitives[kind]) {
    model.change((d) => d.trajectory.push(primitives[kind]()));
    return partName("trajectory", model.trajectory.length - 1);
  }
  const obstacles = {
    sphere: () => ({ type: "sphere", center: [0.3, 0.3, 0.1], radius: 0.05 }),
    capsule: () => ({ type: "capsule", a: [0.3, 0.3, 0], b: [0.3, 0.3, 0.2], radius: 0.03 }),
    box: () => ({ type: "box", min: [0.25, 0.25, 0], max: [0.35, 0.35, 0.1] }),
  };
  if (obstacles[kind]) {
    model.change((d) => d.obstacles.push(obstacles[kind]()));
    return partName("obstacles", model.obstacles.length - 1);
  }
  if (kind === "base") {
    model.change((d) => d.base_regions.push(JSON.parse(JSON.stringify(DEFAULT_BASE_BOX))));
    return partName("base_regions", model.regions.length - 1);
  }
  throw new Error("no such part: " + kind);
}

/// Turns an obstacle into a sphere, capsule or box of about its place and size.
export function setObstacleKind(model, part, kind) {
  const s = splitPart(part);
  const o = model.item(part);
  if (!s || !o || obstacleKind(o) === kind) return;
  const from = obstacleKind(o);
  const centre = from === "sphere" && isPoint3(o.center) ? o.center
    : from === "capsule" && isPoint3(o.a) && isPoint3(o.b) ? mid(o.a, o.b)
    : from === "box" && isPoint3(o.min) && isPoint3(o.max) ? mid(o.min, o.max) : [0.3, 0.3, 0.1];
  const r = Number.isFinite(o.radius) && o.radius > 0 ? o.radius
    : from === "box" && isPoint3(o.min) && isPoint3(o.max) ? Math.max(1e-3, Math.min(...sub(o.max, o.min)) / 2) : 0.05;
  const made = kind === "sphere" ? { type: "sphere", center: round3(centre), radius: r }
    : kind === "capsule" ? { type: "capsule", a: round3(sub(centre, [0, 0, r])), b: round3(add(centre, [0, 0, r])), radius: r }
    : { type: "box", min: round3(sub(centre, [r, r, r])), max: round3(add(centre, [r, r, r])) };
  model.change((d) => { d.obstacles[s[1]] = made; });
}

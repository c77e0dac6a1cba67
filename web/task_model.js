// The task being edited: a modsynth-task/1 document kept as plain JSON, so
// that what is saved, validated and solved is exactly what is shown. Every
// edit goes through change(), which records the document before it for
// undo. Listeners hear "change" after every edit, undo, redo and load (the
// store passes it on to the page).

import { isPoint, primitiveEnd, roundPoint } from "./geometry.js";
import { partName, splitPart } from "./parts.js";
import { isPoint3 } from "./space_geometry.js";

/// A task with nothing in it yet. `robot` is what its robot block starts
/// as (the server's defaults, from GET /api/info); without it the block is
/// empty and the server applies the same defaults.
export function emptyTask(robot = {}) {
  return {
    format: "modsynth-task/1",
    name: "untitled",
    trajectory: [],
    obstacles: [],
    base_regions: [],
    robot: JSON.parse(JSON.stringify(robot)),
  };
}

/// The example of formats.md: a line, an arc and a circle around one obstacle.
export function exampleTask() {
  return {
    format: "modsynth-task/1",
    name: "example",
    trajectory: [
      { type: "line", start: [0.40, 0.10], end: [0.55, 0.10] },
      { type: "arc", start: [0.55, 0.10], end: [0.55, 0.20], center: [0.55, 0.15], direction: "ccw" },
      { type: "circle", start: [0.55, 0.20], center: [0.55, 0.25], direction: "cw" },
    ],
    obstacles: [{ center: [0.30, 0.40], radius: 0.05 }],
    base_regions: [{ min: [-0.10, -0.10], max: [0.10, 0.10] }],
    robot: { dof: [2, 3], link_diameter: 0.03175, min_link_length: 0.05, max_link_length: 1.0 },
  };
}

const HISTORY_LIMIT = 200;

/// Vertex k of a path is where primitive k starts and primitive k-1 ends.
/// A circle starts and ends at one point, so its two vertices are one: the
/// move carries through it.
export function moveVertex(doc, k, p) {
  const t = doc.trajectory;
  let lo = k, hi = k;
  while (lo > 0 && t[lo - 1] && t[lo - 1].type === "circle") --lo;
  while (hi < t.length && t[hi] && t[hi].type === "circle") ++hi;
  for (let j = lo; j <= hi; ++j) {
    if (j < t.length && t[j]) t[j].start = [...p];
    // A helix ends where its turns take it: an end is only checked against that.
    const keepsEnd = t[j - 1] && (t[j - 1].type === "circle" || (t[j - 1].type === "helix" && t[j - 1].end === undefined));
    if (j > 0 && t[j - 1] && !keepsEnd) t[j - 1].end = [...p];
  }
}

export class TaskModel extends EventTarget {
  constructor() {
    super();
    this.doc = emptyTask();
    this.undoStack = [];
    this.redoStack = [];
  }

  get trajectory() { return Array.isArray(this.doc.trajectory) ? this.doc.trajectory : []; }
  get obstacles() { return Array.isArray(this.doc.obstacles) ? this.doc.obstacles : []; }
  /// The strokes of a task of several (formats.md "Several strokes"), each
  /// a list of primitives; empty for a task of one trajectory.
  get strokes() { return Array.isArray(this.doc.strokes) ? this.doc.strokes.filter(Array.isArray) : []; }
  get regions() { return Array.isArray(this.doc.base_regions) ? this.doc.base_regions : []; }

  /// Applies `edit` to the document as one undoable step.
  change(edit) {
    this.undoStack.push(JSON.stringify(this.doc));
    if (this.undoStack.length > HISTORY_LIMIT) this.undoStack.shift();
    this.redoStack = [];
    this.ensureLists();
    edit(this.doc);
    this.notify();
  }

  /// Replaces the document with no way back: what the page starts from.
  reset(doc) {
    this.doc = JSON.parse(JSON.stringify(doc));
    this.undoStack = [];
    this.redoStack = [];
    this.notify();
  }

  /// For a drag: one undo step for the whole gesture, then silent updates.
  beginGesture() { this.change(() => {}); }
  updateInGesture(edit) { edit(this.doc); this.notify(); }

  undo() { this.travel(this.undoStack, this.redoStack); }
  redo() { this.travel(this.redoStack, this.undoStack); }
  get canUndo() { return this.undoStack.length > 0; }
  get canRedo() { return this.redoStack.length > 0; }

  travel(from, to) {
    if (!from.length) return;
    to.push(JSON.stringify(this.doc));
    this.doc = JSON.parse(from.pop());
    this.notify();
  }

  /// Replaces the document (undoable). Anything JSON may come in; the
  /// server says what is wrong with it.
  load(doc) {
    this.change((d) => {
      for (const k of Object.keys(d)) delete d[k];
      Object.assign(d, JSON.parse(JSON.stringify(doc)));
    });
  }

  notify() { this.dispatchEvent(new Event("change")); }

  ensureLists() {
    for (const k of ["trajectory", "obstacles", "base_regions"]) {
      // A task of strokes holds no trajectory besides.
      if (k === "trajectory" && Array.isArray(this.doc.strokes)) continue;
      if (!Array.isArray(this.doc[k])) this.doc[k] = [];
    }
  }

  /// Where the next primitive starts: the end of the last one.
  /// In a task of strokes, the last stroke's: drawing goes on from there.
  pathEnd() {
    const strokes = this.doc.strokes;
    const t = Array.isArray(strokes) ? (Array.isArray(strokes[strokes.length - 1]) ? strokes[strokes.length - 1] : [])
                                     : this.trajectory;
    return t.length ? primitiveEnd(t[t.length - 1]) : null;
  }

  addPrimitive(p) {
    const strokes = this.doc.strokes;
    if (Array.isArray(strokes)) {
      const s = strokes.length - 1;
      if (s >= 0 && Array.isArray(strokes[s])) {
        this.change((d) => d.strokes[s].push(p));
        return `strokes[${s}][${this.doc.strokes[s].length - 1}]`;
      }
      this.change((d) => d.strokes.push([p]));
      return `strokes[${s + 1}][0]`;
    }
    this.change((d) => d.trajectory.push(p));
    return partName("trajectory", this.trajectory.length - 1);
  }

  addObstacle(center, radius) {
    this.change((d) => d.obstacles.push({ center: roundPoint(center), radius }));
    return partName("obstacles", this.obstacles.length - 1);
  }

  addRegion(a, b) {
    const min = roundPoint([Math.min(a[0], b[0]), Math.min(a[1], b[1])]);
    const max = roundPoint([Math.max(a[0], b[0]), Math.max(a[1], b[1])]);
    this.change((d) => d.base_regions.push({ min, max }));
    return partName("base_regions", this.regions.length - 1);
  }

  /// The object a part name refers to, or undefined.
  item(part) {
    const s = splitPart(part);
    if (!s) return undefined;
    const list = this.doc[s[0]];
    return Array.isArray(list) ? list[s[1]] : undefined;
  }

  /// Removes a part. Removing a primitive from the middle of the path joins
  /// its neighbours where it started, so the path stays connected.
  remove(part) {
    const s = splitPart(part);
    if (!s || this.item(part) === undefined) return;
    this.change((d) => {
      const [list, i] = s;
      if (list === "trajectory" && i + 1 < d.trajectory.length && (isPoint(d.trajectory[i].start) || isPoint3(d.trajectory[i].start))) {
        moveVertex(d, i + 1, d.trajectory[i].start);
      }
      d[list].splice(i, 1);
    });
  }

  /// Sets the point `key` ("start", "end", "center", "min", "max") of a
  /// part. A primitive's start or end is shared with its neighbours, which
  /// move with it.
  setPoint(part, key, point, inGesture = false) {
    const s = splitPart(part);
    if (!s) return;
    const edit = (d) => {
      const [list, i] = s;
      const p = roundPoint(point);
      if (list === "trajectory" && (key === "start" || key === "end")) {
        const k = key === "start" || d.trajectory[i].type === "circle" ? i : i + 1;
        moveVertex(d, k, p);
      } else {
        d[list][i][key] = p;
      }
    };
    if (inGesture) this.updateInGesture(edit); else this.change(edit);
  }

  /// Sets a plain field (radius, direction, type ...) of a part.
  setField(part, key, value) {
    const s = splitPart(part);
    if (!s) return;
    this.change((d) => { d[s[0]][s[1]][key] = value; });
  }

  /// Sets a robot setting; an empty value removes it, so its default holds.
  setRobot(key, value) {
    this.change((d) => {
      if (!d.robot || typeof d.robot !== "object") d.robot = {};
      if (value === "" || value === undefined) delete d.robot[key]; else d.robot[key] = value;
    });
  }

  setName(name) { this.change((d) => { d.name = name; }); }
}

// The drawing tools: the points clicked so far for the part being drawn,
// the preview of it under the cursor, the hint for the next click, and
// adding the part to the task once its last point is in.

import { samplePrimitive } from "./geometry.js";
import { POINTS_NEEDED, shapeOf, STARTS_AT_PATH_END } from "./shapes.js";
import { pointsAttr, svg } from "./dom.js";

const HINTS = {
  select: "Select: click a part to edit it, drag to move or resize; drag the background to pan, wheel to zoom.",
  line: ["Line: click its start.", "Line: click its end."],
  arc: ["Arc: click its start.", "Arc: click its end.", "Arc: click a point on the arc."],
  circle: ["Circle: click its start.", "Circle: click its centre (Shift: clockwise)."],
  obstacle: ["Obstacle: click its centre.", "Obstacle: click its rim."],
  region: ["Base region: click a corner.", "Base region: click the opposite corner."],
};

export class DrawTool {
  constructor(store, view, layer) {
    this.store = store;
    this.view = view;
    this.layer = layer;
    this.pending = [];   // points clicked so far for the part being drawn
    this.mouse = null;   // snapped task point under the cursor
  }

  get tool() { return this.store.tool; }
  get clicks() { return this.pending.length; }
  get drawing() { return this.pending.length > 0; }

  /// The cursor is at task point p (snapped), or off the canvas (null).
  hover(p) { this.mouse = p; }

  /// Forgets the points clicked so far; false when there were none.
  cancel() {
    const had = this.drawing;
    this.pending = [];
    this.render();
    return had;
  }

  hint() {
    const h = HINTS[this.tool];
    if (typeof h === "string") return h;
    const start = this.startsAtPathEnd() ? 1 : 0;
    return h[Math.min(h.length - 1, this.pending.length + start)];
  }

  startsAtPathEnd() {
    return STARTS_AT_PATH_END.includes(this.tool) && this.store.model.pathEnd() !== null;
  }

  /// The points of the part being drawn, the path's end first when it
  /// starts there, then the clicks, then `next`.
  points(next) {
    const start = this.startsAtPathEnd() ? [this.store.model.pathEnd()] : [];
    return start.concat(this.pending, next ? [next] : []);
  }

  /// One click at task point p.
  click(p, shiftKey) {
    const pts = this.points(p);
    if (pts.length < POINTS_NEEDED[this.tool]) {
      this.pending.push(p);
    } else {
      // A last click that makes nothing (a point on the chord, a zero
      // radius) is ignored: the points before it stay.
      const shape = shapeOf(this.tool, pts, shiftKey);
      if (shape) {
        this.pending = [];
        this.commit(shape);
      }
    }
    this.render();
  }

  commit(shape) {
    const model = this.store.model;
    let part = null;
    if (shape.kind === "primitive") part = model.addPrimitive(JSON.parse(JSON.stringify(shape.value)));
    else if (shape.kind === "obstacle") part = model.addObstacle(shape.center, shape.radius);
    else if (shape.kind === "region") part = model.addRegion(shape.a, shape.b);
    if (part) this.store.select(part);
  }

  render() {
    const g = this.layer;
    g.replaceChildren();
    if (this.tool === "select" || !this.mouse) return;
    const scr = (p) => this.view.toScreen(p);
    const pts = this.points(this.mouse);
    for (const p of pts.slice(0, -1)) {
      const q = scr(p);
      svg("circle", { cx: q[0], cy: q[1], r: 3.5, class: "preview-point" }, g);
    }
    const m = scr(this.mouse);
    svg("circle", { cx: m[0], cy: m[1], r: 4, class: "preview-point", id: "cursor-mark" }, g);
    const shape = shapeOf(this.tool, pts);
    if (!shape) return;
    if (shape.kind === "primitive") {
      const sampled = samplePrimitive(shape.value);
      if (sampled.length > 1) svg("polyline", { points: pointsAttr(sampled.map(scr)), class: "preview" }, g);
    } else if (shape.kind === "obstacle") {
      const c = scr(shape.center);
      svg("circle", { cx: c[0], cy: c[1], r: shape.radius * this.view.s, class: "preview" }, g);
    } else if (shape.kind === "region") {
      const a = scr(shape.a), b = scr(shape.b);
      svg("rect", { x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(b[0] - a[0]),
                    height: Math.abs(b[1] - a[1]), class: "preview" }, g);
    } else if (shape.kind === "chord") {
      const a = scr(shape.a), b = scr(shape.b);
      svg("line", { x1: a[0], y1: a[1], x2: b[0], y2: b[1], class: "preview" }, g);
    }
  }
}

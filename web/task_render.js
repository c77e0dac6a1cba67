// The task drawn on the canvas as the report draws it, over a metric grid:
// every part carries data-part with its name in the task ("obstacles[1]"),
// marked when selected, in error or in a core, with the server's messages
// written beside the parts they are about.

import { endDirection, isPoint, niceStep, round9, samplePrimitive } from "./geometry.js";
import { handlesOf, HANDLE_PIXELS } from "./handles.js";
import { placeLabels } from "./label_layout.js";
import { splitPart } from "./parts.js";
import { pointsAttr, svg } from "./dom.js";

// The report's colours (src/output/plot.cpp), so a primitive keeps its
// colour from the editor to the result.
// As the report's (src/output/plot.cpp): no red, green or grey, which
// mean obstacles and conflicts, a wall's cells, the arm and base regions.
const COLOURS = ["#1f77b4", "#ff7f0e", "#e7ba52", "#9467bd", "#8c564b",
                 "#e377c2", "#17becf", "#bcbd22", "#006d77", "#393b79"];
export const primitiveColour = (j) => COLOURS[j % COLOURS.length];

const MIN_LABEL_PIXELS = 55;
const SMALL_PIXELS = 24;      // a core part smaller than this gets a ring
const LABEL_CHARS = 90;

export class TaskRender {
  /// `layers` are SVG groups by name (grid, regions, obstacles, trajectory,
  /// labels), bottom to top.
  constructor(layers, store, view) {
    this.layers = layers;
    this.store = store;
    this.view = view;
  }

  render() {
    this.renderGrid();
    this.renderRegions();
    this.renderObstacles();
    this.renderTrajectory();
    this.renderHandles();
    this.renderLabels();
  }

  renderGrid() {
    const g = this.layers.grid, view = this.view;
    g.replaceChildren();
    const [w, h] = view.size();
    const step = view.gridStep(), major = niceStep(step * 4.5), labelled = niceStep(MIN_LABEL_PIXELS / view.s);
    const [x0, y1] = view.toWorld([0, 0]), [x1, y0] = view.toWorld([w, h]);
    const multiple = (v, of) => Math.abs(v / of - Math.round(v / of)) < 1e-6;
    const cls = (i, v) => (i === 0 ? "axis" : multiple(v, major) ? "grid-major" : "grid-minor");
    const label = (v) => (Math.abs(v) < 1e-12 ? 0 : round9(v)).toString();
    for (let i = Math.ceil(x0 / step); i * step <= x1; ++i) {
      const v = i * step, x = view.toScreen([v, 0])[0];
      svg("line", { x1: x, y1: 0, x2: x, y2: h, class: cls(i, v) }, g);
      if (multiple(v, labelled)) svg("text", { x: x + 3, y: h - 6, class: "grid-label" }, g).textContent = label(v);
    }
    for (let i = Math.ceil(y0 / step); i * step <= y1; ++i) {
      const v = i * step, y = view.toScreen([0, v])[1];
      svg("line", { x1: 0, y1: y, x2: w, y2: y, class: cls(i, v) }, g);
      if (multiple(v, labelled)) svg("text", { x: 4, y: y - 3, class: "grid-label" }, g).textContent = label(v);
    }
    svg("text", { x: w - 10, y: 20, "text-anchor": "end", class: "scale-text", id: "grid-scale" }, g).textContent =
      "grid " + (step >= 1 ? step + " m" : round9(step * 100) + " cm") + ", labels in m";
  }

  classes(part, base) {
    const names = [base];
    if (part === this.store.selection) names.push("selected");
    if (this.store.errorsAbout(part).length) names.push("error");
    if (this.store.inCore(part)) names.push("core");
    return names.join(" ");
  }

  renderRegions() {
    const g = this.layers.regions;
    g.replaceChildren();
    this.store.model.regions.forEach((r, i) => {
      if (!r || !isPoint(r.min) || !isPoint(r.max)) return;
      const part = `base_regions[${i}]`;
      const a = this.view.toScreen([r.min[0], r.max[1]]), b = this.view.toScreen([r.max[0], r.min[1]]);
      svg("rect", { x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(b[0] - a[0]),
                    height: Math.abs(b[1] - a[1]), class: this.classes(part, "region"), "data-part": part }, g);
    });
  }

  renderObstacles() {
    const g = this.layers.obstacles;
    g.replaceChildren();
    this.store.model.obstacles.forEach((o, i) => {
      if (!o || !isPoint(o.center) || !(o.radius > 0)) return;
      const part = `obstacles[${i}]`;
      const c = this.view.toScreen(o.center);
      svg("circle", { cx: c[0], cy: c[1], r: o.radius * this.view.s, class: this.classes(part, "obstacle"), "data-part": part }, g);
    });
  }

  renderTrajectory() {
    const g = this.layers.trajectory;
    g.replaceChildren();
    const t = this.store.model.trajectory;
    t.forEach((p, j) => {
      const pts = samplePrimitive(p);
      if (pts.length < 2) return;
      const part = `trajectory[${j}]`;
      const screen = pts.map((q) => this.view.toScreen(q));
      if (this.store.inCore(part)) this.coreHalo(g, screen);
      svg("polyline", { points: pointsAttr(screen), class: this.classes(part, "primitive"), stroke: primitiveColour(j),
                        "data-part": part, "data-type": p.type }, g);
      this.arrow(g, pts, primitiveColour(j));
    });
    if (t.length && isPoint(t[0].start)) {
      const s = this.view.toScreen(t[0].start);
      svg("circle", { cx: s[0], cy: s[1], r: 5, class: "path-start" }, g);
    }
    this.renderStrokes(g);
  }

  /// A task of several strokes (an imported drawing): each stroke's
  /// primitives, coloured along the whole, with a mark where each begins.
  renderStrokes(g) {
    let j = 0;
    this.store.model.strokes.forEach((stroke, s) => {
      stroke.forEach((p, k) => {
        const pts = samplePrimitive(p);
        const part = `strokes[${s}][${k}]`, colour = primitiveColour(j++);
        if (pts.length < 2) return;
        const screen = pts.map((q) => this.view.toScreen(q));
        svg("polyline", { points: pointsAttr(screen), class: this.classes(part, "primitive"), stroke: colour,
                          "data-part": part, "data-type": p.type }, g);
        this.arrow(g, pts, colour);
      });
      if (stroke.length && isPoint(stroke[0].start)) {
        const q = this.view.toScreen(stroke[0].start);
        svg("circle", { cx: q[0], cy: q[1], r: 4, class: "path-start" }, g);
      }
    });
  }

  /// A wide translucent band under a core primitive, and a ring around one
  /// too small to see at this zoom, so that no part of a core goes unnoticed.
  coreHalo(g, screen) {
    svg("polyline", { points: pointsAttr(screen), class: "core-halo" }, g);
    const xs = screen.map((q) => q[0]), ys = screen.map((q) => q[1]);
    if (Math.max(...xs) - Math.min(...xs) < SMALL_PIXELS && Math.max(...ys) - Math.min(...ys) < SMALL_PIXELS) {
      const c = [(Math.max(...xs) + Math.min(...xs)) / 2, (Math.max(...ys) + Math.min(...ys)) / 2];
      svg("circle", { cx: c[0], cy: c[1], r: 18, class: "core-ring" }, g);
    }
  }

  arrow(g, pts, colour) {
    const d = endDirection(pts);
    if (!d) return;
    const tip = this.view.toScreen(pts[pts.length - 1]);
    const dx = d[0], dy = -d[1];  // screen y points down
    const back = [tip[0] - 11 * dx, tip[1] - 11 * dy];
    const side = [-dy * 5, dx * 5];
    svg("polygon", { points: pointsAttr([tip, [back[0] + side[0], back[1] + side[1]], [back[0] - side[0], back[1] - side[1]]]),
                     fill: colour, class: "arrow" }, g);
  }

  /// The selected part's handles, above everything they belong to.
  renderHandles() {
    const part = this.store.selection;
    const g = this.layers.handles;
    g.replaceChildren();
    for (const { handle, point, shape } of handlesOf(this.store.doc, part)) {
      const q = this.view.toScreen(point), r = HANDLE_PIXELS;
      const attrs = { class: "handle", "data-part": part, "data-handle": handle };
      if (shape === "square") svg("rect", { x: q[0] - r + 1, y: q[1] - r + 1, width: 2 * r - 2, height: 2 * r - 2, ...attrs }, g);
      else svg("circle", { cx: q[0], cy: q[1], r, ...attrs }, g);
    }
  }

  /// Messages next to the parts they are about, and a mark on core parts.
  renderLabels() {
    const g = this.layers.labels;
    g.replaceChildren();
    for (const [part, message] of this.store.errors) {
      // Beside its part the message need not name it again.
      const plain = message.startsWith(part + ": ") ? message.slice(part.length + 2) : message;
      this.label(g, part, plain.length > LABEL_CHARS ? plain.slice(0, LABEL_CHARS - 3) + "..." : plain, -10, "error-label");
    }
    this.coreLabels(g);
  }

  /// The parts in conflict, each named beside it, outside the conflict
  /// (round a ring, round its outside) and clear of each other.
  coreLabels(g) {
    const items = [];
    for (const part of this.store.core) {
      const where = this.extent(part);
      if (!where) continue;
      const text = svg("text", { class: "core-label", "data-part": part }, g);
      text.textContent = part;
      const width = typeof text.getComputedTextLength === "function" ? text.getComputedTextLength() : 7 * part.length;
      items.push({ id: part, centre: where.centre, reach: where.reach, width, text });
    }
    placeLabels(items, this.view.size()[0]).forEach((p, i) => {
      const t = items[i].text;
      t.setAttribute("x", p.x);
      t.setAttribute("y", p.y);
      t.setAttribute("text-anchor", p.anchor);
    });
  }

  /// A part's middle on the screen and how far it reaches from there
  /// (pixels), or null.
  extent(part) {
    const model = this.store.model;
    const kind = (splitPart(part) || [])[0];
    const item = model.item(part);
    const boxOf = (pts) => {
      const q = pts.filter(isPoint).map((p) => this.view.toScreen(p));
      if (!q.length) return null;
      const lo = [Math.min(...q.map((p) => p[0])), Math.min(...q.map((p) => p[1]))];
      const hi = [Math.max(...q.map((p) => p[0])), Math.max(...q.map((p) => p[1]))];
      return { centre: [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2], reach: Math.hypot(hi[0] - lo[0], hi[1] - lo[1]) / 2 };
    };
    if (kind === "obstacles") {
      return item && isPoint(item.center) ? { centre: this.view.toScreen(item.center), reach: (item.radius || 0) * this.view.s } : null;
    }
    if (kind === "trajectory" || kind === "strokes") return item ? boxOf(samplePrimitive(item)) : null;
    if (kind === "base_regions") return item ? boxOf([item.min, item.max]) : null;
    if (part === "base_regions") return boxOf(model.regions.flatMap((r) => [r.min, r.max]));
    return null;
  }

  /// A text beside a part, on whichever side leaves it room.
  label(g, part, text, dy, cls) {
    const anchor = this.anchor(part);
    if (!anchor) return;
    const left = anchor[0] > this.view.size()[0] / 2;
    svg("text", { x: anchor[0] + (left ? -10 : 10), y: anchor[1] + dy, "text-anchor": left ? "end" : "start",
                  class: cls, "data-part": part }, g).textContent = text;
  }

  /// A screen point near a part, for its label.
  anchor(part) {
    const model = this.store.model;
    const item = model.item(part);
    const kind = (splitPart(part) || [])[0];
    let p = null;
    if (kind === "trajectory") p = item && (isPoint(item.end) ? item.end : item.start);
    else if (kind === "obstacles") p = item && isPoint(item.center) && [item.center[0] + (item.radius || 0), item.center[1]];
    else if (kind === "base_regions") p = item && item.max;
    else if (part === "base_regions" && model.regions.length) p = model.regions[0].max;
    return isPoint(p) ? this.view.toScreen(p) : null;
  }
}

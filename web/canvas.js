// The drawing surface: a metric grid in an SVG, zoom (wheel) and pan (drag
// the background, or the middle or right button anywhere), the task drawn
// as the report draws it, and the tools that add parts by clicking. Every
// part carries data-part with its name in the task ("obstacles[1]") so that
// the server's messages and explanations can point at it.

import {
  circumcenter, dist, endDirection, isPoint, niceStep, primitiveEnd, round9, roundPoint,
  samplePrimitive, taskBounds, turn,
} from "./geometry.js";
import { splitPart } from "./task_model.js";

const SVG_NS = "http://www.w3.org/2000/svg";
// The report's colours (src/output/plot.cpp), so a primitive keeps its
// colour from the editor to the result.
const COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b",
                 "#e377c2", "#17becf", "#bcbd22", "#7f7f7f", "#d62728"];
export const primitiveColour = (j) => COLOURS[j % COLOURS.length];

const SNAP_PIXELS = 10;   // key points this close to the cursor attract it
const DRAG_PIXELS = 5;    // a press that moves further is a drag, not a click
const MIN_GRID_PIXELS = 14;
const MIN_LABEL_PIXELS = 55;
const POINTS_NEEDED = { line: 2, arc: 3, circle: 2, obstacle: 2, region: 2 };

const HINTS = {
  select: "Select: click a part to edit it, drag to move or resize; drag the background to pan, wheel to zoom.",
  line: ["Line: click its start.", "Line: click its end."],
  arc: ["Arc: click its start.", "Arc: click its end.", "Arc: click a point on the arc."],
  circle: ["Circle: click its start.", "Circle: click its centre (Shift: clockwise)."],
  obstacle: ["Obstacle: click its centre.", "Obstacle: click its rim."],
  region: ["Base region: click a corner.", "Base region: click the opposite corner."],
};

function el(tag, attrs, parent) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

export class EditorCanvas extends EventTarget {
  constructor(svg, model) {
    super();
    this.svg = svg;
    this.model = model;
    this.view = { cx: 0.3, cy: 0.2, s: 600 };  // centre (m) and pixels per metre
    this.tool = "select";
    this.pending = [];        // points clicked so far for the part being drawn
    this.mouse = null;        // snapped task point under the cursor
    this.selected = null;     // part name
    this.errors = new Map();  // part name -> message
    this.core = [];           // part names of an infeasibility core
    this.snapToGrid = true;
    this.press = null;        // the gesture in progress
    this.layers = {};
    for (const name of ["grid", "regions", "obstacles", "trajectory", "labels", "overlay"]) {
      this.layers[name] = el("g", { id: "layer-" + name }, svg);
    }
    this.listen();
    model.addEventListener("change", () => this.render());
    new ResizeObserver(() => this.render()).observe(svg);
  }

  // ---------------------------------------------------------------- view

  size() {
    const r = this.svg.getBoundingClientRect();
    return [r.width || 800, r.height || 600];
  }

  toScreen(p) {
    const [w, h] = this.size();
    return [w / 2 + (p[0] - this.view.cx) * this.view.s, h / 2 - (p[1] - this.view.cy) * this.view.s];
  }

  toWorld(q) {
    const [w, h] = this.size();
    return [this.view.cx + (q[0] - w / 2) / this.view.s, this.view.cy - (q[1] - h / 2) / this.view.s];
  }

  /// Page coordinates of a task point, for whatever clicks on the page.
  clientPoint(p) {
    const r = this.svg.getBoundingClientRect();
    const q = this.toScreen(p);
    return [r.left + q[0], r.top + q[1]];
  }

  gridStep() { return niceStep(MIN_GRID_PIXELS / this.view.s); }

  fit() {
    const b = taskBounds(this.model.doc);
    const [w, h] = this.size();
    if (!b) {
      this.view = { cx: 0.3, cy: 0.2, s: Math.min(w, h) / 1.2 };
    } else {
      const bw = Math.max(b.max[0] - b.min[0], 0.05), bh = Math.max(b.max[1] - b.min[1], 0.05);
      this.view = { cx: (b.min[0] + b.max[0]) / 2, cy: (b.min[1] + b.max[1]) / 2,
                    s: Math.min(w / (bw * 1.25), h / (bh * 1.25)) };
    }
    this.render();
  }

  zoomAt(q, factor) {
    const before = this.toWorld(q);
    this.view.s = Math.min(1e5, Math.max(5, this.view.s * factor));
    const after = this.toWorld(q);
    this.view.cx += before[0] - after[0];
    this.view.cy += before[1] - after[1];
    this.render();
  }

  // ------------------------------------------------------------ settings

  setTool(tool) {
    this.tool = tool;
    this.pending = [];
    this.svg.classList.toggle("select-tool", tool === "select");
    this.renderOverlay();
    this.emit("hint");
  }

  cancelDrawing() {
    this.pending = [];
    this.renderOverlay();
    this.emit("hint");
  }

  select(part) {
    this.selected = part;
    this.render();
    this.emit("select", part);
  }

  /// Marks parts: errors (part -> message, from validation) and an
  /// infeasibility core (part names).
  setHighlights(errors, core) {
    this.errors = errors || new Map();
    this.core = core || [];
    this.render();
  }

  hint() {
    const h = HINTS[this.tool];
    if (typeof h === "string") return h;
    const start = this.startsAtPathEnd() ? 1 : 0;
    return h[Math.min(h.length - 1, this.pending.length + start)];
  }

  startsAtPathEnd() {
    return ["line", "arc", "circle"].includes(this.tool) && this.model.pathEnd() !== null;
  }

  emit(type, detail) { this.dispatchEvent(new CustomEvent(type, { detail })); }

  // ------------------------------------------------------------- drawing

  render() {
    this.renderGrid();
    this.renderRegions();
    this.renderObstacles();
    this.renderTrajectory();
    this.renderLabels();
    this.renderOverlay();
  }

  renderGrid() {
    const g = this.layers.grid;
    g.replaceChildren();
    const [w, h] = this.size();
    const step = this.gridStep(), major = niceStep(step * 4.5), labelled = niceStep(MIN_LABEL_PIXELS / this.view.s);
    const [x0, y1] = this.toWorld([0, 0]), [x1, y0] = this.toWorld([w, h]);
    const multiple = (v, of) => Math.abs(v / of - Math.round(v / of)) < 1e-6;
    const isMajor = (v) => multiple(v, major);
    const label = (v) => (Math.abs(v) < 1e-12 ? 0 : round9(v)).toString();
    for (let i = Math.ceil(x0 / step); i * step <= x1; ++i) {
      const v = i * step, x = this.toScreen([v, 0])[0];
      el("line", { x1: x, y1: 0, x2: x, y2: h, class: i === 0 ? "axis" : isMajor(v) ? "grid-major" : "grid-minor" }, g);
      if (multiple(v, labelled)) el("text", { x: x + 3, y: h - 6, class: "grid-label" }, g).textContent = label(v);
    }
    for (let i = Math.ceil(y0 / step); i * step <= y1; ++i) {
      const v = i * step, y = this.toScreen([0, v])[1];
      el("line", { x1: 0, y1: y, x2: w, y2: y, class: i === 0 ? "axis" : isMajor(v) ? "grid-major" : "grid-minor" }, g);
      if (multiple(v, labelled)) el("text", { x: 4, y: y - 3, class: "grid-label" }, g).textContent = label(v);
    }
    el("text", { x: w - 10, y: 20, "text-anchor": "end", class: "scale-text", id: "grid-scale" }, g).textContent =
      "grid " + (step >= 1 ? step + " m" : round9(step * 100) + " cm") + ", labels in m";
  }

  classes(part, base) {
    const names = [base];
    if (part === this.selected) names.push("selected");
    if (this.hasError(part)) names.push("error");
    if (this.inCore(part)) names.push("core");
    return names.join(" ");
  }

  hasError(part) {
    for (const p of this.errors.keys()) if (p === part || p.startsWith(part + ".")) return true;
    return false;
  }

  /// A core names parts ("obstacles[1]") or whole families ("base_regions").
  inCore(part) {
    const family = part.replace(/\[\d+\]$/, "");
    return this.core.includes(part) || this.core.includes(family);
  }

  renderRegions() {
    const g = this.layers.regions;
    g.replaceChildren();
    this.model.regions.forEach((r, i) => {
      if (!r || !isPoint(r.min) || !isPoint(r.max)) return;
      const part = `base_regions[${i}]`;
      const a = this.toScreen([r.min[0], r.max[1]]), b = this.toScreen([r.max[0], r.min[1]]);
      el("rect", { x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(b[0] - a[0]),
                   height: Math.abs(b[1] - a[1]), class: this.classes(part, "region"), "data-part": part }, g);
      if (part === this.selected) {
        [[r.min[0], r.min[1]], [r.max[0], r.min[1]], [r.max[0], r.max[1]], [r.min[0], r.max[1]]].forEach((c, k) => {
          const q = this.toScreen(c);
          el("rect", { x: q[0] - 5, y: q[1] - 5, width: 10, height: 10, class: "handle",
                       "data-part": part, "data-handle": "corner-" + k }, g);
        });
      }
    });
  }

  renderObstacles() {
    const g = this.layers.obstacles;
    g.replaceChildren();
    this.model.obstacles.forEach((o, i) => {
      if (!o || !isPoint(o.center) || !(o.radius > 0)) return;
      const part = `obstacles[${i}]`;
      const c = this.toScreen(o.center);
      el("circle", { cx: c[0], cy: c[1], r: o.radius * this.view.s, class: this.classes(part, "obstacle"), "data-part": part }, g);
      if (part === this.selected) {
        el("circle", { cx: c[0] + o.radius * this.view.s, cy: c[1], r: 6, class: "handle",
                       "data-part": part, "data-handle": "radius" }, g);
      }
    });
  }

  renderTrajectory() {
    const g = this.layers.trajectory;
    g.replaceChildren();
    const t = this.model.trajectory;
    t.forEach((p, j) => {
      const pts = samplePrimitive(p);
      if (pts.length < 2) return;
      const part = `trajectory[${j}]`;
      const screen = pts.map((q) => this.toScreen(q).map((v) => v.toFixed(1)).join(",")).join(" ");
      if (this.inCore(part)) this.coreHalo(g, pts);
      el("polyline", { points: screen, class: this.classes(part, "primitive"), stroke: primitiveColour(j),
                       "data-part": part, "data-type": p.type }, g);
      el("polyline", { points: screen, class: "hit", "data-part": part }, g);
      this.arrow(g, pts, primitiveColour(j));
    });
    if (t.length && isPoint(t[0].start)) {
      const s = this.toScreen(t[0].start);
      el("circle", { cx: s[0], cy: s[1], r: 5, class: "path-start" }, g);
    }
    this.vertexHandles(g);
  }

  /// A wide translucent band under a core primitive, and a ring around one
  /// too small to see at this zoom, so that no part of a core goes unnoticed.
  coreHalo(g, pts) {
    const screen = pts.map((q) => this.toScreen(q));
    el("polyline", { points: screen.map((q) => q.map((v) => v.toFixed(1)).join(",")).join(" "), class: "core-halo" }, g);
    const xs = screen.map((q) => q[0]), ys = screen.map((q) => q[1]);
    if (Math.max(...xs) - Math.min(...xs) < 24 && Math.max(...ys) - Math.min(...ys) < 24) {
      const c = [(Math.max(...xs) + Math.min(...xs)) / 2, (Math.max(...ys) + Math.min(...ys)) / 2];
      el("circle", { cx: c[0], cy: c[1], r: 18, class: "core-ring" }, g);
    }
  }

  arrow(g, pts, colour) {
    const d = endDirection(pts);
    if (!d) return;
    const tip = this.toScreen(pts[pts.length - 1]);
    const dx = d[0], dy = -d[1];  // screen y points down
    const back = [tip[0] - 11 * dx, tip[1] - 11 * dy];
    const side = [-dy * 5, dx * 5];
    el("polygon", { points: [tip, [back[0] + side[0], back[1] + side[1]], [back[0] - side[0], back[1] - side[1]]]
      .map((q) => q.map((v) => v.toFixed(1)).join(",")).join(" "), fill: colour, class: "arrow" }, g);
  }

  /// Handles on the selected primitive's ends where only lines meet, so that
  /// dragging keeps every arc and circle exact.
  vertexHandles(g) {
    const s = splitPart(this.selected);
    if (!s || s[0] !== "trajectory") return;
    const t = this.model.trajectory, j = s[1];
    for (const k of [j, j + 1]) {
      const before = t[k - 1], after = t[k];
      if ((before && before.type !== "line") || (after && after.type !== "line")) continue;
      const p = after ? after.start : primitiveEnd(before);
      if (!isPoint(p)) continue;
      const q = this.toScreen(p);
      el("circle", { cx: q[0], cy: q[1], r: 6, class: "handle", "data-part": this.selected, "data-handle": "vertex-" + k }, g);
    }
  }

  /// Messages next to the parts they are about, and a mark on core parts.
  renderLabels() {
    const g = this.layers.labels;
    g.replaceChildren();
    for (const [part, message] of this.errors) {
      // Beside its part the message need not name it again.
      const plain = message.startsWith(part + ": ") ? message.slice(part.length + 2) : message;
      this.label(g, part, plain.length > 90 ? plain.slice(0, 87) + "..." : plain, -10, "error-label");
    }
    for (const part of this.core) this.label(g, part, "in conflict: " + part, 16, "core-label");
  }

  /// A text beside a part, on whichever side leaves it room.
  label(g, part, text, dy, cls) {
    const anchor = this.anchor(part);
    if (!anchor) return;
    const left = anchor[0] > this.size()[0] / 2;
    el("text", { x: anchor[0] + (left ? -10 : 10), y: anchor[1] + dy, "text-anchor": left ? "end" : "start",
                 class: cls, "data-part": part }, g).textContent = text;
  }

  /// A screen point near a part, for its label.
  anchor(part) {
    const item = this.model.item(part);
    const kind = (splitPart(part) || [])[0];
    let p = null;
    if (kind === "trajectory") p = item && (isPoint(item.end) ? item.end : item.start);
    else if (kind === "obstacles") p = item && isPoint(item.center) && [item.center[0] + (item.radius || 0), item.center[1]];
    else if (kind === "base_regions") p = item && item.max;
    else if (part === "base_regions" && this.model.regions.length) p = this.model.regions[0].max;
    return isPoint(p) ? this.toScreen(p) : null;
  }

  renderOverlay() {
    const g = this.layers.overlay;
    g.replaceChildren();
    if (this.tool === "select" || !this.mouse) return;
    const pts = this.drawnPoints(this.mouse);
    const scr = (p) => this.toScreen(p);
    for (const p of pts.slice(0, -1)) {
      const q = scr(p);
      el("circle", { cx: q[0], cy: q[1], r: 3.5, class: "preview-point" }, g);
    }
    const m = scr(this.mouse);
    el("circle", { cx: m[0], cy: m[1], r: 4, class: "preview-point", id: "cursor-mark" }, g);
    const shape = this.shapeOf(pts);
    if (!shape) return;
    if (shape.kind === "primitive") {
      const sampled = samplePrimitive(shape.value);
      if (sampled.length > 1) el("polyline", { points: sampled.map((p) => scr(p).join(",")).join(" "), class: "preview" }, g);
    } else if (shape.kind === "obstacle") {
      const c = scr(shape.center);
      el("circle", { cx: c[0], cy: c[1], r: shape.radius * this.view.s, class: "preview" }, g);
    } else if (shape.kind === "region") {
      const a = scr(shape.a), b = scr(shape.b);
      el("rect", { x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(b[0] - a[0]),
                   height: Math.abs(b[1] - a[1]), class: "preview" }, g);
    } else if (shape.kind === "chord") {
      el("line", { x1: scr(shape.a)[0], y1: scr(shape.a)[1], x2: scr(shape.b)[0], y2: scr(shape.b)[1], class: "preview" }, g);
    }
  }

  // ---------------------------------------------------------------- tools

  /// The points of the part being drawn, the path's end first when it
  /// starts there, then the clicks, then `next`.
  drawnPoints(next) {
    const start = this.startsAtPathEnd() ? [this.model.pathEnd()] : [];
    return start.concat(this.pending, next ? [next] : []);
  }

  /// What the points describe so far; null when nothing can be drawn yet.
  shapeOf(pts, shiftKey = false) {
    const [a, b, c] = pts;
    switch (this.tool) {
      case "line":
        return pts.length >= 2 && dist(a, b) > 0 ? { kind: "primitive", value: { type: "line", start: a, end: b } } : null;
      case "arc": {
        if (pts.length === 2) return dist(a, b) > 0 ? { kind: "chord", a, b } : null;
        if (pts.length < 3) return null;
        const center = circumcenter(a, c, b);
        if (!center || dist(a, b) === 0) return null;
        return { kind: "primitive", value: { type: "arc", start: a, end: b, center: roundPoint(center),
                                              direction: turn(a, c, b) > 0 ? "ccw" : "cw" } };
      }
      case "circle":
        return pts.length >= 2 && dist(a, b) > 0
          ? { kind: "primitive", value: { type: "circle", start: a, center: b, direction: shiftKey ? "cw" : "ccw" } } : null;
      case "obstacle":
        return pts.length >= 2 && dist(a, b) > 0 ? { kind: "obstacle", center: a, radius: round9(dist(a, b)) } : null;
      case "region":
        return pts.length >= 2 && a[0] !== b[0] && a[1] !== b[1] ? { kind: "region", a, b } : null;
    }
    return null;
  }

  /// One click of a drawing tool at task point p.
  clickAt(p, shiftKey) {
    const pts = this.drawnPoints(p);
    if (pts.length < POINTS_NEEDED[this.tool]) {
      this.pending.push(p);
    } else {
      // A last click that makes nothing (a point on the chord, a zero
      // radius) is ignored: the points before it stay.
      const shape = this.shapeOf(pts, shiftKey);
      if (shape) {
        this.pending = [];
        this.commit(shape);
      }
    }
    this.renderOverlay();
    this.emit("hint");
  }

  commit(shape) {
    let part = null;
    if (shape.kind === "primitive") part = this.model.addPrimitive(JSON.parse(JSON.stringify(shape.value)));
    else if (shape.kind === "obstacle") part = this.model.addObstacle(shape.center, shape.radius);
    else if (shape.kind === "region") part = this.model.addRegion(shape.a, shape.b);
    if (part) this.select(part);
  }

  /// Key points attract the cursor; otherwise, with snapping on, the grid.
  snap(world, screen) {
    let best = null, bestDist = SNAP_PIXELS;
    for (const k of this.keyPoints()) {
      const d = dist(this.toScreen(k), screen);
      if (d < bestDist) { best = k; bestDist = d; }
    }
    if (best) return [...best];
    if (!this.snapToGrid) return roundPoint(world);
    const step = this.gridStep();
    return roundPoint([Math.round(world[0] / step) * step, Math.round(world[1] / step) * step]);
  }

  keyPoints() {
    const out = [];
    for (const p of this.model.trajectory) {
      if (p && isPoint(p.start)) out.push(p.start);
      if (p && isPoint(p.end)) out.push(p.end);
      if (p && isPoint(p.center)) out.push(p.center);
    }
    for (const o of this.model.obstacles) if (o && isPoint(o.center)) out.push(o.center);
    for (const r of this.model.regions) if (r && isPoint(r.min) && isPoint(r.max)) out.push(r.min, r.max);
    return out;
  }

  // -------------------------------------------------------------- pointer

  listen() {
    const svg = this.svg;
    svg.addEventListener("pointerdown", (e) => this.onDown(e));
    svg.addEventListener("pointermove", (e) => this.onMove(e));
    svg.addEventListener("pointerup", (e) => this.onUp(e));
    svg.addEventListener("pointerleave", () => { this.mouse = null; this.renderOverlay(); this.emit("cursor", null); });
    svg.addEventListener("contextmenu", (e) => e.preventDefault());
    svg.addEventListener("wheel", (e) => {
      e.preventDefault();
      this.zoomAt(this.local(e), Math.exp(-e.deltaY * 0.0015));
    }, { passive: false });
  }

  local(e) {
    const r = this.svg.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  onDown(e) {
    const q = this.local(e), w = this.toWorld(q);
    this.svg.setPointerCapture(e.pointerId);
    const target = e.target.closest ? e.target.closest("[data-part]") : null;
    const part = target && target.dataset.part;
    const background = !part || target.closest("#layer-labels");
    if (e.button === 1 || e.button === 2 || (this.tool === "select" && background)) {
      this.press = { kind: "pan", from: q, view: { ...this.view }, moved: false };
      if (this.tool === "select" && e.button === 0) this.select(null);
      return;
    }
    if (e.button !== 0) return;
    if (this.tool === "select") {
      if (part !== this.selected) this.select(part);
      const item = this.model.item(part);
      this.press = { kind: target.dataset.handle ? "handle" : "move", part, handle: target.dataset.handle,
                     from: q, origin: w, item: JSON.parse(JSON.stringify(item || {})), moved: false };
      return;
    }
    const p = this.snap(w, q);
    this.press = { kind: "draw", from: q, points: this.pending.length };
    this.clickAt(p, e.shiftKey);
  }

  onMove(e) {
    const q = this.local(e), w = this.toWorld(q);
    this.mouse = this.tool === "select" ? w : this.snap(w, q);
    this.emit("cursor", this.mouse);
    const press = this.press;
    if (press && (press.moved || dist(q, press.from) > DRAG_PIXELS)) {
      press.moved = true;
      if (press.kind === "pan") {
        this.view.cx = press.view.cx - (q[0] - press.from[0]) / this.view.s;
        this.view.cy = press.view.cy + (q[1] - press.from[1]) / this.view.s;
        this.svg.classList.add("panning");
        this.render();
        return;
      }
      if (press.kind === "move" || press.kind === "handle") this.dragTo(press, w, q);
    }
    this.renderOverlay();
  }

  onUp(e) {
    const press = this.press;
    this.press = null;
    this.svg.classList.remove("panning");
    if (!press || press.kind !== "draw" || !press.moved) return;
    // Press, drag, release draws an obstacle or region in one gesture.
    if (["obstacle", "region"].includes(this.tool) && this.pending.length === 1 && press.points === 0) {
      const q = this.local(e);
      this.clickAt(this.snap(this.toWorld(q), q), e.shiftKey);
    }
  }

  dragTo(press, w, q) {
    const part = press.part, kind = (splitPart(part) || [])[0];
    const item = press.item;
    if (!press.started) {
      press.started = true;
      this.model.beginGesture();
    }
    const snapped = this.snap(w, q);
    const delta = [snapped[0] - this.snap(press.origin, press.from)[0], snapped[1] - this.snap(press.origin, press.from)[1]];
    const shift = (p) => roundPoint([p[0] + delta[0], p[1] + delta[1]]);
    this.model.updateInGesture((d) => {
      const live = this.model.item(part);
      if (!live) return;
      if (press.kind === "move" && kind === "obstacles" && isPoint(item.center)) live.center = shift(item.center);
      if (press.kind === "move" && kind === "base_regions" && isPoint(item.min) && isPoint(item.max)) {
        live.min = shift(item.min);
        live.max = shift(item.max);
      }
      if (press.handle === "radius" && isPoint(live.center)) live.radius = round9(Math.max(1e-3, dist(live.center, snapped)));
      if (press.handle && press.handle.startsWith("corner-")) this.dragCorner(live, item, +press.handle.slice(7), snapped);
      if (press.handle && press.handle.startsWith("vertex-")) this.model.moveVertexIn(d, +press.handle.slice(7), roundPoint(snapped));
    });
  }

  /// Corner k (counter-clockwise from min) follows the cursor; the opposite
  /// one stays.
  dragCorner(live, item, k, p) {
    const corners = [[item.min[0], item.min[1]], [item.max[0], item.min[1]], [item.max[0], item.max[1]], [item.min[0], item.max[1]]];
    const fixed = corners[(k + 2) % 4];
    live.min = roundPoint([Math.min(fixed[0], p[0]), Math.min(fixed[1], p[1])]);
    live.max = roundPoint([Math.max(fixed[0], p[0]), Math.max(fixed[1], p[1])]);
  }
}

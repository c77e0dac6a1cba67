// The drawing surface: an SVG whose layers the task, the handles and the
// drawing tool's preview are drawn in, and the pointer gestures on it:
// zoom (wheel), pan (drag the background, or the middle or right button
// anywhere), select and drag parts and handles, and the clicks of the
// drawing tools. It shows the hint for the next click and the cursor's
// position beside it.

import { dist, taskBounds } from "./geometry.js";
import { dragEdit, handlesOf, HANDLE_PIXELS } from "./handles.js";
import { handleAt, partAt } from "./hit.js";
import { keyPoints, snapPoint } from "./snap.js";
import { DrawTool } from "./draw_tool.js";
import { ProofRender } from "./proof_render.js";
import { TaskRender } from "./task_render.js";
import { UnderlayRender } from "./underlay.js";
import { ViewTransform } from "./view_transform.js";
import { svg } from "./dom.js";

const DRAG_PIXELS = 5;   // a press that moves further is a drag, not a click
const HIT_PIXELS = 7;    // a click this close to a primitive is on it
const WHEEL_ZOOM = 0.0015;
const LAYERS = ["grid", "underlay", "regions", "obstacles", "proof", "trajectory", "handles", "labels", "overlay"];

export class EditorCanvas {
  constructor(element, store, { hint, cursor }) {
    this.svg = element;
    this.store = store;
    this.hintBox = hint;
    this.cursorBox = cursor;
    this.snapToGrid = true;
    this.press = null;   // the gesture in progress
    const layers = {};
    for (const name of LAYERS) layers[name] = svg("g", { id: "layer-" + name }, element);
    this.view = new ViewTransform(() => this.size());
    this.task = new TaskRender(layers, store, this.view);
    this.underlay = new UnderlayRender(layers.underlay, store, this.view);
    this.proof = new ProofRender(layers.proof, store, this.view);
    this.drawTool = new DrawTool(store, this.view, layers.overlay);
    this.listen();
    for (const type of ["doc", "selection", "validation", "core", "witness", "underlay"]) store.on(type, () => this.render());
    store.on("tool", (tool) => {
      this.drawTool.cancel();
      this.svg.classList.toggle("select-tool", tool === "select");
      this.showHint();
    });
    store.on("view", (view) => { if (view === "editor") this.render(); });
    new ResizeObserver(() => this.render()).observe(element);
  }

  size() {
    const r = this.svg.getBoundingClientRect();
    return [r.width || 800, r.height || 600];
  }

  render() {
    this.task.render();
    this.underlay.render();
    this.proof.render();
    this.drawTool.render();
  }

  /// Page coordinates of a task point, for whatever clicks on the page.
  clientPoint(p) {
    const r = this.svg.getBoundingClientRect();
    const q = this.view.toScreen(p);
    return [r.left + q[0], r.top + q[1]];
  }

  fit() {
    this.view.fit(taskBounds(this.store.doc));
    this.render();
  }

  setSnap(on) { this.snapToGrid = on; }

  /// Stops drawing the part begun; false when none was begun.
  cancelDrawing() {
    const had = this.drawTool.cancel();
    this.showHint();
    return had;
  }

  showHint() { this.hintBox.textContent = this.drawTool.hint(); }

  showCursor(p) {
    this.cursorBox.textContent = p ? `x ${p[0].toFixed(3)}  y ${p[1].toFixed(3)} m` : "";
  }

  snap(world, screen) {
    return snapPoint(world, screen, { points: keyPoints(this.store.doc), view: this.view, toGrid: this.snapToGrid });
  }

  // -------------------------------------------------------------- pointer

  listen() {
    const el = this.svg;
    el.addEventListener("pointerdown", (e) => this.onDown(e));
    el.addEventListener("pointermove", (e) => this.onMove(e));
    el.addEventListener("pointerup", (e) => this.onUp(e));
    el.addEventListener("pointerleave", () => {
      this.drawTool.hover(null);
      this.drawTool.render();
      this.showCursor(null);
    });
    el.addEventListener("contextmenu", (e) => e.preventDefault());
    el.addEventListener("wheel", (e) => {
      e.preventDefault();
      this.view.zoomAt(this.local(e), Math.exp(-e.deltaY * WHEEL_ZOOM));
      this.render();
    }, { passive: false });
  }

  local(e) {
    const r = this.svg.getBoundingClientRect();
    return [e.clientX - r.left, e.clientY - r.top];
  }

  /// What the select tool's press at task point w is on: {part, handle}.
  target(w) {
    const selected = this.store.selection;
    const handle = handleAt(handlesOf(this.store.doc, selected), w, HANDLE_PIXELS / this.view.s);
    if (handle) return { part: selected, handle: handle.handle };
    return { part: partAt(this.store.doc, w, HIT_PIXELS / this.view.s), handle: null };
  }

  onDown(e) {
    const q = this.local(e), w = this.view.toWorld(q);
    this.svg.setPointerCapture(e.pointerId);
    const selecting = this.store.tool === "select";
    const { part, handle } = selecting && e.button === 0 ? this.target(w) : { part: null, handle: null };
    if (e.button === 1 || e.button === 2 || (selecting && !part)) {
      this.press = { kind: "pan", from: q, view: this.view.saved(), moved: false };
      if (selecting && e.button === 0) this.store.select(null);
      return;
    }
    if (e.button !== 0) return;
    if (selecting) {
      if (part !== this.store.selection) this.store.select(part);
      const item = this.store.model.item(part);
      this.press = { kind: "drag", part, handle, from: q, origin: this.snap(w, q),
                     item: JSON.parse(JSON.stringify(item || {})), moved: false };
      return;
    }
    this.press = { kind: "draw", from: q, points: this.drawTool.clicks };
    this.drawTool.click(this.snap(w, q), e.shiftKey);
    this.showHint();
  }

  onMove(e) {
    const q = this.local(e), w = this.view.toWorld(q);
    const mouse = this.store.tool === "select" ? w : this.snap(w, q);
    this.drawTool.hover(mouse);
    this.showCursor(mouse);
    const press = this.press;
    if (press && (press.moved || dist(q, press.from) > DRAG_PIXELS)) {
      press.moved = true;
      if (press.kind === "pan") {
        this.view.panFrom(press.view, press.from, q);
        this.svg.classList.add("panning");
        this.render();
        return;
      }
      if (press.kind === "drag") this.dragTo(press, this.snap(w, q));
    }
    this.drawTool.render();
  }

  onUp(e) {
    const press = this.press;
    this.press = null;
    this.svg.classList.remove("panning");
    if (!press || press.kind !== "draw" || !press.moved) return;
    // Press, drag, release draws an obstacle or region in one gesture.
    if (["obstacle", "region"].includes(this.store.tool) && this.drawTool.clicks === 1 && press.points === 0) {
      const q = this.local(e);
      this.drawTool.click(this.snap(this.view.toWorld(q), q), e.shiftKey);
      this.showHint();
    }
  }

  /// The whole drag is one undo step; the task follows the cursor meanwhile.
  dragTo(press, to) {
    const model = this.store.model;
    if (!press.started) {
      press.started = true;
      model.beginGesture();
    }
    model.updateInGesture(dragEdit(press, press.origin, to));
  }
}

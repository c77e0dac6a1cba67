// Where the task sits on the screen: a centre (m) and a scale (pixels per
// metre), task y up and screen y down. `size` says how large the surface is
// now, since the page may be resized at any time.

import { niceStep } from "./geometry.js";

const MIN_GRID_PIXELS = 14;
const MIN_SCALE = 5, MAX_SCALE = 1e5;
const FIT_MARGIN = 1.25;
const FIT_MIN_SPAN = 0.05;  // m: a single point still gets a sensible zoom

export class ViewTransform {
  constructor(size) {
    this.size = size;
    this.cx = 0.3;
    this.cy = 0.2;
    this.s = 600;
  }

  toScreen(p) {
    const [w, h] = this.size();
    return [w / 2 + (p[0] - this.cx) * this.s, h / 2 - (p[1] - this.cy) * this.s];
  }

  toWorld(q) {
    const [w, h] = this.size();
    return [this.cx + (q[0] - w / 2) / this.s, this.cy - (q[1] - h / 2) / this.s];
  }

  /// The grid spacing (m): a round number at least a few pixels wide.
  gridStep() { return niceStep(MIN_GRID_PIXELS / this.s); }

  /// Shows the box `bounds` ({min, max}, or null for an empty task).
  fit(bounds) {
    const [w, h] = this.size();
    if (!bounds) {
      Object.assign(this, { cx: 0.3, cy: 0.2, s: Math.min(w, h) / 1.2 });
      return;
    }
    const bw = Math.max(bounds.max[0] - bounds.min[0], FIT_MIN_SPAN);
    const bh = Math.max(bounds.max[1] - bounds.min[1], FIT_MIN_SPAN);
    Object.assign(this, { cx: (bounds.min[0] + bounds.max[0]) / 2, cy: (bounds.min[1] + bounds.max[1]) / 2,
                          s: Math.min(w / (bw * FIT_MARGIN), h / (bh * FIT_MARGIN)) });
  }

  /// Zooms by `factor` keeping the task point under screen point q in place.
  zoomAt(q, factor) {
    const before = this.toWorld(q);
    this.s = Math.min(MAX_SCALE, Math.max(MIN_SCALE, this.s * factor));
    const after = this.toWorld(q);
    this.cx += before[0] - after[0];
    this.cy += before[1] - after[1];
  }

  /// Pans so that what was under screen point `from` in view `saved` is now
  /// under `to`.
  panFrom(saved, from, to) {
    this.cx = saved.cx - (to[0] - from[0]) / this.s;
    this.cy = saved.cy + (to[1] - from[1]) / this.s;
  }

  saved() { return { cx: this.cx, cy: this.cy, s: this.s }; }
}

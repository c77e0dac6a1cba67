// Where a click lands: key points of the task (ends, centres, corners)
// attract the cursor within a few pixels; otherwise, with snapping on, the
// grid does.

import { dist, isPoint, roundPoint } from "./geometry.js";

export const SNAP_PIXELS = 10;

/// Every point of a task a click may want to hit exactly.
export function keyPoints(doc) {
  const out = [];
  const list = (k) => (Array.isArray(doc[k]) ? doc[k] : []);
  for (const p of list("trajectory")) {
    if (!p) continue;
    for (const k of ["start", "end", "center"]) if (isPoint(p[k])) out.push(p[k]);
  }
  for (const o of list("obstacles")) if (o && isPoint(o.center)) out.push(o.center);
  for (const r of list("base_regions")) if (r && isPoint(r.min) && isPoint(r.max)) out.push(r.min, r.max);
  return out;
}

/// The snapped task point for the cursor at task point `world` and screen
/// point `screen`. `view` maps task to screen points and gives the grid step.
export function snapPoint(world, screen, { points, view, toGrid }) {
  let best = null, bestDist = SNAP_PIXELS;
  for (const k of points) {
    const d = dist(view.toScreen(k), screen);
    if (d < bestDist) { best = k; bestDist = d; }
  }
  if (best) return [...best];
  if (!toGrid) return roundPoint(world);
  const step = view.gridStep();
  return roundPoint([Math.round(world[0] / step) * step, Math.round(world[1] / step) * step]);
}

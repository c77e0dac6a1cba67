// What a click on the canvas is on: a handle of the selected part, else the
// topmost part (the path over obstacles over base regions, as drawn), else
// the background.

import { dist, distToPolyline, isPoint, samplePrimitive } from "./geometry.js";
import { partName } from "./parts.js";

/// The part under task point p, or null. A primitive is hit within
/// `tolerance` (m) of its curve; obstacles and regions anywhere inside.
export function partAt(doc, p, tolerance) {
  const list = (k) => (Array.isArray(doc[k]) ? doc[k] : []);
  const t = list("trajectory");
  for (let j = t.length - 1; j >= 0; --j) {
    const pts = samplePrimitive(t[j]);
    if (pts.length > 1 && distToPolyline(p, pts) <= tolerance) return partName("trajectory", j);
  }
  const o = list("obstacles");
  for (let i = o.length - 1; i >= 0; --i) {
    if (o[i] && isPoint(o[i].center) && o[i].radius > 0 && dist(p, o[i].center) <= o[i].radius) return partName("obstacles", i);
  }
  const r = list("base_regions");
  for (let i = r.length - 1; i >= 0; --i) {
    const b = r[i];
    if (b && isPoint(b.min) && isPoint(b.max) && Math.min(b.min[0], b.max[0]) <= p[0] && p[0] <= Math.max(b.min[0], b.max[0]) &&
        Math.min(b.min[1], b.max[1]) <= p[1] && p[1] <= Math.max(b.min[1], b.max[1])) return partName("base_regions", i);
  }
  return null;
}

/// The handle (of `handles`, as handlesOf gives them) within `tolerance`
/// (m) of p, the nearest if several; null if none.
export function handleAt(handles, p, tolerance) {
  let best = null, bestDist = tolerance;
  for (const h of handles) {
    const d = h.shape === "square" ? Math.max(Math.abs(p[0] - h.point[0]), Math.abs(p[1] - h.point[1])) : dist(p, h.point);
    if (d <= bestDist) { best = h; bestDist = d; }
  }
  return best;
}

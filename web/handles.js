// The handles of the selected part and what dragging them (or the part)
// does to the task. A primitive's end gets a handle only where lines alone
// meet there, so that dragging keeps every arc and circle exact.

import { dist, isPoint, primitiveEnd, round9, roundPoint } from "./geometry.js";
import { splitPart } from "./parts.js";
import { moveVertex } from "./task_model.js";

export const HANDLE_PIXELS = 6;    // a handle's half size on the screen
const MIN_RADIUS = 1e-3;           // m: an obstacle dragged to nothing keeps this

function itemOf(doc, part) {
  const s = splitPart(part);
  const list = s && doc[s[0]];
  return Array.isArray(list) ? list[s[1]] : undefined;
}

/// A region's corners, counter-clockwise from min.
export function corners(r) {
  return [[r.min[0], r.min[1]], [r.max[0], r.min[1]], [r.max[0], r.max[1]], [r.min[0], r.max[1]]];
}

/// The handles of `part` in `doc`: [{handle, point, shape}] with task points.
/// An obstacle's radius handle sits on its rim, right of the centre.
export function handlesOf(doc, part) {
  const s = splitPart(part), item = itemOf(doc, part);
  if (!s || !item) return [];
  const [list, j] = s;
  if (list === "base_regions") {
    if (!isPoint(item.min) || !isPoint(item.max)) return [];
    return corners(item).map((c, k) => ({ handle: "corner-" + k, point: c, shape: "square" }));
  }
  if (list === "obstacles") {
    if (!isPoint(item.center) || !(item.radius > 0)) return [];
    return [{ handle: "radius", point: [item.center[0] + item.radius, item.center[1]], shape: "circle" }];
  }
  const t = doc.trajectory, out = [];
  for (const k of [j, j + 1]) {
    const before = t[k - 1], after = t[k];
    if ((before && before.type !== "line") || (after && after.type !== "line")) continue;
    const p = after ? after.start : primitiveEnd(before);
    if (isPoint(p)) out.push({ handle: "vertex-" + k, point: p, shape: "circle" });
  }
  return out;
}

/// The edit that dragging does: `drag` is {part, handle (or none for moving
/// the whole part), item (the part as it was when the drag began)}; the
/// cursor has moved from `origin` to `to` (both snapped task points).
export function dragEdit(drag, origin, to) {
  const { part, handle, item } = drag;
  const kind = (splitPart(part) || [])[0];
  const delta = [to[0] - origin[0], to[1] - origin[1]];
  const shift = (p) => roundPoint([p[0] + delta[0], p[1] + delta[1]]);
  return (doc) => {
    const live = itemOf(doc, part);
    if (!live) return;
    if (!handle && kind === "obstacles" && isPoint(item.center)) live.center = shift(item.center);
    if (!handle && kind === "base_regions" && isPoint(item.min) && isPoint(item.max)) {
      live.min = shift(item.min);
      live.max = shift(item.max);
    }
    if (handle === "radius" && isPoint(live.center)) live.radius = round9(Math.max(MIN_RADIUS, dist(live.center, to)));
    if (handle && handle.startsWith("corner-")) {
      // The dragged corner follows the cursor; the opposite one stays.
      const fixed = corners(item)[(+handle.slice(7) + 2) % 4];
      live.min = roundPoint([Math.min(fixed[0], to[0]), Math.min(fixed[1], to[1])]);
      live.max = roundPoint([Math.max(fixed[0], to[0]), Math.max(fixed[1], to[1])]);
    }
    if (handle && handle.startsWith("vertex-")) moveVertex(doc, +handle.slice(7), roundPoint(to));
  };
}

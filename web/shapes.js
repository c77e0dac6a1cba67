// What the clicks of a drawing tool describe: from the points so far to the
// part they would add (or a preview of it). Pure, so the tools' geometry can
// be checked without a page.

import { circumcenter, dist, round9, roundPoint, turn } from "./geometry.js";

/// Points each tool needs, the path's end counted when the part starts there.
export const POINTS_NEEDED = { line: 2, arc: 3, circle: 2, obstacle: 2, region: 2 };

/// Path primitives start where the path ends; other parts start anywhere.
export const STARTS_AT_PATH_END = ["line", "arc", "circle"];

/// The shape `points` describe for `tool`: {kind: "primitive", value},
/// {kind: "obstacle", center, radius}, {kind: "region", a, b} or, for an arc
/// still missing its middle point, {kind: "chord", a, b}; null when nothing
/// can be drawn yet (or the points are degenerate: a zero radius, three
/// points on a line).
export function shapeOf(tool, points, shiftKey = false) {
  const [a, b, c] = points;
  switch (tool) {
    case "line":
      return points.length >= 2 && dist(a, b) > 0 ? { kind: "primitive", value: { type: "line", start: a, end: b } } : null;
    case "arc": {
      if (points.length === 2) return dist(a, b) > 0 ? { kind: "chord", a, b } : null;
      if (points.length < 3) return null;
      const center = circumcenter(a, c, b);
      if (!center || dist(a, b) === 0) return null;
      return { kind: "primitive", value: { type: "arc", start: a, end: b, center: roundPoint(center),
                                            direction: turn(a, c, b) > 0 ? "ccw" : "cw" } };
    }
    case "circle":
      return points.length >= 2 && dist(a, b) > 0
        ? { kind: "primitive", value: { type: "circle", start: a, center: b, direction: shiftKey ? "cw" : "ccw" } } : null;
    case "obstacle":
      return points.length >= 2 && dist(a, b) > 0 ? { kind: "obstacle", center: a, radius: round9(dist(a, b)) } : null;
    case "region":
      return points.length >= 2 && a[0] !== b[0] && a[1] !== b[1] ? { kind: "region", a, b } : null;
  }
  return null;
}

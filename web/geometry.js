// Plane geometry for the editor, in task coordinates (metres, y up). Pure
// functions: tolerant of half-edited documents, they return null where a
// part is not (yet) well formed instead of throwing.

export const TAU = 2 * Math.PI;

export function isPoint(p) {
  return Array.isArray(p) && p.length === 2 && Number.isFinite(p[0]) && Number.isFinite(p[1]);
}

export function dist(a, b) {
  return Math.hypot(a[0] - b[0], a[1] - b[1]);
}

/// A coordinate as stored: 9 decimals (a nanometre) keeps the JSON readable
/// and is far below the 1e-6 m join tolerance.
export function round9(v) {
  return Math.round(v * 1e9) / 1e9;
}

export function roundPoint(p) {
  return [round9(p[0]), round9(p[1])];
}

/// z of (b - a) x (c - b): positive when a, b, c turn left (counter-clockwise).
export function turn(a, b, c) {
  return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
}

/// The centre of the circle through three points; null when they are
/// (nearly) on one line.
export function circumcenter(a, b, c) {
  const d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
  const scale = Math.max(dist(a, b), dist(b, c), dist(a, c));
  if (Math.abs(d) < 1e-9 * scale * scale) return null;
  const a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
  return [(a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
          (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d];
}

export function angleAt(center, p) {
  return Math.atan2(p[1] - center[1], p[0] - center[0]);
}

/// The signed angle an arc turns through: positive counter-clockwise, in
/// (0, 2pi] or [-2pi, 0); a start equal to the end is a full turn (formats.md).
export function arcSweep(start, end, center, direction) {
  let d = angleAt(center, end) - angleAt(center, start);
  if (direction === "cw") {
    while (d >= 0) d -= TAU;
    if (dist(start, end) < 1e-9) d = -TAU;
  } else {
    while (d <= 0) d += TAU;
    if (dist(start, end) < 1e-9) d = TAU;
  }
  return d;
}

/// Where a primitive ends (a circle ends where it starts); null if malformed.
export function primitiveEnd(p) {
  if (!p || typeof p !== "object") return null;
  const end = p.type === "circle" ? p.start : p.end;
  return isPoint(end) ? end : null;
}

/// Points along a primitive, close enough for drawing and hit tests; empty
/// when the primitive is not well formed.
export function samplePrimitive(p) {
  if (!p || !isPoint(p.start)) return [];
  if (p.type === "line") return isPoint(p.end) ? [p.start, p.end] : [];
  if (!isPoint(p.center)) return [];
  const r = dist(p.start, p.center);
  const a0 = angleAt(p.center, p.start);
  const sweep = p.type === "circle"
    ? (p.direction === "cw" ? -TAU : TAU)
    : isPoint(p.end) ? arcSweep(p.start, p.end, p.center, p.direction) : 0;
  const n = Math.max(8, Math.ceil(Math.abs(sweep) / TAU * 96));
  const out = [];
  for (let i = 0; i <= n; ++i) {
    const a = a0 + sweep * i / n;
    out.push([p.center[0] + r * Math.cos(a), p.center[1] + r * Math.sin(a)]);
  }
  if (p.type === "arc" && isPoint(p.end)) out[n] = p.end;
  return out;
}

/// Distance from p to the segment a-b.
export function distToSegment(p, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1];
  const len2 = dx * dx + dy * dy;
  const t = len2 > 0 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2)) : 0;
  return dist(p, [a[0] + t * dx, a[1] + t * dy]);
}

/// Distance from p to a polyline; Infinity when it has no segment.
export function distToPolyline(p, points) {
  let best = Infinity;
  for (let i = 1; i < points.length; ++i) best = Math.min(best, distToSegment(p, points[i - 1], points[i]));
  return best;
}

/// The tangent direction at the end of a primitive's samples (for arrows).
export function endDirection(points) {
  if (points.length < 2) return null;
  const a = points[points.length - 2], b = points[points.length - 1];
  const len = dist(a, b);
  return len > 0 ? [(b[0] - a[0]) / len, (b[1] - a[1]) / len] : null;
}

/// 1, 2 or 5 times a power of ten, the smallest not below x.
export function niceStep(x) {
  const p = Math.pow(10, Math.floor(Math.log10(x)));
  for (const m of [1, 2, 5, 10]) if (m * p >= x * (1 - 1e-12)) return m * p;
  return 10 * p;
}

/// The box around everything drawn in a task; null for an empty one.
export function taskBounds(doc) {
  const pts = [];
  for (const p of doc.trajectory || []) pts.push(...samplePrimitive(p));
  for (const s of Array.isArray(doc.strokes) ? doc.strokes : []) {
    for (const p of Array.isArray(s) ? s : []) pts.push(...samplePrimitive(p));
  }
  for (const o of doc.obstacles || []) {
    if (isPoint(o.center) && Number.isFinite(o.radius)) {
      pts.push([o.center[0] - o.radius, o.center[1] - o.radius], [o.center[0] + o.radius, o.center[1] + o.radius]);
    }
  }
  for (const r of doc.base_regions || []) {
    if (isPoint(r.min)) pts.push(r.min);
    if (isPoint(r.max)) pts.push(r.max);
  }
  if (!pts.length) return null;
  const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
  return { min: [Math.min(...xs), Math.min(...ys)], max: [Math.max(...xs), Math.max(...ys)] };
}

/// Metres for people: millimetres below a metre.
export function lengthText(m) {
  if (!Number.isFinite(m)) return "?";
  return Math.abs(m) < 1 ? (m * 1000).toFixed(1) + " mm" : m.toFixed(3) + " m";
}

export function primitiveLength(p) {
  const pts = samplePrimitive(p);
  if (p && p.type !== "line" && isPoint(p.center) && pts.length) {
    const sweep = p.type === "circle" ? TAU : Math.abs(arcSweep(p.start, p.end, p.center, p.direction));
    return dist(p.start, p.center) * sweep;
  }
  return pts.length === 2 ? dist(pts[0], pts[1]) : NaN;
}

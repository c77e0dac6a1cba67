// Geometry of spatial tasks (formats.md "Spatial tasks") for the editor,
// in task coordinates (metres, z up). Pure functions, tolerant of
// half-edited documents: they return null or [] where a part is not (yet)
// well formed instead of throwing. The page's modules and the 3-D view's
// bundle (web/report3d/editor_view.js) both use them.

export const TAU = 2 * Math.PI;

/// A task in space: `"space": "3d"`.
export function isSpatial(doc) {
  return !!doc && typeof doc === "object" && doc.space === "3d";
}

export function isPoint3(p) {
  return Array.isArray(p) && p.length === 3 && p.every(Number.isFinite);
}

export const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a, s) => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const norm = (a) => Math.hypot(a[0], a[1], a[2]);
export const dist3 = (a, b) => norm(sub(a, b));
export const mid = (a, b) => scale(add(a, b), 0.5);

/// a / |a|; null for a vector of no length.
export function unit(a) {
  const n = isPoint3(a) ? norm(a) : 0;
  return n > 0 ? scale(a, 1 / n) : null;
}

/// v turned by `angle` right-handed about the unit axis k (Rodrigues).
export function rotate(v, k, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(k, v), s)), scale(k, dot(k, v) * (1 - c)));
}

/// The signed angle from u to v about the unit axis n, in (-pi, pi].
function angleAbout(u, v, n) {
  return Math.atan2(dot(cross(u, v), n), dot(u, v));
}

/// The angle an arc turns through about its normal: positive for "ccw", in
/// (0, 2pi], negative for "cw"; a start equal to its end is a full turn.
export function arcSweep3(p) {
  const n = unit(p.normal);
  if (!n || !isPoint3(p.start) || !isPoint3(p.center) || !isPoint3(p.end)) return null;
  const full = dist3(p.start, p.end) < 1e-9;
  let d = angleAbout(sub(p.start, p.center), sub(p.end, p.center), n);
  if (p.direction === "cw") {
    while (d >= 0) d -= TAU;
    if (full) d = -TAU;
  } else {
    while (d <= 0) d += TAU;
    if (full) d = TAU;
  }
  return d;
}

/// The point of a helix at u in [0, 1] (formats.md), or null.
export function helixPoint(p, u) {
  const a = unit(p.axis);
  if (!a || !isPoint3(p.start) || !isPoint3(p.center) || !Number.isFinite(p.pitch) || !Number.isFinite(p.turns)) return null;
  const s = p.direction === "cw" ? -1 : 1;
  const r = rotate(sub(p.start, p.center), a, s * TAU * p.turns * u);
  return add(add(p.center, scale(a, p.pitch * p.turns * u)), r);
}

/// Where a primitive ends (a circle where it starts, a helix where its
/// turns take it); null if malformed.
export function primitiveEnd3(p) {
  if (!p || typeof p !== "object") return null;
  if (p.type === "circle") return isPoint3(p.start) ? p.start : null;
  if (p.type === "helix") return helixPoint(p, 1);
  return isPoint3(p.end) ? p.end : null;
}

/// Points along a primitive, close enough for drawing and picking.
export function samplePrimitive3(p) {
  if (!p || !isPoint3(p.start)) return [];
  if (p.type === "line") return isPoint3(p.end) ? [p.start, p.end] : [];
  if (p.type === "helix") {
    if (!Number.isFinite(p.turns) || p.turns <= 0 || p.turns > 1000) return [];
    const n = Math.max(16, Math.min(4000, Math.ceil(p.turns * 64)));
    const out = [];
    for (let i = 0; i <= n; ++i) {
      const q = helixPoint(p, i / n);
      if (!q) return [];
      out.push(q);
    }
    return out;
  }
  const n = unit(p.normal);
  if (!n || !isPoint3(p.center)) return [];
  const sweep = p.type === "circle" ? (p.direction === "cw" ? -TAU : TAU) : arcSweep3(p);
  if (sweep === null) return [];
  const r = sub(p.start, p.center);
  const k = Math.max(8, Math.ceil(Math.abs(sweep) / TAU * 96));
  const out = [];
  for (let i = 0; i <= k; ++i) out.push(add(p.center, rotate(r, n, sweep * i / k)));
  if (p.type === "arc") out[k] = p.end;
  return out;
}

export function primitiveLength3(p) {
  if (!p || typeof p !== "object") return NaN;
  if (p.type === "line") return isPoint3(p.start) && isPoint3(p.end) ? dist3(p.start, p.end) : NaN;
  if (!isPoint3(p.start) || !isPoint3(p.center)) return NaN;
  if (p.type === "helix") {
    const a = unit(p.axis);
    if (!a || !Number.isFinite(p.turns) || !Number.isFinite(p.pitch)) return NaN;
    const r = norm(sub(sub(p.start, p.center), scale(a, dot(sub(p.start, p.center), a))));
    return p.turns * Math.hypot(TAU * r, p.pitch);
  }
  const sweep = p.type === "circle" ? TAU : arcSweep3(p);
  return sweep === null ? NaN : dist3(p.start, p.center) * Math.abs(sweep);
}

/// The primitives of a task with the part names the server gives them:
/// [{part, primitive}], from `trajectory` or every stroke of `strokes`.
export function namedPrimitives(doc) {
  const out = [];
  if (Array.isArray(doc.strokes)) {
    doc.strokes.forEach((s, i) => (Array.isArray(s) ? s : []).forEach((p, j) => out.push({ part: `strokes[${i}][${j}]`, primitive: p, index: out.length })));
  } else if (Array.isArray(doc.trajectory)) {
    doc.trajectory.forEach((p, j) => out.push({ part: `trajectory[${j}]`, primitive: p, index: j }));
  }
  return out;
}

/// The kind of a spatial obstacle: "sphere", "capsule", "box" or null.
export function obstacleKind(o) {
  if (!o || typeof o !== "object") return null;
  if (o.type === "sphere" || o.type === "capsule" || o.type === "box") return o.type;
  return o.type === undefined && o.center !== undefined && o.radius !== undefined ? "sphere" : null;
}

function boxOf(pts) {
  if (!pts.length) return null;
  return { min: [0, 1, 2].map((i) => Math.min(...pts.map((p) => p[i]))),
           max: [0, 1, 2].map((i) => Math.max(...pts.map((p) => p[i]))) };
}

/// The box of the work in a spatial task, or null: the path, the base boxes
/// and the obstacles, but for an obstacle much larger than the rest (the
/// examples' table top, 2 m across under a path of 20 cm), which would
/// shrink the work to a speck in the view.
export function spatialBounds(doc) {
  const pts = [];
  for (const { primitive } of namedPrimitives(doc)) pts.push(...samplePrimitive3(primitive));
  for (const b of Array.isArray(doc.base_regions) ? doc.base_regions : []) {
    if (b && isPoint3(b.min)) pts.push(b.min);
    if (b && isPoint3(b.max)) pts.push(b.max);
  }
  const work = boxOf(pts);
  const span = work ? Math.max(dist3(work.min, work.max), 0.1) : Infinity;
  for (const o of Array.isArray(doc.obstacles) ? doc.obstacles : []) {
    const k = obstacleKind(o), r = Number.isFinite(o && o.radius) ? o.radius : 0;
    const own = [];
    const around = (c) => { if (isPoint3(c)) own.push(add(c, [r, r, r]), sub(c, [r, r, r])); };
    if (k === "sphere") around(o.center);
    else if (k === "capsule") { around(o.a); around(o.b); }
    else if (k === "box") { if (isPoint3(o.min)) own.push(o.min); if (isPoint3(o.max)) own.push(o.max); }
    const b = boxOf(own);
    if (b && dist3(b.min, b.max) <= 3 * span) pts.push(...own);
  }
  return boxOf(pts);
}

/// The points a part can be dragged by, as {key, point}: a primitive's
/// start, end and centre; a sphere's centre; a capsule's ends; a box's
/// corners; "middle" moves a capsule or a box whole.
export function handles3(list, item) {
  const out = [];
  const put = (key, p) => { if (isPoint3(p)) out.push({ key, point: p }); };
  if (!item || typeof item !== "object") return out;
  if (list === "trajectory") {
    put("start", item.start);
    if (item.type === "line" || item.type === "arc") put("end", item.end);
    if (item.type !== "line") put("center", item.center);
  } else if (list === "obstacles") {
    const k = obstacleKind(item);
    if (k === "sphere") put("center", item.center);
    if (k === "capsule") { put("a", item.a); put("b", item.b); if (isPoint3(item.a) && isPoint3(item.b)) put("middle", mid(item.a, item.b)); }
    if (k === "box") { put("min", item.min); put("max", item.max); if (isPoint3(item.min) && isPoint3(item.max)) put("middle", mid(item.min, item.max)); }
  } else if (list === "base_regions") {
    put("min", item.min);
    put("max", item.max);
    if (isPoint3(item.min) && isPoint3(item.max)) put("middle", mid(item.min, item.max));
  }
  return out;
}

/// The keys a "middle" handle moves together.
export function middlePair(list, item) {
  if (list === "obstacles" && obstacleKind(item) === "capsule") return ["a", "b"];
  return ["min", "max"];
}

/// For a proof of reach: the point of the primitive farthest from the
/// nearest base box's centre, and that centre (for a dashed line between
/// them); null when there is nothing to draw.
export function reachLine(doc, primitive) {
  const pts = samplePrimitive3(primitive);
  const boxes = (Array.isArray(doc.base_regions) ? doc.base_regions : []).filter((b) => b && isPoint3(b.min) && isPoint3(b.max));
  if (!pts.length || !boxes.length) return null;
  let best = null;
  for (const b of boxes) {
    const c = mid(b.min, b.max);
    let far = pts[0];
    for (const p of pts) if (dist3(p, c) > dist3(far, c)) far = p;
    if (!best || dist3(far, c) < best.length) best = { from: c, to: far, length: dist3(far, c) };
  }
  return best;
}

// Where a 3-D view of a spatial task looks from (the report's view and the
// editor's): at the work, the path, the base and the arm, with the room
// round them, not at a table top ten times larger; and at a drawing on a
// surface face-on, from the side the base stands on, as whoever holds the
// pen sees it. Pure functions on [x, y, z] arrays, so that both bundles and
// the unit tests use the same.

/// An obstacle at most this many times the work's span across is framed
/// with it; a larger one (a table top, a floor) is left to show round it.
export const FRAMED_OBSTACLE_RATIO = 3;

const DEFAULT_DIRECTION = [0.9, -1.6, 0.9];
// A path counts as drawn on a surface when it spreads over an area (its
// second extent at least this share of its first) and keeps to a plane
// (its third extent at most this share of its first).
const AREA_SHARE = 0.15;
const FLAT_SHARE = 0.02;
// Face-on, but turned a little up and aside, so that the arm in front of
// the drawing does not hide it and the view keeps its depth.
const UP_TILT = 0.3;
const SIDE_TILT = 0.2;

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const unit = (a) => { const n = norm(a); return n > 0 ? [a[0] / n, a[1] / n, a[2] / n] : null; };
const finite = (p) => Array.isArray(p) && p.length === 3 && p.every(Number.isFinite);

/// {min, max} of the points, or null for none.
export function boxOf(points) {
  const pts = points.filter(finite);
  if (!pts.length) return null;
  return { min: [0, 1, 2].map((i) => Math.min(...pts.map((p) => p[i]))),
           max: [0, 1, 2].map((i) => Math.max(...pts.map((p) => p[i]))) };
}

/// The points to frame: `work` and the corners of each box in `obstacles`
/// ({min, max}) that is not much larger than the work.
export function framedPoints(work, obstacles) {
  const box = boxOf(work);
  const span = box ? Math.max(norm(sub(box.max, box.min)), 0.1) : Infinity;
  const out = work.filter(finite);
  for (const o of obstacles) {
    if (!o || !finite(o.min) || !finite(o.max)) continue;
    if (norm(sub(o.max, o.min)) <= FRAMED_OBSTACLE_RATIO * span) out.push(o.min, o.max);
  }
  return out;
}

/// Eigen-decomposition of a symmetric 3x3 matrix (Jacobi rotations):
/// [{value, vector}] sorted by value, largest first.
export function symmetricEigen(m) {
  const a = m.map((row) => [...row]);
  const v = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  for (let sweep = 0; sweep < 50; ++sweep) {
    const off = Math.abs(a[0][1]) + Math.abs(a[0][2]) + Math.abs(a[1][2]);
    if (off < 1e-15 * (Math.abs(a[0][0]) + Math.abs(a[1][1]) + Math.abs(a[2][2]) + 1e-300)) break;
    for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
      if (a[p][q] === 0) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1), s = t * c;
      for (let k = 0; k < 3; ++k) {
        const akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; ++k) {
        const apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; ++k) {
        const vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  return [0, 1, 2].map((i) => ({ value: a[i][i], vector: [v[0][i], v[1][i], v[2][i]] }))
    .sort((x, y) => y.value - x.value);
}

/// The normal of the plane the path is drawn in, when it is drawn on a
/// plane over an area (not along a line, not in space); else null.
export function drawingNormal(path) {
  const pts = path.filter(finite);
  if (pts.length < 3) return null;
  const c = [0, 1, 2].map((i) => pts.reduce((s, p) => s + p[i], 0) / pts.length);
  const m = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  for (const p of pts) {
    const d = sub(p, c);
    for (let i = 0; i < 3; ++i) for (let j = 0; j < 3; ++j) m[i][j] += d[i] * d[j] / pts.length;
  }
  const [first, second, third] = symmetricEigen(m);
  const extent = (e) => Math.sqrt(Math.max(e.value, 0));
  if (!(extent(first) > 0)) return null;
  if (extent(second) < AREA_SHARE * extent(first) || extent(third) > FLAT_SHARE * extent(first)) return null;
  return unit(third.vector);
}

/// How to look at the work: {centre, radius, direction}, the camera at
/// centre + direction * distance. `path`: points along the path; `work`:
/// every point to keep in view; `base`: where the base stands (or null).
/// A path drawn on a plane is seen face-on from the base's side of it
/// (turned a little up and aside); any other from the front right, above.
export function viewFrame(path, work, base) {
  const box = boxOf(work.length ? work : path) || { min: [-0.5, -0.5, 0], max: [0.5, 0.5, 0.5] };
  const centre = [0, 1, 2].map((i) => (box.min[i] + box.max[i]) / 2);
  const radius = Math.max(norm(sub(box.max, box.min)) / 2, 0.05);
  let direction = unit(DEFAULT_DIRECTION);
  const n = drawingNormal(path);
  if (n) {
    const pathBox = boxOf(path);
    const middle = [0, 1, 2].map((i) => (pathBox.min[i] + pathBox.max[i]) / 2);
    // Towards the base; with no base, towards the usual corner of view.
    const toward = finite(base) ? sub(base, middle) : DEFAULT_DIRECTION;
    const face = dot(n, toward) >= 0 ? n : n.map((x) => -x);
    if (Math.abs(face[2]) > 0.97) {
      // A drawing on a level surface (a table, a floor): from above, and a
      // little from the front.
      direction = unit([0.25, -0.45, 1]);
    } else {
      const side = unit(cross([0, 0, 1], face));
      const up = unit(cross(face, side));
      direction = unit([0, 1, 2].map((i) => face[i] + UP_TILT * up[i] + SIDE_TILT * side[i]));
    }
  }
  return { centre, radius, direction };
}

/// The camera's distance that keeps a sphere of `radius` in a view of
/// `fovDegrees` (vertical) and `aspect` (width / height), with `margin`
/// times the room (the editor leaves more, for the handles' arrows).
export function frameDistance(radius, fovDegrees, aspect, margin = 1.1) {
  const half = (fovDegrees * Math.PI) / 360;
  const horizontal = Math.atan(Math.tan(half) * Math.min(aspect, 1));
  return (radius / Math.sin(Math.min(half, horizontal))) * margin;
}

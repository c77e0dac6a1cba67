// The proof that no robot can do the task, drawn over it from the solution
// JSON's witness (docs/formats.md, "explanation.separation" and
// "explanation.geodesic"), as the report draws it: each closed wall (the
// obstacles' no-go discs, the polygon through their centres and where
// neighbours overlap) or each detour (the shortest way around the obstacles
// and its length against the reach).

import { svg } from "./dom.js";

const TAU = 2 * Math.PI;
const angleOf = (v) => { const a = Math.atan2(v[1], v[0]); return a < 0 ? a + TAU : a; };
const sub = (a, b) => [a[0] - b[0], a[1] - b[1]];
const mod = (x) => ((x % TAU) + TAU) % TAU;
const f1 = (v) => v.toFixed(1);

/// SVG arc (screen pixels) to `to` around `c`, the way that passes angle `via`.
function arcTo(c, r, from, to, via) {
  const a = angleOf(sub(from, c));
  const span = mod(angleOf(sub(to, c)) - a);
  const positive = mod(via - a) <= span;
  const travelled = positive ? span : TAU - span;
  return `A${f1(r)},${f1(r)} 0 ${travelled > Math.PI ? 1 : 0},${positive ? 1 : 0} ${f1(to[0])},${f1(to[1])}`;
}

/// Where two discs overlap, as path data (the smaller disc when one holds the other).
function lens(c1, r1, c2, r2) {
  const d = Math.hypot(c2[0] - c1[0], c2[1] - c1[1]);
  if (d === 0 || d <= Math.abs(r1 - r2)) {
    const [c, r] = r1 < r2 ? [c1, r1] : [c2, r2];
    return `M${f1(c[0] - r)},${f1(c[1])}a${f1(r)},${f1(r)} 0 1,0 ${f1(2 * r)},0a${f1(r)},${f1(r)} 0 1,0 ${f1(-2 * r)},0Z`;
  }
  const u = [(c2[0] - c1[0]) / d, (c2[1] - c1[1]) / d], n = [-u[1], u[0]];
  const a = (d * d + r1 * r1 - r2 * r2) / (2 * d), h = Math.sqrt(Math.max(0, r1 * r1 - a * a));
  const p = [c1[0] + a * u[0] + h * n[0], c1[1] + a * u[1] + h * n[1]];
  const q = [c1[0] + a * u[0] - h * n[0], c1[1] + a * u[1] - h * n[1]];
  return `M${f1(p[0])},${f1(p[1])}` + arcTo(c1, r1, p, q, angleOf(u)) + arcTo(c2, r2, q, p, angleOf([-u[0], -u[1]])) + "Z";
}

export class ProofRender {
  constructor(layer, store, view) {
    this.g = layer;
    this.store = store;
    this.view = view;
  }

  render() {
    this.g.replaceChildren();
    const w = this.store.witness;
    if (!w) return;
    const obstacles = this.store.model.obstacles;
    const half = (Number(this.store.doc.robot && this.store.doc.robot.link_diameter) || 0) / 2;
    const known = (i) => Number.isInteger(i) && obstacles[i] && Array.isArray(obstacles[i].center);
    const centre = (i) => this.view.toScreen(obstacles[i].center);
    const noGo = (i) => (obstacles[i].radius + half) * this.view.s;
    for (const wall of (w.separation && w.separation.walls) || []) this.wall(wall, known, centre, noGo);
    for (const d of (w.geodesic && w.geodesic.detours) || []) this.detour(d, w.geodesic.reach, known, centre, noGo);
  }

  point(p, title) {
    const c = this.view.toScreen(p);
    svg("circle", { cx: c[0], cy: c[1], r: 5, class: "proof-point" }, this.g).append(title);
  }

  wall(wall, known, centre, noGo) {
    const cycle = wall.cycle || [];
    if (cycle.length < 2 || !cycle.every(known)) return;
    const g = svg("g", { class: "wall", "data-base-region": wall.base_region, "data-cycle": cycle.join(" ") }, this.g);
    for (const i of cycle) {
      const c = centre(i);
      svg("circle", { cx: c[0], cy: c[1], r: noGo(i), class: "wall-disc", "data-obstacle": i }, g);
    }
    const pts = cycle.map(centre);
    svg("path", { d: "M" + pts.map((q) => f1(q[0]) + "," + f1(q[1])).join("L") + "Z", class: "wall-cycle" }, g);
    cycle.forEach((i, k) => {
      if (cycle.length === 2 && k === 1) return;
      const j = cycle[(k + 1) % cycle.length];
      const e = svg("path", { d: lens(centre(i), noGo(i), centre(j), noGo(j)), class: "wall-overlap", "data-pair": `${i}-${j}` }, g);
      const depth = (wall.overlaps || [])[k] || 0;
      e.append(this.title(`obstacles[${i}] and obstacles[${j}]: no-go discs overlap by ${(depth * 1000).toFixed(1)} mm`));
    });
    if (Array.isArray(wall.point)) this.point(wall.point, this.title(`trajectory[${wall.primitive}]: behind the wall`));
  }

  detour(d, reach, known, centre, noGo) {
    const route = d.route || [];
    if (route.length < 2) return;
    let prev = this.view.toScreen(route[0].point);
    let path = `M${f1(prev[0])},${f1(prev[1])}`;
    for (const step of route.slice(1)) {
      const to = this.view.toScreen(step.point);
      if (known(step.around)) {
        const c = centre(step.around), mid = sub([(prev[0] + to[0]) / 2, (prev[1] + to[1]) / 2], c);
        const via = Math.hypot(mid[0], mid[1]) > 1e-9 ? angleOf(mid) : angleOf(sub(prev, c)) + 1;
        path += arcTo(c, noGo(step.around), prev, to, via);
      } else {
        path += `L${f1(to[0])},${f1(to[1])}`;
      }
      prev = to;
    }
    const label = `at least ${d.lower_bound.toFixed(2)} m; reach ${Number(reach).toFixed(2)} m`;
    svg("path", { d: path, class: "detour", "data-base-region": d.base_region, "data-primitive": d.primitive }, this.g)
      .append(this.title(`the shortest way from base_regions[${d.base_region}] to trajectory[${d.primitive}]: ${label}`));
    const at = this.view.toScreen(route[Math.floor(route.length / 2)].point);
    const left = at[0] > this.view.size()[0] / 2;
    svg("text", { x: at[0] + (left ? -10 : 10), y: at[1] - 8, "text-anchor": left ? "end" : "start", class: "detour-length" },
        this.g).textContent = label;
    if (Array.isArray(d.point)) this.point(d.point, this.title(`trajectory[${d.primitive}]: beyond reach`));
  }

  title(text) {
    const t = svg("title", {});
    t.textContent = text;
    return t;
  }
}

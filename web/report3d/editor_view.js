// The editor's 3-D view of a spatial task (web/space_view.js drives it from
// the page's state): the path, the obstacles and the base boxes, a floor
// grid with the task frame's axes and an axis gizmo in the corner; orbit
// (drag), pan (right-drag) and zoom (wheel); clicking a part picks it, and
// the selected part's handles are dragged along the x, y and z arrows of
// the one last clicked. A solved task's arm (the DH chain of the solution,
// drawn as the report draws it, scene.js) moves along its samples; a proof
// is drawn over the task. esbuild bundles it with three.js into the page's
// /editor3d.js; nothing is fetched from elsewhere.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { ViewHelper } from "three/addons/helpers/ViewHelper.js";
import { armObjects, capsule, dhFrames, labelledAxes, material, niceStep, origin, place, v3, webglWorks, witnessCells, witnessRuns } from "./scene.js";
import { handles3, isPoint3, mid, namedPrimitives, obstacleKind, samplePrimitive3, spatialBounds } from "../space_geometry.js";
import { frameDistance, viewFrame } from "./view_frame.js";

const CORE = 0xd00000;
const SELECTED = 0x2f6fb3;
const ERROR = 0xff8c00;
const OBSTACLE = 0xe45756;
const OTHER_OBSTACLE = 0xb0b0b0;  // not in a core that is shown: red means "in conflict" then
export const AXES = { x: [1, 0, 0], y: [0, 1, 0], z: [0, 0, 1] };
const AXIS_COLOURS = { x: 0xd62728, y: 0x2ca02c, z: 0x1f77b4 };
const DRAG_PIXELS = 5;        // a press that moves further is a drag, not a click
const ARROW_SCREEN = 0.16;    // an arrow's length, as a share of its distance from the camera
const HOLD_AT_END_S = 0.6;    // the motion rests this long at its end before it starts again
// Between two frames of the motion the page gets this long for the rest
// (the panel, the server's answers): drawn in software, as without a GPU,
// a frame can take the whole of a frame's time.
const MOTION_PAUSE_MS = 25;

function dispose(group) {
  for (const child of [...group.children]) {
    child.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) (Array.isArray(o.material) ? o.material : [o.material]).forEach((m) => m.dispose());
    });
    group.remove(child);
  }
}

/// A tube through points (a polyline), as the report draws the path.
function tube(points, radius, mat) {
  // A point twice in a row (a line typed with its end at its start) would
  // leave the tube's frame undefined there.
  const pts = points.map(v3).filter((p, i, all) => i === 0 || p.distanceTo(all[i - 1]) > 1e-12);
  if (pts.length < 2) return new THREE.Group();
  const path = new THREE.CurvePath();
  for (let i = 1; i < pts.length; ++i) path.add(new THREE.LineCurve3(pts[i - 1], pts[i]));
  return new THREE.Mesh(new THREE.TubeGeometry(path, Math.max(8, pts.length * 2), radius, 8, false), mat);
}

// What is hit by a ray but not drawn: a thicker tube round a thin one, the
// arrows' grips.
const pickerMaterial = () => new THREE.MeshBasicMaterial({ colorWrite: false, depthWrite: false });

/// Moves along the ray o + t r to the point of the line p + s d nearest it:
/// s, or null when the two run parallel.
function lineParameter(p, d, o, r) {
  const w = p.clone().sub(o);
  const a = d.dot(d), b = d.dot(r), c = r.dot(r), e = d.dot(w), f = r.dot(w);
  const denom = a * c - b * b;
  if (Math.abs(denom) < 1e-12 * a * c) return null;
  return (b * f - c * e) / denom;
}

export class EditorView3D {
  /// hooks: {onPick(part | null), onDragStart(part, key), onDrag(part, key,
  /// point), onDragEnd(), onTime({time, duration, playing}), snap() -> step
  /// in metres or 0}.
  constructor(host, hooks) {
    this.host = host;
    this.hooks = hooks;
    // What a browser test reads.
    this.state = { ready: false, error: "", frames: 0, time: 0, duration: 0, playing: false, q: null, ee: null,
                   handle: null, parts: 0 };
    this.doc = null;
    this.marks = {};
    this.size = 1;
    this.activeKey = null;
    this.drag = null;
    this.motion = null;
    this.wall = new Set();  // the obstacles of a wall whose cells are drawn
    if (!webglWorks()) {
      this.state.error = "no WebGL";
      host.textContent = "The 3-D view needs WebGL, which this browser does not offer; the part list edits the task.";
      return;
    }
    const renderer = this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xffffff);
    renderer.autoClear = false;
    host.appendChild(renderer.domElement);
    renderer.domElement.classList.add("view3d-canvas");

    const scene = this.scene = new THREE.Scene();
    scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(1, -2, 3);
    scene.add(sun);
    for (const name of ["floor", "task", "proof", "arm", "handles"]) {
      this[name] = new THREE.Group();
      scene.add(this[name]);
    }
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.001, 1000);
    this.camera.up.set(0, 0, 1);
    this.raycaster = new THREE.Raycaster();
    // Before the orbit controls: a press on a handle must not orbit.
    this.listen(renderer.domElement);
    this.controls = new OrbitControls(this.camera, renderer.domElement);
    this.controls.addEventListener("change", () => this.draw());
    this.gizmo = new ViewHelper(this.camera, renderer.domElement);
    new ResizeObserver(() => this.resize()).observe(host);
    this.resize();
    this.state.ready = true;
  }

  get ok() { return !!this.renderer; }

  resize() {
    if (!this.renderer) return;
    const w = this.host.clientWidth, h = this.host.clientHeight;
    if (!w || !h) return;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  /// Draws at the next frame: edits, drags and orbiting ask many times a
  /// frame, and the scene is rebuilt (when the task changed) and drawn once.
  draw() {
    if (!this.renderer || this.frameRequest) return;
    this.frameRequest = requestAnimationFrame(() => {
      this.frameRequest = 0;
      this.rebuild();
      this.scaleHandles();
      this.renderer.clear();
      this.renderer.render(this.scene, this.camera);
      this.gizmo.render(this.renderer);
      this.state.frames += 1;
    });
  }

  /// The scene of the task as it is now, if it changed since it was built.
  rebuild() {
    if (!this.stale) return;
    this.stale = false;
    this.buildTask();
    this.buildHandles();
  }

  // ------------------------------------------------------------- the task

  /// marks: {selection, inCore(part), hasError(part), colour(j)}.
  setTask(doc, marks) {
    this.doc = doc;
    this.marks = marks;
    if (!this.renderer) return;
    if (!this.framed) this.fit();
    this.stale = true;
    this.draw();
  }

  /// The camera looks at the work (view_frame.js): a drawing on a plane
  /// face-on from the base's side, anything else from the front right,
  /// above; the grid lies under it.
  fit() {
    if (!this.renderer || !this.doc) return;
    const b = spatialBounds(this.doc) || { min: [-0.5, -0.5, 0], max: [0.5, 0.5, 0.5] };
    const path = namedPrimitives(this.doc).flatMap(({ primitive }) => samplePrimitive3(primitive));
    const regions = (Array.isArray(this.doc.base_regions) ? this.doc.base_regions : []).filter((r) => r && isPoint3(r.min) && isPoint3(r.max));
    const frame = viewFrame(path, [b.min, b.max], regions.length ? mid(regions[0].min, regions[0].max) : null);
    const centre = v3(frame.centre);
    this.size = 2 * frame.radius;
    const size = this.size;
    this.camera.near = size / 500;
    this.camera.far = size * 200;
    this.camera.position.copy(centre).addScaledVector(v3(frame.direction), frameDistance(frame.radius, this.camera.fov, this.camera.aspect, 1.35));
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(centre);
    this.controls.update();
    this.state.frame = frame;
    dispose(this.floor);
    const step = niceStep(size);
    const cells = Math.ceil(size * 2.4 / step);
    const grid = new THREE.GridHelper(cells * step, cells, 0x9a9a9a, 0xdddddd);
    grid.rotation.x = Math.PI / 2;
    grid.position.set(Math.round(centre.x / step) * step, Math.round(centre.y / step) * step, Math.min(0, b.min[2]));
    this.floor.add(grid);
    this.floor.add(labelledAxes(new THREE.Vector3(0, 0, Math.min(0, b.min[2])), step));
    this.framed = true;
    this.stale = true;
    this.draw();
  }

  buildTask() {
    dispose(this.task);
    const doc = this.doc, m = this.marks, size = this.size;
    const tag = (o, part) => { o.traverse((x) => { x.userData.part = part; }); return o; };
    let count = 0;
    const prims = namedPrimitives(doc);
    for (const { part, primitive, index } of prims) {
      const pts = samplePrimitive3(primitive);
      if (pts.length < 2) continue;
      const core = m.inCore(part), selected = part === m.selection, bad = m.hasError(part);
      const colour = core ? CORE : selected ? SELECTED : bad ? ERROR : new THREE.Color(m.colour(index)).getHex();
      const radius = size * (core ? 0.006 : selected ? 0.0045 : 0.003);
      this.task.add(tag(tube(pts, radius, new THREE.MeshBasicMaterial({ color: colour })), part));
      this.task.add(tag(tube(pts, size * 0.012, pickerMaterial()), part));
      if (core) {
        const halo = tube(pts, size * 0.014, new THREE.MeshBasicMaterial({ color: CORE, transparent: true, opacity: 0.2, depthWrite: false }));
        this.task.add(tag(halo, part));
      }
      // Which way the tool runs: a cone at the primitive's end, no longer
      // than a third of the primitive (a drawing's pieces are small).
      const a = v3(pts[pts.length - 2]), b = v3(pts[pts.length - 1]);
      let length = 0;
      for (let i = 1; i < pts.length; ++i) length += v3(pts[i]).distanceTo(v3(pts[i - 1]));
      const arrow = Math.min(size * 0.024, length / 3);
      const cone = new THREE.Mesh(new THREE.ConeGeometry(arrow / 3, arrow, 12), new THREE.MeshBasicMaterial({ color: colour }));
      place(cone, b.clone().add(a.clone().sub(b).setLength(arrow)), b);
      cone.scale.set(1, 1, 1);
      this.task.add(tag(cone, part));
      ++count;
    }
    if (prims.length && isPoint3(prims[0].primitive.start)) {
      const start = new THREE.Mesh(new THREE.SphereGeometry(size * 0.007, 16, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
      start.position.copy(v3(prims[0].primitive.start));
      this.task.add(start);
    }
    (Array.isArray(doc.obstacles) ? doc.obstacles : []).forEach((o, i) => {
      const part = `obstacles[${i}]`, kind = obstacleKind(o);
      const core = m.inCore(part), selected = part === m.selection, bad = m.hasError(part);
      // A wall's obstacles are faint, so that the cells they close in show
      // through in their own colour; outlined in red.
      const inWall = this.wall.has(i);
      const colour = core ? CORE : selected ? SELECTED : bad ? ERROR : m.coreShown ? OTHER_OBSTACLE : OBSTACLE;
      const mat = material(colour, inWall ? 0.12 : core || selected ? 0.7 : 0.45);
      let mesh = null;
      if (kind === "sphere" && isPoint3(o.center) && o.radius > 0) {
        mesh = new THREE.Mesh(new THREE.SphereGeometry(o.radius, 32, 16), mat);
        mesh.position.copy(v3(o.center));
      } else if (kind === "capsule" && isPoint3(o.a) && isPoint3(o.b) && o.radius > 0) {
        mesh = capsule(v3(o.a), v3(o.b), o.radius, mat);
      } else if (kind === "box" && isPoint3(o.min) && isPoint3(o.max)) {
        const lo = v3(o.min), hi = v3(o.max), s = hi.clone().sub(lo);
        if (s.x > 0 && s.y > 0 && s.z > 0) {
          mesh = new THREE.Mesh(new THREE.BoxGeometry(s.x, s.y, s.z), mat);
          mesh.position.copy(lo).add(hi).multiplyScalar(0.5);
          if (selected || core) {
            const edges = new THREE.LineSegments(new THREE.EdgesGeometry(mesh.geometry), new THREE.LineBasicMaterial({ color: core ? CORE : SELECTED }));
            edges.position.copy(mesh.position);
            this.task.add(tag(edges, part));
          }
        }
      }
      if (mesh && inWall && mesh.geometry) {
        const edges = new THREE.LineSegments(new THREE.EdgesGeometry(mesh.geometry, 30), new THREE.LineBasicMaterial({ color: CORE }));
        edges.position.copy(mesh.position);
        this.task.add(tag(edges, part));
      }
      if (mesh) { this.task.add(tag(mesh, part)); ++count; }
    });
    (Array.isArray(doc.base_regions) ? doc.base_regions : []).forEach((r, i) => {
      if (!r || !isPoint3(r.min) || !isPoint3(r.max)) return;
      const part = `base_regions[${i}]`;
      const core = m.inCore(part), selected = part === m.selection, bad = m.hasError(part);
      const lo = v3(r.min), hi = v3(r.max);
      const s = hi.clone().sub(lo).max(new THREE.Vector3(1e-4, 1e-4, 1e-4));
      const box = new THREE.BoxGeometry(s.x, s.y, s.z);
      const colour = core ? CORE : selected ? SELECTED : bad ? ERROR : 0x444444;
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(box),
        core || selected ? new THREE.LineBasicMaterial({ color: colour })
                         : new THREE.LineDashedMaterial({ color: colour, dashSize: size * 0.01, gapSize: size * 0.006 }));
      edges.computeLineDistances();
      edges.position.copy(lo).add(hi).multiplyScalar(0.5);
      const fill = new THREE.Mesh(box, new THREE.MeshBasicMaterial({
        color: core ? CORE : selected ? SELECTED : 0x000000, transparent: true, opacity: core || selected ? 0.18 : 0.06, depthWrite: false }));
      fill.position.copy(edges.position);
      // A flat plate is hard to hit: a thicker box to pick it by.
      const grip = new THREE.Mesh(new THREE.BoxGeometry(s.x + size * 0.01, s.y + size * 0.01, s.z + size * 0.01), pickerMaterial());
      grip.position.copy(edges.position);
      this.task.add(tag(edges, part), tag(fill, part), tag(grip, part));
      ++count;
    });
    this.state.parts = count;
  }

  // ----------------------------------------------------------- the handles

  /// The selected part's handles; the active one (last clicked, else the
  /// first) carries the three axis arrows.
  buildHandles() {
    dispose(this.handles);
    this.handleObjects = [];
    this.state.handle = null;
    const part = this.marks.selection;
    const m = /^(trajectory|obstacles|base_regions)\[(\d+)\]$/.exec(part || "");
    if (!m || !this.doc) return;
    const list = Array.isArray(this.doc[m[1]]) ? this.doc[m[1]] : [];
    const hs = handles3(m[1], list[+m[2]]);
    if (!hs.length) return;
    if (!hs.some((h) => h.key === this.activeKey) || this.activePart !== part) this.activeKey = hs[0].key;
    this.activePart = part;
    for (const h of hs) {
      const active = h.key === this.activeKey;
      const g = new THREE.Group();
      g.position.copy(v3(h.point));
      const ball = new THREE.Mesh(new THREE.SphereGeometry(0.06, 16, 8), new THREE.MeshBasicMaterial({ color: active ? SELECTED : 0xffffff, depthTest: false }));
      ball.renderOrder = 10;
      const ring = new THREE.Mesh(new THREE.SphereGeometry(0.075, 16, 8), new THREE.MeshBasicMaterial({ color: SELECTED, side: THREE.BackSide, depthTest: false }));
      ring.renderOrder = 9;
      ball.userData.handle = h.key;
      ring.userData.handle = h.key;
      g.add(ring, ball);
      if (active) {
        for (const [axis, d] of Object.entries(AXES)) {
          const dir = v3(d);
          const mat = new THREE.MeshBasicMaterial({ color: AXIS_COLOURS[axis], depthTest: false });
          const shaft = new THREE.Mesh(new THREE.CylinderGeometry(0.012, 0.012, 1, 8), mat);
          place(shaft, new THREE.Vector3(), dir.clone().multiplyScalar(0.8));
          const tip = new THREE.Mesh(new THREE.ConeGeometry(0.05, 0.2, 12), mat.clone());
          place(tip, dir.clone().multiplyScalar(0.8), dir.clone());
          tip.scale.set(1, 1, 1);
          const grip = new THREE.Mesh(new THREE.CylinderGeometry(0.07, 0.07, 1, 8), pickerMaterial());
          place(grip, dir.clone().multiplyScalar(0.15), dir.clone());
          for (const o of [shaft, tip, grip]) { o.userData.axis = axis; o.renderOrder = 11; }
          g.add(shaft, tip, grip);
        }
        this.state.handle = { part, key: h.key, point: [...h.point] };
      }
      this.handles.add(g);
      this.handleObjects.push({ group: g, key: h.key, point: h.point });
    }
  }

  /// Handles keep their size on the screen whatever the zoom.
  scaleHandles() {
    for (const h of this.handleObjects || []) {
      const s = this.camera.position.distanceTo(h.group.position) * ARROW_SCREEN;
      h.group.scale.setScalar(s);
    }
  }

  /// Page coordinates of a task point.
  clientPoint(p) {
    const r = this.renderer.domElement.getBoundingClientRect();
    const q = v3(p).project(this.camera);
    return [r.left + (q.x + 1) / 2 * r.width, r.top + (1 - q.y) / 2 * r.height];
  }

  /// Page coordinates of a point on the active handle's arrow along `axis`
  /// (where a press grabs it), or null.
  axisClientPoint(axis) {
    this.rebuild();
    const h = (this.handleObjects || []).find((x) => x.key === this.activeKey);
    if (!h) return null;
    const s = this.camera.position.distanceTo(h.group.position) * ARROW_SCREEN;
    return this.clientPoint(v3(h.point).addScaledVector(v3(AXES[axis]), 0.7 * s).toArray());
  }

  // -------------------------------------------------------------- pointer

  ray(e) {
    const r = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2((e.clientX - r.left) / r.width * 2 - 1, 1 - (e.clientY - r.top) / r.height * 2);
    this.raycaster.setFromCamera(ndc, this.camera);
    return this.raycaster;
  }

  listen(el) {
    el.addEventListener("pointerdown", (e) => {
      if (e.button !== 0 || !this.doc) return;
      this.press = { x: e.clientX, y: e.clientY, moved: false };
      this.rebuild();
      this.scaleHandles();
      this.handles.updateMatrixWorld(true);
      // A handle under the pointer is the one meant, even behind an arrow
      // that passes over it: the arrows are long, the handles small.
      const hits = this.ray(e).intersectObjects(this.handles.children, true);
      const handleHit = hits.find((x) => x.object.userData.handle) || null;
      const axisHit = handleHit ? null : hits.find((x) => x.object.userData.axis) || null;
      if (axisHit) {
        const h = this.handleObjects.find((x) => x.key === this.activeKey);
        const d = v3(AXES[axisHit.object.userData.axis]);
        const s0 = lineParameter(v3(h.point), d, this.raycaster.ray.origin, this.raycaster.ray.direction);
        if (s0 === null) return;
        this.controls.enabled = false;
        el.setPointerCapture(e.pointerId);
        this.drag = { part: this.marks.selection, key: h.key, from: v3(h.point), d, s0, axis: axisHit.object.userData.axis };
        this.hooks.onDragStart(this.drag.part, this.drag.key);
      } else if (handleHit) {
        this.controls.enabled = false;
        this.activeKey = handleHit.object.userData.handle;
        this.press.handle = true;
        this.buildHandles();
        this.draw();
      }
    });
    el.addEventListener("pointermove", (e) => {
      if (this.press && Math.hypot(e.clientX - this.press.x, e.clientY - this.press.y) > DRAG_PIXELS) this.press.moved = true;
      if (!this.drag) return;
      const d = this.drag;
      const s = lineParameter(d.from, d.d, ...(() => { const r = this.ray(e).ray; return [r.origin, r.direction]; })());
      if (s === null) return;
      let shift = s - d.s0;
      const step = this.hooks.snap ? this.hooks.snap() : 0;
      if (step > 0) shift = Math.round(shift / step) * step;
      const p = d.from.clone().addScaledVector(d.d, shift).toArray();
      // The moved coordinate lands on the step; the others stay as they were.
      if (step > 0) { const i = "xyz".indexOf(d.axis); p[i] = Math.round(p[i] / step) * step; }
      this.hooks.onDrag(d.part, d.key, p);
    });
    const release = (e) => {
      if (this.drag) {
        this.drag = null;
        this.hooks.onDragEnd();
      } else if (this.press && !this.press.moved && !this.press.handle) {
        this.rebuild();
        const hit = this.ray(e).intersectObjects(this.task.children, true).find((x) => x.object.userData.part);
        this.hooks.onPick(hit ? hit.object.userData.part : null);
      }
      this.press = null;
      this.controls.enabled = true;
    };
    el.addEventListener("pointerup", release);
    el.addEventListener("pointercancel", () => { this.press = null; if (this.drag) { this.drag = null; this.hooks.onDragEnd(); } this.controls.enabled = true; });
  }

  // -------------------------------------------------------------- the proof

  /// The proof drawn over the task: for a primitive out of reach, dashed
  /// red lines from a base box to what it cannot reach, with their ends
  /// marked ([{from, to}]); for a wall, its enclosed cells, each a green
  /// cube (formats.md "explanation.enclosure"), and a red ring at the point
  /// kept out.
  setProof(lines, enclosure = null) {
    if (!this.renderer) return;
    dispose(this.proof);
    for (const { from, to } of lines || []) {
      const g = new THREE.BufferGeometry().setFromPoints([v3(from), v3(to)]);
      const line = new THREE.Line(g, new THREE.LineDashedMaterial({ color: CORE, dashSize: this.size * 0.02, gapSize: this.size * 0.012 }));
      line.computeLineDistances();
      this.proof.add(line);
      for (const p of [from, to]) {
        const dot = new THREE.Mesh(new THREE.SphereGeometry(this.size * 0.008, 16, 8), new THREE.MeshBasicMaterial({ color: CORE }));
        dot.position.copy(v3(p));
        this.proof.add(dot);
      }
    }
    const walls = enclosure && Array.isArray(enclosure.walls) ? enclosure.walls : [];
    this.wall = new Set(walls.flatMap((w) => w.obstacles || []));
    this.state.enclosureCells = 0;
    for (const w of walls) {
      const { object, cells } = witnessCells(witnessRuns(w));
      this.proof.add(object);
      this.state.enclosureCells += cells;
      if (isPoint3(w.point)) {
        const ring = new THREE.Mesh(new THREE.TorusGeometry(this.size * 0.02, this.size * 0.004, 8, 32), new THREE.MeshBasicMaterial({ color: CORE }));
        ring.position.copy(v3(w.point));
        this.proof.add(ring);
      }
    }
    this.stale = true;
    this.draw();
  }

  // ------------------------------------------------------------- the motion

  /// robot: {base, dh: [[a, alpha, d]], D, tool, mod: [l, w, h]};
  /// samples: the solution's [{t, q}]. The arm is posed at the start.
  setMotion(robot, samples) {
    this.clearMotion();
    if (!this.renderer || !samples.length) return;
    this.robot = robot;
    this.armView = armObjects(robot, this.arm);
    const n = robot.dh.length;
    const t = samples.map((s) => s.t);
    const times = t[t.length - 1] > t[0] ? t : t.map((_, i) => i);
    // The tool's trail, drawn up to the moment shown.
    const trail = new Float32Array(samples.length * 3);
    samples.forEach((s, i) => trail.set(origin(dhFrames(robot, s.q)[n]).toArray(), i * 3));
    this.trailGeometry = new THREE.BufferGeometry();
    this.trailGeometry.setAttribute("position", new THREE.BufferAttribute(trail, 3));
    this.arm.add(new THREE.Line(this.trailGeometry, new THREE.LineBasicMaterial({ color: 0x000000 })));
    this.motion = { times, q: samples.map((s) => s.q), T0: times[0], T1: times[times.length - 1] };
    this.state.duration = this.motion.T1 - this.motion.T0;
    this.showTime(this.motion.T0);
  }

  clearMotion() {
    this.play(false);
    this.motion = null;
    this.state.duration = 0;
    this.state.time = 0;
    this.state.q = null;
    this.state.ee = null;
    if (this.renderer) { dispose(this.arm); this.draw(); }
    if (this.hooks.onTime) this.hooks.onTime({ time: 0, duration: 0, playing: false });
  }

  showTime(time) {
    const m = this.motion;
    if (!m) return;
    const N = m.times.length;
    let a = 0, b = N - 1;
    while (a < b) {
      const mid = (a + b + 1) >> 1;
      if (m.times[mid] <= time) a = mid; else b = mid - 1;
    }
    const span = a + 1 < N ? m.times[a + 1] - m.times[a] : 0;
    const f = span > 0 ? Math.min(1, (time - m.times[a]) / span) : 0;
    const qa = m.q[a], qb = a + 1 < N ? m.q[a + 1] : qa;
    const q = qa.map((v, k) => v + (qb[k] - v) * f);
    const ee = this.armView.pose(q);
    this.trailGeometry.setDrawRange(0, a + 1);
    Object.assign(this.state, { time: time - m.T0, q, ee: ee.toArray() });
    this.draw();
    if (this.hooks.onTime) this.hooks.onTime({ time: time - m.T0, duration: m.T1 - m.T0, playing: this.state.playing });
  }

  /// Seconds from the motion's start.
  setTime(t) {
    if (!this.motion) return;
    this.play(false);
    this.showTime(Math.min(this.motion.T1, Math.max(this.motion.T0, this.motion.T0 + t)));
  }

  /// Plays the motion over and over (on) or holds it where it is.
  play(on) {
    this.state.playing = !!on && !!this.motion;
    this.last = null;
    if (this.state.playing) {
      const frame = (now) => {
        if (!this.state.playing || !this.motion) return;
        const m = this.motion;
        let time = m.T0 + this.state.time;
        if (this.last !== null) time += (now - this.last) / 1000;
        this.last = now;
        if (time > m.T1 + HOLD_AT_END_S) time = m.T0;
        this.showTime(Math.min(time, m.T1));
        // The hold at the end is counted past T1.
        if (time > m.T1) this.state.time = time - m.T0;
        setTimeout(() => requestAnimationFrame(frame), MOTION_PAUSE_MS);
      };
      requestAnimationFrame(frame);
    } else if (this.motion && this.hooks.onTime) {
      this.hooks.onTime({ time: this.state.time, duration: this.state.duration, playing: false });
    }
  }
}

// The 3-D view of a spatial solution's report (src/output/report3d.cpp):
// the task (path, obstacles, base regions), the DH arm and its animated
// motion, with orbit / pan / zoom, a floor grid and the planar report's
// controls (#play, #scrub, #clock, #speed, #readout; `#t=12` opens at
// t = 12 s). It reads the element #scene-data. esbuild bundles it with
// three.js into one script that the report carries inline.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { armObjects, capsule, dhFrames, labelledAxes, material, niceStep, origin, v3, webglWorks, witnessCells } from "./scene.js";
import { frameDistance, framedPoints, viewFrame } from "./view_frame.js";

const $ = (id) => document.getElementById(id);
// What a browser test reads: whether the view drew, and how to move it.
const state = { ready: false, error: "", frames: 0, time: 0 };
window.modsynthView = state;

// ------------------------------------------------------------------ the task

function taskObjects(task, scene, size, wall) {
  const core = 0xd00000;
  // With a core shown, red means "in conflict": the other obstacles are grey.
  const hasCore = task.prims.some((p) => p.core) || task.obstacles.some((o) => o.core) ||
    task.regions.some((r) => r.core);
  for (const p of task.prims) {
    const pts = p.pts.map(v3);
    const path = new THREE.CurvePath();
    for (let i = 1; i < pts.length; ++i) path.add(new THREE.LineCurve3(pts[i - 1], pts[i]));
    const radius = size * (p.core ? 0.004 : 0.0025);
    const tube = new THREE.Mesh(
      new THREE.TubeGeometry(path, Math.max(8, pts.length * 2), radius, 8, false),
      new THREE.MeshBasicMaterial({ color: p.core ? core : p.col }));
    tube.userData.primitive = p.i;
    scene.add(tube);
  }
  if (task.prims.length) {
    const start = new THREE.Mesh(new THREE.SphereGeometry(size * 0.007, 16, 8),
      new THREE.MeshBasicMaterial({ color: 0x000000 }));
    start.position.copy(v3(task.prims[0].pts[0]));
    scene.add(start);
  }
  task.obstacles.forEach((o, i) => {
    // A wall's obstacles are drawn faint, outlined, so that the cells they
    // close in show through in their own colour.
    const inWall = wall.has(i);
    const mat = material(o.core ? core : hasCore ? 0xb0b0b0 : 0xe45756, inWall ? 0.12 : 0.55);
    let geometry = null, at = null;
    if (o.type === "sphere") {
      geometry = new THREE.SphereGeometry(o.r, 32, 16);
      at = v3(o.c);
    } else if (o.type === "capsule") {
      scene.add(capsule(v3(o.a), v3(o.b), o.r, mat));
    } else {
      const lo = v3(o.min), hi = v3(o.max);
      geometry = new THREE.BoxGeometry(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
      at = lo.clone().add(hi).multiplyScalar(0.5);
    }
    if (!geometry) return;
    const m = new THREE.Mesh(geometry, mat);
    m.position.copy(at);
    scene.add(m);
    if (inWall) {
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 30), new THREE.LineBasicMaterial({ color: core }));
      edges.position.copy(at);
      scene.add(edges);
    }
  });
  for (const r of task.regions) {
    const lo = v3(r.min), hi = v3(r.max);
    const s = hi.clone().sub(lo).max(new THREE.Vector3(1e-4, 1e-4, 1e-4));
    const box = new THREE.BoxGeometry(s.x, s.y, s.z);
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(box),
      new THREE.LineDashedMaterial({ color: r.core ? core : 0x444444, dashSize: size * 0.01, gapSize: size * 0.006 }));
    edges.computeLineDistances();
    edges.position.copy(lo).add(hi).multiplyScalar(0.5);
    scene.add(edges);
    const fill = new THREE.Mesh(box, new THREE.MeshBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.06, depthWrite: false }));
    fill.position.copy(edges.position);
    scene.add(fill);
  }
}

/// A wall's witness: the enclosed cells, each a green cube of its own (the
/// ones facing the wall; those inside them add nothing), and a red ring
/// round the path point or the base region kept out.
function enclosureObjects(walls, scene, size) {
  let shown = 0;
  for (const w of walls) {
    const { object, cells } = witnessCells(w.runs);
    object.userData.enclosure = w.inside;
    scene.add(object);
    shown += cells;
    const mark = new THREE.Mesh(new THREE.TorusGeometry(size * 0.02, size * 0.004, 8, 32),
      new THREE.MeshBasicMaterial({ color: 0xd00000 }));
    mark.position.copy(v3(w.point));
    scene.add(mark);
  }
  state.enclosureCells = shown;
}

/// What the view is framed on: the path, the base regions, the arm in
/// every pose, a wall's cells and the obstacles not much larger than
/// those (a table top is left to show round them).
function framing(data) {
  const path = data.task.prims.flatMap((p) => p.pts);
  const work = [...path];
  for (const r of data.task.regions) work.push(r.min, r.max);
  for (const w of data.enclosure || []) for (const r of w.runs) work.push(r.slice(0, 3), r.slice(3, 6));
  const obstacles = [];
  for (const o of data.task.obstacles) {
    const box = o.type === "sphere" ? { min: o.c.map((x) => x - o.r), max: o.c.map((x) => x + o.r) }
      : o.type === "capsule" ? { min: o.a.map((x, i) => Math.min(x, o.b[i]) - o.r), max: o.a.map((x, i) => Math.max(x, o.b[i]) + o.r) }
      : { min: o.min, max: o.max };
    if (o.core) work.push(box.min, box.max); else obstacles.push(box);
  }
  if (data.robot && data.motion) {
    const n = data.robot.dh.length, N = data.motion.t.length;
    const stride = Math.max(1, Math.floor(N / 100));
    for (let i = 0; i < N; i += stride) {
      for (const f of dhFrames(data.robot, data.motion.q.slice(i * n, i * n + n))) work.push([f[3], f[7], f[11]]);
    }
  }
  const regions = data.task.regions;
  const base = data.robot ? data.robot.base
    : regions.length ? regions[0].min.map((x, i) => (x + regions[0].max[i]) / 2) : null;
  return viewFrame(path, framedPoints(work, obstacles), base);
}

// ------------------------------------------------------------------ the view

function start() {
  const data = JSON.parse($("scene-data").textContent);
  const host = $("view");
  if (!webglWorks()) {
    state.error = "no WebGL";
    host.classList.add("no-webgl");
    host.textContent = "The 3-D view needs WebGL, which this browser does not offer. The figures and the timing charts below are complete without it.";
    return;
  }
  const width = host.clientWidth || 900, height = host.clientHeight || 640;
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(width, height);
  renderer.setClearColor(0xffffff);
  host.appendChild(renderer.domElement);

  const framed = framing(data);
  const centre = v3(framed.centre);
  const size = 2 * framed.radius;

  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(1, -2, 3);
  scene.add(sun);

  // The floor grid, in the task's xy-plane at the lowest point shown (and
  // never above z = 0), with the task frame's axes at its origin.
  const lowest = Math.min(0, data.bounds.min[2]);
  const step = niceStep(size);
  const cells = Math.ceil(size * 2.4 / step);
  const grid = new THREE.GridHelper(cells * step, cells, 0x9a9a9a, 0xdddddd);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.round(centre.x / step) * step, Math.round(centre.y / step) * step, lowest);
  scene.add(grid);
  scene.add(labelledAxes(new THREE.Vector3(0, 0, lowest), step));

  const wall = new Set((data.enclosure || []).flatMap((w) => w.obstacles));
  taskObjects(data.task, scene, size, wall);
  if (data.enclosure) enclosureObjects(data.enclosure, scene, size);

  const camera = new THREE.PerspectiveCamera(40, width / height, size / 500, size * 200);
  camera.up.set(0, 0, 1);
  camera.position.copy(centre).addScaledVector(v3(framed.direction), frameDistance(framed.radius, 40, width / height));
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();
  state.frame = { centre: framed.centre, radius: framed.radius, direction: framed.direction };
  state.project = (p) => {
    const q = v3(p).project(camera);
    return [(q.x + 1) / 2 * width, (1 - q.y) / 2 * height, q.z];
  };

  let draw = () => {
    renderer.render(scene, camera);
    state.frames += 1;
  };
  controls.addEventListener("change", () => draw());

  const motion = data.motion, robot = data.robot;
  if (!motion || !robot) {
    draw();
    state.ready = true;
    return;
  }
  const arm = armObjects(robot, scene);
  const n = robot.dh.length, N = motion.t.length;
  const times = motion.t[N - 1] > motion.t[0] ? motion.t : motion.t.map((_, i) => i);
  const T0 = times[0], T1 = times[N - 1];
  const qAt = (i) => motion.q.slice(i * n, i * n + n);

  // The EE's trail, drawn up to the current sample.
  const trailPoints = new Float32Array(N * 3);
  for (let i = 0; i < N; ++i) {
    const e = origin(dhFrames(robot, qAt(i))[n]);
    trailPoints.set([e.x, e.y, e.z], i * 3);
  }
  const trailGeometry = new THREE.BufferGeometry();
  trailGeometry.setAttribute("position", new THREE.BufferAttribute(trailPoints, 3));
  const trail = new THREE.Line(trailGeometry, new THREE.LineBasicMaterial({ color: 0x000000 }));
  scene.add(trail);

  const scrub = $("scrub"), play = $("play"), speed = $("speed"), clock = $("clock"), readout = $("readout");
  const phases = ["tracing", "transition after", "travel after"];

  function locate(time) {
    let a = 0, b = N - 1;
    while (a < b) {
      const mid = (a + b + 1) >> 1;
      if (times[mid] <= time) a = mid; else b = mid - 1;
    }
    const span = a + 1 < N ? times[a + 1] - times[a] : 0;
    return { i: a, f: span > 0 ? Math.min(1, (time - times[a]) / span) : 0 };
  }

  let time = T0, playing = false, last = null;
  function render() {
    const at = locate(time);
    const a = qAt(at.i), b = at.i + 1 < N ? qAt(at.i + 1) : a;
    const q = a.map((v, k) => v + (b[k] - v) * at.f);
    arm.pose(q);
    trailGeometry.setDrawRange(0, at.i + 1);
    state.time = time;
    if (scrub) scrub.value = time;
    if (clock) clock.textContent = (time - T0).toFixed(2) + " / " + (T1 - T0).toFixed(2) + " s";
    if (readout)
      readout.textContent = phases[motion.ph[at.i]] + " " + data.names[motion.pr[at.i]] +
        "   q = [" + q.map((v) => v.toFixed(3)).join(", ") + "] rad";
    draw();
  }
  function frame(now) {
    if (!playing) return;
    if (last !== null) time = Math.min(T1, time + (now - last) / 1000 * +(speed ? speed.value : 1));
    last = now;
    render();
    if (time >= T1) { setPlaying(false); return; }
    requestAnimationFrame(frame);
  }
  function setPlaying(on) {
    playing = on;
    if (play) play.textContent = on ? "Pause" : "Play";
    last = null;
    if (on) {
      if (time >= T1) time = T0;
      requestAnimationFrame(frame);
    }
  }
  state.setTime = (t) => { setPlaying(false); time = Math.min(T1, Math.max(T0, T0 + t)); render(); };
  state.duration = T1 - T0;
  if (scrub) {
    scrub.min = T0; scrub.max = T1; scrub.step = "any";
    scrub.addEventListener("input", () => { setPlaying(false); time = +scrub.value; render(); });
  }
  if (play) play.addEventListener("click", () => setPlaying(!playing));
  const modulesBox = $("show-modules");
  if (modulesBox) modulesBox.addEventListener("change", () => { arm.modules.visible = modulesBox.checked; draw(); });
  const trailBox = $("show-trail");
  if (trailBox) trailBox.addEventListener("change", () => { trail.visible = trailBox.checked; draw(); });
  // A link can open the report at a moment of the motion: report.html#t=12.5
  const at = /t=([0-9.]+)/.exec(location.hash);
  if (at) time = Math.min(T1, Math.max(T0, T0 + parseFloat(at[1])));
  render();
  state.ready = true;
  if (/play/.test(location.hash)) setPlaying(true);
}

try {
  start();
} catch (e) {
  state.error = String(e && e.message ? e.message : e);
  throw e;
}

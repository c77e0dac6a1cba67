// The 3-D view of a spatial solution's report (src/output/report3d.cpp):
// the task (path, obstacles, base regions), the DH arm and its animated
// motion, with orbit / pan / zoom, a floor grid and the planar report's
// controls (#play, #scrub, #clock, #speed, #readout; `#t=12` opens at
// t = 12 s). It reads the element #scene-data. esbuild bundles it with
// three.js into one script that the report carries inline.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { armObjects, capsule, dhFrames, material, niceStep, origin, v3, webglWorks } from "./scene.js";

const $ = (id) => document.getElementById(id);
// What a browser test reads: whether the view drew, and how to move it.
const state = { ready: false, error: "", frames: 0, time: 0 };
window.modsynthView = state;

// ------------------------------------------------------------------ the task

function taskObjects(task, scene, size) {
  const core = 0xd00000;
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
  for (const o of task.obstacles) {
    const mat = material(o.core ? core : 0xe45756, 0.55);
    if (o.type === "sphere") {
      const m = new THREE.Mesh(new THREE.SphereGeometry(o.r, 32, 16), mat);
      m.position.copy(v3(o.c));
      scene.add(m);
    } else if (o.type === "capsule") {
      scene.add(capsule(v3(o.a), v3(o.b), o.r, mat));
    } else {
      const lo = v3(o.min), hi = v3(o.max);
      const m = new THREE.Mesh(new THREE.BoxGeometry(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z), mat);
      m.position.copy(lo).add(hi).multiplyScalar(0.5);
      scene.add(m);
    }
  }
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

/// A wall's witness: the enclosed cells (runs of grid cells, as boxes) in
/// translucent green, the wall's obstacles outlined in black, and the side
/// kept out marked by a black ring round the path point or the base region.
function enclosureObjects(walls, task, scene, size) {
  const cellMat = new THREE.MeshBasicMaterial({ color: 0x1a9850, transparent: true, opacity: 0.18, depthWrite: false });
  let shown = 0;
  for (const w of walls) {
    const boxes = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1), cellMat, w.runs.length);
    const m = new THREE.Matrix4();
    w.runs.forEach((r, i) => {
      const lo = v3(r.slice(0, 3)), hi = v3(r.slice(3, 6));
      m.makeScale(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
      m.setPosition(lo.clone().add(hi).multiplyScalar(0.5));
      boxes.setMatrixAt(i, m);
    });
    boxes.userData.enclosure = w.inside;
    scene.add(boxes);
    shown += w.runs.length;
    for (const i of w.obstacles) {
      const o = task.obstacles[i];
      let geometry, at;
      if (o.type === "sphere") {
        geometry = new THREE.SphereGeometry(o.r, 12, 6);
        at = v3(o.c);
      } else if (o.type === "box") {
        const lo = v3(o.min), hi = v3(o.max);
        geometry = new THREE.BoxGeometry(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z);
        at = lo.clone().add(hi).multiplyScalar(0.5);
      } else {
        continue;  // a capsule's core colour says enough
      }
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry),
        new THREE.LineBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.35 }));
      edges.position.copy(at);
      scene.add(edges);
    }
    const mark = new THREE.Mesh(new THREE.TorusGeometry(size * 0.02, size * 0.003, 8, 32),
      new THREE.MeshBasicMaterial({ color: 0x000000 }));
    mark.position.copy(v3(w.point));
    scene.add(mark);
  }
  state.enclosureRuns = shown;
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

  const lo = v3(data.bounds.min), hi = v3(data.bounds.max);
  const centre = lo.clone().add(hi).multiplyScalar(0.5);
  const size = Math.max(hi.clone().sub(lo).length(), 0.1);

  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.8);
  sun.position.set(1, -2, 3);
  scene.add(sun);

  // The floor grid, in the task's xy-plane at the lowest point shown (and
  // never above z = 0), with the task frame's axes at its origin.
  const step = niceStep(size);
  const cells = Math.ceil(size * 1.6 / step);
  const grid = new THREE.GridHelper(cells * step, cells, 0x9a9a9a, 0xdddddd);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.round(centre.x / step) * step, Math.round(centre.y / step) * step, Math.min(0, lo.z));
  scene.add(grid);
  const axes = new THREE.AxesHelper(step);
  axes.position.set(0, 0, Math.min(0, lo.z));
  scene.add(axes);

  taskObjects(data.task, scene, size);
  if (data.enclosure) enclosureObjects(data.enclosure, data.task, scene, size);

  const camera = new THREE.PerspectiveCamera(40, width / height, size / 500, size * 100);
  camera.up.set(0, 0, 1);
  camera.position.copy(centre).add(new THREE.Vector3(0.9, -1.6, 0.9).multiplyScalar(size));
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  controls.update();

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

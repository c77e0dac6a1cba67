// The 3-D view of a spatial solution's report (src/output/report3d.cpp):
// the task (path, obstacles, base regions), the DH arm and its animated
// motion, with orbit / pan / zoom, a floor grid and the planar report's
// controls (#play, #scrub, #clock, #speed, #readout; `#t=12` opens at
// t = 12 s). It reads the element #scene-data. esbuild bundles it with
// three.js into one script that the report carries inline.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";

const $ = (id) => document.getElementById(id);
// What a browser test reads: whether the view drew, and how to move it.
const state = { ready: false, error: "", frames: 0, time: 0 };
window.modsynthView = state;

function webglWorks() {
  try {
    const c = document.createElement("canvas");
    return !!(c.getContext("webgl2") || c.getContext("webgl"));
  } catch (e) {
    return false;
  }
}

// ------------------------------------------------------------------ the chain

/// Frames 0..n of a DH chain (formats.md): frame k = frame k-1 Rz(q) Tz(d)
/// Tx(a) Rx(alpha); each a 3x4 row-major [R | p].
function dhFrames(robot, q) {
  let f = [1, 0, 0, robot.base[0], 0, 1, 0, robot.base[1], 0, 0, 1, robot.base[2]];
  const out = [f];
  for (let k = 0; k < robot.dh.length; ++k) {
    const [a, alpha, d] = robot.dh[k];
    const cq = Math.cos(q[k]), sq = Math.sin(q[k]), ca = Math.cos(alpha), sa = Math.sin(alpha);
    const t = [cq, -sq * ca, sq * sa, a * cq, sq, cq * ca, -cq * sa, a * sq, 0, sa, ca, d];
    const g = new Array(12);
    for (let r = 0; r < 3; ++r) {
      for (let c = 0; c < 4; ++c) {
        let v = f[r * 4] * t[c] + f[r * 4 + 1] * t[4 + c] + f[r * 4 + 2] * t[8 + c];
        if (c === 3) v += f[r * 4 + 3];
        g[r * 4 + c] = v;
      }
    }
    f = g;
    out.push(f);
  }
  return out;
}

const origin = (f) => new THREE.Vector3(f[3], f[7], f[11]);
const column = (f, c) => new THREE.Vector3(f[c], f[4 + c], f[8 + c]);

/// The chain's segments (the d part then the a part of each link, zero
/// lengths dropped) at the given frames.
function segments(robot, frames) {
  const out = [];
  for (let k = 0; k < robot.dh.length; ++k) {
    const [, , d] = robot.dh[k];
    const start = origin(frames[k]);
    const corner = start.clone().addScaledVector(column(frames[k], 2), d);
    const end = origin(frames[k + 1]);
    if (Math.abs(d) > 1e-9) out.push([start, corner]);
    if (corner.distanceTo(end) > 1e-9) out.push([corner, end]);
  }
  return out;
}

// ------------------------------------------------------------------ the scene

function material(colour, opacity) {
  return new THREE.MeshStandardMaterial({
    color: colour, roughness: 0.6, metalness: 0.1,
    transparent: opacity < 1, opacity: opacity, depthWrite: opacity >= 1,
  });
}

const Y = new THREE.Vector3(0, 1, 0);

/// Puts a unit cylinder (height 1 along y) between a and b.
function place(mesh, a, b) {
  const d = b.clone().sub(a);
  const length = d.length();
  mesh.position.copy(a).addScaledVector(d, 0.5);
  if (length > 0) mesh.quaternion.setFromUnitVectors(Y, d.clone().divideScalar(length));
  mesh.scale.set(1, Math.max(length, 1e-9), 1);
}

function capsule(a, b, r, mat) {
  const group = new THREE.Group();
  const body = new THREE.Mesh(new THREE.CylinderGeometry(r, r, 1, 24, 1, true), mat);
  place(body, a, b);
  group.add(body);
  for (const p of [a, b]) {
    const cap = new THREE.Mesh(new THREE.SphereGeometry(r, 24, 12), mat);
    cap.position.copy(p);
    group.add(cap);
  }
  return group;
}

const v3 = (p) => new THREE.Vector3(p[0], p[1], p[2]);

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

/// The arm's meshes, moved by pose(q).
function armObjects(robot, scene) {
  const r = robot.D / 2;
  const linkMat = material(0x3a3a44, 1);
  const toolMat = material(0x111111, 1);
  const moduleMat = material(0xcc3326, 0.85);
  const zero = robot.dh.map(() => 0);
  const count = segments(robot, dhFrames(robot, zero)).length;
  const bodies = [], caps = [];
  for (let i = 0; i < count; ++i) {
    const m = new THREE.Mesh(new THREE.CylinderGeometry(r, r, 1, 24, 1, true), linkMat);
    scene.add(m);
    bodies.push(m);
  }
  for (let i = 0; i <= count; ++i) {
    const m = new THREE.Mesh(new THREE.SphereGeometry(r, 24, 12), linkMat);
    scene.add(m);
    caps.push(m);
  }
  const tool = new THREE.Mesh(new THREE.CylinderGeometry(r * 1.05, r * 1.05, 1, 24, 1, false), toolMat);
  tool.visible = robot.tool > 0;
  scene.add(tool);
  const modules = new THREE.Group();
  const boxes = robot.dh.map(() => {
    const m = new THREE.Mesh(new THREE.BoxGeometry(robot.mod[0], robot.mod[1], robot.mod[2]), moduleMat);
    modules.add(m);
    return m;
  });
  scene.add(modules);
  const ee = new THREE.Mesh(new THREE.SphereGeometry(r * 0.6, 16, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
  scene.add(ee);
  const basis = new THREE.Matrix4();
  return {
    modules,
    pose(q) {
      const frames = dhFrames(robot, q);
      const segs = segments(robot, frames);
      segs.forEach(([a, b], i) => {
        place(bodies[i], a, b);
        caps[i].position.copy(a);
        caps[i + 1].position.copy(b);
      });
      if (robot.tool > 0 && segs.length) {
        const [a, b] = segs[segs.length - 1];
        const d = b.clone().sub(a);
        const from = b.clone().addScaledVector(d, -Math.min(1, robot.tool / d.length()));
        place(tool, from, b);
      }
      boxes.forEach((m, k) => {
        const f = frames[k];
        basis.set(f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10], f[11], 0, 0, 0, 1);
        m.position.set(0, 0, 0);
        m.quaternion.identity();
        m.scale.set(1, 1, 1);
        m.applyMatrix4(basis);
      });
      const e = origin(frames[frames.length - 1]);
      ee.position.copy(e);
      return e;
    },
  };
}

// ------------------------------------------------------------------ the view

function niceStep(span) {
  const raw = span / 10;
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  return raw / p >= 5 ? 5 * p : raw / p >= 2 ? 2 * p : p;
}

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

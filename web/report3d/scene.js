// The 3-D scene's parts that the report's view (viewer.js) and the
// editor's view (editor_view.js) both draw: the DH chain's frames and
// segments, the arm's meshes, capsules and the grid's step. Both bundles
// take them from here, so the arm looks and moves the same in both.
import * as THREE from "three";

export function webglWorks() {
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
export function dhFrames(robot, q) {
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

export const origin = (f) => new THREE.Vector3(f[3], f[7], f[11]);
export const column = (f, c) => new THREE.Vector3(f[c], f[4 + c], f[8 + c]);

/// The chain's segments (the d part then the a part of each link, zero
/// lengths dropped) at the given frames.
export function segments(robot, frames) {
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

export function material(colour, opacity) {
  return new THREE.MeshStandardMaterial({
    color: colour, roughness: 0.6, metalness: 0.1,
    transparent: opacity < 1, opacity: opacity, depthWrite: opacity >= 1,
  });
}

export const Y = new THREE.Vector3(0, 1, 0);

/// Puts a unit cylinder (height 1 along y) between a and b.
export function place(mesh, a, b) {
  const d = b.clone().sub(a);
  const length = d.length();
  mesh.position.copy(a).addScaledVector(d, 0.5);
  if (length > 0) mesh.quaternion.setFromUnitVectors(Y, d.clone().divideScalar(length));
  mesh.scale.set(1, Math.max(length, 1e-9), 1);
}

export function capsule(a, b, r, mat) {
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

export const v3 = (p) => new THREE.Vector3(p[0], p[1], p[2]);

/// The arm's meshes, moved by pose(q).
export function armObjects(robot, scene) {
  const r = robot.D / 2;
  const linkMat = material(0x3a3a44, 1);
  const toolMat = material(0x111111, 1);
  // Slate: red is the obstacles' and a conflict's colour in these views.
  const moduleMat = material(0x5b7088, 0.9);
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

// ------------------------------------------------------------------ the grid

export function niceStep(span) {
  const raw = span / 10;
  const p = Math.pow(10, Math.floor(Math.log10(raw)));
  return raw / p >= 5 ? 5 * p : raw / p >= 2 ? 2 * p : p;
}

// ------------------------------------------------------------- a wall's proof

/// The colour of a wall's enclosed cells, used for nothing else in a view.
export const WITNESS_COLOUR = 0x1a9850;

/// A wall's witness (formats.md "explanation.enclosure") as boxes:
/// [[x0, y0, z0, x1, y1, z1]], one per run of enclosed cells.
export function witnessRuns(wall) {
  const g = wall.grid, h = g.cell, o = g.origin;
  return wall.cells.map(([j, k, i0, i1]) => [o[0] + h * i0, o[1] + h * j, o[2] + h * k,
                                             o[0] + h * (i1 + 1), o[1] + h * (j + 1), o[2] + h * (k + 1)]);
}

/// The enclosed cells that face the wall (a face neighbour is not
/// enclosed): the cells inside them add nothing to the picture. Each as
/// its centre; `h` is the cells' side.
export function boundaryCells(runs) {
  if (!runs.length) return { h: 0, centres: [] };
  const h = runs[0][4] - runs[0][1];
  const x0 = Math.min(...runs.map((r) => r[0])), y0 = Math.min(...runs.map((r) => r[1]));
  const z0 = Math.min(...runs.map((r) => r[2]));
  const key = (i, j, k) => i + "," + j + "," + k;
  const cells = new Set(), list = [];
  for (const r of runs) {
    const j = Math.round((r[1] - y0) / h), k = Math.round((r[2] - z0) / h);
    const i0 = Math.round((r[0] - x0) / h), i1 = Math.round((r[3] - x0) / h) - 1;
    for (let i = i0; i <= i1; ++i) { cells.add(key(i, j, k)); list.push([i, j, k]); }
  }
  const centres = [];
  for (const [i, j, k] of list) {
    const open = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
      .some(([a, b, c]) => !cells.has(key(i + a, j + b, k + c)));
    if (open) centres.push([x0 + (i + 0.5) * h, y0 + (j + 0.5) * h, z0 + (k + 0.5) * h]);
  }
  return { h, centres };
}

/// The enclosed cells of a wall as separate cubes (each shrunk, so that
/// one cell is told from the next), shaded green; returns the group and
/// how many cells it draws.
export function witnessCells(runs) {
  const { h, centres } = boundaryCells(runs);
  const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(h * 0.72, h * 0.72, h * 0.72),
    new THREE.MeshStandardMaterial({ color: WITNESS_COLOUR, roughness: 0.7, metalness: 0 }), Math.max(centres.length, 1));
  const m = new THREE.Matrix4();
  centres.forEach((c, i) => { m.makeTranslation(c[0], c[1], c[2]); mesh.setMatrixAt(i, m); });
  mesh.count = centres.length;
  return { object: mesh, cells: centres.length };
}

// ------------------------------------------------------------------ the axes

/// The task frame's axes at `at`, `length` long, in dark grey with their
/// letters (red, green and blue mean other things in these views).
export function labelledAxes(at, length) {
  const group = new THREE.Group();
  const mat = new THREE.LineBasicMaterial({ color: 0x555555 });
  for (const [name, d] of [["x", [1, 0, 0]], ["y", [0, 1, 0]], ["z", [0, 0, 1]]]) {
    const end = v3(d).multiplyScalar(length);
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), end]), mat));
    const canvas = document.createElement("canvas");
    canvas.width = canvas.height = 64;
    const g = canvas.getContext("2d");
    g.fillStyle = "#555";
    g.font = "bold 44px sans-serif";
    g.textAlign = "center";
    g.textBaseline = "middle";
    g.fillText(name, 32, 34);
    const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(canvas), depthTest: false }));
    sprite.position.copy(end.multiplyScalar(1.12));
    sprite.scale.setScalar(length * 0.22);
    group.add(sprite);
  }
  group.position.copy(at);
  return group;
}

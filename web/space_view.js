// The editor in space: when the task is spatial ("space": "3d") the stage
// shows the 3-D view (web/report3d/editor_view.js, bundled with three.js
// as /editor3d.js, loaded then) instead of the plane's canvas. It follows the store:
// the task with the selected part, the parts in error and in a core; a
// click in the view selects, a drag of a handle's arrow moves the point
// along that axis (one undo step per drag); the solved arm moves along its
// samples under the play / scrub bar; a proof of reach is drawn as a line
// from the base box to the farthest point of the primitive out of reach, a
// wall's proof as the cells it closes in.

import { primitiveColour } from "./task_render.js";
import { isSpatial, reachLine, namedPrimitives } from "./space_geometry.js";
import { setPoint3 } from "./space_edit.js";
import { $ } from "./dom.js";

const SNAP_STEP = 0.001;  // a drag with snap on moves by whole millimetres

/// The solution's DH arm as the report's scene draws it (scene.js).
function armOf(solution, doc) {
  const r = solution.robot, robot = doc.robot || {};
  return {
    base: r.base, dh: r.dh.map((l) => [l.a, l.alpha, l.d]), D: r.link_diameter,
    tool: Number.isFinite(robot.tool_length) ? robot.tool_length : 0,
    mod: [robot.module_length || 0.110, robot.module_width || 0.073, robot.module_height || 0.045],
  };
}

export class SpaceView {
  constructor(store, { snap }) {
    this.store = store;
    this.model = store.model;
    this.spatial = false;
    this.snap = snap;
    this.view = null;      // made when a task in space is first shown
    this.loading = null;
    for (const type of ["doc", "selection", "validation", "core"]) store.on(type, () => this.render());
    store.on("doc", () => { if (this.view) this.view.clearMotion(); });
    store.on("core", () => this.showProof());
    store.on("witness", () => this.showProof());
    store.on("solution", (s) => this.showSolution(s));
    $("play3d").addEventListener("click", () => { if (this.view) this.view.play(!this.view.state.playing); });
    $("scrub3d").addEventListener("input", (e) => { if (this.view) this.view.setTime(+e.target.value); });
    this.render();
  }

  /// three.js is loaded with the first task in space: a planar task's page
  /// does without it.
  ensureView() {
    if (this.view || this.loading) return;
    this.loading = import("./editor3d.js").then(({ EditorView3D }) => {
      this.view = new EditorView3D($("view3d"), {
        onPick: (part) => this.store.select(part),
        onDragStart: () => this.model.beginGesture(),
        onDrag: (part, key, point) => setPoint3(this.model, part, key, point, true),
        onDragEnd: () => {},
        onTime: (t) => this.showTime(t),
        snap: () => (this.snap() ? SNAP_STEP : 0),
      });
      this.render();
      this.fit();
      this.showProof();
      this.showSolution(this.store.solution);
    }, (e) => {
      $("view3d").textContent = "The 3-D view could not be loaded: " + e.message;
    });
  }

  render() {
    const doc = this.store.doc;
    const spatial = isSpatial(doc);
    if (spatial !== this.spatial) {
      this.spatial = spatial;
      document.body.dataset.space = spatial ? "3d" : "plane";
      $("canvas").toggleAttribute("hidden", spatial);
      $("view3d").hidden = !spatial;
      if (spatial && this.view) this.view.resize();
    }
    if (!spatial) return;
    this.ensureView();
    if (!this.view) return;
    const store = this.store;
    this.view.setTask(doc, {
      selection: store.selection,
      inCore: (part) => store.inCore(part),
      hasError: (part) => store.errorsAbout(part).length > 0,
      coreShown: store.core.length > 0,
      colour: primitiveColour,
    });
  }

  /// Frames the whole task (after a load, or on Fit).
  fit() { if (this.spatial && this.view) this.view.fit(); }

  /// For a primitive out of reach: a line from the nearest base box to its
  /// farthest point (the proof's distance, against the longest chain). For
  /// a wall: its enclosed cells, from the solution's witness.
  showProof() {
    const core = this.store.core;
    const doc = this.store.doc;
    const enclosure = this.store.witness && this.store.witness.enclosure;
    const lines = [];
    // A reach proof's core: the longest link, the base regions and the
    // primitives out of reach (a wall's names the obstacles instead).
    if (isSpatial(doc) && !enclosure && core.includes("base_regions") && core.includes("robot.max_link_length")) {
      for (const { part, primitive } of namedPrimitives(doc)) {
        if (!core.includes(part)) continue;
        const line = reachLine(doc, primitive);
        if (line) lines.push(line);
      }
    }
    if (this.view) {
      this.view.setProof(lines, isSpatial(doc) ? enclosure : null);
      this.render();
    }
    return lines;
  }

  showSolution(solution) {
    const doc = this.store.doc;
    if (!this.view) return;
    if (!solution) this.view.clearMotion();
    if (!solution || !isSpatial(doc) || solution.status !== "solved" || !solution.robot || !Array.isArray(solution.robot.dh)) return;
    this.view.setMotion(armOf(solution, doc), solution.samples || []);
    $("motion-bar").hidden = false;
    this.view.play(true);
  }

  showTime({ time, duration, playing }) {
    const bar = $("motion-bar");
    if (!duration) { bar.hidden = true; return; }
    const scrub = $("scrub3d");
    scrub.max = duration;
    scrub.step = "any";
    if (document.activeElement !== scrub) scrub.value = Math.min(time, duration);
    $("clock3d").textContent = `${Math.min(time, duration).toFixed(2)} / ${duration.toFixed(2)} s`;
    $("play3d").textContent = playing ? "Pause" : "Play";
  }
}

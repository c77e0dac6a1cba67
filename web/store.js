// The editor's one state: the task (with its undo history), the selected
// part, the current tool, the server's verdict on the task, the parts of an
// infeasibility core, the synthesis state, the view shown and the server's
// settings. Views read it and call its setters; each setter announces what
// changed with a named event:
//   doc         the task changed (edit, undo, redo, load)
//   selection   another part is selected (detail: its name or null)
//   tool        another tool is picked
//   validation  the server's verdict changed (checking, valid, invalid, empty)
//   core        the infeasibility core changed
//   witness     the proof's witness changed (drawn over the task)
//   solution    a solve's solution arrived (or went: null)
//   synthesis   the solve's state changed (idle, starting, running, solved ...)
//   view        the editor or the result is shown
//   info        the server's settings arrived
//   underlay    the drawing shown under the task changed (or went)

import { concerns, inCore } from "./parts.js";

export const DOCUMENT = "(document)";  // the part named by messages about no part in particular

export class Store extends EventTarget {
  constructor(model) {
    super();
    this.model = model;
    this.selection = null;
    this.tool = "select";
    this.validity = { state: "checking", errors: new Map() };
    this.core = [];
    this.witness = null;
    this.solution = null;
    this.synthesis = "idle";
    this.view = "editor";
    this.info = null;
    this.underlay = null;  // {url, width, height, transform}: an imported drawing
    model.addEventListener("change", () => {
      // A core names the parts of the task as it was solved.
      if (this.core.length) this.setCore([]);
      if (this.witness) this.setWitness(null);
      if (this.solution) this.setSolution(null);
      this.emit("doc");
    });
  }

  /// Calls `fn(detail)` after every event of `type`.
  on(type, fn) { this.addEventListener(type, (e) => fn(e.detail)); }
  emit(type, detail) { this.dispatchEvent(new CustomEvent(type, { detail })); }

  get doc() { return this.model.doc; }

  select(part) {
    this.selection = part || null;
    this.emit("selection", this.selection);
  }

  setTool(tool) {
    this.tool = tool;
    this.emit("tool", tool);
  }

  /// Removes a part and lets go of it.
  remove(part) {
    this.model.remove(part);
    this.select(null);
  }

  /// Starts over from `doc` (undoable), nothing selected, no core.
  load(doc) {
    this.model.load(doc);
    this.setCore([]);
    this.setWitness(null);
    this.select(null);
  }

  /// The drawing to show under the task (null: none); the page's address
  /// of the one before is let go.
  setUnderlay(underlay) {
    if (this.underlay && this.underlay.url) URL.revokeObjectURL(this.underlay.url);
    this.underlay = underlay || null;
    this.emit("underlay", this.underlay);
  }

  // ---------------------------------------------------------- validation

  /// A verdict is being asked for.
  checking() {
    this.validity = { ...this.validity, state: "checking" };
    this.emit("validation", this.validity);
  }

  /// The server's answer, as POST /api/validate gives it: {valid, errors:
  /// [{part, message}], primitives, obstacles, base_regions}.
  setValidation(result) {
    // An empty path is where every task starts, not a mistake to flag.
    const errors = result.errors || [];
    const fresh = !result.valid && !this.model.trajectory.length && errors.length === 1 && errors[0].part === "trajectory";
    this.validity = {
      state: result.valid ? "valid" : fresh ? "empty" : "invalid",
      errors: fresh ? new Map() : new Map(errors.map((e) => [e.part || DOCUMENT, e.message])),
      counts: result.valid ? { primitives: result.primitives, obstacles: result.obstacles, base_regions: result.base_regions } : null,
    };
    this.emit("validation", this.validity);
  }

  /// An error about the task from elsewhere than validation (a file that is
  /// not JSON, a solve refused as invalid).
  setError(part, message) {
    this.setValidation({ valid: false, errors: [{ part: part || DOCUMENT, message }] });
  }

  get errors() { return this.validity.errors; }

  /// The messages about a part or anything inside it.
  errorsAbout(part) {
    return [...this.errors].filter(([p]) => concerns(p, part)).map(([, m]) => m);
  }

  // -------------------------------------------------- core and synthesis

  setCore(parts) {
    this.core = parts || [];
    this.emit("core", this.core);
  }

  inCore(part) { return inCore(this.core, part); }

  /// The solution's "explanation" when it carries an obstacle proof's
  /// witness ("separation" or "geodesic" in the plane, "enclosure" in
  /// space), else null.
  setWitness(explanation) {
    const e = explanation || {};
    this.witness = e.separation || e.geodesic || e.enclosure
      ? { separation: e.separation || null, geodesic: e.geodesic || null, enclosure: e.enclosure || null } : null;
    this.emit("witness", this.witness);
  }

  /// The solution file of the last solve (modsynth-solution/1), for views
  /// that show its motion; null when there is none or the task changed.
  setSolution(solution) {
    this.solution = solution || null;
    this.emit("solution", this.solution);
  }

  setSynthesis(state) {
    this.synthesis = state;
    this.emit("synthesis", state);
  }

  setView(view) {
    this.view = view;
    this.emit("view", view);
  }

  setInfo(info) {
    this.info = info;
    this.emit("info", info);
  }
}

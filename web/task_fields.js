// The panel's task-wide fields: the task's name and robot settings (a key
// left out shows the server's default), the time limit's bounds, and the
// server's messages about them or about no part the page shows.

import { concerns, splitPart } from "./parts.js";
import { DOCUMENT } from "./store.js";
import { isSpatial } from "./space_geometry.js";
import { SPATIAL_ROBOT_DEFAULTS } from "./space_edit.js";
import { $ } from "./dom.js";

export class TaskFields {
  constructor(store) {
    this.store = store;
    this.model = store.model;
    this.bindTaskFields();
    for (const type of ["doc", "validation", "core", "info"]) store.on(type, () => this.render());
    store.on("info", (info) => this.showLimits(info));
    this.render();
  }

  /// A solve may ask for at most the server's time limit, and gets it
  /// unless it asks for less.
  showLimits(info) {
    const field = $("time-limit");
    if (!Number.isFinite(info.time_limit)) return;
    field.max = info.time_limit;
    field.value = info.time_limit;
  }

  render() {
    this.renderTaskFields();
    this.renderDocumentErrors();
  }

  bindTaskFields() {
    $("task-name").addEventListener("change", (e) => this.model.setName(e.target.value));
    for (const input of document.querySelectorAll("input[data-robot]")) {
      input.addEventListener("change", () => {
        const v = parseFloat(input.value);
        this.model.setRobot(input.dataset.robot, Number.isFinite(v) ? v : input.value);
      });
    }
    for (const n of [2, 3, 4, 5, 6]) {
      $("dof-" + n).addEventListener("change", () => {
        this.model.setRobot("dof", this.jointCounts().filter((k) => $("dof-" + k).checked));
      });
    }
  }

  /// The joint counts a task may allow: 2 or 3 in the plane, 3 to 6 in space.
  jointCounts() { return isSpatial(this.model.doc) ? [3, 4, 5, 6] : [2, 3]; }

  renderTaskFields() {
    const doc = this.model.doc, robot = doc.robot && typeof doc.robot === "object" ? doc.robot : {};
    // A key left out gets the server's default: shown greyed in its field.
    // A spatial task's defaults are the contract's (formats.md).
    const defaults = isSpatial(doc) ? SPATIAL_ROBOT_DEFAULTS : (this.store.info && this.store.info.robot_defaults) || {};
    const name = $("task-name");
    if (document.activeElement !== name) name.value = typeof doc.name === "string" ? doc.name : "";
    for (const input of document.querySelectorAll("input[data-robot]")) {
      if (document.activeElement !== input) input.value = robot[input.dataset.robot] ?? "";
      input.placeholder = defaults[input.dataset.robot] ?? "";
    }
    const dof = Array.isArray(robot.dof) ? robot.dof : defaults.dof || [];
    for (const n of this.jointCounts()) $("dof-" + n).checked = dof.includes(n);
    const messages = [];
    for (const e of document.querySelectorAll("#task-box [data-part]")) {
      const part = e.dataset.part;
      const mine = this.store.errorsAbout(part);
      e.classList.toggle("bad", mine.length > 0);
      e.classList.toggle("core-field", this.store.core.includes(part));
      messages.push(...mine);
    }
    $("robot-errors").textContent = messages.join("\n");
  }

  /// Messages about the whole document or a part the canvas cannot show.
  renderDocumentErrors() {
    const fields = [...document.querySelectorAll("#task-box [data-part]")].map((e) => e.dataset.part);
    const shown = (p) => p !== DOCUMENT && (splitPart(p) || fields.some((f) => concerns(p, f)));
    $("document-errors").textContent = [...this.store.errors].filter(([p]) => !shown(p)).map(([, m]) => m).join("\n");
  }
}

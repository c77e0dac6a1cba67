// The side panel's editing parts: the list of task parts, the exact numbers
// of the selected one, and the task's name and robot settings. Messages from
// the server appear beside the field or part they name.

import { dist, isPoint, lengthText, primitiveLength } from "./geometry.js";
import { primitiveColour } from "./task_render.js";
import { concerns, splitPart } from "./parts.js";
import { DOCUMENT } from "./store.js";
import { $, h } from "./dom.js";

const OBSTACLE_COLOUR = "#e45756";
const REGION_COLOUR = "#888";

const POINT_KEYS = {
  line: ["start", "end"],
  arc: ["start", "end", "center"],
  circle: ["start", "center"],
  obstacles: ["center"],
  base_regions: ["min", "max"],
};

export class Panel {
  constructor(store) {
    this.store = store;
    this.model = store.model;
    for (const type of ["doc", "selection", "validation", "core"]) store.on(type, () => this.render());
    this.bindTaskFields();
    this.render();
  }

  render() {
    this.renderParts();
    this.renderSelection();
    this.renderTaskFields();
    this.renderDocumentErrors();
  }

  // ------------------------------------------------------------ part list

  renderParts() {
    const list = $("parts");
    const rows = [];
    this.model.trajectory.forEach((p, j) => rows.push(this.partRow(`trajectory[${j}]`, primitiveColour(j), this.primitiveSummary(p))));
    this.model.obstacles.forEach((o, i) => rows.push(this.partRow(`obstacles[${i}]`, OBSTACLE_COLOUR,
      o && isPoint(o.center) ? `disc at (${o.center.map((v) => v.toFixed(3)).join(", ")}), r ${lengthText(o.radius)}` : "malformed")));
    this.model.regions.forEach((r, i) => rows.push(this.partRow(`base_regions[${i}]`, REGION_COLOUR,
      r && isPoint(r.min) && isPoint(r.max)
        ? `${lengthText(r.max[0] - r.min[0])} x ${lengthText(r.max[1] - r.min[1])}` : "malformed")));
    if (!rows.length) rows.push(h("li", { class: "note" }, "Empty: pick Line, Arc or Circle and click on the canvas."));
    list.replaceChildren(...rows);
  }

  primitiveSummary(p) {
    if (!p || typeof p !== "object") return "malformed";
    const len = primitiveLength(p);
    const dir = p.type === "line" ? "" : ` ${p.direction || "ccw"}`;
    return `${p.type || "?"}${dir}, ${lengthText(len)}`;
  }

  partRow(part, colour, summary) {
    const errors = this.store.errorsAbout(part);
    const cls = [part === this.store.selection ? "selected" : "", errors.length ? "has-error" : ""].join(" ");
    return h("li", { class: cls, "data-part": part, onclick: () => this.store.select(part) },
      h("span", { class: "swatch", style: `background:${colour}` }),
      h("span", { class: "part-name" }, part),
      h("span", { class: "summary" }, summary),
      this.store.inCore(part) ? h("span", { class: "core-badge" }, "conflict") : null,
      h("button", { type: "button", class: "delete", title: "Delete " + part,
                    onclick: (e) => { e.stopPropagation(); this.store.remove(part); } }, "×"),
      errors.map((m) => h("span", { class: "part-error" }, m)));
  }

  // ------------------------------------------------------------ selection

  /// The form is rebuilt only when its shape changes (another part, type or
  /// message), so that typing and tabbing through it are not interrupted;
  /// otherwise only the values of the fields not being edited follow the task.
  renderSelection() {
    const part = this.store.selection;
    const item = part ? this.model.item(part) : undefined;
    const form = $("selection-form");
    $("selection-title").textContent = part ? "Selection: " + part : "Selection";
    if (!item || typeof item !== "object") {
      form.dataset.signature = "";
      form.replaceChildren(h("p", { class: "note" }, "Click a part on the canvas or in the list below to edit its numbers."));
      return;
    }
    const signature = JSON.stringify([part, item.type, this.store.errorsAbout(part)]);
    if (form.dataset.signature !== signature) {
      const active = form.contains(document.activeElement) ? document.activeElement : null;
      form.dataset.signature = signature;
      form.replaceChildren(...this.selectionForm(part, item));
      if (active && active.dataset.key) {
        const axis = active.dataset.axis === undefined ? "" : `[data-axis="${active.dataset.axis}"]`;
        const again = form.querySelector(`[data-key="${active.dataset.key}"]${axis}`);
        if (again) again.focus();
      }
    }
    this.refreshValues(form, item);
  }

  selectionForm(part, item) {
    const kind = splitPart(part)[0];
    const keys = kind === "trajectory" ? POINT_KEYS[item.type] || ["start"] : POINT_KEYS[kind];
    const grid = h("div", { class: "form" });
    if (kind === "trajectory") grid.append(h("label", {}, "type"), h("span", {}, item.type || "?"));
    for (const key of keys) {
      const input = (axis) => h("input", {
        type: "number", step: "any", "aria-label": `${key} ${"xy"[axis]}`, "data-key": key, "data-axis": axis,
        onchange: () => this.editPoint(part, key, grid) });
      grid.append(h("label", {}, key + " (x, y)"), h("span", { class: "pair" }, input(0), input(1)));
      this.fieldErrors(grid, `${part}.${key}`);
    }
    if (kind === "trajectory" && item.type !== "line") {
      grid.append(h("label", {}, "direction"), h("select", {
        "data-key": "direction", onchange: (e) => this.model.setField(part, "direction", e.target.value) },
        h("option", { value: "ccw" }, "counter-clockwise"), h("option", { value: "cw" }, "clockwise")));
      this.fieldErrors(grid, `${part}.direction`);
      grid.append(h("label", {}, "radius"), h("span", { "data-radius-text": true }));
    }
    if (kind === "obstacles") {
      grid.append(h("label", {}, "radius (m)"), h("input", {
        type: "number", step: "any", min: 0, "data-key": "radius",
        onchange: (e) => this.model.setField(part, "radius", parseFloat(e.target.value)) }));
      this.fieldErrors(grid, `${part}.radius`);
    }
    const own = [...this.store.errors].filter(([p]) => p === part).map(([, m]) => m);
    return [...own.map((m) => h("p", { class: "error-text" }, m)), grid,
            h("button", { type: "button", onclick: () => this.store.remove(part) }, "Delete " + part)];
  }

  refreshValues(form, item) {
    for (const field of form.querySelectorAll("[data-key]")) {
      if (field === document.activeElement) continue;
      const key = field.dataset.key;
      if (field.dataset.axis !== undefined) {
        const v = isPoint(item[key]) ? item[key][+field.dataset.axis] : NaN;
        field.value = Number.isFinite(v) ? v : "";
      } else if (key === "radius") {
        field.value = Number.isFinite(item.radius) ? item.radius : "";
      } else if (key === "direction") {
        field.value = item.direction === "cw" ? "cw" : "ccw";
      }
    }
    const radius = form.querySelector("[data-radius-text]");
    if (radius) radius.textContent = isPoint(item.start) && isPoint(item.center) ? lengthText(dist(item.start, item.center)) : "?";
  }

  fieldErrors(grid, path) {
    for (const m of this.store.errorsAbout(path)) grid.append(h("div", { class: "field-error" }, m));
  }

  editPoint(part, key, grid) {
    const values = [...grid.querySelectorAll(`input[data-key="${key}"]`)].map((i) => parseFloat(i.value));
    if (values.every(Number.isFinite)) this.model.setPoint(part, key, values);
  }

  // ------------------------------------------------------------ task, robot

  bindTaskFields() {
    $("task-name").addEventListener("change", (e) => this.model.setName(e.target.value));
    for (const input of document.querySelectorAll("input[data-robot]")) {
      input.addEventListener("change", () => {
        const v = parseFloat(input.value);
        this.model.setRobot(input.dataset.robot, Number.isFinite(v) ? v : input.value);
      });
    }
    for (const n of [2, 3]) {
      $("dof-" + n).addEventListener("change", () => {
        this.model.setRobot("dof", [2, 3].filter((k) => $("dof-" + k).checked));
      });
    }
  }

  renderTaskFields() {
    const doc = this.model.doc, robot = doc.robot && typeof doc.robot === "object" ? doc.robot : {};
    const name = $("task-name");
    if (document.activeElement !== name) name.value = typeof doc.name === "string" ? doc.name : "";
    for (const input of document.querySelectorAll("input[data-robot]")) {
      if (document.activeElement !== input) input.value = robot[input.dataset.robot] ?? "";
    }
    const dof = Array.isArray(robot.dof) ? robot.dof : [2, 3];
    for (const n of [2, 3]) $("dof-" + n).checked = dof.includes(n);
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

// The panel's exact numbers of the selected part: its points, direction
// and radius as fields, with the server's messages beside the fields they
// name.

import { dist, isPoint, lengthText } from "./geometry.js";
import { splitPart } from "./parts.js";
import { isPoint3, isSpatial, obstacleKind } from "./space_geometry.js";
import { radiusText, spatialFields } from "./spatial_form.js";
import { $, h } from "./dom.js";

const POINT_KEYS = {
  line: ["start", "end"],
  arc: ["start", "end", "center"],
  circle: ["start", "center"],
  obstacles: ["center"],
  base_regions: ["min", "max"],
};

export class SelectionForm {
  constructor(store) {
    this.store = store;
    this.model = store.model;
    for (const type of ["doc", "selection", "validation"]) store.on(type, () => this.render());
    this.render();
  }

  /// The form is rebuilt only when its shape changes (another part, type or
  /// message), so that typing and tabbing through it are not interrupted;
  /// otherwise only the values of the fields not being edited follow the task.
  render() {
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
      form.replaceChildren(...(isSpatial(this.model.doc) ? this.spatialForm(part, item) : this.selectionForm(part, item)));
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

  /// A part of a spatial task: its points in x, y and z (spatial_form.js).
  spatialForm(part, item) {
    const grid = spatialFields(this.model, part, item, (g, path) => this.fieldErrors(g, path));
    const own = [...this.store.errors].filter(([p]) => p === part).map(([, m]) => m);
    return [...own.map((m) => h("p", { class: "error-text" }, m)), grid,
            h("button", { type: "button", onclick: () => this.store.remove(part) }, "Delete " + part)];
  }

  refreshValues(form, item) {
    for (const field of form.querySelectorAll("[data-key]")) {
      if (field === document.activeElement) continue;
      const key = field.dataset.key;
      if (field.dataset.axis !== undefined) {
        const v = Array.isArray(item[key]) ? item[key][+field.dataset.axis] : NaN;
        field.value = Number.isFinite(v) ? v : "";
      } else if (key === "radius" || key === "pitch" || key === "turns") {
        field.value = Number.isFinite(item[key]) ? item[key] : "";
      } else if (key === "direction") {
        field.value = item.direction === "cw" ? "cw" : "ccw";
      } else if (key === "kind") {
        field.value = obstacleKind(item) || "sphere";
      }
    }
    const radius = form.querySelector("[data-radius-text]");
    if (radius) {
      radius.textContent = isPoint3(item.start) ? radiusText(item)
        : isPoint(item.start) && isPoint(item.center) ? lengthText(dist(item.start, item.center)) : "?";
    }
  }

  fieldErrors(grid, path) {
    for (const m of this.store.errorsAbout(path)) grid.append(h("div", { class: "field-error" }, m));
  }

  editPoint(part, key, grid) {
    const values = [...grid.querySelectorAll(`input[data-key="${key}"]`)].map((i) => parseFloat(i.value));
    if (values.every(Number.isFinite)) this.model.setPoint(part, key, values);
  }
}

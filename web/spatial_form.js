// The panel's exact numbers of a part of a spatial task: x, y and z of
// its points, a primitive's normal or axis, direction, pitch and turns, an
// obstacle's kind and radius, with the server's messages beside the
// fields they name (selection_form.js shows them and keeps the values).

import { lengthText } from "./geometry.js";
import { splitPart } from "./parts.js";
import { dist3, isPoint3, obstacleKind } from "./space_geometry.js";
import { setObstacleKind, setPoint3 } from "./space_edit.js";
import { h } from "./dom.js";

const POINT_KEYS = {
  line: ["start", "end"],
  arc: ["start", "end", "center"],
  circle: ["start", "center"],
  helix: ["start", "center"],
  sphere: ["center"],
  capsule: ["a", "b"],
  box: ["min", "max"],
  base_regions: ["min", "max"],
};
const DIRECTION_KEY = { arc: "normal", circle: "normal", helix: "axis" };

function triple(key, label, onchange) {
  const input = (axis) => h("input", {
    type: "number", step: "any", "aria-label": `${key} ${"xyz"[axis]}`, "data-key": key, "data-axis": axis, onchange });
  return [h("label", {}, label), h("span", { class: "triple" }, input(0), input(1), input(2))];
}

function numbers(grid, key) {
  return [...grid.querySelectorAll(`input[data-key="${key}"]`)].map((i) => parseFloat(i.value));
}

/// The form's fields for `part` (trajectory[j], obstacles[i] or
/// base_regions[k]); `errors(path)` appends the messages about a field.
export function spatialFields(model, part, item, errors) {
  const kind = splitPart(part)[0];
  const grid = h("div", { class: "form" });
  const shape = kind === "trajectory" ? item.type : kind === "obstacles" ? obstacleKind(item) : kind;
  if (kind === "trajectory") grid.append(h("label", {}, "type"), h("span", {}, item.type || "?"));
  if (kind === "obstacles") {
    grid.append(h("label", {}, "kind"), h("select", {
      "data-key": "kind", onchange: (e) => setObstacleKind(model, part, e.target.value) },
      ["sphere", "capsule", "box"].map((k) => h("option", { value: k }, k))));
    errors(grid, `${part}.type`);
  }
  for (const key of POINT_KEYS[shape] || ["start"]) {
    grid.append(...triple(key, key + " (x, y, z)", () => {
      const v = numbers(grid, key);
      if (v.every(Number.isFinite)) setPoint3(model, part, key, v);
    }));
    errors(grid, `${part}.${key}`);
  }
  const dirKey = kind === "trajectory" ? DIRECTION_KEY[item.type] : null;
  if (dirKey) {
    grid.append(...triple(dirKey, dirKey + " (x, y, z)", () => {
      const v = numbers(grid, dirKey);
      if (v.every(Number.isFinite)) model.setField(part, dirKey, v);
    }));
    errors(grid, `${part}.${dirKey}`);
    grid.append(h("label", {}, "direction"), h("select", {
      "data-key": "direction", onchange: (e) => model.setField(part, "direction", e.target.value) },
      h("option", { value: "ccw" }, `counter-clockwise about the ${dirKey}`), h("option", { value: "cw" }, `clockwise about the ${dirKey}`)));
    errors(grid, `${part}.direction`);
  }
  const scalar = (key, label) => {
    grid.append(h("label", {}, label), h("input", {
      type: "number", step: "any", "data-key": key, onchange: (e) => model.setField(part, key, parseFloat(e.target.value)) }));
    errors(grid, `${part}.${key}`);
  };
  if (item.type === "helix") { scalar("pitch", "pitch (m per turn)"); scalar("turns", "turns"); }
  if (kind === "trajectory" && item.type !== "line") grid.append(h("label", {}, "radius"), h("span", { "data-radius-text": true }));
  if (shape === "sphere" || shape === "capsule") scalar("radius", "radius (m)");
  return grid;
}

/// The radius a curved primitive has, as the form shows it.
export function radiusText(item) {
  return isPoint3(item.start) && isPoint3(item.center) ? lengthText(dist3(item.start, item.center)) : "?";
}

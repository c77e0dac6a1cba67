// The panel's list of task parts: each with its colour, a summary, a mark
// when it is in a conflict, the server's messages about it and a delete
// button; a click selects it.

import { isPoint, lengthText, primitiveLength } from "./geometry.js";
import { primitiveColour } from "./task_render.js";
import { dist3, isPoint3, isSpatial, obstacleKind, primitiveLength3, sub } from "./space_geometry.js";
import { $, h } from "./dom.js";

const OBSTACLE_COLOUR = "#e45756";
const REGION_COLOUR = "#888";

export class PartList {
  constructor(store) {
    this.store = store;
    this.model = store.model;
    for (const type of ["doc", "selection", "validation", "core"]) store.on(type, () => this.render());
    this.render();
  }

  render() {
    if (isSpatial(this.model.doc)) return this.renderSpatial();
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

  /// The parts of a task in space: primitives, spheres, capsules, boxes
  /// and base boxes with their sizes.
  renderSpatial() {
    const rows = [];
    const at = (p) => isPoint3(p) ? `(${p.map((v) => v.toFixed(3)).join(", ")})` : "?";
    const sizes = (b) => b && isPoint3(b.min) && isPoint3(b.max) ? sub(b.max, b.min).map(lengthText).join(" x ") : "malformed";
    this.model.trajectory.forEach((p, j) => rows.push(this.partRow(`trajectory[${j}]`, primitiveColour(j),
      !p || typeof p !== "object" ? "malformed"
        : `${p.type || "?"}${p.type === "line" ? "" : " " + (p.direction || "ccw")}, ${lengthText(primitiveLength3(p))}`)));
    this.model.obstacles.forEach((o, i) => {
      const k = obstacleKind(o);
      const summary = k === "sphere" ? `sphere at ${at(o.center)}, r ${lengthText(o.radius)}`
        : k === "capsule" ? `capsule ${lengthText(isPoint3(o.a) && isPoint3(o.b) ? dist3(o.a, o.b) : NaN)} long, r ${lengthText(o.radius)}`
        : k === "box" ? `box ${sizes(o)}` : "malformed";
      rows.push(this.partRow(`obstacles[${i}]`, OBSTACLE_COLOUR, summary));
    });
    this.model.regions.forEach((r, i) => rows.push(this.partRow(`base_regions[${i}]`, REGION_COLOUR, `box ${sizes(r)}`)));
    if (!rows.length) rows.push(h("li", { class: "note" }, "Empty: add a line, an arc, a circle or a helix with the buttons above."));
    $("parts").replaceChildren(...rows);
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
}

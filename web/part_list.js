// The panel's list of task parts: each with its colour, a summary, a mark
// when it is in a conflict, the server's messages about it and a delete
// button; a click selects it.

import { isPoint, lengthText, primitiveLength } from "./geometry.js";
import { primitiveColour } from "./task_render.js";
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
}

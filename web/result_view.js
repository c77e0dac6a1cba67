// A finished solve shown to the user: the figures in the panel, the
// report's drawing (robot animated along the path, reachable space, swept
// regions) in the Result tab, the downloads, and for a task without a
// robot the parts in conflict, the explanation and the changes suggested.

import * as api from "./api.js";
import { lengthText } from "./geometry.js";
import { isSpatial } from "./space_geometry.js";
import { $, h } from "./dom.js";

// How the panel names the files a job offers, in the order it lists them
// (the task itself is not offered: the page holds it).
const DOWNLOAD_LABELS = {
  "solution.json": "solution JSON", "robot.urdf": "URDF", "trajectory.csv": "CSV",
  "joint-trajectory.yaml": "ROS 2 joint trajectory",
  "report.html": "report", "build-sheet.md": "build sheet", "solve.log": "log",
};
/// Results that come with the report's drawing.
export const REPORTED = ["solved", "infeasible", "unknown"];

/// The report is laid out for a page of its own; in the Result tab its plot
/// (an SVG with a viewBox, so it scales) should fit the frame's height.
function fitReport(frame) {
  const doc = frame.contentDocument;
  if (!doc || !doc.head) return;
  const style = doc.createElement("style");
  style.textContent = "body { margin: 8px 14px; } h1 { font-size: 18px; } header .note { margin: 2px 0 6px; }" +
    " #plot { width: auto; height: calc(100vh - 150px); min-height: 320px; max-width: 100%; }";
  doc.head.append(style);
}

/// Where the proof of an answer without a robot is drawn, in the words of
/// its kind of proof (null when nothing is drawn but the parts in conflict).
export function proofNote(ex, spatial) {
  const core = Array.isArray(ex.core) ? ex.core : [];
  if (ex.separation) return "The closed wall is drawn in red on the canvas: the obstacles grown by half the tube, and where they overlap.";
  if (ex.geodesic) return "The shortest way around the obstacles is drawn in red on the canvas, with its length against the reach.";
  if (!spatial) return null;
  if (ex.enclosure) {
    return "The wall is drawn in the 3-D view: its obstacles outlined in red, the cells it closes in as green cubes, " +
      "and a red ring at the point it keeps out.";
  }
  if (core.includes("robot.max_link_length") && core.includes("base_regions") && core.some((p) => /^(trajectory|strokes)\[/.test(p))) {
    return "The primitive out of reach is drawn thick and red in the 3-D view, with a dashed red line from the base box to its farthest point.";
  }
  return core.length ? "The parts in conflict are drawn red in the 3-D view." : null;
}

export class ResultView {
  constructor(store) {
    this.store = store;
    this.jobId = null;  // the job whose result is shown
  }

  clear() {
    this.jobId = null;
    this.store.setWitness(null);
    this.store.setSolution(null);
    for (const id of ["result-summary", "explanation", "downloads"]) $(id).replaceChildren();
    $("tab-result").disabled = true;
    $("report").removeAttribute("src");
  }

  showResult(job) {
    this.jobId = job.id;
    const r = job.result;
    const rows = [["Status", h("span", { class: "status-badge " + r.status }, r.status)]];
    if (r.status === "solved") {
      rows.push(["Joints", String(r.dof)], ["Total link length", lengthText(r.total_link_length)],
                ["Clearance margin", r.clearance_margin === null ? "no obstacles" : lengthText(r.clearance_margin)]);
    } else if (r.message && !REPORTED.includes(r.status)) {
      // An answer without a robot is explained below, once.
      rows.push(["Why", r.message]);
    }
    rows.push(["Solve time", r.seconds.toFixed(2) + " s"]);
    const table = h("table", { id: "summary-table" }, rows.map(([k, v]) => h("tr", {}, h("th", {}, k), h("td", {}, v))));
    $("result-summary").replaceChildren(table);
    const spatial = isSpatial(this.store.doc);
    if (r.status === "solved") this.addRobotRows(job, table);
    // In space the arm moves in the editor's own 3-D view; the report
    // waits in its tab.
    if (REPORTED.includes(r.status)) this.showReport(api.fileUrl(job, "report.html"), r.status === "solved" && !spatial);
    if (r.status !== "solved") {
      this.store.setCore(r.core);
      this.showExplanation(r);
      this.showWitness(job);
    }
  }

  /// The proof drawn over the task, from the solution's witness, and one
  /// note that says where it is drawn and how.
  async showWitness(job) {
    try {
      const s = await (await fetch(api.fileUrl(job, "solution.json"))).json();
      if (this.jobId !== job.id) return;  // cleared since: the task changed
      this.store.setWitness(s.explanation);
      const about = proofNote(s.explanation || {}, isSpatial(this.store.doc));
      const old = $("proof-note");
      if (old) old.remove();
      if (about && $("explanation-message")) $("explanation-message").after(h("p", { id: "proof-note", class: "note" }, about));
    } catch (e) {
      // The explanation above already says why.
    }
  }

  /// Link lengths and base, from the solution itself.
  async addRobotRows(job, table) {
    let s = null;
    try {
      s = await (await fetch(api.fileUrl(job, "solution.json"))).json();
      // A spatial arm is a DH chain: its rows (a, alpha, d) instead of links.
      const links = Array.isArray(s.robot.dh)
        ? s.robot.dh.map((l) => `(${lengthText(l.a)}, ${(l.alpha * 180 / Math.PI).toFixed(0)}°, ${lengthText(l.d)})`).join(" ")
        : s.robot.link_lengths.map(lengthText).join(" + ");
      table.append(h("tr", {}, h("th", {}, Array.isArray(s.robot.dh) ? "DH (a, α, d)" : "Links"), h("td", { id: "summary-links" }, links)),
                   h("tr", {}, h("th", {}, "Base"), h("td", {}, `(${s.robot.base.map((v) => v.toFixed(3)).join(", ")}) m`)));
    } catch (e) {
      // The summary above already says the essentials.
    }
    if (s && this.jobId === job.id) this.store.setSolution(s);
  }

  /// The report's own drawing, animated when there is a motion ("#t=0&play":
  /// a bare "#play" would scroll to the report's Play button).
  showReport(url, open) {
    const frame = $("report");
    frame.onload = () => fitReport(frame);
    frame.src = url + (open ? "#t=0&play" : "");
    $("tab-result").disabled = false;
    if (open) this.store.setView("result");
  }

  showExplanation(r) {
    const items = (r.core || []).map((p) => h("li", { "data-part": p }, h("code", {}, p)));
    $("explanation").replaceChildren(
      h("p", { id: "explanation-message" }, r.message || "No robot was found."),
      items.length ? h("p", {}, isSpatial(this.store.doc) ? "The parts in conflict, red in the 3-D view:"
                                                            : "The parts in conflict, outlined in red on the canvas:") : null,
      items.length ? h("ul", { id: "core-list" }, items) : null,
      r.status === "infeasible" ? h("p", { id: "suggestions-status", class: "note" }, "Looking for the smallest changes that remove the conflict…") : null);
  }

  showSuggestions(job) {
    const box = $("explanation");
    const status = $("suggestions-status");
    if (status) status.remove();
    const ex = job.explanation;
    const suggestions = ex && Array.isArray(ex.suggestions) ? ex.suggestions : [];
    if (suggestions.length) {
      box.append(h("p", {}, "Changes that would remove the conflict (each re-checked):"),
        h("ul", { id: "suggestions" }, suggestions.map((s) =>
          h("li", { "data-part": s.part }, h("strong", {}, s.change), h("br"), h("span", { class: "note" }, "then: " + s.outcome)))));
    } else {
      box.append(h("p", { id: "suggestions", class: "note" },
        job.explanation_note || "No single change of one part removes the conflict."));
    }
  }

  showDownloads(job) {
    const links = Object.entries(DOWNLOAD_LABELS).filter(([name]) => job.files[name]).map(([name, label]) =>
      h("a", { href: job.files[name] + "?download=1", download: name, "data-file": name }, label));
    $("downloads").replaceChildren(...links);
  }
}

// Synthesis from the page: POST /api/solve, then the job's progress stream
// (stage, elapsed time) until it ends, and its result: the report (robot
// animated along the path, reachable space, swept regions) in the Result
// tab, the figures and downloads in the panel, and for an infeasible task
// its core, explanation and suggested changes. Closing the page closes the
// stream, which cancels the solve on the server.

import * as api from "./api.js";
import { lengthText } from "./geometry.js";
import { $, h } from "./dom.js";

// How the panel names the files a job offers, in the order it lists them
// (the task itself is not offered: the page holds it).
const DOWNLOAD_LABELS = {
  "solution.json": "solution JSON", "robot.urdf": "URDF", "trajectory.csv": "CSV",
  "report.html": "report", "build-sheet.md": "build sheet", "solve.log": "log",
};
// Results that come with the report's drawing.
const REPORTED = ["solved", "infeasible", "unknown"];
const CLOCK_MS = 100;

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

export class Synthesis {
  constructor(store) {
    this.store = store;
    this.job = null;
    this.events = null;
    this.clock = null;
    this.shownResult = false;
    $("cancel").addEventListener("click", () => this.cancel());
  }

  get running() { return this.job !== null && !this.job.done; }

  setState(state) { this.store.setSynthesis(state); }

  async start(doc, timeLimit) {
    if (this.running) return;
    this.reset();
    $("run-box").hidden = false;
    $("run-stage").textContent = "starting";
    this.setState("starting");
    let status, body;
    try {
      ({ status, body } = await api.solve(doc, timeLimit));
    } catch (e) {
      return this.fail("the server cannot be reached: " + e.message);
    }
    if (status !== 202) {
      if (status === 422) this.store.setError(body.part, body.error);
      const prefix = status === 429 ? "the server is busy: " : "";
      return this.fail(prefix + (body.error || "HTTP " + status));
    }
    this.follow(body);
  }

  reset() {
    this.closeStream();
    this.job = null;
    this.shownResult = false;
    for (const id of ["run-error", "result-summary", "explanation", "downloads"]) $(id).replaceChildren();
    $("tab-result").disabled = true;
    $("report").removeAttribute("src");
    $("run-bar").style.width = "0";
    $("run-clock").textContent = "";
    this.store.setCore([]);
  }

  fail(message, stage = "not started") {
    $("run-error").textContent = message;
    $("run-stage").textContent = stage;
    this.setState("failed");
    this.buttons();
  }

  follow(job) {
    this.job = job;
    document.body.dataset.jobId = job.id;
    this.setState("running");
    this.buttons();
    this.update(job);
    this.events = new EventSource(job.links.events);
    this.events.addEventListener("state", (e) => this.update(JSON.parse(e.data)));
    this.events.addEventListener("tick", (e) => this.tick(JSON.parse(e.data).elapsed));
    // EventSource reconnects by itself after a network error; say so
    // meanwhile. It gives up (CLOSED) when the server answers with an
    // error, e.g. after a restart that forgot the job.
    this.events.addEventListener("error", () => {
      if (!this.running) return;
      if (this.events && this.events.readyState === EventSource.CLOSED) {
        this.closeStream();
        this.job = { ...this.job, done: true };
        this.fail("the server no longer knows this solve (was it restarted?)", "lost");
      } else {
        $("run-error").textContent = "lost the connection to the server; retrying...";
      }
    });
    this.events.addEventListener("open", () => { $("run-error").textContent = ""; });
    this.clock = setInterval(() => this.showClock(), CLOCK_MS);
  }

  async cancel() {
    if (!this.running) return;
    $("cancel").disabled = true;
    try {
      const job = await api.cancel(this.job);
      if (job) this.update(job);
    } catch (e) {
      $("run-error").textContent = "cancel failed: " + e.message;
    }
  }

  tick(elapsed) {
    this.elapsedAt = { value: elapsed, at: performance.now() };
  }

  showClock() {
    if (!this.job || !this.elapsedAt) return;
    const live = this.job.done ? 0 : (performance.now() - this.elapsedAt.at) / 1000;
    const elapsed = this.job.done ? this.job.elapsed : this.elapsedAt.value + live;
    $("run-clock").textContent = `${elapsed.toFixed(1)} s of at most ${this.job.time_limit} s`;
    $("run-bar").style.width = Math.min(100, 100 * elapsed / this.job.time_limit) + "%";
  }

  update(job) {
    if (!this.job || job.id !== this.job.id || job.version < this.job.version) return;
    this.job = job;
    this.tick(job.elapsed);
    // The clock and the stage change together, never one ahead of the other.
    this.showClock();
    const phase = job.phase === "explain" ? "explaining: " : "";
    $("run-stage").textContent = job.done ? "finished: " + job.status : phase + job.stage;
    if (job.result && !this.shownResult) {
      this.shownResult = true;
      this.showResult(job);
    }
    if (job.done) this.finish(job);
  }

  finish(job) {
    this.closeStream();
    this.showClock();
    this.showDownloads(job);
    if (job.result && job.result.status === "infeasible") this.showSuggestions(job);
    if (job.status === "cancelled") $("run-error").textContent = job.cancel_reason;
    else if (!job.result) $("run-error").textContent = job.status;
    else if (!REPORTED.includes(job.result.status)) $("run-error").textContent = job.result.message;
    this.setState(job.status);
    this.buttons();
  }

  closeStream() {
    if (this.events) this.events.close();
    this.events = null;
    if (this.clock) clearInterval(this.clock);
    this.clock = null;
  }

  buttons() {
    $("cancel").disabled = !this.running;
    $("synthesize").disabled = this.running;
  }

  // -------------------------------------------------------------- results

  showResult(job) {
    const r = job.result;
    const rows = [["Status", h("span", { class: "status-badge " + r.status }, r.status)]];
    if (r.status === "solved") {
      rows.push(["Joints", String(r.dof)], ["Total link length", lengthText(r.total_link_length)],
                ["Clearance margin", r.clearance_margin === null ? "no obstacles" : lengthText(r.clearance_margin)]);
    } else if (r.message) {
      rows.push(["Why", r.message]);
    }
    rows.push(["Solve time", r.seconds.toFixed(2) + " s"]);
    const table = h("table", { id: "summary-table" }, rows.map(([k, v]) => h("tr", {}, h("th", {}, k), h("td", {}, v))));
    $("result-summary").replaceChildren(table);
    if (r.status === "solved") this.addRobotRows(job, table);
    if (REPORTED.includes(r.status)) this.showReport(api.fileUrl(job, "report.html"), r.status === "solved");
    if (r.status !== "solved") {
      this.store.setCore(r.core);
      this.showExplanation(r);
    }
  }

  /// Link lengths and base, from the solution itself.
  async addRobotRows(job, table) {
    try {
      const s = await (await fetch(api.fileUrl(job, "solution.json"))).json();
      const links = s.robot.link_lengths.map(lengthText).join(" + ");
      table.append(h("tr", {}, h("th", {}, "Links"), h("td", { id: "summary-links" }, links)),
                   h("tr", {}, h("th", {}, "Base"), h("td", {}, `(${s.robot.base.map((v) => v.toFixed(3)).join(", ")}) m`)));
    } catch (e) {
      // The summary above already says the essentials.
    }
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
      items.length ? h("p", {}, "The parts in conflict, outlined in red on the canvas:") : null,
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

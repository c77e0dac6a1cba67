// A solve from the page: POST /api/solve, then the job's progress stream
// (the pipeline's stages done, the latest step, elapsed time) until it
// ends, with a Cancel button; its result goes to the result view. Closing
// the page closes the stream, which cancels the solve on the server. When
// the task changes, the result of the task before goes (a running solve of
// it is cancelled): what is shown is always about the task on the page.

import * as api from "./api.js";
import { REPORTED, ResultView } from "./result_view.js";
import { $, h } from "./dom.js";

const CLOCK_MS = 100;

/// The pipeline's steps as the page shows them, each with the progress
/// stages (the job's `stages`, run/progress.h) that belong to it.
export const STEPS = [
  { name: "proofs", stages: ["proofs"] },
  { name: "front stage", stages: ["front stage"] },
  { name: "refinement", stages: ["search", "refinement"] },
  { name: "verification", stages: ["verification", "shortening"] },
  { name: "timing", stages: ["timing", "modules"] },
];
const EXPLAIN_STEP = { name: "explanation", stages: ["explanation"] };

/// The steps of a job: [{name, state: "done" | "current" | "skipped" |
/// "todo"}] and the share done (0..1). A solve runs the steps in order
/// (going back to the front stage for more joints), so every step before
/// the furthest reached is done or skipped; an infeasible task's solve
/// ends early and is then explained.
export function stepsOf(job) {
  const reached = new Set(job.stages || []);
  const explained = job.phase === "explain" || reached.has("explanation") ||
    (job.done && job.result && job.result.status === "infeasible");
  const steps = explained ? [...STEPS, EXPLAIN_STEP] : STEPS;
  let furthest = -1;
  steps.forEach((st, i) => { if (st.stages.some((x) => reached.has(x))) furthest = i; });
  if (explained) furthest = steps.length - 1;
  const solved = job.done && job.result && job.result.status === "solved";
  const out = steps.map((st, i) => {
    const seen = st.stages.some((x) => reached.has(x));
    const state = job.done ? (seen || solved ? "done" : "skipped")
      : i < furthest ? (seen ? "done" : "skipped") : i === furthest ? "current" : "todo";
    return { name: st.name, state };
  });
  const finished = out.filter((st) => st.state === "done" || st.state === "skipped").length;
  return { steps: out, share: job.done ? 1 : finished / out.length };
}

export class Synthesis {
  constructor(store) {
    this.store = store;
    this.results = new ResultView(store);
    this.job = null;
    this.events = null;
    this.clock = null;
    this.shownResult = false;
    $("cancel").addEventListener("click", () => this.cancel());
    // A result is about the task it was asked for: another task (an edit,
    // another example, a file) takes it away.
    store.on("doc", () => this.taskChanged());
  }

  taskChanged() {
    if (!this.job && !this.results.jobId) return;
    if (this.running) this.cancel("the task changed");
    this.reset();
    $("run-box").hidden = true;
    this.setState("idle");
    this.buttons();
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
    $("run-error").replaceChildren();
    this.results.clear();
    $("run-bar").style.width = "0";
    $("run-clock").textContent = "";
    $("run-steps").replaceChildren();
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

  /// Stops the running solve; `why` (given when the page, not the user,
  /// stops it) means its answer is no longer wanted.
  async cancel(why = "") {
    if (!this.running) return;
    $("cancel").disabled = true;
    const job = this.job;
    try {
      const stopped = await api.cancel(job);
      if (stopped && !why) this.update(stopped);
    } catch (e) {
      if (!why) $("run-error").textContent = "cancel failed: " + e.message;
    }
  }

  tick(elapsed) {
    this.elapsedAt = { value: elapsed, at: performance.now() };
  }

  /// The time so far, with the limit beside it (the bar shows the steps).
  showClock() {
    if (!this.job || !this.elapsedAt) return;
    const live = this.job.done ? 0 : (performance.now() - this.elapsedAt.at) / 1000;
    const elapsed = this.job.done ? this.job.elapsed : this.elapsedAt.value + live;
    $("run-clock").textContent = `${elapsed.toFixed(1)} s` + (this.job.done ? "" : ` (time limit ${this.job.time_limit} s)`);
  }

  /// The pipeline's steps, done, under way and to come, and the bar.
  showSteps(job) {
    const { steps, share } = stepsOf(job);
    $("run-steps").replaceChildren(...steps.map((st) => h("li", { class: st.state, "data-step": st.name }, st.name)));
    $("run-bar").style.width = Math.round(100 * share) + "%";
    $("run-meter").dataset.share = share.toFixed(3);
  }

  update(job) {
    if (!this.job || job.id !== this.job.id || job.version < this.job.version) return;
    this.job = job;
    this.tick(job.elapsed);
    // The clock, the steps and the stage change together, never one ahead
    // of the other.
    this.showClock();
    this.showSteps(job);
    const phase = job.phase === "explain" ? "explaining: " : "";
    $("run-stage").textContent = job.done ? "finished: " + job.status : phase + job.stage;
    if (job.result && !this.shownResult) {
      this.shownResult = true;
      this.results.showResult(job);
    }
    if (job.done) this.finish(job);
  }

  finish(job) {
    this.closeStream();
    this.showClock();
    this.results.showDownloads(job);
    if (job.result && job.result.status === "infeasible") this.results.showSuggestions(job);
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
}

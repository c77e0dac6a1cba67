// A solve from the page: POST /api/solve, then the job's progress stream
// (stage, elapsed time) until it ends, with a Cancel button; its result
// goes to the result view. Closing the page closes the stream, which
// cancels the solve on the server.

import * as api from "./api.js";
import { REPORTED, ResultView } from "./result_view.js";
import { $ } from "./dom.js";

const CLOCK_MS = 100;

export class Synthesis {
  constructor(store) {
    this.store = store;
    this.results = new ResultView(store);
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
    $("run-error").replaceChildren();
    this.results.clear();
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

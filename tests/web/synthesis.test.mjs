// What the page says about a solve (web/synthesis.js, web/result_view.js):
// its progress as the pipeline's steps done, and one note on where the
// proof of an answer without a robot is drawn, in the words of its proof.

import assert from "node:assert/strict";
import { test } from "node:test";

import { STEPS, stepsOf } from "../../web/synthesis.js";
import { proofNote } from "../../web/result_view.js";

const states = (job) => stepsOf(job).steps.map((s) => `${s.name}:${s.state}`);

test("a running solve shows the steps before the furthest reached as done", () => {
  const job = { done: false, phase: "solve", stages: ["front stage", "search", "refinement"] };
  assert.deepEqual(states(job), ["proofs:skipped", "front stage:done", "refinement:current", "verification:todo", "timing:todo"]);
  assert.equal(stepsOf(job).share, 2 / 5);
  // Back to the front stage for more joints: the furthest step stays.
  job.stages.push("verification");
  assert.equal(stepsOf(job).steps[3].state, "current");
});

test("a solved job is done at every step, whatever its time", () => {
  const job = { done: true, phase: "done", stages: ["front stage", "search", "refinement", "verification", "shortening", "timing"],
                result: { status: "solved" }, elapsed: 0.3, time_limit: 60 };
  const { steps, share } = stepsOf(job);
  assert.equal(share, 1);
  assert.ok(steps.every((s) => s.state === "done"));
  assert.equal(steps.length, STEPS.length);
});

test("an infeasible task proved at once is explained next, and finished when done", () => {
  const running = { done: false, phase: "explain", stages: ["proofs", "explanation"], result: { status: "infeasible" } };
  assert.deepEqual(states(running), ["proofs:done", "front stage:skipped", "refinement:skipped", "verification:skipped",
                                     "timing:skipped", "explanation:current"]);
  assert.equal(stepsOf(running).share, 5 / 6);
  const done = { ...running, done: true, phase: "done" };
  assert.equal(stepsOf(done).share, 1);
  assert.equal(stepsOf(done).steps[5].state, "done");
  assert.equal(stepsOf({ done: false, phase: "solve" }).share, 0);
});

test("the proof note names the proof the solution carries, and only that one", () => {
  const wall = { core: ["trajectory[0]", "obstacles[0]", "base_regions", "robot.link_diameter"], enclosure: { walls: [] } };
  assert.match(proofNote(wall, true), /cells it closes in/);
  assert.doesNotMatch(proofNote(wall, true), /out of reach|dashed/);
  const reach = { core: ["robot.max_link_length", "base_regions", "trajectory[0]"] };
  assert.match(proofNote(reach, true), /out of reach .* dashed red line/);
  assert.match(proofNote({ separation: {}, core: [] }, false), /closed wall is drawn in red on the canvas/);
  assert.match(proofNote({ geodesic: {}, core: [] }, false), /shortest way around/);
  assert.equal(proofNote({ core: ["trajectory[0]"] }, false), null);
  assert.match(proofNote({ core: ["trajectory[0]", "obstacles[2]"] }, true), /parts in conflict are drawn red/);
});

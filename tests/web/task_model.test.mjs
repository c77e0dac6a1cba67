// The task being edited (web/task_model.js), part names (web/parts.js) and
// the page's state store (web/store.js).

import assert from "node:assert/strict";
import { test } from "node:test";

import { TaskModel, emptyTask, exampleTask } from "../../web/task_model.js";
import { concerns, inCore, partName, splitPart } from "../../web/parts.js";
import { DOCUMENT, Store } from "../../web/store.js";

const line = (a, b) => ({ type: "line", start: a, end: b });

function modelWith(doc) {
  const model = new TaskModel();
  model.reset(doc);
  return model;
}

test("parts are named as the server names them", () => {
  const model = new TaskModel();
  assert.equal(model.addPrimitive(line([0, 0], [1, 0])), "trajectory[0]");
  assert.equal(model.addPrimitive(line([1, 0], [1, 1])), "trajectory[1]");
  assert.equal(model.addObstacle([0.5, 0.5], 0.1), "obstacles[0]");
  assert.equal(model.addRegion([0.2, 0.1], [-0.1, -0.3]), "base_regions[0]");
  assert.deepEqual(model.item("base_regions[0]"), { min: [-0.1, -0.3], max: [0.2, 0.1] });
  assert.deepEqual(model.item("trajectory[1]"), line([1, 0], [1, 1]));
  assert.equal(model.item("trajectory[7]"), undefined);
  assert.deepEqual(splitPart("trajectory[12]"), ["trajectory", 12]);
  assert.deepEqual(splitPart("trajectory[1].end"), ["trajectory", 1]);
  assert.equal(splitPart("robot.dof"), null);
  assert.equal(partName("obstacles", 3), "obstacles[3]");
  assert.throws(() => partName("robot", 0));
});

test("messages and cores are matched to parts by name", () => {
  assert.ok(concerns("trajectory[1].end", "trajectory[1]"));
  assert.ok(concerns("robot.dof[0]", "robot.dof"));
  assert.ok(!concerns("trajectory[10]", "trajectory[1]"));
  assert.ok(!concerns("trajectory", "trajectory[1]"));
  assert.ok(inCore(["base_regions", "trajectory[0]"], "base_regions[2]"));
  assert.ok(inCore(["base_regions", "trajectory[0]"], "trajectory[0]"));
  assert.ok(!inCore(["trajectory[0]"], "trajectory[1]"));
});

test("every edit is one undo step, redo replays it, a new edit forgets redo", () => {
  const model = new TaskModel();
  let changes = 0;
  model.addEventListener("change", () => ++changes);
  assert.ok(!model.canUndo);
  model.addObstacle([0, 0], 0.1);
  model.addObstacle([1, 0], 0.2);
  model.setField("obstacles[1]", "radius", 0.3);
  assert.equal(changes, 3);
  model.undo();
  assert.equal(model.obstacles[1].radius, 0.2);
  model.undo();
  assert.equal(model.obstacles.length, 1);
  assert.ok(model.canRedo);
  model.redo();
  assert.deepEqual(model.obstacles[1], { center: [1, 0], radius: 0.2 });
  model.setName("renamed");
  assert.ok(!model.canRedo);
  model.undo(); model.undo(); model.undo();
  assert.deepEqual(model.doc, emptyTask());
  assert.ok(!model.canUndo);
  model.undo();   // nothing left: no change
  assert.deepEqual(model.doc, emptyTask());
});

test("a drag is one undo step however far it goes", () => {
  const model = modelWith(exampleTask());
  model.beginGesture();
  for (const r of [0.06, 0.07, 0.08]) model.updateInGesture((d) => { d.obstacles[0].radius = r; });
  assert.equal(model.obstacles[0].radius, 0.08);
  model.undo();
  assert.equal(model.obstacles[0].radius, 0.05);
  assert.ok(!model.canUndo);
});

test("removing a primitive from the middle keeps the path connected", () => {
  const model = modelWith({ ...emptyTask(), trajectory: [line([0, 0], [1, 0]), line([1, 0], [1, 1]), line([1, 1], [0, 1])] });
  model.remove("trajectory[1]");
  assert.deepEqual(model.trajectory, [line([0, 0], [1, 0]), line([1, 0], [0, 1])]);
  model.remove("trajectory[5]");   // no such part: nothing happens
  assert.equal(model.trajectory.length, 2);
  model.undo();
  assert.equal(model.trajectory.length, 3);
});

test("moving a shared vertex moves both primitives, and through a circle", () => {
  const model = modelWith(exampleTask());
  model.setPoint("trajectory[0]", "end", [0.56, 0.1]);
  assert.deepEqual(model.trajectory[0].end, [0.56, 0.1]);
  assert.deepEqual(model.trajectory[1].start, [0.56, 0.1]);
  // The circle starts and ends where the arc ends.
  model.setPoint("trajectory[2]", "start", [0.55, 0.21]);
  assert.deepEqual(model.trajectory[1].end, [0.55, 0.21]);
  assert.deepEqual(model.trajectory[2].start, [0.55, 0.21]);
  assert.deepEqual(model.pathEnd(), [0.55, 0.21]);
});

test("a loaded task serialises back to the same JSON", () => {
  const task = exampleTask();
  task.robot.link_diameter = 0.02;
  task.name = "round trip";
  task.extra = { kept: [1, 2, 3] };   // unknown keys are the server's to judge
  const model = new TaskModel();
  model.load(task);
  assert.equal(JSON.stringify(model.doc), JSON.stringify(task));
  assert.deepEqual(JSON.parse(JSON.stringify(model.doc)), task);
  // The model holds its own copy.
  task.obstacles[0].radius = 9;
  assert.equal(model.obstacles[0].radius, 0.05);
  // Loading is undoable; resetting is not.
  model.undo();
  assert.deepEqual(model.doc, emptyTask());
  model.reset(task);
  assert.ok(!model.canUndo);
});

test("a new task's robot starts from the defaults it is given", () => {
  const defaults = { dof: [2, 3], max_link_length: 1.0 };
  const task = emptyTask(defaults);
  assert.deepEqual(task.robot, defaults);
  task.robot.dof.push(4);   // a copy: the defaults stay as they were
  assert.deepEqual(defaults.dof, [2, 3]);
  assert.deepEqual(emptyTask().robot, {});
  assert.deepEqual(emptyTask().trajectory, []);
});

test("robot settings: set, and an empty value falls back to the default", () => {
  const model = new TaskModel();
  model.setRobot("max_link_length", 0.5);
  assert.equal(model.doc.robot.max_link_length, 0.5);
  model.setRobot("max_link_length", "");
  assert.ok(!("max_link_length" in model.doc.robot));
});

test("the store announces each change by name", () => {
  const store = new Store(new TaskModel());
  const heard = [];
  for (const type of ["doc", "selection", "validation", "core", "tool"]) store.on(type, () => heard.push(type));
  const part = store.model.addObstacle([0, 0], 0.1);
  store.select(part);
  store.setTool("line");
  assert.deepEqual(heard, ["doc", "selection", "tool"]);
  assert.equal(store.selection, "obstacles[0]");
  store.remove(part);
  assert.equal(store.selection, null);
  assert.equal(store.model.obstacles.length, 0);
});

test("the store keeps the server's verdict and clears a core on edit", () => {
  const store = new Store(new TaskModel());
  // An empty path is where a task starts: no error to show.
  store.setValidation({ valid: false, errors: [{ part: "trajectory", message: "trajectory: is empty" }] });
  assert.equal(store.validity.state, "empty");
  assert.equal(store.errors.size, 0);
  store.model.addPrimitive(line([0, 0], [1, 0]));
  store.setValidation({ valid: false, errors: [{ part: "trajectory[0].end", message: "trajectory[0].end: bad" }] });
  assert.equal(store.validity.state, "invalid");
  assert.deepEqual(store.errorsAbout("trajectory[0]"), ["trajectory[0].end: bad"]);
  assert.deepEqual(store.errorsAbout("trajectory[1]"), []);
  store.setError(undefined, "not JSON");
  assert.deepEqual([...store.errors], [[DOCUMENT, "not JSON"]]);
  store.setValidation({ valid: true, errors: [], primitives: 1, obstacles: 0, base_regions: 0 });
  assert.equal(store.validity.state, "valid");
  assert.equal(store.validity.counts.primitives, 1);

  const cores = [];
  store.on("core", (c) => cores.push(c));
  store.setCore(["trajectory[0]", "base_regions"]);
  assert.ok(store.inCore("trajectory[0]") && store.inCore("base_regions[3]"));
  store.model.setName("edited");   // the core was about the task as solved
  assert.deepEqual(store.core, []);
  assert.deepEqual(cores, [["trajectory[0]", "base_regions"], []]);
});

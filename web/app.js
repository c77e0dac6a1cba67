// The editor page: one store holds the state; the canvas, the panel's
// parts, the toolbar, validation and synthesis each follow it and change it
// only through its setters. This file makes them and gives the toolbar its
// commands.

import * as api from "./api.js";
import * as files from "./files.js";
import { EditorCanvas } from "./canvas.js";
import { PartList } from "./part_list.js";
import { SelectionForm } from "./selection_form.js";
import { Store } from "./store.js";
import { Synthesis } from "./synthesis.js";
import { TaskFields } from "./task_fields.js";
import { TaskModel, emptyTask, exampleTask } from "./task_model.js";
import { Toolbar } from "./toolbar.js";
import { Validation } from "./validation.js";
import { SpaceView } from "./space_view.js";
import { DEFAULT_BASE_BOX, SPATIAL_EXAMPLES, addSpatialPart, emptySpatialTask, fetchSpatialExample } from "./space_edit.js";
import { isSpatial } from "./space_geometry.js";
import { $, h } from "./dom.js";
import { lengthText } from "./geometry.js";

const model = new TaskModel();
const store = new Store(model);
const canvas = new EditorCanvas($("canvas"), store, { hint: $("hint"), cursor: $("cursor") });
const validation = new Validation(store);
const synthesis = new Synthesis(store);
const space = new SpaceView(store, { snap: () => $("snap").checked });
new SelectionForm(store);
new PartList(store);
new TaskFields(store);

function setTool(tool) { store.setTool(tool); }

const newTask = () => emptyTask(store.info ? store.info.robot_defaults : undefined);

/// `underlay`: the drawing to show under the task, if it came from one.
function loadDocument(doc, tool, underlay = null) {
  store.setUnderlay(underlay);
  store.load(doc);
  canvas.fit();
  space.fit();
  setTool(tool || "select");
}

const fit = () => (isSpatial(store.doc) ? space.fit() : canvas.fit());

async function openFile(file) {
  // Until the file's task is checked, the verdict shown is not about it.
  validation.abandon();
  store.checking();
  const { doc, error } = await files.read(file);
  if (error) store.setError(null, error);
  else loadDocument(doc);
}

/// The placement asked for in the panel; what is left empty the server
/// decides (the file's own units, the drawing's origin at the task's).
function importOptions() {
  const list = (id) => $(id).value.split(",").map((v) => v.trim()).filter((v) => v !== "").map(Number);
  const at = list("import-at");
  const place = $("import-place").value;
  const options = { width: parseFloat($("import-width").value), tolerance: parseFloat($("import-tolerance").value) };
  if (place === "flat") {
    options.at = at.length === 2 && at.every(Number.isFinite) ? at : undefined;
  } else {
    // The server names a surface that is not one; the numbers go as typed.
    options[place] = list("import-" + place);
    // Round a cylinder the drawing faces the base: the task's first box.
    const b = isSpatial(store.doc) && store.model.regions[0] || DEFAULT_BASE_BOX;
    options.base = [...b.min, ...b.max];
  }
  return options;
}

async function importDrawing(file) {
  $("import-error").textContent = "";
  $("import-status").textContent = "importing " + file.name + " …";
  const { status, body } = await api.importDrawing(file, importOptions());
  if (status !== 200) {
    $("import-status").textContent = "";
    $("import-error").textContent = `${file.name}: ${body.error || "HTTP " + status}`;
    return;
  }
  // The drawing makes the path and its obstacles; the base regions and the
  // robot of the task being edited stay when it lives where the drawing
  // went (in the plane, or in space).
  const doc = { ...body.task };
  const current = store.doc;
  if (isSpatial(current) === isSpatial(doc)) {
    if (Array.isArray(current.base_regions) && current.base_regions.length) doc.base_regions = current.base_regions;
    if (current.robot && typeof current.robot === "object" && Object.keys(current.robot).length) doc.robot = current.robot;
  }
  const u = body.underlay;
  const underlay = u && !/\.dxf$/i.test(file.name)
    ? { url: URL.createObjectURL(file), width: u.width, height: u.height, transform: u.transform } : null;
  validation.abandon();
  store.checking();
  loadDocument(doc, "select", underlay);
  const where = body.surface === "plane" ? " on a plane" : body.surface === "cylinder" ? " round a cylinder" : "";
  $("import-status").textContent = `${file.name}: ${body.primitives} primitives in ${body.strokes} stroke${body.strokes === 1 ? "" : "s"}${where}, ` +
    `deviation ${lengthText(body.deviation)} (tolerance ${lengthText(body.tolerance)})`;
}

/// A task in space from an example of tasks/spatial/, or an empty one.
async function startSpatial(name) {
  try {
    loadDocument(name === "empty" ? emptySpatialTask() : await fetchSpatialExample(name));
  } catch (e) {
    store.setError(null, "the example could not be loaded: " + e.message);
  }
}

for (const name of [...SPATIAL_EXAMPLES, "empty"]) {
  $("example3d").append(h("option", { value: name }, name === "empty" ? "empty 3-D task" : name));
}
$("example3d").addEventListener("change", (e) => {
  const name = e.target.value;
  e.target.value = "";
  if (name) startSpatial(name);
});
for (const b of document.querySelectorAll("button.add3d")) {
  b.addEventListener("click", () => store.select(addSpatialPart(model, b.dataset.add)));
}
$("import-place").addEventListener("change", (e) => { $("import-box").dataset.place = e.target.value; });
// A drawing dragged over the stage: the panel shows where it will go
// (flat, on a plane, round a cylinder) and with which numbers.
$("editor-view").addEventListener("dragenter", (e) => {
  if (!e.dataTransfer || ![...e.dataTransfer.types].includes("Files")) return;
  $("import-box").classList.add("offer");
  $("import-box").scrollIntoView({ block: "nearest" });
});
for (const type of ["dragleave", "drop"]) $("editor-view").addEventListener(type, () => $("import-box").classList.remove("offer"));

new Toolbar(store, {
  undo: () => model.undo(),
  redo: () => model.redo(),
  fit,
  snap: (on) => canvas.setSnap(on),
  newTask: () => loadDocument(newTask(), "line"),
  example: () => loadDocument(exampleTask()),
  open: openFile,
  importDrawing,
  save: () => files.save(store.doc),
  synthesize: (timeLimit) => {
    store.setView("editor");
    synthesis.start(store.doc, timeLimit);
  },
  escape: () => { if (!canvas.cancelDrawing()) setTool("select"); },
});

async function main() {
  try {
    store.setInfo(await api.info());
  } catch (e) {
    // The page works without: the server applies its own limits and defaults.
  }
  store.on("doc", () => files.keep(store.doc));
  model.reset(files.restore() || newTask());
  canvas.fit();
  space.fit();
  setTool(model.trajectory.length ? "select" : "line");
  store.setSynthesis("idle");
  // For scripts driving the page (the end-to-end test among them).
  window.modsynth = { store, model, canvas, synthesis, clientPoint: (p) => canvas.clientPoint(p), setTool, loadDocument,
                      get view3d() { return space.view; }, proofLines: () => space.showProof() };
  document.body.dataset.ready = "true";
}

main();

// The editor page: wires the task model, the canvas, the panel and
// synthesis to the toolbar, the keyboard and the server's validation.

import { EditorCanvas } from "./canvas.js";
import { Panel } from "./panel.js";
import { Synthesis } from "./synthesis.js";
import { TaskModel, emptyTask, exampleTask } from "./task_model.js";

const $ = (id) => document.getElementById(id);
const STORAGE_KEY = "modsynth-task";
const VALIDATE_DELAY_MS = 200;
const TOOL_KEYS = { v: "select", l: "line", a: "arc", c: "circle", o: "obstacle", b: "region" };

const model = new TaskModel();
const canvas = new EditorCanvas($("canvas"), model);
const panel = new Panel(model, canvas);
const synthesis = new Synthesis();
let core = [];

// ------------------------------------------------------------- validation

let validateTimer = null;
let validationRound = 0;

function scheduleValidation() {
  clearTimeout(validateTimer);
  document.body.dataset.validity = "checking";
  validateTimer = setTimeout(validate, VALIDATE_DELAY_MS);
}

/// Asks the server, which holds the one definition of a valid task, and
/// shows its message next to the part it names.
async function validate() {
  const round = ++validationRound;
  let result;
  try {
    const res = await fetch("/api/validate", {
      method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(model.doc) });
    result = await res.json();
    if (!res.ok) result = { valid: false, errors: [{ part: result.part || "(document)", message: result.error }] };
  } catch (e) {
    result = { valid: false, errors: [{ part: "(document)", message: "cannot reach the server: " + e.message }] };
  }
  if (round !== validationRound) return;  // a newer edit is being checked
  showValidation(result);
}

function showValidation(result) {
  // An empty path is where every task starts, not a mistake to flag.
  const fresh = !model.trajectory.length && result.errors.length === 1 && result.errors[0].part === "trajectory";
  if (fresh) result = { valid: false, fresh, errors: [] };
  const errors = new Map(result.errors.map((e) => [e.part || "(document)", e.message]));
  canvas.setHighlights(errors, core);
  panel.setErrors(errors);
  const pill = $("validity");
  pill.className = "pill " + (result.valid ? "valid" : result.fresh ? "" : "invalid");
  pill.textContent = result.valid
    ? `valid: ${result.primitives} primitives, ${result.obstacles} obstacles, ${result.base_regions} base regions`
    : result.fresh ? "empty: draw the path with Line, Arc or Circle" : "invalid: " + result.errors[0].message;
  pill.title = pill.textContent;
  document.body.dataset.validity = result.valid ? "valid" : result.fresh ? "empty" : "invalid";
}

function showCore(parts) {
  core = parts || [];
  canvas.setHighlights(canvas.errors, core);
  panel.setCore(core);
}

// ------------------------------------------------------------------ files

function loadDocument(doc, tool) {
  model.load(doc);
  showCore([]);
  canvas.select(null);
  canvas.fit();
  setTool(tool || "select");
}

async function openFile(file) {
  // Until the file's task is checked, the verdict shown is not about it.
  document.body.dataset.validity = "checking";
  const text = await file.text();
  let doc;
  try {
    doc = JSON.parse(text);
  } catch (e) {
    // The server names the line and column where the syntax breaks.
    const res = await fetch("/api/validate", { method: "POST", headers: { "Content-Type": "application/json" }, body: text });
    const body = await res.json().catch(() => ({ error: e.message }));
    showValidation({ valid: false, errors: [{ part: "(document)", message: `${file.name}: ${body.error || e.message}` }] });
    return;
  }
  loadDocument(doc);
}

function saveFile() {
  const name = (typeof model.doc.name === "string" && model.doc.name.trim()) || "task";
  const blob = new Blob([JSON.stringify(model.doc, null, 2) + "\n"], { type: "application/json" });
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name.replace(/[^A-Za-z0-9_.-]+/g, "-") + ".json";
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// ---------------------------------------------------------------- toolbar

function setTool(tool) {
  canvas.setTool(tool);
  for (const b of document.querySelectorAll("button.tool")) b.classList.toggle("active", b.dataset.tool === tool);
}

function showView(view) {
  $("editor-view").hidden = view !== "editor";
  $("result-view").hidden = view !== "result";
  for (const b of document.querySelectorAll("#tabs button")) b.setAttribute("aria-selected", String(b.dataset.view === view));
  if (view === "editor") canvas.render();
}

function bindToolbar() {
  for (const b of document.querySelectorAll("button.tool")) b.addEventListener("click", () => setTool(b.dataset.tool));
  $("undo").addEventListener("click", () => model.undo());
  $("redo").addEventListener("click", () => model.redo());
  $("fit").addEventListener("click", () => canvas.fit());
  $("snap").addEventListener("change", (e) => { canvas.snapToGrid = e.target.checked; });
  $("new").addEventListener("click", () => loadDocument(emptyTask(), "line"));
  $("example").addEventListener("click", () => loadDocument(exampleTask()));
  $("open").addEventListener("click", () => $("open-file").click());
  $("open-file").addEventListener("change", (e) => {
    if (e.target.files[0]) openFile(e.target.files[0]);
    e.target.value = "";
  });
  $("save").addEventListener("click", saveFile);
  $("synthesize").addEventListener("click", () => {
    showView("editor");
    synthesis.start(model.doc, parseFloat($("time-limit").value));
  });
  for (const b of document.querySelectorAll("#tabs button")) b.addEventListener("click", () => showView(b.dataset.view));
}

function bindKeys() {
  document.addEventListener("keydown", (e) => {
    const typing = /^(INPUT|SELECT|TEXTAREA)$/.test(document.activeElement.tagName);
    const key = e.key.toLowerCase();
    if ((e.ctrlKey || e.metaKey) && key === "z") {
      if (!typing) { e.preventDefault(); e.shiftKey ? model.redo() : model.undo(); }
      return;
    }
    if ((e.ctrlKey || e.metaKey) && key === "y") {
      if (!typing) { e.preventDefault(); model.redo(); }
      return;
    }
    if (typing || e.ctrlKey || e.metaKey || e.altKey) return;
    if (key === "escape") canvas.pending.length ? canvas.cancelDrawing() : setTool("select");
    else if ((key === "delete" || key === "backspace") && canvas.selected) {
      model.remove(canvas.selected);
      canvas.select(null);
    } else if (key === "f") canvas.fit();
    else if (TOOL_KEYS[key]) setTool(TOOL_KEYS[key]);
  });
}

// ------------------------------------------------------------------ start

function restore() {
  try {
    const saved = JSON.parse(localStorage.getItem(STORAGE_KEY));
    if (saved && typeof saved === "object") return saved;
  } catch (e) {
    // Nothing usable saved: start empty.
  }
  return null;
}

function main() {
  bindToolbar();
  bindKeys();
  model.addEventListener("change", () => {
    $("undo").disabled = !model.canUndo;
    $("redo").disabled = !model.canRedo;
    if (core.length) showCore([]);  // the core named the task as it was solved
    localStorage.setItem(STORAGE_KEY, JSON.stringify(model.doc));
    scheduleValidation();
  });
  canvas.addEventListener("hint", () => { $("hint").textContent = canvas.hint(); });
  canvas.addEventListener("cursor", (e) => {
    $("cursor").textContent = e.detail ? `x ${e.detail[0].toFixed(3)}  y ${e.detail[1].toFixed(3)} m` : "";
  });
  synthesis.addEventListener("core", (e) => showCore(e.detail));
  synthesis.addEventListener("show", (e) => showView(e.detail));
  synthesis.addEventListener("invalid", (e) => showValidation({
    valid: false, errors: [{ part: e.detail.part || "(document)", message: e.detail.error }] }));

  const saved = restore();
  model.doc = saved || emptyTask();
  model.notify();
  model.undoStack = [];
  $("undo").disabled = true;
  canvas.fit();
  setTool(model.trajectory.length ? "select" : "line");
  // For scripts driving the page (the end-to-end test among them).
  window.modsynth = { model, canvas, synthesis, clientPoint: (p) => canvas.clientPoint(p), setTool, loadDocument };
  document.body.dataset.ready = "true";
}

main();

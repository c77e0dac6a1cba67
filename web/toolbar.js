// The page's controls around the canvas: the toolbar's buttons and verdict
// pill, the Editor and Result tabs and the keyboard shortcuts. They show
// the store's state and turn clicks and keys into the page's commands.

import { $ } from "./dom.js";

const TOOL_KEYS = { v: "select", l: "line", a: "arc", c: "circle", o: "obstacle", b: "region" };

/// `commands`: {undo, redo, fit, snap(on), newTask, example, open(file),
/// importDrawing(file), save, synthesize, remove, escape}. A file dropped on
/// the canvas is imported when it is a drawing, opened otherwise.
export class Toolbar {
  constructor(store, commands) {
    this.store = store;
    this.commands = commands;
    this.bindButtons();
    this.bindKeys();
    store.on("doc", () => this.showHistory());
    store.on("tool", (tool) => {
      for (const b of document.querySelectorAll("button.tool")) b.classList.toggle("active", b.dataset.tool === tool);
    });
    store.on("validation", (v) => this.showValidity(v));
    store.on("view", (view) => this.showView(view));
    store.on("synthesis", (state) => { document.body.dataset.synthesis = state; });
  }

  bindButtons() {
    const c = this.commands, store = this.store;
    for (const b of document.querySelectorAll("button.tool")) b.addEventListener("click", () => store.setTool(b.dataset.tool));
    $("undo").addEventListener("click", c.undo);
    $("redo").addEventListener("click", c.redo);
    $("fit").addEventListener("click", c.fit);
    $("snap").addEventListener("change", (e) => c.snap(e.target.checked));
    $("new").addEventListener("click", c.newTask);
    $("example").addEventListener("click", c.example);
    $("open").addEventListener("click", () => $("open-file").click());
    $("open-file").addEventListener("change", (e) => {
      if (e.target.files[0]) c.open(e.target.files[0]);
      e.target.value = "";
    });
    $("import").addEventListener("click", () => $("import-file").click());
    $("import-file").addEventListener("change", (e) => {
      if (e.target.files[0]) c.importDrawing(e.target.files[0]);
      e.target.value = "";
    });
    this.bindDrop($("editor-view"));
    $("save").addEventListener("click", c.save);
    $("synthesize").addEventListener("click", () => c.synthesize(parseFloat($("time-limit").value)));
    for (const b of document.querySelectorAll("#tabs button")) b.addEventListener("click", () => store.setView(b.dataset.view));
  }

  bindDrop(target) {
    const c = this.commands;
    const hasFiles = (e) => e.dataTransfer && [...e.dataTransfer.types].includes("Files");
    target.addEventListener("dragover", (e) => {
      if (!hasFiles(e)) return;
      e.preventDefault();
      target.classList.add("dropping");
    });
    target.addEventListener("dragleave", () => target.classList.remove("dropping"));
    target.addEventListener("drop", (e) => {
      target.classList.remove("dropping");
      const file = e.dataTransfer && e.dataTransfer.files[0];
      if (!file) return;
      e.preventDefault();
      if (/\.(svg|dxf)$/i.test(file.name)) c.importDrawing(file); else c.open(file);
    });
  }

  bindKeys() {
    const c = this.commands, store = this.store;
    document.addEventListener("keydown", (e) => {
      const typing = /^(INPUT|SELECT|TEXTAREA)$/.test(document.activeElement.tagName);
      const key = e.key.toLowerCase();
      if ((e.ctrlKey || e.metaKey) && key === "z") {
        if (!typing) { e.preventDefault(); e.shiftKey ? c.redo() : c.undo(); }
        return;
      }
      if ((e.ctrlKey || e.metaKey) && key === "y") {
        if (!typing) { e.preventDefault(); c.redo(); }
        return;
      }
      if (typing || e.ctrlKey || e.metaKey || e.altKey) return;
      if (key === "escape") c.escape();
      else if ((key === "delete" || key === "backspace") && store.selection) store.remove(store.selection);
      else if (key === "f") c.fit();
      else if (TOOL_KEYS[key]) store.setTool(TOOL_KEYS[key]);
    });
  }

  showHistory() {
    $("undo").disabled = !this.store.model.canUndo;
    $("redo").disabled = !this.store.model.canRedo;
  }

  showValidity(v) {
    document.body.dataset.validity = v.state;
    if (v.state === "checking") return;
    const pill = $("validity");
    const c = v.counts;
    pill.className = "pill " + (v.state === "empty" ? "" : v.state);
    pill.textContent = v.state === "valid"
      ? `valid: ${c.primitives} primitives, ${c.obstacles} obstacles, ${c.base_regions} base regions`
      : v.state === "empty" ? "empty: draw the path with Line, Arc or Circle" : "invalid: " + [...v.errors.values()][0];
    pill.title = pill.textContent;
  }

  showView(view) {
    $("editor-view").hidden = view !== "editor";
    $("result-view").hidden = view !== "result";
    for (const b of document.querySelectorAll("#tabs button")) b.setAttribute("aria-selected", String(b.dataset.view === view));
  }
}

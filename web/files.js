// The task in and out of the page: Open and Save of modsynth-task/1 files,
// and the copy kept in the browser so that a reload finds the task again.

import * as api from "./api.js";

const STORAGE_KEY = "modsynth-task";
const DEFAULT_NAME = "task";

/// The task kept from the last visit, or null.
export function restore() {
  try {
    const saved = JSON.parse(localStorage.getItem(STORAGE_KEY));
    if (saved && typeof saved === "object") return saved;
  } catch (e) {
    // Nothing usable saved: start empty.
  }
  return null;
}

export function keep(doc) {
  localStorage.setItem(STORAGE_KEY, JSON.stringify(doc));
}

/// Reads a file the user picked: {doc} or, when it is not JSON, {error}
/// with the server's word on where the syntax breaks.
export async function read(file) {
  const text = await file.text();
  try {
    return { doc: JSON.parse(text) };
  } catch (e) {
    const result = await api.validate(text);
    const message = (result.errors && result.errors[0] && result.errors[0].message) || e.message;
    return { error: `${file.name}: ${message}` };
  }
}

/// Downloads the task as <its name>.json.
export function save(doc) {
  const name = (typeof doc.name === "string" && doc.name.trim()) || DEFAULT_NAME;
  const blob = new Blob([JSON.stringify(doc, null, 2) + "\n"], { type: "application/json" });
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name.replace(/[^A-Za-z0-9_.-]+/g, "-") + ".json";
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// Every edit is checked by the server, which holds the one definition of a
// valid task: shortly after the task last changed, POST /api/validate, and
// the answer goes to the store (where the canvas and the panel find it).

import * as api from "./api.js";

const DELAY_MS = 200;   // typing and dragging settle before a check

export class Validation {
  constructor(store) {
    this.store = store;
    this.timer = null;
    this.round = 0;
    store.on("doc", () => this.schedule());
  }

  schedule() {
    clearTimeout(this.timer);
    this.store.checking();
    this.timer = setTimeout(() => this.check(), DELAY_MS);
  }

  async check() {
    const round = ++this.round;
    const result = await api.validate(this.store.doc);
    if (round !== this.round) return;  // a newer edit is being checked
    this.store.setValidation(result);
  }

  /// Forgets any check under way: its answer would be about another task.
  abandon() {
    clearTimeout(this.timer);
    ++this.round;
  }
}

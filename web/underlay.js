// The drawing a task was imported from, drawn faintly under it: the file
// itself as an image, carried from its page (SVG pixels, y down) to the
// task's metres by the map the server placed it with, then to the screen.

import { svg } from "./dom.js";

export class UnderlayRender {
  constructor(layer, store, view) {
    this.layer = layer;
    this.store = store;
    this.view = view;
  }

  render() {
    this.layer.replaceChildren();
    const u = this.store.underlay;
    if (!u) return;
    // Task to screen: x' = s (x - cx) + w/2, y' = -s (y - cy) + h/2.
    const [w, h] = this.view.size(), s = this.view.s;
    const screen = [s, 0, 0, -s, w / 2 - s * this.view.cx, h / 2 + s * this.view.cy];
    svg("image", { href: u.url, x: 0, y: 0, width: u.width, height: u.height, preserveAspectRatio: "none",
                   transform: `matrix(${compose(screen, u.transform).join(" ")})`, class: "underlay" }, this.layer);
  }
}

/// The SVG matrix of `outer` after `inner`, both as [a, b, c, d, e, f].
export function compose(outer, inner) {
  const [a, b, c, d, e, f] = outer, [p, q, r, s, t, u] = inner;
  return [a * p + c * q, b * p + d * q, a * r + c * s, b * r + d * s, a * t + c * u + e, b * t + d * u + f];
}

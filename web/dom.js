// Element builders shared by the page's views.

export const $ = (id) => document.getElementById(id);

/// An HTML element: attributes (class, on<event> handlers, plain ones; false
/// and null leave one out) and children (strings, elements, arrays, null).
export function h(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v;
    else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else if (v !== undefined && v !== null && v !== false) e.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) e.append(c);
  return e;
}

const SVG_NS = "http://www.w3.org/2000/svg";

/// An SVG element, appended to `parent` when given.
export function svg(tag, attrs, parent) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

/// Screen points as an SVG points attribute.
export const pointsAttr = (points) => points.map((q) => q.map((v) => v.toFixed(1)).join(",")).join(" ");

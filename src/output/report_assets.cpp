#include "report_assets.h"

namespace modsynth::output::assets {

const char* const kStyle = R"CSS(
body { font: 14px/1.45 system-ui, sans-serif; margin: 16px 24px; color: #222; }
h1 { font-size: 22px; margin: 0 0 4px; }
h2 { font-size: 16px; margin: 18px 0 6px; }
.status { font-size: 13px; padding: 2px 8px; border-radius: 10px; vertical-align: middle; }
.status.solved { background: #d8f0d8; color: #175c17; }
.status.infeasible, .status.unknown { background: #fbdcdc; color: #8a1414; }
main { display: flex; gap: 24px; align-items: flex-start; flex-wrap: wrap; }
#plot { border: 1px solid #ccc; background: #fff; }
aside { min-width: 320px; max-width: 460px; }
table { border-collapse: collapse; width: 100%; }
th, td { text-align: left; padding: 3px 8px; border-bottom: 1px solid #eee; vertical-align: top; }
th { font-weight: 600; white-space: nowrap; }
#controls { display: flex; align-items: center; gap: 10px; margin-top: 8px; }
#scrub { flex: 1; }
#play { width: 70px; }
#clock, #readout { font-variant-numeric: tabular-nums; }
#readout { color: #555; margin-top: 4px; min-height: 1.4em; }
#toggles label { margin-right: 12px; }
.swatch { display: inline-block; width: 14px; height: 4px; margin-right: 6px; vertical-align: middle; }
ul.legend { list-style: none; padding: 0; margin: 0; }
.note { color: #555; font-size: 13px; }
#explanation { border-left: 4px solid #d62728; padding: 4px 12px; background: #fff5f5; }
li.core-part { margin: 2px 0; }
.reach { fill: #e4e4e4; }
.swept, .swept-transition { opacity: 0.12; stroke-linejoin: round; }
.swept-transition { stroke-dasharray: 4 3; }
.base-region { fill: rgba(0, 0, 0, 0.05); stroke: #444; stroke-dasharray: 5 3; }
.obstacle { fill: #e45756; fill-opacity: 0.8; stroke: #a32020; }
.obstacle-margin { fill: none; stroke: #a32020; stroke-dasharray: 2 3; }
.primitive { fill: none; stroke-width: 2.5; stroke-linecap: round; }
.primitive.active { stroke-width: 5; }
.travel { fill: none; stroke: #555; stroke-width: 1.5; stroke-dasharray: 6 4; }
.path-start { fill: #fff; stroke: #000; }
.core { stroke: #d00 !important; stroke-width: 6 !important; stroke-dasharray: none !important; }
.wall-disc { fill: #d00; fill-opacity: 0.10; stroke: #d00; stroke-width: 1; }
.wall-cycle { fill: none; stroke: #900; stroke-width: 2; stroke-dasharray: 6 4; }
.wall-overlap { fill: #900; fill-opacity: 0.75; stroke: #600; stroke-width: 1; }
.detour { fill: none; stroke: #d00; stroke-width: 3; stroke-linejoin: round; }
.detour-length { font-size: 13px; fill: #900; font-weight: bold; paint-order: stroke; stroke: #fff; stroke-width: 4px; }
.proof-point { fill: #fff; stroke: #d00; stroke-width: 3; }
.reach-limit { fill: none; stroke-width: 2 !important; stroke-dasharray: 10 6 !important; }
.pose { fill: none; stroke: #555; stroke-opacity: 0.3; stroke-linecap: round; stroke-linejoin: round; }
#robot .link { stroke: #333; stroke-opacity: 0.85; stroke-linecap: round; }
#robot .joint { fill: #fff; stroke: #000; stroke-width: 1.5; }
#robot .ee { fill: #000; }
#robot .base-marker { fill: #333; }
.chart polyline { fill: none; }
#trail { fill: none; stroke: #000; stroke-opacity: 0.55; stroke-width: 1.2; }
#scale-bar path { fill: none; stroke: #000; stroke-width: 1.5; }
#scale-bar text { font-size: 12px; }
.baseline-arm { fill: none; stroke: #1f4e9c; stroke-opacity: 0.35; stroke-dasharray: 6 4; stroke-linecap: round; }
.baseline-trail { fill: none; stroke: #000; stroke-width: 1.5; stroke-dasharray: 5 3; }
.baseline-point { fill: #fff; stroke: #1f4e9c; stroke-width: 1.5; }
.baseline-outside { fill: #d00; }
#comparison td, #comparison th { padding-right: 0.8em; }
.hidden { display: none; }
)CSS";

const char* const kScript = R"JS(
(function () {
  "use strict";
  const data = document.getElementById("motion-data");
  if (!data) return;
  const D = JSON.parse(data.textContent);
  const n = D.L.length, N = D.pr.length;
  const times = D.t[N - 1] > D.t[0] ? D.t : D.t.map(function (_, i) { return i; });
  const T0 = times[0], T1 = times[N - 1];
  const $ = function (id) { return document.getElementById(id); };
  const links = document.querySelectorAll("#robot .link");
  const joints = document.querySelectorAll("#robot .joint, #robot .ee");
  const prims = document.querySelectorAll("#trajectory .primitive");
  const reach = document.querySelectorAll("#reachable .reach");
  const swept = document.querySelectorAll("#swept path");
  const scrub = $("scrub"), play = $("play"), speed = $("speed"), clock = $("clock");
  const readout = $("readout"), trail = $("trail");

  function px(p) { return [D.f.p + (p[0] - D.f.x0) * D.f.s, D.f.p + (D.f.y1 - p[1]) * D.f.s]; }
  function q(i) { return D.q.slice(i * n, i * n + n); }
  function fk(qs) {
    let x = D.base[0], y = D.base[1], a = 0;
    const pts = [[x, y]];
    for (let k = 0; k < n; ++k) {
      a += qs[k]; x += D.L[k] * Math.cos(a); y += D.L[k] * Math.sin(a);
      pts.push([x, y]);
    }
    return pts;
  }
  const eeText = [];
  for (let i = 0; i < N; ++i) {
    const e = px(fk(q(i))[n]);
    eeText.push(e[0].toFixed(1) + "," + e[1].toFixed(1));
  }

  // The largest i with times[i] <= time, and how far towards i + 1.
  function locate(time) {
    let lo = 0, hi = N - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (times[mid] <= time) lo = mid; else hi = mid - 1;
    }
    const span = lo + 1 < N ? times[lo + 1] - times[lo] : 0;
    return { i: lo, a: span > 0 ? Math.min(1, (time - times[lo]) / span) : 0 };
  }

  let time = T0, playing = false, last = null, shownPrimitive = -1, trailIndex = -1;

  function showPrimitive(j) {
    if (j === shownPrimitive) return;
    shownPrimitive = j;
    prims.forEach(function (p) { p.classList.toggle("active", +p.dataset.primitive === j); });
    const onlyCurrent = $("only-current").checked;
    reach.forEach(function (r) {
      r.classList.toggle("hidden", r.dataset.primitive !== "all" && +r.dataset.primitive !== j);
    });
    swept.forEach(function (s) {
      s.classList.toggle("hidden", onlyCurrent && +s.dataset.primitive !== j);
    });
  }

  function render() {
    const at = locate(time);
    const a = q(at.i), b = at.i + 1 < N ? q(at.i + 1) : a;
    const qs = a.map(function (v, k) { return v + (b[k] - v) * at.a; });
    const pts = fk(qs).map(px);
    links.forEach(function (l, k) {
      l.setAttribute("x1", pts[k][0]); l.setAttribute("y1", pts[k][1]);
      l.setAttribute("x2", pts[k + 1][0]); l.setAttribute("y2", pts[k + 1][1]);
    });
    joints.forEach(function (c, k) { c.setAttribute("cx", pts[k][0]); c.setAttribute("cy", pts[k][1]); });
    if (at.i !== trailIndex) {
      trailIndex = at.i;
      trail.setAttribute("points", eeText.slice(0, at.i + 1).join(" "));
    }
    showPrimitive(D.pr[at.i]);
    scrub.value = time;
    clock.textContent = (time - T0).toFixed(2) + " / " + (T1 - T0).toFixed(2) + " s";
    readout.textContent = ["tracing", "transition after", "travel after"][D.ph[at.i]] + " " +
      (D.nm ? D.nm[D.pr[at.i]] : "trajectory[" + D.pr[at.i] + "]") + "   q = [" + qs.map(function (v) { return v.toFixed(3); }).join(", ") + "] rad";
  }

  function frame(now) {
    if (!playing) return;
    if (last !== null) time = Math.min(T1, time + (now - last) / 1000 * +speed.value);
    last = now;
    render();
    if (time >= T1) { setPlaying(false); return; }
    requestAnimationFrame(frame);
  }

  function setPlaying(on) {
    playing = on;
    play.textContent = on ? "Pause" : "Play";
    last = null;
    if (on) {
      if (time >= T1) time = T0;
      requestAnimationFrame(frame);
    }
  }

  scrub.min = T0; scrub.max = T1; scrub.step = "any";
  play.addEventListener("click", function () { setPlaying(!playing); });
  scrub.addEventListener("input", function () { setPlaying(false); time = +scrub.value; render(); });
  $("only-current").addEventListener("change", function () { const j = shownPrimitive; shownPrimitive = -1; showPrimitive(j); });
  document.querySelectorAll("#toggles input[data-layer]").forEach(function (box) {
    box.addEventListener("change", function () {
      $(box.dataset.layer).classList.toggle("hidden", !box.checked);
    });
  });
  // A link can open the report at a moment of the motion: report.html#t=12.5
  const start = /t=([0-9.]+)/.exec(location.hash);
  if (start) time = Math.min(T1, Math.max(T0, T0 + parseFloat(start[1])));
  render();
  if (/play/.test(location.hash)) setPlaying(true);
})();
)JS";

}  // namespace modsynth::output::assets

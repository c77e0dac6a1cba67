// The labels of the parts in conflict (web/label_layout.js): outside their
// parts, away from the conflict's middle, never over each other.

import assert from "node:assert/strict";
import { test } from "node:test";

import { placeLabels } from "../../web/label_layout.js";

const LINE = 14;
function box(p, width) {
  return { x: p.anchor === "start" ? p.x : p.x - width, y: p.y - LINE + 3, w: width, h: LINE };
}
const overlap = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;

/// tasks/infeasible/ring-around-path: twelve discs of 60 mm round a circle,
/// at 800 px per metre, each labelled by its part name.
function ring() {
  const items = [];
  for (let i = 0; i < 12; ++i) {
    const a = (2 * Math.PI * i) / 12;
    items.push({ id: `obstacles[${i}]`, centre: [400 + 160 * Math.cos(a), 300 - 160 * Math.sin(a)], reach: 48,
                 width: 7 * `obstacles[${i}]`.length });
  }
  items.push({ id: "trajectory[0]", centre: [400, 300], reach: 80, width: 7 * 13 });
  items.push({ id: "base_regions", centre: [80, 560], reach: 56, width: 7 * 12 });
  return items;
}

test("no two labels of a ring of obstacles overlap", () => {
  const items = ring();
  const placed = placeLabels(items);
  assert.equal(placed.length, items.length);
  const boxes = placed.map((p, i) => box(p, items[i].width));
  for (let i = 0; i < boxes.length; ++i) {
    for (let j = i + 1; j < boxes.length; ++j) {
      assert.ok(!overlap(boxes[i], boxes[j]), `${items[i].id} and ${items[j].id} overlap: ${JSON.stringify([boxes[i], boxes[j]])}`);
    }
  }
});

test("a ring's labels stand outside the ring, each beyond its own disc", () => {
  const items = ring();
  placeLabels(items).forEach((p, i) => {
    if (!items[i].id.startsWith("obstacles")) return;
    const it = items[i];
    const b = box(p, it.width);
    // The label's nearest point to the disc's centre lies outside the disc.
    const nx = Math.max(b.x, Math.min(it.centre[0], b.x + b.w)), ny = Math.max(b.y, Math.min(it.centre[1], b.y + b.h));
    assert.ok(Math.hypot(nx - it.centre[0], ny - it.centre[1]) >= it.reach, `${it.id}'s label covers its disc`);
    // ... and farther from the ring's middle than the disc's centre.
    const mx = b.x + b.w / 2, my = b.y + b.h / 2;
    assert.ok(Math.hypot(mx - 400, my - 300) > 160, `${it.id}'s label is inside the ring`);
  });
});

test("labels on the left of the conflict end at their part, on the right start at it", () => {
  const placed = placeLabels([{ id: "a", centre: [100, 100], reach: 10, width: 50 }, { id: "b", centre: [300, 100], reach: 10, width: 50 }]);
  assert.equal(placed[0].anchor, "end");
  assert.ok(placed[0].x <= 100 - 10);
  assert.equal(placed[1].anchor, "start");
  assert.ok(placed[1].x >= 300 + 10);
  assert.deepEqual(placeLabels([]), []);
});

test("a label near the canvas's edge stays on the canvas", () => {
  const [p] = placeLabels([{ id: "base_regions", centre: [30, 500], reach: 20, width: 84 },
                           { id: "trajectory[0]", centre: [400, 300], reach: 50, width: 91 }], 800);
  assert.ok(p.anchor === "end" && p.x - 84 >= 0, JSON.stringify(p));
});

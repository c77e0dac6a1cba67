// Where the labels of the parts in conflict go on the canvas: each outside
// its part, away from the middle of the conflict (a ring of obstacles gets
// its labels round the outside), and moved further out until it overlaps
// no label placed before it. Pure: screen points in, label boxes out.

const GAP = 8;          // pixels between a part and its label
const STEP = 6;         // pixels a label moves out per try
const TRIES = 40;
const LINE = 14;        // a label's height in pixels

const overlap = (a, b) => a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;

/// items: [{id, centre: [x, y], reach, width}], `reach` the part's extent
/// from its centre (a disc's radius, half a box's diagonal, 0 for a point),
/// `width` the label's in pixels; `viewWidth` (optional) the canvas's, which
/// a label is kept inside. Returns [{id, x, y, anchor}]: the text's point (x
/// at the anchor's side, y its baseline) and its SVG text-anchor, in the
/// order given; a label that finds no free place within its tries keeps its
/// last one.
export function placeLabels(items, viewWidth = Infinity) {
  if (!items.length) return [];
  const middle = [0, 1].map((i) => items.reduce((s, it) => s + it.centre[i], 0) / items.length);
  const placed = [];
  return items.map((it, index) => {
    let d = [it.centre[0] - middle[0], it.centre[1] - middle[1]];
    let n = Math.hypot(d[0], d[1]);
    // A part at the middle (or the only one): its label to the right,
    // the usual place, turned a little for each such part before it.
    if (n < 1e-9) {
      const a = -Math.PI / 6 + index * 0.7;
      d = [Math.cos(a), Math.sin(a)];
      n = 1;
    }
    d = [d[0] / n, d[1] / n];
    const anchor = d[0] >= 0 ? "start" : "end";
    let box = null;
    for (let t = 0; t <= TRIES; ++t) {
      const r = it.reach + GAP + t * STEP;
      const px = it.centre[0] + d[0] * r, py = it.centre[1] + d[1] * r;
      // Above the point when the label leaves upwards, below when down.
      const top = d[1] < -0.3 ? py - LINE : d[1] > 0.3 ? py : py - LINE / 2;
      let x = anchor === "start" ? px : px - it.width;
      x = Math.max(2, Math.min(x, viewWidth - it.width - 2));
      box = { x, y: top, w: it.width, h: LINE };
      if (!placed.some((p) => overlap(p, box))) break;
    }
    placed.push(box);
    return { id: it.id, x: anchor === "start" ? box.x : box.x + box.w, y: box.y + LINE - 3, anchor };
  });
}

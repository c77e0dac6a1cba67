#!/usr/bin/env python3
"""Re-checks the witness of a wall in space (formats.md "Spatial tasks",
`explanation.enclosure`) with nothing but the task, in exact rational
arithmetic, sharing no code with modsynth's prover.

usage: check_enclosure.py TASK.json SOLUTION.json
Exit 0 and "ok: ..." when every wall holds; exit 1 and the first reason
otherwise.

A wall holds when: its obstacles exist; its point lies on its primitive
(1e-6 m); the cells are inside the grid and off its border; every face
neighbour of a cell that the cells do not hold lies inside one of the
wall's obstacles grown by link_diameter / 2 (all eight corners strictly
inside the grown shape, which is convex); on the enclosed side every cell
that meets the side's box and is not inside a grown obstacle is held, and
no held cell meets the other side's box. A wall may hold no cells: then
every cell the enclosed side meets lies inside a grown obstacle, and no
free point there can start a chain. The base side's box is the base
region grown by link_diameter / 2; the point's is the point grown by
tool_length + 1 mm. Every base region needs a wall.
"""
import json
import math
import sys
from fractions import Fraction as F

OFF_PATH = F(1, 1000)


class Bad(Exception):
    pass


def vec(v):
    return [F(x) for x in v]


def primitives(task):
    if "strokes" in task:
        return [p for stroke in task["strokes"] for p in stroke]
    return task["trajectory"]


# ---------------------------------------------------------------- the path


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return [x / n for x in a]


def on_primitive(p, prim, tol=1e-6):
    """Distance (floats suffice: 1e-6 m) from p to the primitive."""
    kind = prim["type"]
    if kind == "line":
        a, b = prim["start"], prim["end"]
        ab = sub(b, a)
        t = max(0.0, min(1.0, dot(sub(p, a), ab) / dot(ab, ab)))
        return norm(sub(p, [x + t * y for x, y in zip(a, ab)])) <= tol
    if kind in ("arc", "circle"):
        c, n = prim["center"], unit(prim["normal"])
        r0 = sub(prim["start"], c)
        radius = norm(r0)
        v = sub(p, c)
        if abs(dot(v, n)) > tol or abs(norm(v) - radius) > tol:
            return False
        if kind == "circle" or prim["start"] == prim["end"]:
            return True
        s = 1.0 if prim["direction"] == "ccw" else -1.0
        u, w = unit(r0), cross(n, unit(r0))

        def angle(q):
            a = math.atan2(dot(sub(q, c), w), dot(sub(q, c), u)) * s
            return a % (2 * math.pi)

        return angle(p) <= angle(prim["end"]) + tol / radius
    if kind == "helix":
        c, a = prim["center"], unit(prim["axis"])
        s = 1.0 if prim["direction"] == "ccw" else -1.0
        turns, pitch = prim["turns"], prim["pitch"]
        r0 = sub(prim["start"], c)

        def at(u):
            th = s * 2 * math.pi * turns * u
            k = cross(a, r0)
            rot = [r0[i] * math.cos(th) + k[i] * math.sin(th) for i in range(3)]
            return [c[i] + pitch * turns * u * a[i] + rot[i] for i in range(3)]

        u0 = dot(sub(p, c), a) / (pitch * turns)
        return 0.0 - 1e-9 <= u0 <= 1.0 + 1e-9 and norm(sub(p, at(max(0, min(1, u0))))) <= tol
    raise Bad("unknown primitive type " + kind)


# ------------------------------------------------------------ the obstacles


def grown_inside(p, o, half):
    """p strictly inside obstacle o grown by `half`, exactly."""
    if "min" in o:
        lo, hi = vec(o["min"]), vec(o["max"])
        d2 = sum(max(F(0), lo[i] - p[i], p[i] - hi[i]) ** 2 for i in range(3))
        return d2 < half * half
    r = F(o["radius"]) + half
    if "a" in o:
        a, b = vec(o["a"]), vec(o["b"])
        ab = sub(b, a)
        l2 = dot(ab, ab)
        t = min(F(1), max(F(0), dot(sub(p, a), ab) / l2)) if l2 else F(0)
        q = [a[i] + t * ab[i] for i in range(3)]
        return dot(sub(p, q), sub(p, q)) < r * r
    c = vec(o["center"])
    return dot(sub(p, c), sub(p, c)) < r * r


def float_bounds(o, half):
    if "min" in o:
        return [x - half for x in o["min"]], [x + half for x in o["max"]]
    r = o["radius"] + half
    if "a" in o:
        return ([min(x, y) - r for x, y in zip(o["a"], o["b"])],
                [max(x, y) + r for x, y in zip(o["a"], o["b"])])
    return [x - r for x in o["center"]], [x + r for x in o["center"]]


# -------------------------------------------------------------- one wall


def check_wall(task, w, half, reach):
    obstacles = task["obstacles"]
    ids = w["obstacles"]
    if not ids or any(not (0 <= i < len(obstacles)) for i in ids):
        raise Bad("obstacles: not indices of the task's obstacles")
    prims = primitives(task)
    j = w["primitive"]
    if not 0 <= j < len(prims):
        raise Bad("primitive %d: no such primitive" % j)
    if not on_primitive(w["point"], prims[j]):
        raise Bad("point %s is not on primitive %d" % (w["point"], j))
    grid = w["grid"]
    origin, cell, size = vec(grid["origin"]), F(grid["cell"]), grid["size"]
    if cell <= 0 or any(n < 3 for n in size):
        raise Bad("grid: empty")

    def corner(axis, i):
        return origin[axis] + i * cell

    cells = set()
    for j_, k_, i0, i1 in w["cells"]:
        for i in range(i0, i1 + 1):
            c = (i, j_, k_)
            if not all(0 < c[a] < size[a] - 1 for a in range(3)):
                raise Bad("cell %s is on the grid's border or outside it" % (c,))
            cells.add(c)

    shapes = [(obstacles[i], float_bounds(obstacles[i], float(half))) for i in ids]
    inside_cache = {}

    def corner_inside(v, k):
        key = (v, k)
        if key not in inside_cache:
            p = [corner(a, v[a]) for a in range(3)]
            inside_cache[key] = grown_inside(p, shapes[k][0], half)
        return inside_cache[key]

    def blocked(c):
        lo = [float(corner(a, c[a])) for a in range(3)]
        hi = [float(corner(a, c[a] + 1)) for a in range(3)]
        for k, (_, (blo, bhi)) in enumerate(shapes):
            if any(hi[a] < blo[a] or lo[a] > bhi[a] for a in range(3)):
                continue
            if all(corner_inside((c[0] + (m & 1), c[1] + (m >> 1 & 1), c[2] + (m >> 2 & 1)), k)
                   for m in range(8)):
                return True
        return False

    for c in cells:
        for a in range(3):
            for step in (-1, 1):
                n = list(c)
                n[a] += step
                n = tuple(n)
                if n not in cells and not blocked(n):
                    raise Bad("cell %s beside the enclosed cells is not inside an obstacle" % (n,))

    def meeting(lo, hi):
        """The cells meeting the box, and whether it leaves the grid."""
        rng, leaves = [], False
        for a in range(3):
            first = math.floor((lo[a] - origin[a]) / cell)
            last = math.floor((hi[a] - origin[a]) / cell)
            if first < 1 or last > size[a] - 2:
                leaves = True
            rng.append(range(max(0, first - 1), min(size[a] - 1, last) + 1))
        out = [(i, j_, k_) for i in rng[0] for j_ in rng[1] for k_ in rng[2]
               if all(corner(a, (i, j_, k_)[a]) <= hi[a] and corner(a, (i, j_, k_)[a] + 1) >= lo[a]
                      for a in range(3))]
        return out, leaves

    region = task["base_regions"][w["base_region"]]
    seed = meeting([F(x) - half for x in region["min"]], [F(x) + half for x in region["max"]])
    p = vec(w["point"])
    target = meeting([x - reach for x in p], [x + reach for x in p])
    inside, outside = (seed, target) if w["inside"] == "base_region" else (target, seed)
    if w["inside"] not in ("base_region", "point"):
        raise Bad("inside: " + str(w["inside"]))
    if inside[1]:
        raise Bad("the enclosed side reaches the grid's border")
    for c in inside[0]:
        if c not in cells and not blocked(c):
            raise Bad("cell %s of the enclosed side is free and not held" % (c,))
    for c in outside[0]:
        if c in cells:
            raise Bad("cell %s of the other side is held" % (c,))
    return len(cells)


def main():
    task = json.load(open(sys.argv[1]))
    solution = json.load(open(sys.argv[2]))
    try:
        if solution.get("status") != "infeasible":
            raise Bad("status is not infeasible")
        walls = solution["explanation"]["enclosure"]["walls"]
        robot = task.get("robot", {})
        half = F(robot.get("link_diameter", 0.03175)) / 2
        reach = F(robot.get("tool_length", 0.0)) + OFF_PATH
        regions = set()
        total = 0
        for w in walls:
            total += check_wall(task, w, half, reach)
            regions.add(w["base_region"])
        if regions != set(range(len(task.get("base_regions", [])))) or not regions:
            raise Bad("not every base region has a wall")
        core = set(solution["explanation"].get("core", []))
        for w in walls:
            for i in w["obstacles"]:
                if "obstacles[%d]" % i not in core:
                    raise Bad("obstacles[%d] of a wall is not in the core" % i)
    except (Bad, KeyError, TypeError, ValueError) as e:
        print("not a proof: %s" % e)
        return 1
    print("ok: %d wall(s), %d enclosed cells" % (len(walls), total))
    return 0


if __name__ == "__main__":
    sys.exit(main())

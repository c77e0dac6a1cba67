// Part names, the task's own addresses ("trajectory[2]", "robot.dof"): the
// server names parts this way in its messages and cores, and the page tags
// what it draws with them, so both sides meet on these strings.

const LISTS = ["trajectory", "obstacles", "base_regions"];

/// "trajectory[2]" -> ["trajectory", 2]; null for other names.
export function splitPart(part) {
  const m = /^(trajectory|obstacles|base_regions)\[(\d+)\]/.exec(part || "");
  return m ? [m[1], +m[2]] : null;
}

export function partName(list, index) {
  if (!LISTS.includes(list)) throw new Error("not a list of parts: " + list);
  return `${list}[${index}]`;
}

/// Whether a message about `path` is about `part` or something inside it
/// ("trajectory[1].end" is about "trajectory[1]", "robot.dof[0]" about "robot.dof").
export function concerns(path, part) {
  return path === part || path.startsWith(part + ".") || path.startsWith(part + "[");
}

/// A core names parts ("obstacles[1]") or whole families ("base_regions").
export function inCore(core, part) {
  return core.includes(part) || core.includes(part.replace(/\[\d+\]$/, ""));
}

// The server's JSON API as the page uses it (README "JSON API").

const JSON_HEADERS = { "Content-Type": "application/json" };

/// GET /api/info: the server's limits (time_limit, max_body, ...).
export async function info() {
  const res = await fetch("/api/info");
  if (!res.ok) throw new Error("HTTP " + res.status);
  return res.json();
}

/// POST /api/validate with a task (an object, or text that may not even be
/// JSON: the server then names the line and column where it breaks). The
/// answer always has the validate shape {valid, errors: [{part, message}]}.
export async function validate(task) {
  const body = typeof task === "string" ? task : JSON.stringify(task);
  try {
    const res = await fetch("/api/validate", { method: "POST", headers: JSON_HEADERS, body });
    const result = await res.json();
    if (res.ok) return result;
    return { valid: false, errors: [{ part: result.part, message: result.error }] };
  } catch (e) {
    return { valid: false, errors: [{ message: "cannot reach the server: " + e.message }] };
  }
}

/// POST /api/solve: {status, body} (202 and the job when it started).
export async function solve(task, timeLimit) {
  const query = Number.isFinite(timeLimit) && timeLimit > 0 ? "?time_limit=" + timeLimit : "";
  const res = await fetch("/api/solve" + query, { method: "POST", headers: JSON_HEADERS, body: JSON.stringify(task) });
  const body = await res.json().catch(() => ({ error: res.statusText }));
  return { status: res.status, body };
}

/// POST the job's cancel link: the job as stopped, or null.
export async function cancel(job) {
  const res = await fetch(job.links.cancel, { method: "POST" });
  return res.ok ? res.json() : null;
}

/// A file of a job. The job lists its files once it is done; a result
/// arrives before that (an infeasible task is then explained), so the
/// address is also made from the job's own link.
export function fileUrl(job, name) {
  return (job.files && job.files[name]) || job.links.self + "/files/" + name;
}

/// POST /api/import: a drawing file (.svg or .dxf) to a task, placed by
/// `options` ({width, at: [x, y], tolerance, base}, each optional), or on a
/// surface in space ({plane: 9 numbers} or {cylinder: 7}, with `base` a box
/// of 6). {status, body}: 200 with {task, primitives, deviation, underlay
/// ...}, or an error naming the element or option that could not be read.
export async function importDrawing(file, options = {}) {
  const dxf = /\.dxf$/i.test(file.name);
  const query = new URLSearchParams({ format: dxf ? "dxf" : "svg", name: file.name.replace(/\.[^.]*$/, "") || "drawing" });
  if (options.width > 0) query.set("width", options.width);
  if (options.tolerance > 0) query.set("tolerance", options.tolerance);
  if (Array.isArray(options.at)) query.set("at", options.at.join(","));
  if (Array.isArray(options.plane)) query.set("plane", options.plane.join(","));
  if (Array.isArray(options.cylinder)) query.set("cylinder", options.cylinder.join(","));
  if (Array.isArray(options.base)) query.set("base", options.base.join(","));
  const type = dxf ? "application/dxf" : "image/svg+xml";
  try {
    const res = await fetch("/api/import?" + query, { method: "POST", headers: { "Content-Type": type }, body: file });
    const body = await res.json().catch(() => ({ error: res.statusText }));
    return { status: res.status, body };
  } catch (e) {
    return { status: 0, body: { error: "cannot reach the server: " + e.message } };
  }
}

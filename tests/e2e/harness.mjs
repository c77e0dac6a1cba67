// What the browser tests of the reports share: checks that are counted and
// reported, and Debian's Chromium driven by playwright-core, or exit 77
// (skipped) when either is missing (./scripts/test installs both).

import fs from "node:fs";

export const SKIP = 77;
export const CHROMIUM = "/usr/bin/chromium";
// Without the networking flags Chromium keeps calling home, and this
// machine's closed network refuses every call.
const QUIET = ["--headless", "--no-sandbox", "--disable-background-networking", "--disable-component-update",
               "--disable-sync", "--no-first-run"];
/// Pages without WebGL.
export const PLAIN_FLAGS = [...QUIET, "--disable-gpu"];
/// WebGL without a GPU: ANGLE on SwiftShader.
export const WEBGL_FLAGS = [...QUIET, "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                            "--ignore-gpu-blocklist"];

export class Checks {
  constructor(name) {
    this.name = name;
    this.count = 0;
    this.failures = [];
  }

  check(cond, what) {
    ++this.count;
    if (!cond) {
      this.failures.push(what);
      console.log("FAIL: " + what);
    }
  }

  /// Prints the tally and exits: 0 when every check passed.
  finish() {
    console.log(`${this.name}: ${this.count - this.failures.length} passed, ${this.failures.length} failed`);
    process.exit(this.failures.length ? 1 : 0);
  }
}

/// playwright-core's chromium, or exit 77 saying what is missing.
export async function chromiumOrSkip(name) {
  if (!fs.existsSync(CHROMIUM)) {
    console.log(`${name}: skipped: ${CHROMIUM} is missing (Debian packages chromium, chromium-driver)`);
    process.exit(SKIP);
  }
  try {
    return (await import("playwright-core")).chromium;
  } catch (e) {
    console.log(`${name}: skipped: playwright-core is not installed (npm ci in tests/e2e): ` + e.message);
    process.exit(SKIP);
  }
}

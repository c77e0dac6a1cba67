#!/usr/bin/env bash
# Runs the unit tests of the editor's modules (tests/web/*.test.mjs) with the
# Node.js pinned in tests/e2e/package.json (installed by `npm ci` there,
# which ./scripts/test runs). Exit 77 (skipped) when it is not installed.
here=$(cd "$(dirname "$0")" && pwd)
node=$here/../e2e/node_modules/.bin/node
if [ ! -x "$node" ]; then
  echo "web_unit: skipped: $node is missing (run npm ci in tests/e2e; ./scripts/test does)"
  exit 77
fi
cd "$here/../.." && exec "$node" --test tests/web/

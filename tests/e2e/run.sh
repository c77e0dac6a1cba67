#!/usr/bin/env bash
# Runs a browser test (MODSYNTH_E2E_TEST, default editor.test.mjs) with the
# Node.js pinned in package.json (installed by `npm ci` here, which
# ./scripts/test runs): Debian 12's Node.js 18 is too old for
# playwright-core. Exit 77 (skipped) when it is not installed.
here=$(cd "$(dirname "$0")" && pwd)
node=$here/node_modules/.bin/node
if [ ! -x "$node" ]; then
  echo "e2e: skipped: $node is missing (run npm ci in tests/e2e; ./scripts/test does)"
  exit 77
fi
exec "$node" "$here/${MODSYNTH_E2E_TEST:-editor.test.mjs}" "$@"

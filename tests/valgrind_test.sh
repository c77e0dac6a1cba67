#!/usr/bin/env bash
# The DXF text import under valgrind's memcheck: dxflib left the version an
# MTEXT's angle depends on uninitialised, and the drawing changed from run
# to run. Any read of memory nobody set fails the test; the one known and
# harmless read inside libhersheyfont is suppressed (valgrind.supp says
# why). Skipped (77) without valgrind, which is not a dependency.
set -u
tests=$1
if ! command -v valgrind >/dev/null; then
  echo "valgrind is not installed: skipped"
  exit 77
fi
exec valgrind --quiet --error-exitcode=1 --suppressions="$(dirname "$0")/valgrind.supp" \
  "$tests" "DXF: an MTEXT's angle does not depend on what memory held"

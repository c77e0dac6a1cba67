#!/usr/bin/env bash
# Every C++ file the project tracks is laid out as .clang-format says:
# clang-format-14 changes nothing. To fix a failure, run
#   git ls-files '*.cpp' '*.h' | xargs clang-format-14 -i
set -euo pipefail
cd "${1:?usage: format_test.sh SOURCE_DIR}"
command -v clang-format-14 >/dev/null ||
  { echo "clang-format-14 is missing: ./scripts/install-deps --for-tests installs it"; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' 2>/dev/null ||
                     find src include tests -name '*.cpp' -o -name '*.h')
[ ${#files[@]} -gt 0 ] || { echo "no C++ files found"; exit 1; }
if ! clang-format-14 --dry-run -Werror "${files[@]}" 2>/tmp/format_test.$$; then
  grep -c "error:" /tmp/format_test.$$ | sed 's/$/ places need formatting; the first:/'
  head -20 /tmp/format_test.$$
  rm -f /tmp/format_test.$$
  exit 1
fi
rm -f /tmp/format_test.$$
echo "${#files[@]} files formatted as .clang-format says"

# Shared by the shell tests: sourced after `set -u`, with the modsynth
# binary and the source root as $1 and $2. Gives bin, root, a temporary
# folder removed on exit, fail() to record a failure, and finish() to print
# the closing line CTest logs read and exit with the verdict.
bin=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
finish() {  # name
    echo "$(( failures == 0 ? 1 : 0 )) passed, $(( failures == 0 ? 0 : 1 )) failed: $1"
    [ "$failures" -eq 0 ]
}

#!/usr/bin/env bash
# scripts/build recovers from whatever an earlier run left in build/: a
# configure that failed (here: before a package was installed), an
# interrupted configure, a cache written for another source folder (a moved
# checkout) and another build type. The real script runs on a one-file
# project of its own, so nothing of modsynth is rebuilt.
#
# usage: build_recovery_test.sh SOURCE_DIR
set -u
root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
passes=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passes=$((passes + 1)); }

# A project that needs a "package" (Dep, found through deps/ once it is
# "installed"), built by a copy of the real scripts/build.
make_project() {  # dir
  mkdir -p "$1/scripts"
  cp "$root/scripts/build" "$1/scripts/build"
  cat >"$1/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.22)
project(recovery LANGUAGES CXX)
find_package(Dep REQUIRED PATHS ${CMAKE_SOURCE_DIR}/deps NO_DEFAULT_PATH)
add_executable(hello hello.cpp)
add_executable(other hello.cpp)
EOF
  echo 'int main() { return 0; }' >"$1/hello.cpp"
}
install_dep() { mkdir -p "$1/deps" && echo 'set(Dep_FOUND TRUE)' >"$1/deps/DepConfig.cmake"; }

build() {  # dir: runs its scripts/build, output in $tmp/out
  (cd "$1" && timeout 120 ./scripts/build) >"$tmp/out" 2>&1
}
check_built() {  # dir case
  if build "$1" && [ -x "$1/build/hello" ]; then pass; else fail "$2: scripts/build did not recover: $(tail -3 "$tmp/out")"; fi
}

# 1. `cmake -S . -B build` run by hand before the package was installed.
p=$tmp/failed
make_project "$p"
cmake -S "$p" -B "$p/build" >/dev/null 2>&1 && fail "failed configure: the fixture configured without its package"
[ -f "$p/build/CMakeCache.txt" ] || fail "failed configure: the fixture left no cache to recover from"
install_dep "$p"
check_built "$p" "a configure that failed"
# ... and a second run reuses everything: nothing is rebuilt.
build "$p"
if ! grep -qE "Building|Linking" "$tmp/out"; then pass; else fail "a second run rebuilt: $(grep -E 'Building|Linking' "$tmp/out")"; fi

# 2. An interrupted configure: a cache cut short, no Makefile.
p=$tmp/interrupted
make_project "$p"
install_dep "$p"
cmake -S "$p" -B "$p/build" >/dev/null 2>&1 || fail "interrupted: the fixture does not configure"
head -n 5 "$p/build/CMakeCache.txt" >"$tmp/cut" && mv "$tmp/cut" "$p/build/CMakeCache.txt"
rm -f "$p/build/Makefile"
check_built "$p" "an interrupted configure"

# 3. A moved checkout: its cache names the folder it came from.
p=$tmp/before-move
make_project "$p"
install_dep "$p"
build "$p" || fail "moved: the fixture does not build before the move"
echo kept >"$p/build/kept.txt"
mv "$p" "$tmp/after-move"
p=$tmp/after-move
check_built "$p" "a moved checkout"
if grep -q "written for .*before-move" "$tmp/out"; then pass; else fail "moved: no line says the cache was set aside: $(head -3 "$tmp/out")"; fi
if [ -f "$p/build/kept.txt" ]; then pass; else fail "moved: files the user kept in build/ were removed"; fi

# 4. Another build type.
p=$tmp/debug
make_project "$p"
install_dep "$p"
cmake -S "$p" -B "$p/build" -DCMAKE_BUILD_TYPE=Debug >/dev/null 2>&1 || fail "debug: the fixture does not configure"
check_built "$p" "a Debug build folder"
if grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$p/build/CMakeCache.txt"; then pass; else fail "debug: the build type is not Release"; fi

# 5. Named targets (scripts/demo builds the program alone): only those.
p=$tmp/targets
make_project "$p"
install_dep "$p"
(cd "$p" && timeout 120 ./scripts/build hello) >"$tmp/out" 2>&1 || fail "targets: scripts/build hello failed: $(tail -3 "$tmp/out")"
if [ -x "$p/build/hello" ] && [ ! -e "$p/build/other" ]; then pass; else fail "targets: scripts/build hello did not build hello alone"; fi

echo "$passes passed, $failures failed: build recovery"
[ "$failures" -eq 0 ]

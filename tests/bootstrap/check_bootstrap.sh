#!/usr/bin/env bash
# The README's two set-up commands in the README's order, on a clean copy of the repository
# (issue 40): `scripts/bootstrap.sh demo` configured build/ without tests, and `scripts/bootstrap.sh
# test` then found that cache, kept it, and ctest ran no test at all ("No tests were found!!!") and
# went on green. This runs the configure steps of both commands (the functions bootstrap.sh runs,
# sourced from it; no compilation, no dependency installation: about 15 s) and checks what each
# leaves in the folders:
#   1. demo in a fresh clone: build/ in Release without tests, and the test runner refuses it;
#   2. test after demo: build/ with tests, benchmarks and examples (ctest lists the suite);
#   3. demo after test: the tests stay configured, Release;
#   4. test on a build/ configured by hand in Debug without tests: Release with tests;
#   5. the sanitizer folder configured by hand without tests: configure_fuzz turns them on.
# Usage: tests/bootstrap/check_bootstrap.sh   (a CTest, label bootstrap; exit 77 = skipped: not a git checkout)
set -euo pipefail
src="$(cd "$(dirname "$0")/../.." && pwd)"
if ! git -C "$src" rev-parse --verify -q HEAD >/dev/null 2>&1; then
  echo "check_bootstrap: $src is not a git checkout; skipped"
  exit 77
fi
tmp="$(mktemp -d "${TMPDIR:-/tmp}/seflex-bootstrap-check.XXXXXX")"
trap 'rm -rf "$tmp"' EXIT
# A clean clone of the checkout: its tracked files as committed, plus uncommitted changes to them
# (git stash create makes that commit without touching the checkout; empty when there are none).
# git stash create refreshes the index, and fails (silently, exit 1) while another git command holds
# the checkout's index lock (an editor's or a shell prompt's `git status`): it is given a copy.
index="$(git -C "$src" rev-parse --path-format=absolute --git-path index)"
cp "$index" "$tmp/index"
rev="$(GIT_INDEX_FILE="$tmp/index" git -C "$src" stash create)"
mkdir "$tmp/clone"
git -C "$src" archive "${rev:-HEAD}" | tar -x -C "$tmp/clone"
cd "$tmp/clone"

failures=0
check() {  # description, then a command that must succeed
  local what="$1"; shift
  if "$@"; then echo "ok: $what"; else echo "FAILED: $what" >&2; failures=$((failures + 1)); fi
}
cache_is() {  # folder, VARIABLE, value
  grep -q "^$2:[A-Z]*=$3\$" "$1/CMakeCache.txt"
}
listed_tests() {  # folder: how many tests ctest lists (built or not)
  (cd "$1" && ctest -N | sed -n 's/^Total Tests: *//p')
}
quiet() {  # command: its output only if it fails
  local log="$tmp/step.log"
  "$@" > "$log" 2>&1 || { cat "$log" >&2; return 1; }
}

# shellcheck source=../../scripts/bootstrap.sh
source scripts/bootstrap.sh
bootstrap_tools
jobs=1

# 1. scripts/bootstrap.sh demo on a fresh clone
quiet configure_demo
check "demo: build/ in Release" cache_is build CMAKE_BUILD_TYPE Release
check "demo: a fresh build/ has no tests" cache_is build SEFLEX_BUILD_TESTS OFF
out="$(run_ctest build 2>&1)" && rc=0 || rc=$?
check "the test runner refuses a folder without tests" test "$rc" -ne 0
check "  and says so: '$(tail -1 <<< "$out")'" grep -q "no test in build" <<< "$out"

# 2. scripts/bootstrap.sh test after it
quiet configure_tests
check "test after demo: tests on" cache_is build SEFLEX_BUILD_TESTS ON
check "test after demo: benchmarks on" cache_is build SEFLEX_BUILD_BENCH ON
check "test after demo: examples on" cache_is build SEFLEX_BUILD_EXAMPLES ON
check "test after demo: Release" cache_is build CMAKE_BUILD_TYPE Release
# one entry per test folder until built (test_<folder>_NOT_BUILT), then every discovered test
folders=$(find tests -mindepth 2 -maxdepth 2 -name '*.cpp' -printf '%h\n' | sort -u | grep -cv -e '^tests/support$' -e '^tests/parallel$')
n=$(listed_tests build)
check "test after demo: ctest lists the suite ($n entries, $folders test folders)" test "${n:-0}" -ge "$folders"

# 3. scripts/bootstrap.sh demo again: the tests stay
quiet configure_demo
check "demo after test: tests still on" cache_is build SEFLEX_BUILD_TESTS ON
check "demo after test: Release" cache_is build CMAKE_BUILD_TYPE Release

# 4. a build/ configured by hand (Debug, no tests), then the test command
quiet configure build -DCMAKE_BUILD_TYPE=Debug -DSEFLEX_BUILD_TESTS=OFF
quiet configure_tests
check "test after a Debug build/ without tests: Release" cache_is build CMAKE_BUILD_TYPE Release
check "test after a Debug build/ without tests: tests on" cache_is build SEFLEX_BUILD_TESTS ON

# 5. the sanitizer folder configured by hand without tests, then the test command's configure
if command -v clang++ >/dev/null 2>&1; then
  quiet configure build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSEFLEX_FUZZ=ON -DSEFLEX_BUILD_TESTS=OFF -DSEFLEX_MPI=OFF
  quiet configure_fuzz build-fuzz
  check "build-fuzz: tests on" cache_is build-fuzz SEFLEX_BUILD_TESTS ON
  check "build-fuzz: fuzzing and sanitizers on" cache_is build-fuzz SEFLEX_FUZZ ON
  check "build-fuzz: RelWithDebInfo" cache_is build-fuzz CMAKE_BUILD_TYPE RelWithDebInfo
else
  echo "check_bootstrap: no clang++; the build-fuzz checks are skipped"
fi

if [ "$failures" -gt 0 ]; then
  echo "check_bootstrap: $failures checks failed" >&2
  exit 1
fi
echo "check_bootstrap: all checks passed"

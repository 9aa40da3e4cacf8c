#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/bootstrap.sh demo   install what is missing, build, run the main job
#   scripts/bootstrap.sh test   install what is missing, build, run the whole test suite (CTest),
#                               then the bad-input tests again under ASan + UBSan
# Build folders: build/ (Release) and build-asan/ (sanitizers); bench/fuzz.sh uses build-fuzz/ (clang).
# Parallelism: $SEFLEX_JOBS or nproc.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
jobs="${SEFLEX_JOBS:-$(nproc)}"
case "$mode" in
  demo|test) ;;
  *) echo "usage: scripts/bootstrap.sh demo|test" >&2; exit 2 ;;
esac

scripts/install-deps.sh

cmake_args=()
command -v ninja >/dev/null 2>&1 && cmake_args=(-G Ninja)
# A compiler cache (ccache, installed by install-deps.sh) makes a rebuild of unchanged sources in
# any checkout of the project a cache hit; paths are taken relative to the checkout.
if command -v ccache >/dev/null 2>&1; then
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"
fi

configure() {  # build-dir, extra cmake args
  local dir="$1"; shift
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S . -B "$dir" "${cmake_args[@]}" "$@"
  fi
}

if [ "$mode" = demo ]; then
  configure build -DCMAKE_BUILD_TYPE=Release -DSEFLEX_BUILD_TESTS=OFF -DSEFLEX_BUILD_BENCH=OFF
  cmake --build build -j "$jobs" --target seflex
  exec scripts/main-job.sh build/apps/seflex
fi

configure build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"
(cd build && ctest --output-on-failure -j "$jobs" --timeout 900)

# The bad-input tests again under ASan + UBSan (gcc). The libFuzzer harnesses (fuzz/, clang) run with
# bench/fuzz.sh SECONDS; they are not part of this command yet (docs/reliability.md: CI time).
# (No distributed backend there: the input tests run the serial commands only.)
configure build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSEFLEX_SANITIZE=ON -DSEFLEX_BUILD_BENCH=OFF -DSEFLEX_BUILD_EXAMPLES=OFF -DSEFLEX_MPI=OFF
cmake --build build-asan -j "$jobs" --target seflex test_input
(cd build-asan && ctest --output-on-failure -j "$jobs" -L input --timeout 900)
echo "bootstrap: all tests passed"

#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/bootstrap.sh demo   install what is missing, build, run the main job
#   scripts/bootstrap.sh test   install what is missing, build, run the whole test suite (CTest),
#                               then the bad-input and card tests again under ASan + UBSan and every fuzz
#                               harness for 20 s (clang)
# Build folders: build/ (Release) and build-fuzz/ (clang, sanitizers + fuzzers; bench/fuzz.sh uses it too).
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
# any checkout of the project a cache hit; paths are taken relative to the checkout. CCACHE_NOHASHDIR:
# the sanitizer folder compiles with debug line tables, and ccache then hashes the build folder's
# absolute path by default, which would miss in every fresh clone (CI's); without it, a hit's line
# tables name the folder of the checkout that compiled it first (file names stay relative).
if command -v ccache >/dev/null 2>&1; then
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
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

# The sanitizer stage, one clang folder (build-fuzz; docs/reliability.md): ASan + UBSan + libFuzzer's
# coverage counters (-DSEFLEX_FUZZ=ON). It builds seflex, the test executables that hold the bad-input
# and card tests and the multibody kernels' tests (target sanitizer_tests, tests/CMakeLists.txt) and the
# fuzz harnesses; runs the bad-input tests (label input, fuzz regression inputs included) and the Nastran card
# tests (label cards: 41 tests, 17 s there; the rest of the suite takes hours under the sanitizers, see
# docs/reliability.md), the multibody kernels' unit tests (the AIC kernel, assembly, stiffening, the
# condensed LU, Newton's stopping and sampling, FFRF-LM's system: 26 tests, 15 s there; they found an
# offset on a null pointer in the frame recovery's warm start that the Release suite cannot see),
# then every harness for
# $SEFLEX_CI_FUZZ_SECONDS (default 20) from its seeds in a fresh corpus (a temporary folder, not the
# long-run corpus of bench/fuzz.sh; fixed libFuzzer seed): any crash, sanitizer report, leak, hang or
# allocation over 2 GB fails the run. No distributed backend there (the input tests run serial commands).
configure build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSEFLEX_FUZZ=ON -DSEFLEX_BUILD_BENCH=OFF -DSEFLEX_BUILD_EXAMPLES=OFF -DSEFLEX_MPI=OFF
cmake --build build-fuzz -j "$jobs" --target seflex sanitizer_tests fuzz_all
sanitizer_labels='^(input|cards)$'
sanitizer_kernels='^(CondensedLu|NewtonRate|AicKernel|Assembly|FfrfSystem|Stiffening)[.]'
echo "bootstrap: sanitizer stage: $(cd build-fuzz && ctest -N -L "$sanitizer_labels" | tail -1 | sed 's/Total Tests: //') tests labelled input or cards, $(cd build-fuzz && ctest -N -R "$sanitizer_kernels" | tail -1 | sed 's/Total Tests: //') multibody kernel tests"
(cd build-fuzz && ctest --output-on-failure -j "$jobs" -L "$sanitizer_labels" --timeout 900)
(cd build-fuzz && ctest --output-on-failure -j "$jobs" -R "$sanitizer_kernels" --timeout 900)
fuzz_dir="$(mktemp -d "${TMPDIR:-/tmp}/seflex-ci-fuzz.XXXXXX")"
SEFLEX_FUZZ_BUILD=build-fuzz SEFLEX_FUZZ_NO_BUILD=1 SEFLEX_FUZZ_DIR="$fuzz_dir" SEFLEX_FUZZ_SEED=1 \
  bench/fuzz.sh "${SEFLEX_CI_FUZZ_SECONDS:-20}" ||
  { echo "bootstrap: fuzzing found something; inputs and logs kept in $fuzz_dir" >&2; exit 1; }
rm -rf "$fuzz_dir"
echo "bootstrap: all tests passed"

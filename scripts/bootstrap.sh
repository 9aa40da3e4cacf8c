#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/bootstrap.sh demo   install what is missing, build, run the main job
#   scripts/bootstrap.sh test   install what is missing, build, run the whole test suite (CTest),
#                               then the bad-input tests again under ASan + UBSan and every fuzzer
#                               for 20 s (bench/fuzz.sh)
# Build folders: build/ (Release) and build-fuzz/ (clang: ASan + UBSan + libFuzzer harnesses).
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

generator=()
command -v ninja >/dev/null 2>&1 && generator=(-G Ninja)

configure() {  # build-dir, extra cmake args
  local dir="$1"; shift
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    cmake -S . -B "$dir" "${generator[@]}" "$@"
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

# One clang build for the sanitizers and the fuzzers (-DSEFLEX_FUZZ=ON: ASan + UBSan + coverage on every
# target): the bad-input tests run in it, then every libFuzzer harness for a short time (bench/fuzz.sh,
# corpus inside the build folder; SEFLEX_FUZZ_SECONDS per harness, default 20).
configure build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSEFLEX_FUZZ=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DSEFLEX_BUILD_BENCH=OFF -DSEFLEX_BUILD_EXAMPLES=OFF
cmake --build build-fuzz -j "$jobs" --target seflex test_input fuzz_all
(cd build-fuzz && ctest --output-on-failure -j "$jobs" -L input --timeout 900)
SEFLEX_FUZZ_NO_BUILD=1 SEFLEX_FUZZ_BUILD=build-fuzz SEFLEX_FUZZ_DIR="$(pwd)/build-fuzz/fuzz-corpus" SEFLEX_FUZZ_NICE=0 SEFLEX_FUZZ_SEED=1 \
  bench/fuzz.sh "${SEFLEX_FUZZ_SECONDS:-20}"
echo "bootstrap: all tests passed"

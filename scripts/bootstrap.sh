#!/usr/bin/env bash
# The two set-up commands of the README:
#   scripts/bootstrap.sh demo   install what is missing, build, run the main job
#   scripts/bootstrap.sh test   install what is missing, build, run the whole test suite (CTest),
#                               then the bad-input and card tests again under ASan + UBSan and every fuzz
#                               harness for 20 s (clang)
# Build folders: build/ (Release) and build-fuzz/ (clang, sanitizers + fuzzers; bench/fuzz.sh uses it too).
# Parallelism: $SEFLEX_JOBS or nproc.
#
# Either command may follow the other, in any folder state: each re-runs cmake on its folder with
# every option it needs (cmake re-configures an existing cache in about 2 s and rebuilds only what
# the change touches), so `demo` then `test` builds and runs the suite although `demo` configured
# build/ without tests, and `demo` after `test` keeps the test executables (it builds only seflex).
# A ctest run that finds no test fails, and every run prints how many tests it runs.
#
# The functions below are also sourced (`source scripts/bootstrap.sh`, nothing runs then) by
# bench/fuzz.sh (configure_fuzz) and by tests/bootstrap/check_bootstrap.sh, which checks on a clean
# copy of the repository that the configure steps of the two commands in the README's order give a
# folder with tests.
set -euo pipefail

bootstrap_tools() {  # sets cmake_generator and cmake_launcher; exports the ccache settings
  cmake_generator=()
  command -v ninja >/dev/null 2>&1 && cmake_generator=(-G Ninja)
  # A compiler cache (ccache, installed by install-deps.sh) makes a rebuild of unchanged sources in
  # any checkout of the project a cache hit; paths are taken relative to the checkout. CCACHE_NOHASHDIR:
  # the sanitizer folder compiles with debug line tables, and ccache then hashes the build folder's
  # absolute path by default, which would miss in every fresh clone (CI's); without it, a hit's line
  # tables name the folder of the checkout that compiled it first (file names stay relative).
  cmake_launcher=()
  if command -v ccache >/dev/null 2>&1; then
    cmake_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
  fi
}

# configure DIR [cmake -D options...]: configure DIR, or re-configure it with these options when it
# has a cache already (the generator is given the first time only: cmake refuses another one).
configure() {
  local dir="$1"; shift
  local generator=()
  [ -f "$dir/CMakeCache.txt" ] || generator=("${cmake_generator[@]}")
  cmake -S . -B "$dir" "${generator[@]}" "${cmake_launcher[@]}" "$@"
}

# build/ for the main job: Release without sanitizers. A new folder gets no tests or benchmarks (less
# to configure); a folder configured with them keeps them (only seflex is built).
configure_demo() {
  local first=()
  [ -f build/CMakeCache.txt ] || first=(-DSEFLEX_BUILD_TESTS=OFF -DSEFLEX_BUILD_BENCH=OFF)
  configure build -DCMAKE_BUILD_TYPE=Release -DSEFLEX_SANITIZE=OFF -DSEFLEX_FUZZ=OFF "${first[@]}"
}

# build/ for the suite: Release, tests, benchmarks and examples on, whatever configured it before.
configure_tests() {
  configure build -DCMAKE_BUILD_TYPE=Release -DSEFLEX_SANITIZE=OFF -DSEFLEX_FUZZ=OFF \
    -DSEFLEX_BUILD_TESTS=ON -DSEFLEX_BUILD_BENCH=ON -DSEFLEX_BUILD_EXAMPLES=ON
}

# The sanitizer and fuzzing folder (default build-fuzz): clang, ASan + UBSan + libFuzzer's coverage
# counters, tests on, no benchmarks, examples or distributed backend.
configure_fuzz() {
  configure "${1:-build-fuzz}" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSEFLEX_FUZZ=ON -DSEFLEX_BUILD_TESTS=ON -DSEFLEX_BUILD_BENCH=OFF -DSEFLEX_BUILD_EXAMPLES=OFF -DSEFLEX_MPI=OFF
}

# run_ctest DIR [ctest selection options...]: the tests of DIR that the options select, after
# printing how many there are; fails when there are none (a folder configured without tests, a
# selection that matches nothing).
run_ctest() {
  local dir="$1"; shift
  local n
  n=$(cd "$dir" && ctest -N "$@" | sed -n 's/^Total Tests: *//p')
  echo "bootstrap: $dir: ${n:-0} tests${*:+ ($*)}"
  if [ "${n:-0}" -eq 0 ]; then
    echo "bootstrap: no test in $dir${*:+ for $*}; expected the suite (is the folder configured with -DSEFLEX_BUILD_TESTS=ON and built?)" >&2
    return 1
  fi
  (cd "$dir" && ctest --output-on-failure --no-tests=error -j "${jobs:-$(nproc)}" --timeout 900 "$@")
}

bootstrap_main() {
  cd "$(dirname "${BASH_SOURCE[0]}")/.."
  local mode="${1:-}"
  jobs="${SEFLEX_JOBS:-$(nproc)}"
  case "$mode" in
    demo|test) ;;
    *) echo "usage: scripts/bootstrap.sh demo|test" >&2; exit 2 ;;
  esac

  scripts/install-deps.sh
  bootstrap_tools

  if [ "$mode" = demo ]; then
    configure_demo
    cmake --build build -j "$jobs" --target seflex
    exec scripts/main-job.sh build/apps/seflex
  fi

  configure_tests
  cmake --build build -j "$jobs"
  run_ctest build

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
  configure_fuzz build-fuzz
  cmake --build build-fuzz -j "$jobs" --target seflex sanitizer_tests fuzz_all
  run_ctest build-fuzz -L '^(input|cards)$'
  run_ctest build-fuzz -R '^(CondensedLu|NewtonRate|AicKernel|Assembly|FfrfSystem|Stiffening)[.]'
  local fuzz_dir
  fuzz_dir="$(mktemp -d "${TMPDIR:-/tmp}/seflex-ci-fuzz.XXXXXX")"
  SEFLEX_FUZZ_BUILD=build-fuzz SEFLEX_FUZZ_NO_BUILD=1 SEFLEX_FUZZ_DIR="$fuzz_dir" SEFLEX_FUZZ_SEED=1 \
    bench/fuzz.sh "${SEFLEX_CI_FUZZ_SECONDS:-20}" ||
    { echo "bootstrap: fuzzing found something; inputs and logs kept in $fuzz_dir" >&2; exit 1; }
  rm -rf "$fuzz_dir"
  echo "bootstrap: all tests passed"
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  bootstrap_main "$@"
fi

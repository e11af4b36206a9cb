#!/usr/bin/env bash
# Installs the dependencies, builds everything with warnings as errors, runs
# the whole test suite, then builds and runs it again under AddressSanitizer
# and UndefinedBehaviorSanitizer, then runs each libFuzzer target for a short
# smoke time (scripts/fuzz.sh). Used by CI (.ci/run) and by the README.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

bash scripts/setup.sh
# Every test draws text with the fonts setup.sh installs, whatever else the
# machine has (tests/text/fonts.conf).
export FONTCONFIG_FILE=$PWD/tests/text/fonts.conf

# CASTELJAU_PYTHON=ON: the Python package is required here (configuring fails
# without python3-dev and pybind11-dev), and its pytest suite (tests/python,
# under Debian's python3) runs in ctest as python.pytest.
# The benchmarks are not built here (no test runs them, and they took a
# minute of CI's 15): scripts/examples.sh, the README's first command, builds them.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCASTELJAU_WERROR=ON -DCASTELJAU_PYTHON=ON \
      -DCASTELJAU_BUILD_BENCH=OFF
cmake --build build -j "$jobs"

# The unit tests (suites named in capitals) of build dir $1 as $jobs shards
# of the one binary rather than one process per test: each process start
# loads OpenImageIO's 260 shared libraries (some 0.2 s), which for 480
# tests cost more than the tests (release: 50 s of the 130 s of ctest).
# Twice as many shards as cores: gtest deals the tests out in turn, not by
# their cost, and the few slow property tests made one of two shards run
# 30 s longer than the other under the sanitizers; the scheduler evens out
# four.
unit_test_shards() {
  local dir=$1 pids=() shard shards=$((2 * jobs))
  for ((shard = 0; shard < shards; shard++)); do
    # timeout: a hang guard (a shard takes a minute under the sanitizers).
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard GTEST_BRIEF=1 \
      timeout 1200 "$dir/tests/casteljau_tests" > "$dir/unit_tests.$shard.log" 2>&1 &
    pids+=($!)
  done
  for ((shard = 0; shard < shards; shard++)); do
    if ! wait "${pids[$shard]}"; then
      cat "$dir/unit_tests.$shard.log"; echo "unit tests in $dir: shard $shard failed"; exit 1
    fi
  done
  grep -h "PASSED" "$dir"/unit_tests.*.log || true
}

# The named tests of build dir $1 through ctest (ctest's arguments follow),
# with the unit test shards beside them: ctest's longest tests (the bad-input
# and agreement scripts, a process each) leave a core idle for most of their
# run, which the shards fill.
named_and_unit_tests() {
  local dir=$1 status=0 units
  shift
  unit_test_shards "$dir" > "$dir/unit_shards.log" 2>&1 &
  units=$!
  ctest --test-dir "$dir" -j "$jobs" --output-on-failure "$@" || status=$?
  if ! wait "$units"; then status=1; fi
  cat "$dir/unit_shards.log"
  [[ $status -eq 0 ]] || { echo "tests in $dir failed"; exit 1; }
}

# The paint tests of build dir $1 once more with the baseline (SSE2) forms
# of the loops that have wider ones (CASTELJAU_NO_AVX2, paint/cpu.h): on a
# CPU with AVX2 the baseline forms otherwise run only at the ends of rows.
baseline_forms() {
  CASTELJAU_NO_AVX2=1 GTEST_BRIEF=1 timeout 600 "$1/tests/casteljau_tests" \
    --gtest_filter='Cpu.*:FillRun.*:Pixel8.*:ImageShader.*:Gradient.*:Canvas*:Pattern*'
}

# The named tests through ctest (CLI, agreement, bad input, Python, fuzz
# replays, install), and the unit tests.
named_and_unit_tests build -E '^[A-Z]'
baseline_forms build

# Sanitizers: the same tests, minus the install test (its consumer project is
# built without the sanitizer runtime the instrumented library needs) and the
# Python package (an instrumented module cannot load into python3; the
# configuration leaves it out). One clang build serves this pass and the
# fuzzing smoke below (-DCASTELJAU_FUZZ=ON with the tests: ASan, UBSan and
# libFuzzer's coverage on one library), where two builds of the library
# took a third of CI's 15 minutes. -g1: line tables only, which is all a
# sanitizer's stack trace reads (file:line), at 10-30% less compile time per
# file than -g. -O1: a third less compile time than -O2, for tests that run
# a little slower.
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCASTELJAU_WERROR=ON -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DCASTELJAU_FUZZ=ON -DCASTELJAU_BUILD_BENCH=OFF -DCASTELJAU_PYTHON=OFF
cmake --build build-asan -j "$jobs"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp
# The named tests through ctest, and the unit tests in shards (400
# sanitizer start-ups cost more than the tests: 153 s of ctest against 80).
# Not the rsvg agreement (40 s here, for pictures the unit shards render
# under the sanitizers too: EffectFormats draws every effects file, and
# the svg_render fuzz target the examples' kinds of content).
named_and_unit_tests build-asan -E '^install\.|^[A-Z]|^svg\.rsvg_agreement$'
baseline_forms build-asan
unset ASAN_OPTIONS UBSAN_OPTIONS LSAN_OPTIONS

# Fuzzing smoke: 4 s per target from the seed corpus (and the regressions,
# which this replays: the fuzz build has no ctest replays), with a fixed seed
# so that a run is repeatable, on the sanitizer build; campaigns run
# scripts/fuzz.sh 600 or more. (With seven targets at 6 s and the sanitizer
# pass at -O2, the whole command took 1002 s on the 2-core machine: over
# CI's 15 minutes.)
FUZZ_SEED=1 FUZZ_BUILD=build-asan bash scripts/fuzz.sh 4

#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (build-fuzz/), then runs each for SECONDS
# (default 60; CI runs a short smoke time, a campaign 600 or more).
# Usage: [FUZZ_SEED=N] [FUZZ_OPT=-O1] [FUZZ_BUILD=DIR] scripts/fuzz.sh [SECONDS] [TARGET...]
# FUZZ_BUILD: an existing clang build configured with -DCASTELJAU_FUZZ=ON
# (CI's sanitizer build, which holds the tests too) instead of build-fuzz/.
#
# Each run starts from a copy of the seed corpus and the regressions
# (tests/fuzz/corpus/NAME, regressions/NAME: the checked-in seeds stay small),
# with the token dictionary for the SVG and path-data targets, and fails on
# the first finding, which libFuzzer writes to build-fuzz/findings/NAME/.
# Keep such an input as a regression, tests/fuzz/regressions/NAME/ under a
# name that says what broke: ctest replays it.
# The limits are the ones promised for hostile input: 1 GiB of memory and
# 2 s per input for the readers. The resident size libFuzzer checks counts
# ASan's shadow, redzones and quarantine too (the svg_render seeds and
# regressions peak at 880 MB, 460 MB without the quarantine), and the
# static renderer of the render targets keeps its buffers from input to
# input, as a long-running program's does. The render targets get 10 s:
# what parses is valid input, which may be pathological (a million dashes, a
# stroke 1e22 px wide) and is promised bounded time, not 2 s, and ASan slows
# it several times.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"; shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(path_data svg_read svg_render patch_read patch_render filter_graph text_layout image_decode)

# -g1: line tables only, enough for the sanitizers' file:line stack traces.
# FUZZ_OPT: the optimisation level (-O2; CI's short smoke builds at -O1,
# a third less compile time for a few seconds of fuzzing).
build=${FUZZ_BUILD:-build-fuzz}
if [[ -z ${FUZZ_BUILD:-} ]]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="${FUZZ_OPT:--O2} -g1 -DNDEBUG" \
      -DCASTELJAU_FUZZ=ON -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_}"

status=0
for name in "${targets[@]}"; do
    work="$build/work/$name" findings="$build/findings/$name"
    rm -rf "$work"; mkdir -p "$work" "$findings"
    cp tests/fuzz/corpus/"$name"/* "$work"/
    [[ -d tests/fuzz/regressions/$name ]] && cp tests/fuzz/regressions/"$name"/* "$work"/
    timeout=2
    [[ $name == *_render || $name == text_layout ]] && timeout=10
    dict=()
    case "$name" in
        svg_*) dict=(-dict=tests/fuzz/svg.dict) ;;
        path_data) dict=(-dict=tests/fuzz/path_data.dict) ;;
        text_layout) dict=(-dict=tests/fuzz/text_layout.dict) ;;
    esac
    echo "fuzz_$name: ${seconds}s"
    if ! UBSAN_OPTIONS=print_stacktrace=1 LSAN_OPTIONS=suppressions=tests/lsan.supp "$build/tests/fuzz/fuzz_$name" "$work" "${dict[@]}" \
            -max_total_time="$seconds" -rss_limit_mb=1024 -malloc_limit_mb=1024 -timeout="$timeout" \
            -artifact_prefix="$findings/" -print_final_stats=1 -seed="${FUZZ_SEED:-0}" >"$build/fuzz_$name.log" 2>&1; then
        echo "fuzz_$name: FINDING, see $build/fuzz_$name.log and $findings/"
        tail -n 40 "$build/fuzz_$name.log"
        status=1
    else
        grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$build/fuzz_$name.log" | tr '\n' ' '
        echo
    fi
done
exit "$status"

#!/usr/bin/env bash
# Start to file: the whole-process wall time of command A against command B
# (issue 25's second target: `casteljau render` against rsvg-convert), the
# two run in turn, A B A B ..., after one warm-up run of each, so that a
# comparison holds while the machine's speed drifts. Prints each command's
# median and the median of the pair-by-pair ratios A / B. The commands are
# split as the shell splits words; their output goes to /dev/null.
#
#   bash bench/cli/start_to_file.sh [-n PAIRS] 'COMMAND A' 'COMMAND B'
#
# e.g. (from the build directory's parent, the tiger at 1024 px):
#   bash bench/cli/start_to_file.sh -n 9 \
#     'build/cli/casteljau render tiger.svg --width 1024 -o /tmp/a.png' \
#     'rsvg-convert -w 1024 tiger.svg -o /tmp/b.png'
set -euo pipefail
pairs=9
if [[ ${1:-} == -n ]]; then pairs=$2; shift 2; fi
if [[ $# -ne 2 ]]; then
  echo "usage: $0 [-n PAIRS] 'COMMAND A' 'COMMAND B'" >&2
  exit 2
fi
read -r -a a <<< "$1"
read -r -a b <<< "$2"

# One run's wall time in microseconds, from bash's own clock (no process
# started around the command's).
run_us() {
  local t0=${EPOCHREALTIME/./} t1
  "$@" > /dev/null 2>&1 || { echo "failed: $*" >&2; exit 1; }
  t1=${EPOCHREALTIME/./}
  echo $((t1 - t0))
}

run_us "${a[@]}" > /dev/null
run_us "${b[@]}" > /dev/null
ta=() tb=()
for ((i = 0; i < pairs; i++)); do
  ta+=("$(run_us "${a[@]}")")
  tb+=("$(run_us "${b[@]}")")
done
python3 - "${ta[*]}" "${tb[*]}" <<'PY'
import statistics, sys
a = [int(v) / 1000 for v in sys.argv[1].split()]
b = [int(v) / 1000 for v in sys.argv[2].split()]
ratios = [x / y for x, y in zip(a, b)]
print(f"A: median {statistics.median(a):.1f} ms (min {min(a):.1f}, max {max(a):.1f})")
print(f"B: median {statistics.median(b):.1f} ms (min {min(b):.1f}, max {max(b):.1f})")
print(f"A / B: median {statistics.median(ratios):.3f} of {len(ratios)} pairs")
PY

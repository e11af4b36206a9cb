#!/usr/bin/env bash
# Black-box tests of `casteljau flatten`: exit statuses, messages and JSON.
# Usage: flatten_cli_test.sh PATH/TO/casteljau
set -u
bin="$1"
source "$(dirname "$0")/harness.sh"

cubic='M0 0 C 50 100 150 -100 200 0'
expect json_fields 0 '^\{"segments": [0-9]+, "max_error_px": [0-9.e-]+, "ns_per_curve": [0-9.e+-]+, "points": \[\[0, 0\]' -- flatten --path "$cubic" --json
expect uniform_segments 0 '"segments": 12,' -- flatten --path "$cubic" --flatten uniform --segments 12 --json
expect text_output 0 '^segments [0-9]+, max error' -- flatten --path "$cubic"
expect help 0 'tolerance' -- flatten --help
expect top_help 0 'flatten' -- --help
expect bad_path 2 'offset 10: expected a number' -- flatten --path 'M0 0 L 10 x'
expect no_moveto 2 'offset 0: path data must begin with a moveto' -- flatten --path 'L 10 10'
expect overflow 2 "number '1e999' is out of range" -- flatten --path 'M0 0 L 1e999 0'
expect nan_word 2 "expected a number, found 'N'" -- flatten --path 'M0 0 L NaN 0'
expect tolerance_zero 2 'tolerance 0: must be' -- flatten --path "$cubic" --tolerance 0
expect tolerance_negative 2 'tolerance -1: must be' -- flatten --path "$cubic" --tolerance -1
expect tolerance_nan 2 'tolerance' -- flatten --path "$cubic" --tolerance nan
expect segments_zero 2 'segments' -- flatten --path "$cubic" --flatten uniform --segments 0
expect bad_method 2 'flatten' -- flatten --path "$cubic" --flatten sideways
expect missing_path 2 'path' -- flatten
expect no_subcommand 2 'subcommand' --

# The adaptive polyline meets the tolerance and uses fewer segments than Wang's uniform N.
a=$("$bin" flatten --path "$cubic" --tolerance 0.1 --json)
u=$("$bin" flatten --path "$cubic" --tolerance 0.1 --flatten uniform --json)
sa=$(sed -E 's/^\{"segments": ([0-9]+).*/\1/' <<<"$a"); su=$(sed -E 's/^\{"segments": ([0-9]+).*/\1/' <<<"$u")
ea=$(sed -E 's/.*"max_error_px": ([0-9.e-]+).*/\1/' <<<"$a")
if (( sa < su )) && awk -v e="$ea" 'BEGIN { exit !(e <= 0.1 + 1e-9) }'; then pass
else fail "adaptive_vs_uniform: adaptive $sa (error $ea), uniform $su"; fi

finish "flatten CLI"

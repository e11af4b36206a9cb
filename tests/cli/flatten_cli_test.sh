#!/usr/bin/env bash
# Black-box tests of `casteljau flatten`: exit statuses, messages and JSON.
# Usage: flatten_cli_test.sh PATH/TO/casteljau
set -u
bin="$1"
fails=0; passes=0

check() { # name expected_status stderr_or_stdout_regex -- args...
    local name="$1" want="$2" pattern="$3"; shift 4
    local out status
    out="$("$bin" "$@" 2>&1)"; status=$?
    if [[ $status -ne $want ]]; then
        echo "FAIL $name: exit $status, want $want"; echo "$out" | head -5; fails=$((fails+1)); return
    fi
    if ! grep -Eq -- "$pattern" <<<"$out"; then
        echo "FAIL $name: output does not match /$pattern/"; echo "$out" | head -5; fails=$((fails+1)); return
    fi
    passes=$((passes+1))
}

cubic='M0 0 C 50 100 150 -100 200 0'
check json_fields 0 '^\{"segments": [0-9]+, "max_error_px": [0-9.e-]+, "ns_per_curve": [0-9.e+-]+, "points": \[\[0, 0\]' -- flatten --path "$cubic" --json
check uniform_segments 0 '"segments": 12,' -- flatten --path "$cubic" --flatten uniform --segments 12 --json
check text_output 0 '^segments [0-9]+, max error' -- flatten --path "$cubic"
check help 0 'tolerance' -- flatten --help
check top_help 0 'flatten' -- --help
check bad_path 2 'offset 10: expected a number' -- flatten --path 'M0 0 L 10 x'
check no_moveto 2 'offset 0: path data must begin with a moveto' -- flatten --path 'L 10 10'
check overflow 2 "number '1e999' is out of range" -- flatten --path 'M0 0 L 1e999 0'
check nan_word 2 "expected a number, found 'N'" -- flatten --path 'M0 0 L NaN 0'
check tolerance_zero 2 'tolerance 0: must be' -- flatten --path "$cubic" --tolerance 0
check tolerance_negative 2 'tolerance -1: must be' -- flatten --path "$cubic" --tolerance -1
check tolerance_nan 2 'tolerance' -- flatten --path "$cubic" --tolerance nan
check segments_zero 2 'segments' -- flatten --path "$cubic" --flatten uniform --segments 0
check bad_method 2 'flatten' -- flatten --path "$cubic" --flatten sideways
check missing_path 2 'path' -- flatten
check no_subcommand 2 'subcommand' --

# The adaptive polyline meets the tolerance and uses fewer segments than Wang's uniform N.
a=$("$bin" flatten --path "$cubic" --tolerance 0.1 --json)
u=$("$bin" flatten --path "$cubic" --tolerance 0.1 --flatten uniform --json)
sa=$(sed -E 's/^\{"segments": ([0-9]+).*/\1/' <<<"$a"); su=$(sed -E 's/^\{"segments": ([0-9]+).*/\1/' <<<"$u")
ea=$(sed -E 's/.*"max_error_px": ([0-9.e-]+).*/\1/' <<<"$a")
if (( sa < su )) && awk -v e="$ea" 'BEGIN { exit !(e <= 0.1 + 1e-9) }'; then passes=$((passes+1))
else echo "FAIL adaptive_vs_uniform: adaptive $sa (error $ea), uniform $su"; fails=$((fails+1)); fi

echo "$passes passed, $fails failed"
[[ $fails -eq 0 ]]

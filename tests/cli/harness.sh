# The black-box CLI tests' shared harness; sourced with $bin set.
#   expect NAME STATUS REGEX [--] ARGS...   runs $bin ARGS, checks status and output
#   pass / fail MESSAGE                     count a check by hand
#   finish NAME                             prints the tally; the exit status tells
fails=0; passes=0
pass() { passes=$((passes+1)); }
fail() { echo "FAIL $*"; fails=$((fails+1)); }

expect() {
    local name="$1" want="$2" pattern="$3"; shift 3
    [[ "${1-}" == -- ]] && shift
    local out status
    out="$("$bin" "$@" 2>&1)"; status=$?
    if [[ $status -ne $want ]]; then fail "$name: exit $status, want $want: $(head -3 <<<"$out")"; return; fi
    if ! grep -Eq -- "$pattern" <<<"$out"; then fail "$name: output does not match /$pattern/: $(head -3 <<<"$out")"; return; fi
    pass
}

finish() {
    echo "$1: $passes passed, $fails failed"
    [[ $fails -eq 0 ]]
}

#!/usr/bin/env bash
# Files per second of `casteljau render` on many files against shell loops of
# rsvg-convert, on two seeded corpora:
#   icons:  1,000 icon SVGs (bench/cli/make_icons.py, seed 1) rendered 64 px wide;
#   tigers: 100 copies of the Ghostscript tiger under different names, 1024 px wide.
# Each corpus is rendered, in rounds that alternate the ways (so that a
# neighbour's build slows all of them alike), by:
#   args      casteljau render ALL.svg -o OUT/ --width W   (one process, every core)
#   args-t1   the same with --threads 1 (one file at a time: what every core adds)
#   list      casteljau render --from-list LIST -o OUT/ --width W
#   cli-loop  for f in ...; do casteljau render "$f" -o OUT/NAME.png --width W; done
#             (on the first --loop-files files only: a process start costs ~0.2 s)
#   rsvg-loop for f in ...; do rsvg-convert -w W "$f" -o OUT/NAME.png; done
#   rsvg-xargs  the same rsvg-convert calls, `xargs -P $(nproc)`: a loop on every core
# The medians over the rounds are printed: files per second (wall time), CPU
# time a file (user + system of every process: steadier than wall time on a
# shared machine), and the speed-up over rsvg-loop (files per second over
# rsvg-loop's). Every output folder is checked to hold one PNG per input.
#
#   bash bench/cli/batch_bench.sh [--cli build/cli/casteljau] [--tiger FILE] [--rounds 3]
#        [--only icons|tigers] [--loop-files 100] [--work DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cli="$here/../../build/cli/casteljau"
tiger=/work/bench-data/tiger.svg
rounds=3
only=""
loop_files=100
work=""
while [[ $# -gt 0 ]]; do
    case "$1" in
    --cli) cli="$2"; shift 2 ;;
    --tiger) tiger="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --only) only="$2"; shift 2 ;;
    --loop-files) loop_files="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    *) echo "unknown argument $1" >&2; exit 2 ;;
    esac
done
cli=$(realpath "$cli")
if [[ -z $work ]]; then work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; fi
mkdir -p "$work"
cd "$work"

# The corpora, made once per work folder.
if [[ ! -d icons ]]; then python3 "$here/make_icons.py" icons --count 1000 --seed 1; fi
if [[ ! -d tigers ]]; then
    mkdir tigers
    for i in $(seq -w 0 99); do cp "$tiger" "tigers/tiger$i.svg"; done
fi

# render WAY WIDTH FILE...: renders the files into out/ one way.
render() {
    local way="$1" width="$2" f
    shift 2
    case "$way" in
    args) "$cli" render "$@" -o out/ --width "$width" ;;
    args-t1) "$cli" render "$@" -o out/ --width "$width" --threads 1 ;;
    list) printf '%s\n' "$@" >list.txt && "$cli" render --from-list list.txt -o out/ --width "$width" ;;
    cli-loop)
        for f in "$@"; do "$cli" render "$f" -o "out/$(basename "$f" .svg).png" --width "$width"; done ;;
    rsvg-loop)
        for f in "$@"; do rsvg-convert -w "$width" "$f" -o "out/$(basename "$f" .svg).png"; done ;;
    rsvg-xargs)
        printf '%s\n' "$@" | xargs -P "$(nproc)" -I{} sh -c \
            'rsvg-convert -w "$1" "$2" -o "out/$(basename "$2" .svg).png"' _ "$width" {} ;;
    esac
}

# run WAY WIDTH FILE...: prints the wall seconds and the CPU seconds (user +
# system, every process and thread) of rendering the files one way.
run() {
    local way="$1" got
    rm -rf out && mkdir out
    local TIMEFORMAT='%R %U %S'
    { time render "$@" 2>err.log; } 2>time.txt
    got=$(ls out | grep -c '\.png$' || true)
    if [[ $got -ne $(($# - 2)) ]]; then
        echo "$way: $got PNGs for $(($# - 2)) inputs: $(head -3 err.log)" >&2
        exit 1
    fi
    awk '{print $1, $2 + $3}' time.txt
}

ways=(args args-t1 list cli-loop rsvg-loop rsvg-xargs)
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'; }

echo "| corpus | way | files | files/s | wall s | CPU ms a file | speed-up over rsvg-loop |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for spec in icons:64 tigers:1024; do
    corpus=${spec%%:*}; width=${spec##*:}
    [[ -n $only && $only != "$corpus" ]] && continue
    files=("$corpus"/*.svg)
    declare -A walls=() cpus=() counts=()
    for ((r = 0; r < rounds; r++)); do
        for way in "${ways[@]}"; do
            set -- "${files[@]}"
            [[ $way == cli-loop ]] && set -- "${files[@]:0:loop_files}"
            counts[$way]=$#
            read -r wall cpu < <(run "$way" "$width" "$@")
            walls[$way]+="$wall "
            cpus[$way]+="$cpu "
        done
    done
    med() { tr ' ' '\n' <<<"$1" | grep . | median; }
    rate() { echo "${counts[$1]} / $(med "${walls[$1]}")" | bc -l; }
    ref=$(rate rsvg-loop)
    for way in "${ways[@]}"; do
        printf '| %s, %d px | %s | %d | %.1f | %.2f | %.1f | %.2f |\n' "$corpus" "$width" "$way" \
            "${counts[$way]}" "$(rate "$way")" "$(med "${walls[$way]}")" \
            "$(echo "1000 * $(med "${cpus[$way]}") / ${counts[$way]}" | bc -l)" \
            "$(echo "$(rate "$way") / $ref" | bc -l)"
    done
    unset walls cpus counts
done

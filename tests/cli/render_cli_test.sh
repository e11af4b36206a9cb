#!/usr/bin/env bash
# Black-box tests of `casteljau render`: statuses, messages, outputs and the
# promise that a failed render never writes or damages an output file.
# Usage: render_cli_test.sh PATH/TO/casteljau DATA_DIR
set -u
bin="$1"; data="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/harness.sh"

# Formats by extension; sizes from --width/--height/--scale.
for ext in png tif exr jpg; do
    expect "format_$ext" 0 '' render "$data/ok.svg" -o "$tmp/ok.$ext" --scale 2
    [[ -s "$tmp/ok.$ext" ]] && pass || fail "format_$ext: no file"
done
[[ "$(oiiotool --info "$tmp/ok.png" 2>/dev/null)" == *"80 x   60"* ]] && pass || fail "scale: $(oiiotool --info "$tmp/ok.png")"
expect width 0 '' render "$data/ok.svg" -o "$tmp/w.png" --width 400
[[ "$(oiiotool --info "$tmp/w.png" 2>/dev/null)" == *"400 x  300"* ]] && pass || fail "width: $(oiiotool --info "$tmp/w.png")"
expect exclusive 2 'excludes' render "$data/ok.svg" -o "$tmp/x.png" --width 10 --height 10

# --stats: the fields of the contract, medians over --repeat. The stage
# times are measured (a nonzero digit): the renderer reads its stage clocks
# only when asked (RenderOptions::time_stages).
expect stats 0 '"segments_in": [0-9]+, "segments_out": [0-9]+, "max_error_px": [0-9.e-]+, "parse_ms": [0-9.e-]+, "flatten_ms": [0-9.]*[1-9][0-9.e-]*, "raster_ms": [0-9.]*[1-9][0-9.e-]*, "encode_ms": [0-9.e-]+, "frame_ms": [0-9.e-]+, "total_ms": [0-9.e-]+, "width": 40, "height": 30, "threads": [0-9]+, "pixels": "u8", "repeat": 5' \
    render "$data/ok.svg" -o "$tmp/s.png" --stats - --repeat 5
# Threads: the same image bytes and the same counts as one thread.
"$bin" render "$data/../../../examples/svg/opacity.svg" -o "$tmp/t1.png" --threads 1 --stats "$tmp/t1.json" 2>/dev/null
"$bin" render "$data/../../../examples/svg/opacity.svg" -o "$tmp/t3.png" --threads 3 --stats "$tmp/t3.json" 2>/dev/null
cmp -s "$tmp/t1.png" "$tmp/t3.png" && pass || fail "threads: images differ"
[[ "$(grep -o '"segments_out": [0-9]*' "$tmp/t1.json")" == "$(grep -o '"segments_out": [0-9]*' "$tmp/t3.json")" ]] && pass || fail "threads: counts differ"
# 8-bit pixels: the same bytes on any number of threads; an unknown format is refused.
"$bin" render "$data/../../../examples/svg/opacity.svg" -o "$tmp/u1.png" --pixels u8 --threads 1 2>/dev/null
"$bin" render "$data/../../../examples/svg/opacity.svg" -o "$tmp/u3.png" --pixels u8 --threads 3 2>/dev/null
[[ -s "$tmp/u1.png" ]] && cmp -s "$tmp/u1.png" "$tmp/u3.png" && pass || fail "u8 threads: images differ"
expect pixels_u8_stats 0 '"pixels": "u8"' render "$data/ok.svg" -o "$tmp/u.png" --pixels u8 --stats -
# Auto (the default): the 8-bit canvas for 8-bit files, float for EXR and TIFF.
expect pixels_exr_default 0 '"pixels": "float"' render "$data/ok.svg" -o "$tmp/u.exr" --stats -
expect pixels_float_asked 0 '"pixels": "float"' render "$data/ok.svg" -o "$tmp/f.png" --pixels float --stats -
expect pixels_bad 2 'pixels' render "$data/ok.svg" -o "$tmp/x.png" --pixels u16
expect stats_file 0 '' render "$data/ok.svg" -o "$tmp/s.png" --stats "$tmp/stats.json"
grep -q '"frame_ms"' "$tmp/stats.json" && pass || fail "stats file"
expect aliased 0 '' render "$data/ok.svg" -o "$tmp/a.png" --antialias off --background '#fff'
expect uniform 0 '' render "$data/ok.svg" -o "$tmp/u.png" --flatten uniform --segments 3

# Several inputs into a folder; a file with bad path data is drawn up to the
# error with a warning (SVG 2, 9.5.4). --partial-path-data, once the way to
# ask for that, is still accepted.
expect folder 0 'warning: .*bad_path.svg:2' render "$data/ok.svg" "$data/bad_path.svg" -o "$tmp/outdir/"
[[ -s "$tmp/outdir/ok.png" && -s "$tmp/outdir/bad_path.png" ]] && pass || fail "folder outputs: $(ls "$tmp/outdir")"
# One input that cannot be drawn among several: status 2, the others still
# rendered, nothing for the bad one. --strict makes bad path data such an input.
expect folder_one_bad 2 'bad_path.svg:2' render "$data/ok.svg" "$data/bad_path.svg" -o "$tmp/outdir2/" --strict
[[ -s "$tmp/outdir2/ok.png" && ! -e "$tmp/outdir2/bad_path.png" ]] && pass || fail "folder_one_bad: $(ls "$tmp/outdir2")"

# Bad input, pathological input and unwritable outputs: tests/bad_input.
expect bad_path 0 'warning: .*bad_path.svg:2: <path>: attribute d: path data: at offset 21.*drawn up to there' \
    render "$data/bad_path.svg" -o "$tmp/bp.png"
expect bad_path_strict 2 'error: .*bad_path.svg:2: <path>: attribute d: path data: at offset 21' \
    render "$data/bad_path.svg" -o "$tmp/bp2.png" --strict
expect bad_path_partial 0 'drawn up to there' render "$data/bad_path.svg" -o "$tmp/bp.png" --partial-path-data
expect missing_file 2 'does not exist|not exist' render "$tmp/nope.svg" -o "$tmp/n.png"
expect bad_background 2 'not a color' render "$data/ok.svg" -o "$tmp/b.png" --background nocolor
expect bad_tolerance 2 'tolerance' render "$data/ok.svg" -o "$tmp/b.png" --tolerance 0
expect too_big 2 'outside the limits' render "$data/ok.svg" -o "$tmp/b.png" --scale 1000
ls "$tmp"/b.png >/dev/null 2>&1 && fail "a failed render wrote b.png" || pass
ls "$tmp" | grep -q '\.tmp-' && fail "temporary files left behind: $(ls "$tmp")" || pass

# compare: images, heat map and a report with the table; bad input as for render.
expect compare 0 '\| adaptive \| [0-9]+ \| 0\.[0-9]+' compare "$data/ok.svg" -o "$tmp/cmp" --segments 6
for f in adaptive.png uniform_equal_error.png uniform_n.png heat_map.png report.md; do
    [[ -s "$tmp/cmp/$f" ]] && pass || fail "compare: no $f"
done
grep -q 'uniform, equal error' "$tmp/cmp/report.md" && pass || fail "compare: report.md lacks the equal-error row"
expect compare_bad 2 'zero_size.svg:1' compare "$data/../../bad_input/zero_size.svg" -o "$tmp/cmp2"

finish "render CLI"

#!/usr/bin/env bash
# Black-box tests of `casteljau patch`: the bundled examples render with
# their measured error within the tolerance, stats carry the contract's
# fields, meshes are written, and bad input gets status 2 with file:line and
# leaves an existing output untouched.
# Usage: patch_cli_test.sh PATH/TO/casteljau EXAMPLES_DIR
set -u
bin="$1"; examples="$2"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
source "$(dirname "$0")/harness.sh"
# The max_error_px of a stats line is at most the tolerance.
error_within() { # name stats_json tolerance
    local e; e=$(grep -o '"max_error_px": [0-9.e-]*' <<<"$2" | cut -d' ' -f2)
    awk -v e="$e" -v t="$3" 'BEGIN { exit !(e != "" && e <= t) }' && pass || fail "$1: max_error_px $e > $3"
}

fields='"patches": [0-9]+, "tessellate": "(adaptive|uniform)", "steps": [0-9]+, "pieces": [0-9]+, "budget_reached": false, "tolerance_px": [0-9.e-]+, "triangles": [0-9]+, "vertices": [0-9]+, "max_error_px": [0-9.e-]+, "parse_ms": [0-9.e-]+, "tessellate_ms": [0-9.e-]+, "raster_ms": [0-9.e-]+, "encode_ms": [0-9.e-]+, "total_ms": [0-9.e-]+, "width": 320, "height": 240'
for f in arch.map pipe.map wave.bpt terrain.json; do
    for tol in 0.25 0.1; do
        expect "$f@$tol" 0 "$fields" patch "$examples/patch/$f" -o "$tmp/$f.png" --width 320 --height 240 --tolerance $tol --stats -
        error_within "$f@$tol" "$("$bin" patch "$examples/patch/$f" -o "$tmp/$f.png" --width 320 --height 240 --tolerance $tol --stats - 2>/dev/null)" $tol
    done
    # Uniform without --steps: the fewest steps that meet the tolerance, measured.
    error_within "$f uniform" "$("$bin" patch "$examples/patch/$f" -o "$tmp/u.png" --width 320 --height 240 --tessellate uniform --stats - 2>/dev/null)" 0.25
done
expect steps 0 '"tessellate": "uniform", "steps": 3, .*"triangles": 72,' patch "$examples/patch/wave.bpt" -o "$tmp/s.png" --width 320 --height 240 --tessellate uniform --steps 3 --stats -
expect view_wire_texture 0 '' patch "$examples/patch/pipe.map" -o "$tmp/v.png" --view 120,-30 --wireframe --texture none
expect image_texture 0 '' patch "$examples/patch/arch.map" -o "$tmp/t.png" --texture "$tmp/v.png" --width 64 --height 48
[[ "$(oiiotool --info "$tmp/t.png" 2>/dev/null)" == *"64 x   48"* ]] && pass || fail "size: $(oiiotool --info "$tmp/t.png")"

# Meshes: OBJ counts match the stats; PLY has a header.
out=$("$bin" patch "$examples/patch/wave.bpt" -o "$tmp/m.png" --mesh "$tmp/m.obj" --stats - 2>&1)
[[ "$(grep -c '^f ' "$tmp/m.obj")" == "$(grep -o '"triangles": [0-9]*' <<<"$out" | cut -d' ' -f2)" ]] && pass || fail "obj faces"
expect ply 0 '' patch "$examples/patch/wave.bpt" -o "$tmp/m.png" --mesh "$tmp/m.ply"
head -c 3 "$tmp/m.ply" | grep -q ply && pass || fail "ply header"

# Bad input: status 2, file:line, and an existing output left untouched.
printf 'keep' > "$tmp/keep.png"
printf '1\n3 3\n0 0 0\n1 0 x\n' > "$tmp/bad.bpt"
expect bad_number 2 'bad.bpt:4: z: .x. is not a finite number' patch "$tmp/bad.bpt" -o "$tmp/keep.png"
printf '{\n"patches": [{"type": "bezier", "degree": [3, 3], "points": [[0,0,0]]}]}\n' > "$tmp/bad.json"
expect bad_count 2 'bad.json:2: "points" has 1 points, expected 4 x 4 = 16' patch "$tmp/bad.json" -o "$tmp/keep.png"
printf 'patchDef2 { t ( 4 3 0 0 0 ) }' > "$tmp/even.map"
expect even_grid 2 'even.map:1: patch grid 4 x 3: both sizes must be odd' patch "$tmp/even.map" -o "$tmp/keep.png"
printf '2\n1 1\n0 0 0\n1 0 0\n0 1 0\n1 1 1\n' > "$tmp/short.bpt"
expect truncated 2 'short.bpt:7: unexpected end of file' patch "$tmp/short.bpt" -o "$tmp/keep.png"
[[ "$(cat "$tmp/keep.png")" == keep ]] && pass || fail "existing output was touched"
printf 'solid x' > "$tmp/model.stl"
expect unknown_format 2 'unknown patch format' patch "$tmp/model.stl" -o "$tmp/x.png"
expect missing 2 'does not exist|not exist' patch "$tmp/none.bpt" -o "$tmp/x.png"
expect tolerance 2 'in \[0.01, 1\]' patch "$examples/patch/wave.bpt" -o "$tmp/x.png" --tolerance 2
expect bad_texture 2 'texture' patch "$examples/patch/wave.bpt" -o "$tmp/x.png" --texture "$tmp/none.png"
expect bad_view 2 'view' patch "$examples/patch/wave.bpt" -o "$tmp/x.png" --view 10
expect unwritable 1 'cannot|folder' patch "$examples/patch/wave.bpt" -o "$tmp/nodir/x.png"

finish "patch CLI"

#!/usr/bin/env bash
# Agreement with an independent renderer: every SVG given is rendered by
# casteljau and by rsvg-convert (librsvg, which uses Cairo) over white at
# tolerance 0.1 px (Cairo's default), and compared with oiiotool.
# Required: mean absolute difference < 1/255. Documented per-pixel bound:
# 0.2, except files named *stars* (self-intersecting outlines), 0.45: where
# several edges of one outline cross inside a pixel, exact-area coverage folds
# the accumulated winding (the FreeType rule) while Cairo samples, and the two
# legitimately differ there.
# Usage: rsvg_agreement.sh PATH/TO/casteljau FILE.svg...
set -u
bin="$1"; shift
command -v rsvg-convert >/dev/null || { echo "rsvg-convert is missing (apt-get install librsvg2-bin)"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fails=0; passes=0
for svg in "$@"; do
    n=$(basename "$svg" .svg)
    "$bin" render "$svg" -o "$tmp/$n.ours.png" --background white --tolerance 0.1 2>/dev/null
    rsvg-convert -b white "$svg" -o "$tmp/$n.rsvg.png"
    report=$(oiiotool "$tmp/$n.ours.png" --ch R,G,B "$tmp/$n.rsvg.png" --ch R,G,B --diff 2>&1)
    mean=$(sed -nE 's/.*Mean error = ([0-9.e+-]+).*/\1/p' <<<"$report")
    max=$(sed -nE 's/.*Max error  = ([0-9.e+-]+).*/\1/p' <<<"$report")
    bound=0.2; [[ $n == *stars* ]] && bound=0.45
    if awk -v m="${mean:-1}" -v x="${max:-1}" -v b="$bound" 'BEGIN { exit !(m < 1/255 && x <= b) }'; then
        passes=$((passes+1)); echo "ok   $n: mean $mean, max $max (bound $bound)"
    else
        fails=$((fails+1)); echo "FAIL $n: mean $mean, max $max (bound $bound)"
    fi
done
echo "$passes passed, $fails failed"
[[ $fails -eq 0 ]]

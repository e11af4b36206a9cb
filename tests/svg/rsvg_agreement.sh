#!/usr/bin/env bash
# Agreement with an independent renderer: every SVG given is rendered by
# casteljau and by rsvg-convert (librsvg, which uses Cairo) at tolerance 0.1 px
# (Cairo's default), twice:
# * Over white, compared with oiiotool.
#   Required: mean absolute difference < 1/255. Documented per-pixel bound:
#   0.2, except files named *stars* (self-intersecting outlines), 0.45: where
#   several edges of one outline cross inside a pixel, exact-area coverage folds
#   the accumulated winding (the FreeType rule) while Cairo samples, and the two
#   legitimately differ there. Files named *text*: 1, the mean alone
#   decides: Pango rounds glyph positions and librsvg draws hinted outlines,
#   so glyph edges stand a fraction of a pixel apart all along the text.
#   Files named *cones*: 1 as well. A radial gradient's cone (SVG 2) ends
#   in a hard edge, antialiased by neither renderer: each paints a pixel or
#   not by its centre, and pixman's fixed-point parameters put a few pixel
#   centres along the edge on the other side of it.
# * Over transparency (no background for either), the PNGs decoded here as
#   stored: both are straight (un-premultiplied) 8-bit RGBA, and a value
#   divided by alpha once too often, or not at all, shows in the color.
#   Alpha: mean difference < 1/255, per-pixel bound as over white (coverage
#   is what alpha holds). Straight color, where both alphas are > 0: the
#   mean difference weighted by the smaller alpha < 2/255 per channel
#   (rsvg-convert derives it from 8-bit premultiplied values, about a step
#   off ours even where alpha is high, and any value at all at alpha 1/255:
#   a blur's faint tails would outweigh everything else unweighted), and the
#   difference times the smaller alpha (what shows once composited) within
#   the per-pixel bound as over white.
# Most examples paint an opaque background, so a generated SVG of translucent
# shapes over transparency (issue 21's rectangle among them) is always added.
# Usage: rsvg_agreement.sh PATH/TO/casteljau FILE.svg...
set -u
bin="$1"; shift
# Both renderers draw text with the tests' own fonts, whatever the machine has.
export FONTCONFIG_FILE="${FONTCONFIG_FILE:-$(cd "$(dirname "$0")/../text" && pwd)/fonts.conf}"
command -v rsvg-convert >/dev/null || { echo "rsvg-convert is missing (apt-get install librsvg2-bin)"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/translucent.svg" <<'EOF'
<svg xmlns="http://www.w3.org/2000/svg" width="120" height="80">
  <rect x="4" y="4" width="60" height="40" fill="#776699" fill-opacity="0.51"/>
  <circle cx="60" cy="40" r="30" fill="#20c040" fill-opacity="0.25"/>
  <circle cx="85" cy="45" r="25" fill="#ff0000" fill-opacity="0.02"/>
  <path d="M4 76 L116 6" stroke="#e0d010" stroke-width="5" stroke-opacity="0.98"/>
  <g opacity="0.6"><rect x="70" y="50" width="45" height="25" rx="6" fill="#336699"/></g>
</svg>
EOF
# Prints the transparent-background comparison of two 8-bit RGB(A) PNGs; exits 1 if out of bounds.
compare_transparent() {
    python3 - "$@" <<'EOF'
import struct, sys, zlib

def read_png(path):
    """The samples of an 8-bit, non-interlaced RGB or RGBA PNG, as RGBA bytes."""
    data = open(path, 'rb').read()
    pos, idat = 8, []
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        if kind == b'IHDR':
            w, h, depth, ctype, _, _, interlace = struct.unpack('>IIBBBBB', data[pos + 8:pos + 21])
        elif kind == b'IDAT':
            idat.append(data[pos + 8:pos + 8 + n])
        pos += 12 + n
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f'{path}: not 8-bit RGB(A) non-interlaced')
    bpp = 4 if ctype == 6 else 3
    raw, stride = zlib.decompress(b''.join(idat)), w * bpp
    px, prev = bytearray(), bytearray(stride)
    for y in range(h):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(bpp, stride): line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:
            line = bytearray((x + u) & 255 for x, u in zip(line, prev))
        elif kind in (3, 4):
            for i in range(stride):
                a, b = (line[i - bpp] if i >= bpp else 0), prev[i]
                if kind == 3:
                    line[i] = (line[i] + (a + b) // 2) & 255
                    continue
                c = prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        px += line
        prev = line
    if bpp == 3:
        rgba = bytearray(b'\xff' * (4 * w * h))
        for c in range(3): rgba[c::4] = px[c::3]
        px = rgba
    return w, h, px

(w, h, ours), (w2, h2, rsvg) = read_png(sys.argv[1]), read_png(sys.argv[2])
bound = float(sys.argv[3])
if (w, h) != (w2, h2):
    sys.exit(f'sizes differ: {w}x{h} and {w2}x{h2}')
alpha_sum = alpha_max = weights = 0
color_sum, weighted_max, counted = [0, 0, 0], [0.0, 0.0, 0.0], 0
for i in range(0, 4 * w * h, 4):
    ao, ar = ours[i + 3], rsvg[i + 3]
    alpha_sum += abs(ao - ar)
    alpha_max = max(alpha_max, abs(ao - ar))
    if ao and ar:
        counted += 1
        weights += min(ao, ar)
        for c in range(3):
            d = abs(ours[i + c] - rsvg[i + c])
            color_sum[c] += d * min(ao, ar)
            weighted_max[c] = max(weighted_max[c], d * min(ao, ar) / 255)
alpha_mean = alpha_sum / (w * h) / 255
color_mean = [s / max(weights, 1) / 255 for s in color_sum]
weighted_max = [m / 255 for m in weighted_max]
ok = (alpha_mean < 1 / 255 and alpha_max / 255 <= bound and all(m < 2 / 255 for m in color_mean)
      and all(m <= bound for m in weighted_max))
print('alpha mean %.5f, max %.4f; straight RGB over %d px: alpha-weighted mean %s, max x alpha %s' % (
    alpha_mean, alpha_max / 255, counted, ' '.join('%.5f' % m for m in color_mean),
    ' '.join('%.4f' % m for m in weighted_max)))
sys.exit(0 if ok else 1)
EOF
}
fails=0; passes=0
for svg in "$@" "$tmp/translucent.svg"; do
    n=$(basename "$svg" .svg)
    bound=0.2; [[ $n == *stars* ]] && bound=0.45; [[ $n == *text* || $n == *cones* ]] && bound=1
    "$bin" render "$svg" -o "$tmp/$n.ours.png" --background white --tolerance 0.1 2>/dev/null
    rsvg-convert -b white "$svg" -o "$tmp/$n.rsvg.png"
    report=$(oiiotool "$tmp/$n.ours.png" --ch R,G,B "$tmp/$n.rsvg.png" --ch R,G,B --diff 2>&1)
    mean=$(sed -nE 's/.*Mean error = ([0-9.e+-]+).*/\1/p' <<<"$report")
    max=$(sed -nE 's/.*Max error  = ([0-9.e+-]+).*/\1/p' <<<"$report")
    # Identical images: oiiotool prints only PASS, no error figures.
    if [[ -z $mean && $report == *PASS* && $report != *error* ]]; then mean=0 max=0; fi
    if awk -v m="${mean:-1}" -v x="${max:-1}" -v b="$bound" 'BEGIN { exit !(m < 1/255 && x <= b) }'; then
        passes=$((passes+1)); echo "ok   $n over white: mean $mean, max $max (bound $bound)"
    else
        fails=$((fails+1)); echo "FAIL $n over white: mean $mean, max $max (bound $bound)"
    fi
    "$bin" render "$svg" -o "$tmp/$n.ours-clear.png" --tolerance 0.1 2>/dev/null
    rsvg-convert "$svg" -o "$tmp/$n.rsvg-clear.png"
    if report=$(compare_transparent "$tmp/$n.ours-clear.png" "$tmp/$n.rsvg-clear.png" "$bound" 2>&1); then
        passes=$((passes+1)); echo "ok   $n over transparency: $report (bound $bound)"
    else
        fails=$((fails+1)); echo "FAIL $n over transparency: $report (bound $bound)"
    fi
done
echo "$passes passed, $fails failed"
[[ $fails -eq 0 ]]

#!/usr/bin/env python3
"""Hostile and pathological input through the casteljau CLI (issues 7 and 21).

Four promises, one case each:
* Input that cannot be drawn at all (the files in this folder, and large ones
  generated here: not well-formed, no <svg> root, an unusable size, over a
  limit): exit status 2, a message that names the file and line and what is
  wrong, nothing written and an existing output untouched; within 2 s of CPU
  and 1 GiB (or the wider bounds of BAD_BOUNDS).
* Input in error that the SVG and CSS specs say how to recover from (an
  invalid value, bad path data, a gradient href cycle): drawn (status 0) with
  one located warning, as browsers draw it; with --strict, status 2 with that
  message as the error and the output untouched.
* Pathological but valid input: rendered (status 0) within bounded CPU time
  and memory (the bounds below, about 5x what was measured on a 2-core machine).
* Output that cannot be written (a folder, a path under a file, a full disk,
  simulated with RLIMIT_FSIZE): status 1, the existing file intact, no
  temporary file left behind.

Time is the child's CPU time (user + system, from os.wait4), which other load
on the machine does not inflate, so the bounds hold on a busy machine; a
wall-clock bound stays only as a hang guard (HANG_S). Memory is the child's
peak resident size. Under the sanitizers (MODE 'sanitized') times are allowed
10x and memory is not checked: ASan's shadow memory is counted in the
resident size.

Usage: bad_input_test.py PATH/TO/casteljau THIS_FOLDER plain|sanitized
"""
import base64
import os
import random
import re
import resource
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import zlib

# DATA without symlinks: an SVG image's warnings name its file by its
# canonical path, and the checks below expect the path the CLI was given.
BIN, DATA, MODE = os.path.abspath(sys.argv[1]), os.path.realpath(sys.argv[2]), sys.argv[3]
SLOW = 10.0 if MODE == "sanitized" else 1.0
GIB = 1 << 30
HANG_S = 120  # a hang guard, far beyond every bound below
# Text is set with the fonts the tests draw with (tests/text/fonts.conf),
# whatever the machine has: the same fonts, the same fallbacks, the same cost.
ENV = dict(os.environ, FONTCONFIG_FILE=os.path.join(DATA, "..", "text", "fonts.conf"))
DEJAVU_SANS = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
failures = []


def run(args, cwd, preexec=None, env=None):
    """Runs casteljau ARGS; returns (status, stderr, CPU seconds, max RSS bytes)."""
    with tempfile.TemporaryFile() as err:
        p = subprocess.Popen([BIN] + args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=err,
                             preexec_fn=preexec, env=env or ENV)
        killer = threading.Timer(HANG_S, p.kill)
        killer.start()
        _, status, usage = os.wait4(p.pid, 0)
        killer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        cpu = usage.ru_utime + usage.ru_stime
        return p.returncode, err.read().decode(errors="replace"), cpu, usage.ru_maxrss * 1024


def check(name, ok, detail):
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else ": " + detail))
    if not ok:
        failures.append(name)


def check_bounds(name, seconds, rss, max_s, max_bytes=GIB):
    print("     %s: %.2f s CPU, %.0f MiB" % (name, seconds, rss / 2**20))
    check(name + " time", seconds <= max_s * SLOW, "%.2f s CPU, bound %.1f s" % (seconds, max_s * SLOW))
    if MODE == "plain":
        check(name + " memory", rss <= max_bytes, "%.0f MiB, bound %.0f MiB" % (rss / 2**20, max_bytes / 2**20))


def precious(path):
    with open(path, "w") as f:
        f.write("precious\n")


def intact(path):
    with open(path, "rb") as f:  # an image written over it is not text
        return f.read() == b"precious\n"


def leftovers(folder):
    return [f for f in os.listdir(folder) if ".tmp-" in f]


# --- bad input ---------------------------------------------------------------

# file -> the message after "FILE:LINE: " (a regular expression)
BAD = {
    "truncated_xml.svg": r"1: malformed XML",
    "size_1e308.svg": r"1: <svg>: the document size 1e\+308 px exceeds the limit",
    "zero_size.svg": r"1: <svg>: the document size 0 must be positive",
    "huge_size.svg": r"1: <svg>: the document size 1e\+06 px exceeds the limit",
    "entity_bomb.svg": r"14: entity references add more than 16777216 bytes \(the limit\)",
    "external_entity.svg": r"5: entity 'ext' is external \(SYSTEM or PUBLIC\), and external entities are not read",
    "not_svg.svg": r"1: the root element is <html>, not <svg>",
    "nested_groups_10k.svg": r"258: <g>: elements nested deeper than 256",
    "use_bomb.svg": r"1: <svg>: more than 1000000 elements once <use> is expanded",
    "marker_bomb.svg": r"3: <path>: more than 1000000 elements once its markers are drawn",
    "path_attribute_50MB.svg": r"2: <path>: attribute d is 52428800 bytes, over the limit",
    "bpt_wrong_count.bpt": r"7: unexpected end of file",
    "bpt_nan.bpt": r"5: y: 'nan' is not a finite number",
    "bpt_truncated.bpt": r"5: unexpected end of file",
    "bpt_degree_too_high.bpt": r"2: degree m: 4 is not in 1..3",
    "map_even_grid.map": r"7: patch grid 4 x 3: both sizes must be odd",
    "map_wrong_count.map": r"11: expected '\(', found '\)'",
    "json_wrong_count.json": r"3: \"points\" has 3 points, expected 2 x 2 = 4",
    "json_inf.json": r"4: '1e999' is not a finite JSON number",
    "json_deep.json": r"1: nested deeper than 64 levels",
    "mask_use_bomb.svg": r"1: <svg>: more than 1000000 elements once <use> is expanded",
    # References through clip paths, masks and patterns are not counted up
    # front as <use> is: each walk of their content counts, and the limit
    # stops the walk after 1M elements have been built (BAD_BOUNDS).
    "mask_content_bomb.svg": r"3: <rect>: more than 1000000 elements, <use> instances included",
    "clip_path_content_bomb.svg": r"3: <rect>: more than 1000000 elements, <use> instances included",
    "pattern_content_bomb.svg": r"3: <rect>: more than 1000000 elements, <use> instances included",
    "text_tspans_nested_300.svg": r"258: <tspan>: elements nested deeper than 256",
}

# Cases over the 2 s and 1 GiB every other refusal keeps: file -> (CPU
# seconds, bytes). The content bombs build 1M elements before the limit
# stops them: 2.9 to 3.9 s and 1.0 to 1.6 GB measured, about what a file of
# 1M plain rectangles costs to read (1.5 GB).
BAD_BOUNDS = {
    "mask_content_bomb.svg": (20.0, 2.5 * GIB),
    "clip_path_content_bomb.svg": (15.0, 2.5 * GIB),
    "pattern_content_bomb.svg": (18.0, 2.5 * GIB),
}

# Recovered from as the specs say: file -> its one warning, after "FILE:LINE: ".
RECOVERED = {
    "bad_path_data.svg": r"2: <path>: attribute d: path data: at offset 20: expected a number",
    "bad_points.svg": r"2: <polygon>: attribute points: odd number of coordinates",
    "not_a_number.svg": r"2: <rect>: attribute width: 'abc' is not a length; ignored",
    "negative_size.svg": r"1: <svg>: attribute width: '-3' is negative; ignored",
    "nan_number.svg": r"2: <circle>: attribute r: 'nan' is not a length; ignored",
    "inf_number.svg": r"2: <rect>: attribute width: 'inf' is not a length; ignored",
    "overflowing_number.svg": r"2: <rect>: attribute width: '1e309' is not a length; ignored",
    "path_1e308_overflow.svg": r"2: <path>: attribute d: .*overflow the double range",
    "gradient_href_cycle.svg": r"2: <linearGradient>: href '#b' makes a cycle; the chain ends here",
    "use_cycle.svg": r"2: <use>: href '#a' contains the use itself; skipped",
    "mask_self_cycle.svg": r"2: <mask>: <mask> #m refers back to itself; the element is not drawn",
    "mask_mutual_cycle.svg": r"3: <mask>: <mask> #a refers back to itself; the element is not drawn",
    "clip_path_cycle.svg": r"3: <clipPath>: <clipPath> #a refers back to itself; the element is not drawn",
    "pattern_self_fill.svg": r"3: <rect>: pattern #p paints its own content; none is used",
    "image_missing_file.svg": r"2: <image>: the image cannot be drawn: .*missing_image\.png: cannot open the file",
    # The warning comes from the innermost copy, named by its canonical path
    # (DATA is one); under --strict each copy's error wraps the next one's.
    "image_of_itself.svg": r"2: <image>: .*SVG images nested deeper than \d+ \(the limit\); not drawn",
    # Generated: a PNG header of 100000 x 100000 pixels whose body is cut
    # short, refused from its header, before any pixel is decoded.
    "image_file_100000_squared.svg":
        r"2: <image>: the image cannot be drawn: .*png_100000_squared\.png: image of 100000 x 100000 "
        r"pixels exceeds the limit of 33554432 pixels",
    "image_data_100000_squared.svg":
        r"2: <image>: the image cannot be drawn: image of 100000 x 100000 pixels exceeds the limit",
    "filter_missing.svg": r"2: <rect>: url\(#nope\) names no <filter>; the element is not drawn",
    # The feImage draws the rectangle again, whose filter is the one being
    # read: that copy is not drawn.
    "filter_image_of_itself.svg": r"3: <rect>: <filter> #f refers back to itself; the element is not drawn",
    "text_rotate_nan.svg": r"2: <text>: attribute rotate: not a list of numbers; ignored",
    "text_path_no_href.svg": r"3: <textPath>: href names no path or shape; its text is not drawn",
    "text_path_href_self.svg": r"3: <textPath>: href names no path or shape; its text is not drawn",
    "text_path_href_text.svg": r"3: <textPath>: href names no path or shape; its text is not drawn",
    "text_tref_missing.svg": r"3: <tref>: href '#nope' names no element; skipped",
}

def png_header_only(w, h):
    """A PNG that declares w x h RGBA pixels (a valid IHDR), then an IDAT
    of 256 bytes of which only the zlib header is there."""
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" + ihdr +
            struct.pack(">I", zlib.crc32(b"IHDR" + ihdr)) + struct.pack(">I", 256) + b"IDAT\x78\x9c")


def content_bomb(kind, attr):
    """Ten levels of <kind>, each holding 10 rectangles that each refer to
    the level below by `attr`, and one rectangle referring to the top:
    10^10 elements once every reference's content is walked."""
    body = '<%s id="e0"><rect width="100" height="100" fill="#fff"/></%s>\n' % (kind, kind)
    for i in range(1, 10):
        rect = '<rect width="100" height="100" fill="#fff" %s="url(#e%d)"/>' % (attr, i - 1)
        body += '<%s id="e%d">%s</%s>\n' % (kind, i, rect * 10, kind)
    return body + '<rect width="100" height="100" fill="#2a6fb0" %s="url(#e9)"/>\n' % attr


def generate_bad(folder):
    def svg(name, body):
        with open(os.path.join(folder, name), "w") as f:
            f.write('<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">\n%s</svg>\n' % body)
    svg("mask_content_bomb.svg", content_bomb("mask", "mask"))
    svg("clip_path_content_bomb.svg", content_bomb("clipPath", "clip-path"))
    # Patterns in objectBoundingBox units are built anew for each element.
    body = '<pattern id="e0" width="0.5" height="0.5"><rect width="1" height="1" fill="#2a6fb0"/></pattern>\n'
    for i in range(1, 10):
        body += '<pattern id="e%d" width="0.5" height="0.5">%s</pattern>\n' % (
            i, '<rect width="5" height="5" fill="url(#e%d)"/>' % (i - 1) * 10)
    svg("pattern_content_bomb.svg", body + '<rect width="100" height="100" fill="url(#e9)"/>\n')
    png = png_header_only(100000, 100000)
    with open(os.path.join(folder, "png_100000_squared.png"), "wb") as f:
        f.write(png)
    svg("image_file_100000_squared.svg", '<image href="png_100000_squared.png" width="100" height="100"/>\n')
    svg("image_data_100000_squared.svg", '<image width="100" height="100" href="data:image/png;base64,%s"/>\n'
        % base64.b64encode(png).decode())
    # 200,000 vertices, each with a marker of 10 elements: 2M elements.
    with open(os.path.join(folder, "marker_bomb.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n<marker id="m">')
        f.write('<rect width="1" height="1"/>' * 10 + '</marker>\n<path d="M0 0')
        f.write(" l1 0" * 200000 + '" marker-mid="url(#m)"/>\n</svg>\n')
    with open(os.path.join(folder, "not_svg.svg"), "w") as f:
        f.write('<html xmlns="http://www.w3.org/1999/xhtml"><body/></html>\n')
    with open(os.path.join(folder, "nested_groups_10k.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n')
        f.write("<g>\n" * 10000 + '<rect width="1" height="1"/>' + "</g>" * 10000 + "</svg>\n")
    with open(os.path.join(folder, "path_attribute_50MB.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n<path d="M0 0')
        f.write(" " * (50 * 2**20 - 4) + '"/>\n</svg>\n')
    # Text: tspans nested 300 deep, one a line (the 256th is refused, on line 258).
    with open(os.path.join(folder, "text_tspans_nested_300.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">\n<text y="8">\n')
        f.write("<tspan>a\n" * 300 + "</tspan>" * 300 + "</text>\n</svg>\n")


def bad_input(work):
    generate_bad(work)
    out = os.path.join(work, "out", "kept.png")
    os.makedirs(os.path.dirname(out), exist_ok=True)

    def refused(name, src, command, message, max_s=2.0, max_bytes=GIB):
        precious(out)
        status, err, seconds, rss = run(command, work)
        where = re.escape(os.path.basename(src)) + ":" + message
        check(name + " status 2", status == 2, "status %d: %s" % (status, err.strip()[-300:]))
        check(name + " message", re.search(where, err) is not None, "expected /%s/ in %r" % (where, err[-300:]))
        check(name + " untouched", intact(out) and not leftovers(os.path.dirname(out)),
              "the output was changed or a temporary file left: %s" % os.listdir(os.path.dirname(out)))
        check_bounds(name, seconds, rss, max_s, max_bytes)

    for name, message in sorted(BAD.items()):
        # The content bombs take seconds of building up to the element limit,
        # ten times that under the sanitizers, for code the other cases run
        # there too: only the plain pass runs them.
        if MODE == "sanitized" and name in BAD_BOUNDS:
            continue
        src = os.path.join(DATA, name) if os.path.exists(os.path.join(DATA, name)) else os.path.join(work, name)
        kind = "patch" if name.endswith((".bpt", ".map", ".json")) else "render"
        refused(name, src, [kind, src, "-o", out], message, *BAD_BOUNDS.get(name, (2.0, GIB)))
    for name, message in sorted(RECOVERED.items()):
        src = os.path.join(DATA, name) if os.path.exists(os.path.join(DATA, name)) else os.path.join(work, name)
        drawn = os.path.join(work, "out", name + ".png")
        status, err, seconds, rss = run(["render", src, "-o", drawn], work)
        where = "warning: " + re.escape(src) + ":" + message
        check(name + " drawn", status == 0 and os.path.getsize(drawn) > 0, "status %d: %s" % (status, err[-300:]))
        check(name + " one warning", len(re.findall(where, err)) == 1 and err.count("warning:") == 1,
              "expected one /%s/ in %r" % (where, err[-300:]))
        check_bounds(name, seconds, rss, 2.0)
        refused(name + " --strict", src, ["render", src, "-o", out, "--strict"], message)


# --- pathological but valid input -------------------------------------------

SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">\n%s</svg>\n'


def generate_valid(folder):
    def svg(name, w, h, body):
        with open(os.path.join(folder, name), "w") as f:
            f.write(SVG % (w, h, body))
    # 1M segments: a zigzag of lines and cubics across a 1024 px image.
    steps = []
    for i in range(250000):
        steps.append("l4 -60 c1 20 2 40 0 60" if i % 2 else "l-4 60 c-1 -20 -2 -40 0 -60")
    svg("path_1M_segments.svg", 1024, 1024,
        '<path d="M10 500 %s" fill="#2a6fb0" stroke="black" stroke-width="0.5"/>\n' % " ".join(steps))
    svg("control_points_1e9_apart.svg", 200, 200,
        '<path d="M10 10 C 1e9 -1e9 -1e9 1e9 190 190 Z" fill="#d9582b" stroke="black" stroke-width="3"/>\n'
        '<path d="M0 100 Q 5e8 1e9 200 100" fill="none" stroke="#3d9a50" stroke-width="2" stroke-dasharray="5 3"/>\n')
    svg("circle_1e7_px_off_canvas.svg", 512, 512,
        '<circle cx="5000256" cy="256" r="5000000" fill="#c9a227" stroke="black" stroke-width="4"/>\n'
        '<circle cx="-4999900" cy="-4999900" r="7071000" fill="none" stroke="#444" stroke-width="2" '
        'stroke-dasharray="7 5"/>\n')
    # One subpath of 8000 round joins on a stroke 1e6 px wide, all within reach
    # of the image: 4400 outline points a join (1.2 GB before the outline's
    # point limit counted a subpath as it grew).
    zigzag = " ".join("L%d 30" % (30 if i % 2 else 34) for i in range(8001))
    svg("round_joins_1e6_px_wide.svg", 64, 64,
        '<path d="M30 30 %s" fill="none" stroke="black" stroke-width="1e6" '
        'stroke-linejoin="round"/>\n' % zigzag)
    # A stroke 1e300 wide on coordinates of 1e308: squares of its lengths
    # overflow (12.7 GB before the stroker scaled such strokes down).
    svg("stroke_1e300_wide.svg", 10, 10,
        '<path d="M0 0 L1e308 1e308 L-1e308 1 Z" fill="none" stroke="black" stroke-width="1e300"/>\n')
    rects = "".join('<rect x="%.2f" y="%.2f" width="0.3" height="0.3" fill="#%06x"/>\n'
                    % ((i * 7.31) % 1000, (i * 3.17) % 1000, (i * 2654435761) & 0xffffff)
                    for i in range(100000))
    svg("subpixel_shapes_100k.svg", 1000, 1000, rects)
    # A bicubic patch whose first row collapses to one point (the teapot lid's pole).
    rows = ["0 0 50 0 0 50 0 0 50 0 0 50",
            "-30 -10 40 -10 -30 40 10 -30 40 30 -10 40",
            "-50 -20 20 -20 -50 20 20 -50 20 50 -20 20",
            "-60 -30 0 -30 -60 0 30 -60 0 60 -30 0"]
    # Tiles of 1e-6 px over 4M pixels: the tile is drawn into one pixel.
    svg("pattern_tiles_1e-6_px.svg", 2000, 2000,
        '<pattern id="p" patternUnits="userSpaceOnUse" width="1e-6" height="1e-6">'
        '<rect width="5e-7" height="5e-7" fill="#2a6fb0"/><circle cx="7e-7" cy="7e-7" r="2e-7" fill="#d9582b"/>'
        '</pattern>\n<rect width="2000" height="2000" fill="url(#p)"/>\n')
    # A tile of 1e6 user units scaled by 1000: 1e9 px a side on the device,
    # drawn at a lower resolution (kMaxTilePixels).
    svg("pattern_tile_1e9_px.svg", 1000, 1000,
        '<pattern id="p" patternUnits="userSpaceOnUse" width="1e6" height="1e6" patternTransform="scale(1000)">'
        '<circle cx="5e5" cy="5e5" r="4e5" fill="#2a6fb0"/><rect width="1e3" height="1e3" fill="#d9582b"/>'
        '</pattern>\n<rect width="1000" height="1000" fill="url(#p)"/>\n')
    # Each clip path (mask) clipped (masked) by the next, 200 deep: a layer
    # for each level's content and one for its clip.
    body = "".join('<clipPath id="c%d" clip-path="url(#c%d)"><circle cx="250" cy="250" r="%d"/></clipPath>\n'
                   % (i, i + 1, 240 - i) for i in range(199))
    svg("clip_paths_nested_200.svg", 500, 500, body + '<clipPath id="c199"><rect width="500" height="500"/>'
        '</clipPath>\n<rect width="500" height="500" fill="#2a6fb0" clip-path="url(#c0)"/>\n')
    body = "".join('<mask id="m%d" mask="url(#m%d)"><circle cx="250" cy="250" r="%d" fill="#fff"/></mask>\n'
                   % (i, i + 1, 240 - i) for i in range(199))
    svg("masks_nested_200.svg", 500, 500, body + '<mask id="m199"><rect width="500" height="500" fill="#fff"/>'
        '</mask>\n<rect width="500" height="500" fill="#2a6fb0" mask="url(#m0)"/>\n')
    # An SVG image of itself under three hrefs: max_image_nesting (8) bounds
    # the depth, not the breadth; 3^9 copies are read (and 3^9 warnings told).
    hrefs = ["image_of_itself_3_hrefs.svg", "./image_of_itself_3_hrefs.svg", "image_of_itself_3_hrefs.svg?b"]
    svg("image_of_itself_3_hrefs.svg", 64, 64, '<rect width="64" height="32" fill="#2a6fb0"/>\n' + "".join(
        '<image href="%s" x="%d" y="32" width="21" height="32"/>\n' % (h, 21 * i) for i, h in enumerate(hrefs)))
    # Filters at their limits: a region of 2e6 px a side (drawn over the
    # frame grown by kMaxFilterMargin), deviations, radii and octaves far
    # over their bounds, the largest convolution kernel (32 x 32), and a
    # chain of 400 primitives.
    svg("filter_region_2e6_px.svg", 400, 400,
        '<filter id="f" filterUnits="userSpaceOnUse" x="-1e6" y="-1e6" width="2e6" height="2e6">'
        '<feGaussianBlur stdDeviation="40"/><feOffset dx="30" dy="20"/></filter>\n'
        '<rect x="50" y="50" width="300" height="300" fill="#2a6fb0" filter="url(#f)"/>\n')
    svg("filter_values_1e9.svg", 300, 300,
        '<filter id="f"><feGaussianBlur stdDeviation="1e9"/><feMorphology operator="dilate" radius="1e9"/>'
        '<feTurbulence baseFrequency="0.05" numOctaves="1000000000"/>'
        '<feDisplacementMap in2="SourceGraphic" scale="1e9"/><feOffset dx="1e300"/></filter>\n'
        '<rect width="300" height="300" fill="#2a6fb0" filter="url(#f)"/>\n')
    svg("filter_kernel_32x32.svg", 200, 200,
        '<filter id="f"><feConvolveMatrix order="32" kernelMatrix="%s"/></filter>\n'
        '<circle cx="100" cy="100" r="80" fill="#2a6fb0" filter="url(#f)"/>\n' % " ".join(["1"] * 1024))
    svg("filter_primitives_400.svg", 200, 200,
        '<filter id="f">%s</filter>\n<rect width="160" height="160" fill="#2a6fb0" filter="url(#f)"/>\n'
        % ('<feOffset dx="0.1"/><feColorMatrix type="hueRotate" values="10"/>' * 200))
    with open(os.path.join(folder, "patch_collapsed_edge.bpt"), "w") as f:
        f.write("1\n3 3\n")
        for r in rows:
            v = r.split()
            for k in range(0, 12, 3):
                f.write(" ".join(v[k:k + 3]) + "\n")
    generate_text(folder, svg)


def broken_font(src, dst, family, tables, seed):
    """A copy of the font `src` renamed `family` (the same length as
    "DejaVu Sans", so that the name table's offsets hold) whose `tables` are
    random bytes: fontconfig indexes it by its intact name and cmap, and
    FreeType and HarfBuzz get the rest."""
    with open(src, "rb") as f:
        d = bytearray(f.read())
    for enc in ("latin-1", "utf-16-be"):
        d = d.replace("DejaVu Sans".encode(enc), family.encode(enc))
    rng = random.Random(seed)
    for i in range(struct.unpack(">H", d[4:6])[0]):
        tag, _, offset, length = struct.unpack(">4sIII", d[12 + 16 * i:28 + 16 * i])
        if tag in tables:
            d[offset:offset + length] = rng.randbytes(length)
    with open(dst, "wb") as f:
        f.write(d)


def generate_text(folder, svg):
    # Fonts that do not parse, for --font-dir: random bytes named .ttf, the
    # first 10 KB of DejaVu Sans (its table directory, no table whole), and
    # DejaVu Sans with random outlines and layout tables (Broken Sans) or
    # random advances and layout tables (Wobbly Sans), which fontconfig does
    # index.
    fonts = os.path.join(folder, "text_fonts")
    os.makedirs(fonts, exist_ok=True)
    with open(os.path.join(fonts, "garbage.ttf"), "wb") as f:
        f.write(random.Random(3).randbytes(4096))
    if os.path.exists(DEJAVU_SANS):
        with open(DEJAVU_SANS, "rb") as f, open(os.path.join(fonts, "DejaVuSans-10KB.ttf"), "wb") as g:
            g.write(f.read(10240))
        broken_font(DEJAVU_SANS, os.path.join(fonts, "BrokenSans.ttf"), "Broken Sans",
                    (b"glyf", b"hmtx", b"GSUB", b"GPOS", b"GDEF", b"kern"), 1)
        broken_font(DEJAVU_SANS, os.path.join(fonts, "WobblySans.ttf"), "Wobbly Sans",
                    (b"hmtx", b"hhea", b"GSUB", b"GPOS", b"GDEF", b"kern"), 2)
    # The same fonts as the only ones there are: no system font to fall back on.
    with open(os.path.join(folder, "no_fonts.conf"), "w") as f:
        f.write('<?xml version="1.0"?>\n<fontconfig><cachedir prefix="xdg">fontconfig</cachedir></fontconfig>\n')
    svg("text_only_broken_fonts.svg", 300, 100,
        '<text x="10" y="30" font-size="20" font-family="Broken Sans">Broken: fi AV &#x0301;e&#x4E00;</text>\n'
        '<text x="10" y="60" font-size="20" font-family="Wobbly Sans" text-decoration="underline" '
        'textLength="200">Wobbly: fi AV &#x05D0;1</text>\n'
        '<text x="10" y="90" font-size="20" font-family="garbage, serif" writing-mode="vertical-rl">none</text>\n')
    # A million characters in one element: the first 1e5 (max_text_characters)
    # are drawn, with a warning, which --strict leaves a warning.
    svg("text_chars_1e6.svg", 400, 100, '<text x="0" y="50" font-size="10">%s</text>\n'
        % ("lorem ipsum dolor sit amet " * 37038))
    # 1e5 tspans of one character each: 1e5 spans and shapes.
    svg("text_tspans_1e5.svg", 400, 100, '<text x="0" y="50" font-size="10">%s</text>\n'
        % "".join("<tspan>%s</tspan>" % "abcdefghij"[i % 10] for i in range(100000)))
    # x, y, dx, dy and rotate lists of 1e5 values on 30 characters, some huge.
    n = 100000
    svg("text_lists_1e5.svg", 400, 100,
        '<text x="%s" y="50" dx="%s" dy="%s" rotate="%s" font-size="10">%s<tspan dx="%s">%s</tspan></text>\n'
        % (" ".join("%d" % (i % 400) for i in range(n)), " ".join(["0.5"] * n),
           " ".join(["-1e300", "1e300"] * (n // 2)), " ".join(["1e308", "-7.5"] * (n // 2)), "xyz" * 10,
           " ".join(["-1e308"] * n), "abc"))
    # 1e5 characters, each with its own x: 1e5 chunks, each shaped alone.
    svg("text_chunks_1e5.svg", 400, 100, '<text y="50" font-size="10" x="%s">%s</text>\n'
        % (" ".join("%d" % (i % 400) for i in range(n)), "abcdefghij" * (n // 10)))
    # 1e4 chunks of 1e4 tspans: each chunk is shaped with the styles of
    # every span of the element (1e8 font look-ups when each is looked up).
    svg("text_chunks_1e4_of_1e4_tspans.svg", 400, 100, '<text y="50" font-size="10" x="%s">%s</text>\n'
        % (" ".join("%d" % (i % 400) for i in range(10000)), "<tspan>a</tspan>" * 10000))
    # 50 chunks on a textPath of 1e5 segments: the path measured once, not
    # once a chunk.
    svg("text_path_1e5_segments_50_chunks.svg", 400, 100,
        '<path id="p" d="M0 50 %s"/>\n<text font-size="10"><textPath href="#p"><tspan x="%s">%s</tspan>'
        '</textPath></text>\n' % (" ".join(["q2 -5 4 0 q2 5 4 0"] * 50000),
                                   " ".join(str(8 * i) for i in range(50)), "a" * 50))
    # 2e4 different characters that no font has (plane 15, private use):
    # a fallback search for each.
    svg("text_fallback_2e4_chars.svg", 400, 100, '<text y="50" font-size="10">%s</text>\n'
        % "".join(chr(c) for c in range(0xF0000, 0xF0000 + 20000)))
    # Tspans nested 200 deep, each underlined, overlined and struck
    # through, around 5000 characters: 200 x 3 decorations for each.
    svg("text_decorations_nested_200.svg", 400, 100, '<text y="50" font-size="10">%s%s%s</text>\n'
        % ('<tspan text-decoration="underline overline line-through">' * 200, "abcdefghij" * 500,
           "</tspan>" * 200))


# file -> (extra arguments, time bound in seconds). The CPU time includes
# the system's, which is mostly page faults: on the 2-core machines of
# 2026-11-29 a fault cost about 6 us (a paravirtualized kernel), and the cases
# that build hundreds of MB took 2-3.3 s where the bound of 2 had been 5x
# their time: those bounds are about 2x that machine's slowest run.
VALID = {
    "path_1M_segments.svg": ([], 10.0),
    "control_points_1e9_apart.svg": ([], 2.0),
    "circle_1e7_px_off_canvas.svg": ([], 2.0),
    "subpixel_shapes_100k.svg": ([], 5.0),
    "round_joins_1e6_px_wide.svg": ([], 5.0),
    "stroke_1e300_wide.svg": ([], 2.0),
    "patch_collapsed_edge.bpt": (["--width", "320", "--height", "240"], 2.0),
    "pattern_tiles_1e-6_px.svg": ([], 3.0),
    "pattern_tile_1e9_px.svg": ([], 2.0),
    "clip_paths_nested_200.svg": ([], 2.0),
    "masks_nested_200.svg": ([], 2.0),
    "image_of_itself_3_hrefs.svg": ([], 4.0),
    "filter_region_2e6_px.svg": ([], 2.0),
    "filter_values_1e9.svg": ([], 6.0),
    "filter_kernel_32x32.svg": ([], 3.0),
    "filter_primitives_400.svg": ([], 3.0),
    # Text (the files named text_* in this folder, and generate_text's).
    "text_fonts_broken.svg": (["--font-dir", "text_fonts"], 2.0),
    "text_only_broken_fonts.svg": (["--font-dir", "text_fonts"], 2.0),
    "text_path_degenerate.svg": ([], 2.0),
    "text_path_bad_hrefs.svg": ([], 2.0),
    "text_tref_cycles.svg": ([], 2.0),
    "text_values_extreme.svg": ([], 2.0),
    "text_invalid_utf8.svg": ([], 2.0),
    "text_invalid_char_refs.svg": ([], 2.0),
    "text_unicode_edges.svg": ([], 2.0),
    "text_bidi_nested_200.svg": ([], 2.0),
    "text_chars_1e6.svg": ([], 4.0),
    "text_tspans_1e5.svg": ([], 7.0),
    "text_lists_1e5.svg": ([], 2.0),
    "text_chunks_1e5.svg": ([], 5.0),
    "text_chunks_1e4_of_1e4_tspans.svg": ([], 2.0),
    "text_path_1e5_segments_50_chunks.svg": ([], 2.0),
    "text_fallback_2e4_chars.svg": ([], 2.0),
    "text_decorations_nested_200.svg": ([], 2.0),
}

# Cases run with another fontconfig configuration than tests/text/fonts.conf
# (a file generate_valid writes): file -> configuration.
VALID_FONTCONFIG = {"text_only_broken_fonts.svg": "no_fonts.conf"}


# Only their time is at stake here, which the sanitizers inflate tenfold;
# the code they run is run under the sanitizers by the unit tests
# (tests/filter, tests/svg/filter_test.cpp) and the filter_graph fuzzer.
PLAIN_ONLY = {"filter_region_2e6_px.svg", "filter_values_1e9.svg", "filter_kernel_32x32.svg",
              "filter_primitives_400.svg"}


def valid_input(work):
    generate_valid(work)
    for name, (extra, bound) in sorted(VALID.items()):
        if MODE == "sanitized" and name in PLAIN_ONLY:
            continue
        src = os.path.join(DATA, name) if os.path.exists(os.path.join(DATA, name)) else name
        out = os.path.join(work, name + ".png")
        command = ["patch" if name.endswith(".bpt") else "render", src, "-o", out] + extra
        env = dict(ENV, FONTCONFIG_FILE=os.path.join(work, VALID_FONTCONFIG[name])) if name in VALID_FONTCONFIG else None
        status, err, seconds, rss = run(command, work, env=env)
        check(name + " renders", status == 0 and os.path.getsize(out) > 0, "status %d: %s" % (status, err[-300:]))
        check_bounds(name, seconds, rss, bound)


# --- output that cannot be written --------------------------------------------

def full_disk(room=4096):
    """A disk that takes files of `room` bytes at most."""
    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a failed write, not a killed process
        resource.setrlimit(resource.RLIMIT_FSIZE, (room, room))
    return limit


def unwritable_output(work):
    ok_svg = os.path.join(DATA, "..", "cli", "data", "ok.svg")
    patch = os.path.join(DATA, "..", "..", "examples", "patch", "wave.bpt")
    os.makedirs(os.path.join(work, "is_a_folder.png"), exist_ok=True)
    precious(os.path.join(work, "a_file"))
    cases = [
        ("folder", ["render", ok_svg, "-o", "is_a_folder.png"], None, r"is a folder", None),
        ("under_a_file", ["render", ok_svg, "-o", "a_file/x.png"], None, r"a_file/x.png", None),
    ]
    # At scale 20 (800 x 600) every format's file is well over the 4096 bytes
    # the disk takes (at scale 8 a right-coloured PNG of the circle fits).
    for ext in ["png", "tif", "exr", "jpg"]:
        cases.append(("full_disk_" + ext, ["render", ok_svg, "-o", "kept." + ext, "--scale", "20"],
                      full_disk(), r"kept\.%s: write failed" % ext, "kept." + ext))
    for ext in ["obj", "ply"]:
        cases.append(("full_disk_mesh_" + ext, ["patch", patch, "-o", "p.png", "--width", "64", "--height", "48",
                                                "--mesh", "kept." + ext], full_disk(),
                      r"kept\.%s: write failed" % ext, "kept." + ext))
    # The 1 x 1 image fits in 300 bytes, the statistics do not.
    cases.append(("full_disk_stats", ["patch", patch, "-o", "q.png", "--width", "1", "--height", "1",
                                      "--stats", "kept.json"], full_disk(300), r"kept\.json: write failed",
                  "kept.json"))
    for name, command, preexec, message, kept in cases:
        if kept:
            precious(os.path.join(work, kept))
        status, err, _, _ = run(command, work, preexec)
        check(name + " status 1", status == 1, "status %d: %s" % (status, err[-300:]))
        check(name + " message", re.search(message, err) is not None, "expected /%s/ in %r" % (message, err[-300:]))
        if kept:
            check(name + " intact", intact(os.path.join(work, kept)), "the existing file was changed")
    check("no temporary files", not leftovers(work), "left: %s" % leftovers(work))


with tempfile.TemporaryDirectory() as tmp:
    for part in (bad_input, valid_input, unwritable_output):
        folder = os.path.join(tmp, part.__name__)
        os.makedirs(folder)
        part(folder)

print("bad input: %d failed" % len(failures) if failures else "bad input: all passed")
sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""Writes the two files bench/README's fourteenth session measures the
memory budget on (render/memory_gate.h), into the folder given (default .):

  uturns.svg   8,000 round U-turns on a stroke 1e6 px wide, 1024 px: each
               128-row strip's outline outgrows the stroker's point limit
  offsets.svg  sixteen offsets of the source merged, 4096 x 1024: every
               result lives until the merge, 273 MB of images a band

Usage: make_memory_cases.py [FOLDER], then
  /usr/bin/time -f "%e s %U user %M KB" build/cli/casteljau render FILE -o o.png --threads T
"""
import os
import sys

SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d">%s</svg>\n'

folder = sys.argv[1] if len(sys.argv) > 1 else "."
turns = " ".join("L%d 30" % (30 if i % 2 else 34) for i in range(8001))
with open(os.path.join(folder, "uturns.svg"), "w") as f:
    f.write(SVG % (1024, 1024, '<path d="M30 30 %s" fill="none" stroke="black" stroke-width="1e6" '
                               'stroke-linejoin="round"/>' % turns))
offsets = "".join('<feOffset in="SourceGraphic" dx="%d" result="o%d"/>' % (i, i) for i in range(16))
merge = "".join('<feMergeNode in="o%d"/>' % i for i in range(16))
with open(os.path.join(folder, "offsets.svg"), "w") as f:
    f.write(SVG % (4096, 1024, '<filter id="f" x="0" y="0" width="1" height="1">%s<feMerge>%s</feMerge>'
                               '</filter><rect width="4096" height="1024" fill="#2a6fb0" filter="url(#f)"/>'
                               % (offsets, merge)))

#!/usr/bin/env python3
"""Writes N seeded icon-sized SVGs (a 24 x 24 view box drawn at 24-64 px): a few filled
paths of lines, quadratics, cubics and arcs, stroked paths with joins, caps and sometimes
dashes, and a linear or radial gradient in about half of them. The same seed gives the same
files, byte for byte.

    python3 bench/cli/make_icons.py OUT_DIR [--count 1000] [--seed 1]
"""

import argparse
import os
import random


def color(r):
    return "#%02x%02x%02x" % (r.randrange(256), r.randrange(256), r.randrange(256))


def point(r):
    return f"{r.uniform(2, 22):.2f} {r.uniform(2, 22):.2f}"


def path_data(r):
    d = [f"M{point(r)}"]
    for _ in range(r.randrange(2, 6)):
        kind = r.randrange(4)
        if kind == 0:
            d.append(f"L{point(r)}")
        elif kind == 1:
            d.append(f"Q{point(r)} {point(r)}")
        elif kind == 2:
            d.append(f"C{point(r)} {point(r)} {point(r)}")
        else:
            rx, ry = r.uniform(2, 9), r.uniform(2, 9)
            d.append(f"A{rx:.2f} {ry:.2f} {r.uniform(0, 90):.0f} {r.randrange(2)} "
                     f"{r.randrange(2)} {point(r)}")
    if r.random() < 0.6:
        d.append("Z")
    return " ".join(d)


def gradient(r, ident):
    stops = "".join(f'<stop offset="{o:.2f}" stop-color="{color(r)}"/>'
                    for o in sorted(r.uniform(0, 1) for _ in range(r.randrange(2, 4))))
    if r.random() < 0.5:
        return (f'<linearGradient id="{ident}" x1="0" y1="0" x2="{r.uniform(0.3, 1):.2f}" '
                f'y2="{r.uniform(0, 1):.2f}">{stops}</linearGradient>')
    return (f'<radialGradient id="{ident}" cx="{r.uniform(0.3, 0.7):.2f}" '
            f'cy="{r.uniform(0.3, 0.7):.2f}" r="{r.uniform(0.3, 0.8):.2f}">{stops}'
            '</radialGradient>')


def icon(r):
    size = r.randrange(24, 65)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size}" height="{size}" '
           'viewBox="0 0 24 24">']
    fill_with_gradient = r.random() < 0.5
    if fill_with_gradient:
        out.append(f"<defs>{gradient(r, 'g')}</defs>")
    for i in range(r.randrange(2, 6)):
        fill = "url(#g)" if fill_with_gradient and i == 0 else color(r)
        if r.random() < 0.35:
            dash = f' stroke-dasharray="{r.uniform(1, 3):.1f} {r.uniform(0.5, 2):.1f}"' \
                if r.random() < 0.3 else ""
            out.append(f'<path d="{path_data(r)}" fill="none" stroke="{color(r)}" '
                       f'stroke-width="{r.uniform(0.5, 3):.2f}" '
                       f'stroke-linejoin="{r.choice(["miter", "round", "bevel"])}" '
                       f'stroke-linecap="{r.choice(["butt", "round", "square"])}"{dash}/>')
        else:
            out.append(f'<path d="{path_data(r)}" fill="{fill}" '
                       f'fill-opacity="{r.uniform(0.5, 1):.2f}"/>')
    out.append("</svg>\n")
    return "\n".join(out)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out")
    p.add_argument("--count", type=int, default=1000)
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    r = random.Random(args.seed)
    for i in range(args.count):
        with open(os.path.join(args.out, f"icon{i:04d}.svg"), "w") as f:
            f.write(icon(r))


if __name__ == "__main__":
    main()

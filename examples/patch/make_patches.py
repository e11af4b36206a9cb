#!/usr/bin/env python3
"""Writes the bundled patch examples (run from anywhere; rewrites the files here).

  arch.map      a Quake 3 style curved arch: a half-cylinder vault (5 x 9
                biquadratic grid) on a curved floor (3 x 5), plus a brush the
                reader must skip
  pipe.map      a pipe bend: a 90 degree elbow, 5 x 17 biquadratic grid,
                section in eight 45 degree arcs, texture coordinates along it
  wave.bpt      a bicubic Bezier surface: 2 x 2 patches on a shared 7 x 7 grid
  terrain.json  a uniform bicubic B-spline surface: a 7 x 9 grid (4 x 6 pieces)
                with a camera
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def arc_controls(n_arcs, total_angle):
    """Unit-radius quadratic arc control points (angle, radius scale), 2n+1 of them."""
    step = total_angle / n_arcs
    out = []
    for i in range(2 * n_arcs + 1):
        a = i * step / 2
        out.append((a, 1.0 if i % 2 == 0 else 1.0 / math.cos(step / 2)))
    return out


def patch_def(texture, grid):
    rows, cols = len(grid), len(grid[0])
    lines = ["patchDef2", "{", texture, f"( {rows} {cols} 0 0 0 )", "("]
    for row in grid:
        pts = " ".join("( %s )" % " ".join("%.6g" % v for v in p) for p in row)
        lines.append(f"( {pts} )")
    lines += [")", "}"]
    return "\n".join(lines)


def write_map(name, comment, patches):
    body = ["// " + comment, "{", '"classname" "worldspawn"',
            "// a brush: skipped by the patch reader",
            "{", "( 0 0 -64 ) ( 1 0 -64 ) ( 0 1 -64 ) common/caulk 0 0 0 0.5 0.5 0 0 0", "}"]
    for p in patches:
        body += ["{", p, "}"]
    body.append("}")
    with open(os.path.join(HERE, name), "w") as f:
        f.write("\n".join(body) + "\n")


def arch():
    vault = []
    for r in range(5):  # along the arch's depth
        row = []
        for k, (a, s) in enumerate(arc_controls(4, math.pi)):
            row.append((128 * s * math.cos(a), 48 * r, 96 + 128 * s * math.sin(a), k / 2, r / 2))
        vault.append(row)
    floor = []
    for r in range(3):
        row = []
        for k in range(5):
            x = -160 + 80 * k
            sag = -24 if (k == 2 and r == 1) else 0  # a shallow dip in the middle
            row.append((x, 96 * r, sag, k, r))
        floor.append(row)
    write_map("arch.map", "casteljau example: a curved arch on a dipped floor",
              [patch_def("textures/gothic/arch", vault), patch_def("textures/gothic/floor", floor)])


def pipe():
    bend = arc_controls(2, math.pi / 2)      # 5 points along the elbow
    section = arc_controls(8, 2 * math.pi)   # 17 points around the pipe
    R, r = 128.0, 40.0
    grid = []
    for i, (a, s) in enumerate(bend):
        row = []
        for j, (b, t) in enumerate(section):
            radial = R + r * t * math.cos(b)
            row.append((radial * s * math.cos(a), radial * s * math.sin(a), r * t * math.sin(b),
                        i / 2, j / 4))
        grid.append(row)
    write_map("pipe.map", "casteljau example: a 90 degree pipe bend", [patch_def("textures/pipes/elbow", grid)])


def wave():
    n = 7
    z = [[60 * math.sin(0.9 * k) * math.cos(0.7 * r) for k in range(n)] for r in range(n)]
    lines = ["4"]
    for pr in range(2):
        for pk in range(2):
            lines.append("3 3")
            for r in range(4):
                for k in range(4):
                    R, K = 3 * pr + r, 3 * pk + k
                    lines.append("%.6g %.6g %.6g" % (60 * K, 60 * R, z[R][K]))
    with open(os.path.join(HERE, "wave.bpt"), "w") as f:
        f.write("\n".join(lines) + "\n")


def terrain():
    rows, cols = 7, 9
    points, st = [], []
    for r in range(rows):
        for k in range(cols):
            h = 40 * math.sin(1.3 * k) * math.sin(0.9 * r) + (120 if (r, k) == (3, 4) else 0)
            points.append([50.0 * k, 50.0 * r, round(h, 4)])
            st.append([k / (cols - 1) * 2, r / (rows - 1) * 2])
    scene = {
        "patches": [{"type": "bspline", "degree": [3, 3], "size": [rows, cols],
                     "points": points, "st": st}],
        "camera": {"eye": [520, -330, 420], "target": [200, 150, 20], "up": [0, 0, 1], "fov": 40},
    }
    with open(os.path.join(HERE, "terrain.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    arch()
    pipe()
    wave()
    terrain()

#!/usr/bin/python3
"""Write the four rigid wall meshes (ASCII STL) of the biaxial box into meshes/.

Geometry of the published sample (scale 1): walls at x = 0, x = W, y = 0, y = H with
W = 0.075 m, H = 0.150 m; z extent +-0.05 m (thin periodic z of the 2D box).
The platens (bottom, top) reach 20 % of W beyond each side wall and the side walls
20 % of H beyond each platen, so the corners stay closed while walls move; all nodes
stay inside the simulation box written by scripts/generate_sample.py (margin 30 %).
in.prepare loads them with `scale ${scale}` for any sample size (the z extent scales
too; it stays far larger than the largest disk radius, 1.5 mm, at scale >= 0.1), and
scripts/generate_sample.py gives the box the same z extent, +-0.05 m x scale: LIGGGHTS
needs the box z extent to follow the meshes' (in.prepare explains why and checks it).

Each wall is cut into strips of at most --seg (15 mm) along its length, two triangles
each: LIGGGHTS 3.8 aborts with "assertion failed (./src/region_neighbor_list_I.h:165)"
when a wall of 210 mm x 100 mm is made of only two triangles (measured; 4 or more
strips per wall run).

    /usr/bin/python3 make_meshes.py [--out meshes] [--seg 0.015]
"""
import argparse
import math
import os

W, H, Z, EXT = 0.075, 0.150, 0.05, 0.2


def strip_wall(name, p, q, seg):
    """Wall from p to q (x, y) over z in [-Z, Z], cut in strips of length <= seg."""
    n = max(1, int(math.ceil(math.hypot(q[0] - p[0], q[1] - p[1]) / seg - 1e-9)))
    out = ["solid %s" % name]
    for k in range(n):
        a = [p[i] + (q[i] - p[i]) * k / n for i in range(2)]
        b = [p[i] + (q[i] - p[i]) * (k + 1) / n for i in range(2)]
        v = [(a[0], a[1], -Z), (b[0], b[1], -Z), (b[0], b[1], Z), (a[0], a[1], Z)]
        for tri in ((v[0], v[1], v[2]), (v[0], v[2], v[3])):
            out.append("  facet normal 0 0 0\n    outer loop")
            out += ["      vertex %.9g %.9g %.9g" % t for t in tri]
            out.append("    endloop\n  endfacet")
    out.append("endsolid %s\n" % name)
    return "\n".join(out), n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "meshes"))
    ap.add_argument("--seg", type=float, default=0.015, help="longest strip [m] (0.015)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    x0, x1 = -EXT * W, (1 + EXT) * W
    y0, y1 = -EXT * H, (1 + EXT) * H
    walls = {"bottom": ((x0, 0), (x1, 0)), "top": ((x0, H), (x1, H)),
             "left": ((0, y0), (0, y1)), "right": ((W, y0), (W, y1))}
    for name, (p, q) in walls.items():
        text, n = strip_wall(name, p, q, a.seg)
        with open(os.path.join(a.out, name + ".stl"), "w") as f:
            f.write(text)
        print("wrote %s: %d strips, %d triangles" % (os.path.join(a.out, name + ".stl"), n, 2 * n))


if __name__ == "__main__":
    main()

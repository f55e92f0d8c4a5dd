#!/usr/bin/python3
"""Generate the 2D biaxial sample: disks at HALF size, without overlap, in a box.

Writes a LIGGGHTS data file (atom_style granular: ``atom-ID type diameter density
x y z``, z = 0) whose disks the preparation script (examples/biaxial/in.prepare)
grows to full size.

Size distribution ("uniform by mass" between d_min = 0.5 mm and d_max = 3 mm)
----------------------------------------------------------------------------
In 2D the mass of a disk is m = pi d^2/4 * rho (unit thickness).  "Uniform by
mass" means the mass fraction carried by diameters in [d, d + dd] is the same for
every d:  g(d) = 1/(d_max - d_min).  The number pdf is therefore
    f(d) = g(d)/d^2 / int(g/d^2) = [d_min d_max/(d_max - d_min)] / d^2 ,
with number CDF F(d) = (1/d_min - 1/d)/(1/d_min - 1/d_max), sampled by inversion
    d(u) = 1 / (1/d_min - u (1/d_min - 1/d_max)),  u in (0, 1).
The mass CDF is linear, so D50 by mass = (d_min + d_max)/2 = 1.75 mm
(the number median is 2 d_min d_max/(d_min + d_max) = 0.857 mm), and
E[d^2] = d_min d_max, i.e. a mean disk area of pi d_min d_max/4 = 1.178 mm^2.

The u values are stratified (u_i = (i + 0.5)/N in shuffled order, one random
jitter per stratum), so that every sample, even a small one, follows the law
closely; the count N is the smallest such that the full-size disks fill
(1 - porosity) of the box:  N = ceil((1 - n) W H / (pi d_min d_max / 4))
(8 403 for 75 x 150 mm and n = 0.12).  in.prepare grows to the exact porosity.

Placement: random sequential addition, largest disk first, at half diameter,
centres kept one FULL radius away from the walls (so growing never pushes a disk
into a wall), overlap test against a uniform cell grid.

Deterministic: the same options (and numpy's PCG64 generator) give the same file.
"""
import argparse
import math
import os
import sys

import numpy as np

from liggghts_membrane.grains import d50_by_mass

MARGIN = 0.3   # the box beyond the walls, a fraction of the width and height (--margin)


def diameters(n, dmin, dmax, rng):
    """n full-size diameters, uniform by mass on [dmin, dmax], stratified in u."""
    u = (np.arange(n) + rng.random(n)) / n
    rng.shuffle(u)
    return 1.0 / (1.0 / dmin - u * (1.0 / dmin - 1.0 / dmax))


def place(rhalf, rfull, width, height, rng, max_tries):
    """Random sequential addition of disks of radius rhalf (sorted descending)."""
    n = len(rhalf)
    cell = 2.0 * rhalf.max()            # a disk overlaps only disks in the 3x3 cells
    nx = max(1, int(width / cell))
    ny = max(1, int(height / cell))
    cx, cy = width / nx, height / ny
    grid = [[[] for _ in range(ny)] for _ in range(nx)]
    pos = np.zeros((n, 2))
    for i in range(n):
        r, m = rhalf[i], rfull[i]
        if width - 2 * m <= 0 or height - 2 * m <= 0:
            sys.exit("generate_sample.py: the box %g x %g m is too small for a disk of diameter "
                     "%g m: a larger --scale (or --width, --height) or a smaller --dmax"
                     % (width, height, 2 * m))
        for _ in range(max_tries):
            x = m + rng.random() * (width - 2 * m)
            y = m + rng.random() * (height - 2 * m)
            ix = min(int(x / cx), nx - 1)
            iy = min(int(y / cy), ny - 1)
            ok = True
            for jx in range(max(ix - 1, 0), min(ix + 2, nx)):
                for jy in range(max(iy - 1, 0), min(iy + 2, ny)):
                    for j in grid[jx][jy]:
                        dx = x - pos[j, 0]
                        dy = y - pos[j, 1]
                        s = r + rhalf[j]
                        if dx * dx + dy * dy < s * s:
                            ok = False
                            break
                    if not ok:
                        break
                if not ok:
                    break
            if ok:
                pos[i] = (x, y)
                grid[ix][iy].append(i)
                break
        else:
            sys.exit("generate_sample.py: could not place disk %d of %d after %d tries (--max-tries): "
                     "the box is too full at half size; a higher --porosity or a larger --max-tries"
                     % (i + 1, n, max_tries))
    return pos


MAX_DISKS = 10_000_000   # ~1 GB of data file and hours of placement: beyond any run of this project


def disk_count(a):
    """The number of disks that fill (1 - porosity) of the box at full size (a float:
    inf or beyond MAX_DISKS for absurd options)."""
    width, height = a.width * a.scale, a.height * a.scale
    mean_area = math.pi * a.dmin * a.dmax / 4.0
    return (1.0 - a.porosity) * width * height / mean_area


def check_args(p, a):
    """Every option in its range, or p.error (exit 2) naming it, its value and the range."""
    def bad(option, value, need):
        p.error(f"{option} {value}: needs {need}")

    for option, value, need in (("--width", a.width, "a box width [m] > 0"),
                                ("--height", a.height, "a box height [m] > 0"),
                                ("--scale", a.scale, "a size factor > 0 (1 = the published sample)"),
                                ("--dmin", a.dmin, "a diameter [m] > 0"),
                                ("--dmax", a.dmax, "a diameter [m] > 0"),
                                ("--density", a.density, "a particle density [kg/m^3] > 0")):
        if not (math.isfinite(value) and value > 0):
            bad(option, value, need)
    if a.zhalf is not None and not (math.isfinite(a.zhalf) and a.zhalf > 0):
        bad("--zhalf", a.zhalf, "a half z extent [m] > 0 (or leave it out: 0.05 x scale)")
    if not (math.isfinite(a.porosity) and 0 <= a.porosity < 1):
        bad("--porosity", a.porosity, "a porosity from 0 to below 1 (0.12)")
    if not (math.isfinite(a.margin) and 0 <= a.margin <= 100):
        bad("--margin", a.margin, "a fraction of width and height from 0 to 100 (0.3)")
    if a.dmin > a.dmax:
        p.error(f"--dmin {a.dmin} > --dmax {a.dmax}: the smallest diameter must not exceed the largest")
    if not 0 <= a.seed < 2 ** 63:
        bad("--seed", a.seed, "an integer from 0 to 2^63 - 1")
    if not 1 <= a.ntypes <= 1000:
        bad("--ntypes", a.ntypes, "an integer from 1 to 1000 (3: soil, membrane, walls)")
    if a.max_tries < 1:
        bad("--max-tries", a.max_tries, "an integer >= 1")
    n = disk_count(a)
    if not n > 0:
        p.error(f"--porosity {a.porosity} with a box {a.width * a.scale:g} x {a.height * a.scale:g} m "
                "holds no disk: a larger --scale or a lower --porosity")
    if not n <= MAX_DISKS:
        p.error(f"{n:.3g} disks (--scale {a.scale:g}, box {a.width * a.scale:g} x "
                f"{a.height * a.scale:g} m, d {a.dmin:g}-{a.dmax:g} m): more than {MAX_DISKS:,}; "
                "a smaller --scale (8: 538 000 disks)")
    folder = os.path.dirname(os.path.abspath(a.out))
    if os.path.isdir(a.out) or not os.path.isdir(folder):
        p.error(f"--out {a.out}: " + ("a folder; give a file name" if os.path.isdir(a.out)
                                      else f"no folder {os.path.dirname(a.out) or '.'}"))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--width", type=float, default=0.075, help="box width at scale 1 [m] (0.075)")
    p.add_argument("--height", type=float, default=0.150, help="box height at scale 1 [m] (0.150)")
    p.add_argument("--scale", type=float, default=1.0,
                   help="size factor of the sample: box sides x scale, disk count x scale^2, "
                        "disk sizes unchanged (1 = published sample, ~8400 disks)")
    p.add_argument("--seed", type=int, default=12345, help="random seed (12345)")
    p.add_argument("--dmin", type=float, default=0.5e-3, help="smallest full diameter [m] (0.5e-3)")
    p.add_argument("--dmax", type=float, default=3.0e-3, help="largest full diameter [m] (3e-3)")
    p.add_argument("--porosity", type=float, default=0.12,
                   help="porosity of the full-size disks that sets the count (0.12)")
    p.add_argument("--density", type=float, default=2e8, help="particle density [kg/m^3] (2e8)")
    p.add_argument("--margin", type=float, default=MARGIN,
                   help="simulation box beyond the walls, as a fraction of width/height (0.3): "
                        "room for the side walls to move out")
    p.add_argument("--zhalf", type=float, default=None,
                   help="half z extent of the thin periodic box [m] (default 0.05 x scale: the z extent "
                        "of the wall meshes, examples/biaxial/make_meshes.py, which in.prepare scales "
                        "with the sample; in.prepare refuses a data file whose box differs)")
    p.add_argument("--ntypes", type=int, default=3,
                   help="atom types declared (3): 1 = soil, 2 = membrane (reserved), 3 = walls")
    p.add_argument("--max-tries", type=int, default=100000)
    p.add_argument("--out", default="sample.data", help="output data file (sample.data)")
    a = p.parse_args()
    check_args(p, a)

    width, height = a.width * a.scale, a.height * a.scale
    rng = np.random.Generator(np.random.PCG64(a.seed))
    n = int(math.ceil(disk_count(a)))
    d = np.sort(diameters(n, a.dmin, a.dmax, rng))[::-1]
    rfull = 0.5 * d
    rhalf = 0.25 * d
    pos = place(rhalf, rfull, width, height, rng, a.max_tries)

    solid = math.pi * np.sum(rfull ** 2)
    por_full = 1.0 - solid / (width * height)
    por_half = 1.0 - 0.25 * solid / (width * height)
    # D50 by mass of the drawn sample
    d50 = d50_by_mass(d, 2)
    mx, my = a.margin * width, a.margin * height
    # z: the box must follow the meshes (their z extent scales with the sample): LIGGGHTS
    # bins the mesh elements, and their periodic ghost images in z, over the box only
    # (surface_mesh_I.h, RegionNeighborList); with a box thinner than the elements
    # (rBound > box z) it makes ghost images two periods away, outside the bins, and
    # aborts with "assertion failed (./src/region_neighbor_list_I.h:165)"
    zhalf = a.zhalf if a.zhalf is not None else 0.05 * a.scale
    with open(a.out, "w") as f:
        f.write("LIGGGHTS data: %d disks at HALF size, uniform by mass %g-%g m (full), box %g x %g m, "
                "seed %d, scale %g, full-size porosity %.6f, half-size porosity %.6f, D50(mass) %.6g m, "
                "walls x 0 %.9g y 0 %.9g\n\n"
                % (n, a.dmin, a.dmax, width, height, a.seed, a.scale, por_full, por_half, d50, width, height))
        f.write("%d atoms\n" % n)
        f.write("%d atom types\n\n" % a.ntypes)
        f.write("%.9g %.9g xlo xhi\n" % (-mx, width + mx))
        f.write("%.9g %.9g ylo yhi\n" % (-my, height + my))
        f.write("%.9g %.9g zlo zhi\n\n" % (-zhalf, zhalf))
        f.write("Atoms\n\n")
        for i in range(n):
            f.write("%d 1 %.9g %.9g %.9g %.9g 0\n" % (i + 1, 2 * rhalf[i], a.density, pos[i, 0], pos[i, 1]))
    print("wrote %s: %d disks, box %.6g x %.6g m, full-size porosity %.5f (half size %.5f), "
          "D50 by mass %.4g mm, d %.4g-%.4g mm (full)"
          % (a.out, n, width, height, por_full, por_half, d50 * 1e3, d.min() * 1e3, d.max() * 1e3))


if __name__ == "__main__":
    main()

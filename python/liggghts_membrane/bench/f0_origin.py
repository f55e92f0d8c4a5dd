#!/usr/bin/python3
"""Where the large mean contact force of the rigid-wall case comes from.

The published comparison reports a larger mean normal contact force f0 with rigid
walls than with the membrane. This benchmark shears samples with both boundaries and
records (bench/f0_origin.inc) f0 of the disk-disk contacts (the OUT table's f0), f0
with the wall contacts counted as well (compute fabric walls yes), and f0 of the
contacts between disks at least 5 D50 away from every wall for the whole shear
(compute fabric region). It tabulates their means over the last 2 % of axial strain.

    /usr/bin/python3 bench/f0_origin.py [--scale 0.5] [--seeds 12345] [--strain 0.10] [--jobs 2]

Writes bench/f0_origin.csv and .md (runs kept under out/f0_origin/).
"""
import argparse
import concurrent.futures as cf
import csv
import os

import numpy as np

from liggghts_membrane.bench.common import HERE, ROOT, prepare, shear
from liggghts_membrane.readers import read_columns

EXTRA = os.path.join(HERE, "f0_origin.inc")
COLUMNS = ["f0", "f0_walls", "f0_inner"]


def one(case, seed, scale, strain, rundir):
    folder = os.path.join(rundir, "scale%g_seed%d" % (scale, seed))
    restart = prepare(scale, seed, folder)
    out = os.path.join(folder, "shear_%s.txt" % case)
    shear(case, restart, out, {"eatarget": strain, "extra": EXTRA})
    t, _ = read_columns(out + ".f0")
    last = t["ea"] >= t["ea"][-1] - 0.02
    row = {"case": case, "seed": seed}
    for c in COLUMNS:
        row[c] = float(np.mean(t[c][last]))
    row["contacts_inner"] = float(np.mean(t["contacts_inner"][last]))
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scale", type=float, default=0.5)
    ap.add_argument("--seeds", type=int, nargs="+", default=[12345])
    ap.add_argument("--strain", type=float, default=0.10)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    rundir = os.path.join(ROOT, "out", "f0_origin")
    with cf.ThreadPoolExecutor(a.jobs) as pool:
        list(pool.map(lambda s: prepare(a.scale, s, os.path.join(rundir, "scale%g_seed%d" % (a.scale, s))), a.seeds))
        rows = [j.result() for j in [pool.submit(one, case, s, a.scale, a.strain, rundir)
                                     for s in a.seeds for case in ("rigid", "membrane")]]
    with open(os.path.join(HERE, "f0_origin.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = ["# The origin of the rigid-wall mean contact force", "",
             "`/usr/bin/python3 bench/f0_origin.py --scale %g --seeds %s` (default rate, to %g axial strain): "
             "mean f0 [N] over the last 2 %% of strain; f0 = disk-disk contacts (the OUT table), with walls = "
             "the wall contacts counted too, inner = contacts between disks at least 5 D50 from every wall."
             % (a.scale, " ".join(map(str, a.seeds)), a.strain), "",
             "| case | seed | f0 | f0 with walls | f0 inner | inner contacts |", "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %d | %.2f | %.2f | %.2f | %.0f |" % (r["case"], r["seed"], r["f0"], r["f0_walls"],
                                                               r["f0_inner"], r["contacts_inner"]))
    for s in a.seeds:
        rg = next(r for r in rows if r["seed"] == s and r["case"] == "rigid")
        mb = next(r for r in rows if r["seed"] == s and r["case"] == "membrane")
        lines.append("| rigid / membrane | %d | %.3f | %.3f | %.3f | |"
                     % (s, rg["f0"] / mb["f0"], rg["f0_walls"] / mb["f0_walls"], rg["f0_inner"] / mb["f0_inner"]))
    with open(os.path.join(HERE, "f0_origin.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Coordination at 100 kPa against the porosity the disks are grown to.

The published procedure states that growth to a porosity of 0.12-0.14 gives
at least three contacts per disk. This benchmark prepares samples with
examples/biaxial/in.prepare at growth porosities n0 (several seeds each) and
tabulates what its PREPARED line reports at 100 kPa: the final porosity,
C_n (contacts per disk, rattlers included), Z_m (rattlers excluded) and the
rattler fraction, as mean and range over the seeds.

    /usr/bin/python3 bench/porosity_coordination.py [--scale 0.25] [--seeds 1 2 3]
        [--porosities 0.10 0.12 0.14 0.16] [--jobs 2]

Writes bench/porosity_coordination_scale<scale>.csv and .md (runs are kept
under out/porosity_coordination/ and reused).
"""
import argparse
import concurrent.futures as cf
import csv
import os
import time

from liggghts_membrane.bench import common
from liggghts_membrane.bench.common import HERE, ROOT
from liggghts_membrane.readers import key_value_lines

# the key=value line 'prepared ...' of in.prepare: {our name: its key}
FIELDS = {"porosity": "porosity", "C_n": "cn_fabric", "Z_m": "zm", "rattlers": "rattlers",
          "min_wall": "min_wall_ratio"}


def prepared_values(screen_text):
    lines = key_value_lines(screen_text, "prepared")
    if not lines:
        return None
    return {key: float(lines[0].get(name, float("nan"))) for key, name in FIELDS.items()}


def prepare(scale, seed, n0, rundir):
    """One preparation at growth porosity n0 (reused when it finished): its PREPARED
    values and the seconds it took (about 0 when reused)."""
    folder = os.path.join(rundir, "scale%g_seed%d_n%g" % (scale, seed, n0))
    t0 = time.time()
    common.prepare(scale, seed, folder, {"n0": n0})
    with open(os.path.join(folder, "screen.prepare")) as f:
        values = prepared_values(f.read())
    return values, time.time() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scale", type=float, default=0.25)
    ap.add_argument("--seeds", type=int, nargs="+", default=[12345, 13345, 14345])
    ap.add_argument("--porosities", type=float, nargs="+", default=[0.10, 0.12, 0.14, 0.16])
    ap.add_argument("--jobs", type=int, default=2, help="preparations at a time, 1 rank each")
    ap.add_argument("--rundir", default=os.path.join(ROOT, "out", "porosity_coordination"))
    args = ap.parse_args()

    t0 = time.time()
    tasks = [(n0, seed) for n0 in args.porosities for seed in args.seeds]
    with cf.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {t: pool.submit(prepare, args.scale, t[1], t[0], args.rundir) for t in tasks}
        results = {t: f.result() for t, f in futures.items()}

    rows = []
    for (n0, seed), (values, took) in results.items():
        rows.append(dict(n0=n0, seed=seed, seconds=round(took, 1), **values))
    stem = os.path.join(HERE, "porosity_coordination_scale%g" % args.scale)
    with open(stem + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    md = ["# Coordination at 100 kPa against the growth porosity\n",
          "Command: `/usr/bin/python3 bench/porosity_coordination.py --scale %g --seeds %s "
          "--porosities %s`  " % (args.scale, " ".join(map(str, args.seeds)),
                                  " ".join("%g" % n for n in args.porosities)),
          "Each cell: mean [min, max] over %d seeds (examples/biaxial/in.prepare, 1 rank; "
          "this invocation took %.1f min).\n" % (len(args.seeds), (time.time() - t0) / 60.0),
          "A minimum wall stress of 0 means the grown packing carried no load (too loose to "
          "jam at that porosity): the consolidation then starts from zero stress.\n",
          "| growth porosity n0 | porosity at 100 kPa | C_n (rattlers in) | Z_m (rattlers out) "
          "| rattler fraction | min wall stress / σ3 |",
          "|---|---|---|---|---|---|"]
    for n0 in args.porosities:
        cells = []
        for key in ("porosity", "C_n", "Z_m", "rattlers", "min_wall"):
            v = [r[key] for r in rows if r["n0"] == n0]
            cells.append("%.3f [%.3f, %.3f]" % (sum(v) / len(v), min(v), max(v)))
        md.append("| %g | %s |" % (n0, " | ".join(cells)))
    with open(stem + ".md", "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


if __name__ == "__main__":
    main()

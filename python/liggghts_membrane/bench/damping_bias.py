#!/usr/bin/python3
"""What the damping adds to the platen stress, for each damping setting and rate.

The shear scripts (examples/biaxial/in.shear_rigid, damping.inc) write, in the
column sdamp of their OUT table, the moment of the damping force about the
sample centre over the area, sum_i F_d,y (y_i - y_c) / (W H): in the static
balance of a column under body forces this is what the damping adds to the
platen stress s1 over the mean internal sigma_yy. This benchmark shears one
prepared sample with rigid walls for each setting and rate to a small axial
strain and tabulates the mean and standard deviation of sdamp / sigma_3 over
the rows after the platen speed ramp, next to the estimate for viscous drag on
the affine field, gamma rate N H / (12 W).

    /usr/bin/python3 bench/damping_bias.py [--restart out/biaxial/prepared.restart]
        [--rates 0.0025 0.01] [--strain 0.005] [--np 1] [--jobs 2]

Writes bench/damping_bias.csv and .md (runs kept under out/damping_bias/, reused).
"""
import argparse
import concurrent.futures as cf
import csv
import os
import re
import sys

import numpy as np

from liggghts_membrane.bench.common import ROOT, HERE, script_parameters, shear
from liggghts_membrane.params import number

# the confining stress [Pa], default viscous damping [N s/m], local damping and rate [1/s]
# of the shear scripts, read from them
SIGMA3, GVISC, ADAMP, RATE0 = (number(script_parameters("in.shear_rigid"), n)
                               for n in ("sigma", "gvisc", "adamp", "rate"))

# name -> the -var settings of in.shear_rigid
SETTINGS = {
    "viscous %g N s/m, relative to the affine field (default)" % GVISC: {"damping": 0, "affine": 1},
    "viscous %g N s/m, absolute velocity" % GVISC: {"damping": 0, "affine": 0},
    "local damping alpha %g (the paper's)" % ADAMP: {"damping": 1},
}


def bias(restart, rate, strain, name, settings, np_, rundir):
    tag = "%s_rate%g" % (re.sub(r"[^a-z0-9]+", "_", name.split(",")[0] + name.split(",")[-1]), rate)
    # the same number of steps at every rate: the strain asked for is that at RATE0
    run = shear("rigid", restart, os.path.join(rundir, tag + ".txt"),
                dict(settings, rate=rate, eatarget=strain * rate / RATE0), np_)
    after = run.after_ramp()
    ratio = run.table["sdamp"][after] / SIGMA3
    estimate = (GVISC * rate * run.atoms * np.mean(run.table["H"][after])
                / (12 * np.mean(run.table["W"][after])) / SIGMA3)
    return {"setting": name, "rate": rate, "atoms": run.atoms, "rows": int(after.sum()),
            "mean_pct": 100 * ratio.mean(), "sd_pct": 100 * ratio.std(ddof=1),
            "affine_estimate_pct": 100 * estimate}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--restart", default=os.path.join(ROOT, "out", "biaxial", "prepared.restart"))
    ap.add_argument("--rates", type=float, nargs="+", default=[0.02 / 60, RATE0, 0.01])
    ap.add_argument("--strain", type=float, default=0.005, help="axial strain at the scripts' rate (%g /s); at "
                    "another rate the strain of the same number of steps" % RATE0)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    restart = os.path.abspath(a.restart)
    if not os.path.exists(restart):
        sys.exit("no prepared sample at %s: run ./run.sh first (or give --restart)" % os.path.relpath(restart, ROOT))
    rundir = os.path.join(ROOT, "out", "damping_bias")
    os.makedirs(rundir, exist_ok=True)
    with cf.ThreadPoolExecutor(a.jobs) as pool:
        jobs = [pool.submit(bias, restart, rate, a.strain, name, args, a.np, rundir)
                for rate in a.rates for name, args in SETTINGS.items()]
        rows = [j.result() for j in jobs]

    with open(os.path.join(HERE, "damping_bias.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    rows.sort(key=lambda r: (r["rate"], list(SETTINGS).index(r["setting"])))
    lines = ["# Damping bias on the platen stress",
             "",
             "`/usr/bin/python3 bench/damping_bias.py` (rigid walls, %d disks, sample %s, axial strain "
             "to %g at %g /s, the same number of steps at the other rates; the rows after the platen "
             "speed ramp). sdamp / sigma_3 = sum F_d,y (y - y_c) / (W H "
             "sigma_3), mean and standard deviation over the rows; the last column is the drag of fix viscous "
             "%g N s/m on the affine field, gamma rate N H / (12 W sigma_3)."
             % (rows[0]["atoms"], os.path.relpath(restart, ROOT), a.strain, RATE0, GVISC),
             "",
             "| setting | rate [1/s] | rows | sdamp / sigma_3 [%] | sd [%] | affine-drag estimate [%] |",
             "|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %g | %d | %+.3f | %.3f | %.3f |" % (r["setting"], r["rate"], r["rows"], r["mean_pct"],
                                                               r["sd_pct"], r["affine_estimate_pct"]))
    with open(os.path.join(HERE, "damping_bias.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

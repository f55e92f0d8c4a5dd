#!/usr/bin/python3
"""Density scaling: the curves at rho = 2e8 kg/m^3 (the scripts' default) and at the
real density of quartz, 2650 kg/m^3, at one inertial number I = rate D50 sqrt(rho/p).

Lowering the density by s^2 (s = sqrt(2e8/2650) = 274.7) at one I means a rate s
times higher; for the same trajectories every other time scale of the scripts follows:
time step dt/s, viscous damping gvisc/s (a force gvisc v with v s times larger), servo
speed limit vmax s (the servo gain 1/(K_n dt) follows from dt). The contact law has no
rate dependence (no contact damping, no gravity), so the two runs are the same
equations in another time unit: they may differ only by round-off, amplified by the
chaotic dynamics of the packing. The benchmark shears quarter-size samples (several
seeds) with both densities and compares the difference between densities with the
sample-to-sample scatter.

    /usr/bin/python3 bench/density_scaling.py [--scale 0.25] [--seeds 12345 13345 14345]
        [--strain 0.05] [--cases rigid [membrane]] [--jobs 2]

Writes bench/density_scaling.csv and .md (runs kept under out/density_scaling/).
"""
import argparse
import concurrent.futures as cf
import csv
import math
import os

import numpy as np

from liggghts_membrane.bench.common import HERE, ROOT, prepare, script_parameters, shear
from liggghts_membrane.curves import analyse_curves
from liggghts_membrane.params import number

# the defaults of in.shear_* (shear_setup.inc), read from the scripts
RHO, DT, RATE, GVISC, VMAX = (number(script_parameters("in.shear_rigid"), n)
                              for n in ("rho", "dt", "rate", "gvisc", "vmax"))
RHO_REAL = 2650.0     # quartz [kg/m^3]


def settings_for(rho, strain):
    s = math.sqrt(RHO / rho)
    return {"rho": rho, "dt": DT / s, "rate": RATE * s, "gvisc": GVISC / s, "vmax": VMAX * s, "eatarget": strain}


def one(case, seed, rho, scale, strain, rundir):
    folder = os.path.join(rundir, "scale%g_seed%d" % (scale, seed))
    restart = prepare(scale, seed, folder)
    run = shear(case, restart, os.path.join(folder, "shear_%s_rho%g.txt" % (case, rho)), settings_for(rho, strain))
    c = analyse_curves(run.table)
    t = run.table
    common = np.linspace(0.001, 0.999 * min(t["ea"][-1], strain), 200)
    curve = np.interp(common, t["ea"], t["s1/s3"])
    return {"case": case, "seed": seed, "rho": rho, "peak": c["peak_ratio"], "ea_peak": c["ea_peak"],
            "ratio_end": c["ratio_end"], "ev_end": float(t["ev"][-1]), "curve": curve}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scale", type=float, default=0.25)
    ap.add_argument("--seeds", type=int, nargs="+", default=[12345, 13345, 14345])
    ap.add_argument("--strain", type=float, default=0.05)
    ap.add_argument("--cases", nargs="+", default=["rigid"])
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    rundir = os.path.join(ROOT, "out", "density_scaling")
    with cf.ThreadPoolExecutor(a.jobs) as pool:
        # prepare each sample once before its shears run side by side
        list(pool.map(lambda seed: prepare(a.scale, seed, os.path.join(rundir, "scale%g_seed%d" % (a.scale, seed))),
                      a.seeds))
        jobs = [pool.submit(one, case, seed, rho, a.scale, a.strain, rundir)
                for case in a.cases for seed in a.seeds for rho in (RHO, RHO_REAL)]
        rows = [j.result() for j in jobs]

    keys = ["peak", "ea_peak", "ratio_end", "ev_end"]
    with open(os.path.join(HERE, "density_scaling.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "seed", "rho"] + keys)
        for r in rows:
            w.writerow([r["case"], r["seed"], r["rho"]] + ["%.6g" % r[k] for k in keys])

    lines = ["# Density scaling at one inertial number", "",
             "`/usr/bin/python3 bench/density_scaling.py --scale %g --seeds %s --strain %g` (%s; rho = 2e8 at rate %g /s "
             "against rho = 2650 at rate %.4g /s, dt, gvisc and vmax scaled with them). Per quantity: the largest "
             "|difference| between the two densities over the seeds, against the sample scatter (standard "
             "deviation over the seeds at rho = 2e8); the curves: the largest |difference| of s1/s3 along "
             "the strain over the seeds." % (a.scale, " ".join(map(str, a.seeds)), a.strain, ", ".join(a.cases), RATE,
                                              settings_for(RHO_REAL, a.strain)["rate"]), "",
             "| case | quantity | max abs(rho 2650 - rho 2e8) | sample scatter (sd) | ratio |", "|---|---|---|---|---|"]
    for case in a.cases:
        pairs = [(next(r for r in rows if r["case"] == case and r["seed"] == s and r["rho"] == RHO),
                  next(r for r in rows if r["case"] == case and r["seed"] == s and r["rho"] == RHO_REAL))
                 for s in a.seeds]
        for k in keys:
            diff = max(abs(b[k] - h[k]) for h, b in pairs)
            sd = float(np.std([h[k] for h, _ in pairs], ddof=1))
            lines.append("| %s | %s | %.3g | %.3g | %.3g |" % (case, k, diff, sd, diff / sd if sd > 0 else float("nan")))
        curve_diff = max(float(np.max(np.abs(b["curve"] - h["curve"]))) for h, b in pairs)
        curve_sd = float(np.max(np.std([h["curve"] for h, _ in pairs], axis=0, ddof=1)))
        lines.append("| %s | s1/s3 along the curve | %.3g | %.3g (largest) | %.3g |"
                     % (case, curve_diff, curve_sd, curve_diff / curve_sd))
    with open(os.path.join(HERE, "density_scaling.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

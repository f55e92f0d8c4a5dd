#!/usr/bin/python3
"""The biaxial examples beyond 8 000 disks: a scale-2 sample (33 614 disks, 150 x 300 mm,
the size that aborted with "assertion failed (./src/region_neighbor_list_I.h:165)" in a
box of fixed z extent) prepared briefly (a few thousand steps: grown to porosity 0.12 and
consolidated towards 100 kPa, not to equilibrium) and sheared for a few hundred steps
with rigid side walls and with fix membrane2d, on NP ranks. Checks that it runs and
prints sane values:

- the box z extent is +-0.05 m x 2 (generate_sample.py) and no LIGGGHTS error;
- the preparation reaches porosity 0.12 when grown and writes its PREPARED lines;
  its four wall stresses are positive and within a factor 2 of 100 kPa;
- both shears hold (a START line), keep all 33 614 atoms, and write finite output
  lines: sigma_1 > 0, stress ratio within 0.5-10, rigid sigma_3 within a factor 2 of
  100 kPa, membrane: the applied 100 kPa.  The briefly prepared packing is not in
  equilibrium (its wall stresses are 120-135 kPa, and held 300 steps only, it pushes
  the platens to s1/s3 ~ 5 within 100 steps while ea ~ 1e-8): physical values are
  tested on the quarter-size sample (biaxial_small.py), here only that the large
  sample runs through all three scripts.

    biaxial_large.py EXE NP
"""
import math
import os
import subprocess
import sys
import tempfile

from example_run import Checks, ROOT, run, table

NATOMS = 33614
# a brief preparation (5 000 steps): 25 growth stages of 80 steps under 10 x the viscous
# damping (m/gvisc = 2 ms; with the default 2000 N s/m growth this fast moves disks more
# than 5 % of their radius per step and the guard stops it), short relaxation and ramp,
# one equilibrium check each
PREPARE = ["-var", "nstage", "25", "-var", "nsgrow", "80", "-var", "gvisc", "20000", "-var", "nsrelax", "500",
           "-var", "nramp", "1500", "-var", "ncheck", "500", "-var", "maxcheck", "1"]
SHEAR = ["-var", "nsettle", "300", "-var", "interrupt", "300", "-var", "nout", "100", "-var", "ndump", "100000"]


def main():
    exe, np_ = os.path.abspath(sys.argv[1]), sys.argv[2]
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe]
    check = Checks()
    failures = check.failures

    with tempfile.TemporaryDirectory() as work:
        data, restart = os.path.join(work, "sample.data"), os.path.join(work, "prepared.restart")
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "generate_sample.py"),
                        "--scale", "2", "--seed", "7", "--out", data], check=True, stdout=subprocess.DEVNULL)
        with open(data) as f:
            head = f.read(2000)
        check("%d atoms" % NATOMS in head and "-0.1 0.1 zlo zhi" in head,
              "data file: %d disks, box z extent +-0.1 m" % NATOMS)
        out = run(mpi + ["-in", "in.prepare", "-var", "data", data, "-var", "out", restart, "-log", "none"]
                  + PREPARE, os.path.join(work, "prepare.txt"))
        check("ERROR" not in out, "prepare: no ERROR")
        grown = [l for l in out.splitlines() if l.startswith("grown: porosity")]
        por = float(grown[0].split()[2]) if grown else float("nan")
        check(abs(por - 0.12) < 1e-6, "grown to porosity %.6f = 0.12" % por)
        walls = [l for l in out.splitlines() if l.startswith("PREPARED walls")]
        st = [float(x) for x in walls[0].split("stresses l r b t")[1].split()[:4]] if walls else []
        check(len(st) == 4 and all(5e4 < x < 2e5 for x in st),
              "prepared wall stresses l r b t %s within a factor 2 of 100 kPa" % " ".join("%.0f" % x for x in st))

        for case in ("rigid", "membrane"):
            path = os.path.join(work, "shear_%s.txt" % case)
            out = run(mpi + ["-in", "in.shear_%s" % case, "-var", "restart", restart, "-var", "out", path,
                             "-log", "none"] + SHEAR, os.path.join(work, "%s.txt" % case))
            check("ERROR" not in out, "%s: no ERROR" % case)
            start = [l for l in out.splitlines() if l.startswith("START of shear")]
            check(bool(start), "%s: holding phase done" % case)
            print("     " + (start[0][:200] if start else ""))
            loops = [l for l in out.splitlines() if "Loop time" in l]
            check(bool(loops) and all("with %d atoms" % NATOMS in l for l in loops),
                  "%s: no atom lost (%d atoms)" % (case, NATOMS))
            t = table(path)
            rows = len(t.get("step", []))
            finite = rows > 0 and all(math.isfinite(v) for c in t.values() for v in c)
            check(rows >= 3 and finite, "%s: %d finite output lines" % (case, rows))
            for k in range(rows):
                print("     step %d ea %.2e s1 %.0f s3 %.0f s1/s3 %.3f" % (t["step"][k], t["ea"][k], t["s1"][k],
                                                                      t["s3"][k], t["s1/s3"][k]))
            if rows:
                ratio, s1, s3 = t["s1/s3"], t["s1"], t["s3"]
                check(all(s > 0 for s in s1) and all(0.5 < r < 10 for r in ratio),
                      "%s: sigma_1 > 0, stress ratio %.3f-%.3f within 0.5-10" % (case, min(ratio), max(ratio)))
                if case == "rigid":
                    check(all(5e4 < s < 2e5 for s in s3), "rigid: sigma_3 %.0f-%.0f Pa within a factor 2 of 100 kPa"
                          % (min(s3), max(s3)))
                else:
                    check(all(abs(s - 1e5) < 1e-6 for s in s3), "membrane: applied pressure 100 kPa")
    if failures:
        sys.exit("FAIL: %d check(s)" % len(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()

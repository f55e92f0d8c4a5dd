"""The rigid-boundary comparison (examples/triaxial/run_comparison.sh --quick's scripts)
on two small cuboid samples (W = 16 mm, about 400 spheres):

  prepared: the platen and the four side walls each within 2 % of p;
  sheared with the side walls: the walls' mean stress within 3 % of p after the hold,
    q rising above 0.3 p;
  sheared with the membrane: the platen within 10 % of p after the hold, the
    membrane's frames between the platens with lateral loads summing to zero, q
    rising above 0.3 p;
  compare_boundaries.py: the table has a row per measure with both boundaries and
    the paired difference, and the figure is written.

Usage: comparison_small.py EXE NP"""
import os
import sys
import tempfile

from example_run import ROOT, Checks, run, table
from triaxial_small import check_frames, vtk_frames
from liggghts_membrane.readers import key_value_lines

EXAMPLE = os.path.join(ROOT, "examples", "triaxial")
P = 1e5
SEEDS = ("86028121", "104395301")
SMALL = ["-var", "W", "0.016"]


def liggghts(exe, np_, args, log):
    return run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe] + args,
               log, cwd=EXAMPLE)


def main():
    exe, np_ = sys.argv[1], sys.argv[2]
    check = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        for seed in SEEDS:
            sample = os.path.join(tmp, "cuboid_" + seed)
            log = liggghts(exe, np_, ["-in", "in.cuboid_prepare", "-var", "seed", seed, "-var", "out",
                                      sample, "-var", "hfill", "0.06", "-var", "nsettle", "8000",
                                      "-var", "ncompress", "12000"] + SMALL, sample + ".log")
            got = key_value_lines(log, "cuboid_compressed")[0]     # in.cuboid_prepare's key=value line
            stresses = [got[k] for k in ("sigma1", "sxlo", "sxhi", "sylo", "syhi")]
            check(max(abs(s / P - 1) for s in stresses) < 0.02,
                  "seed %s prepared: platen and side walls at %s Pa" %
                  (seed, " ".join("%.0f" % s for s in stresses)))
            height = got["H"]
            for boundary in ("walls", "membrane"):
                out = os.path.join(tmp, "%s_%s" % (boundary, seed))
                log = liggghts(exe, np_, ["-in", "in.cuboid_shear", "-var", "sample", sample,
                                          "-var", "boundary", boundary, "-var", "out", out,
                                          "-var", "nhold", "2000", "-var", "vtkevery", "2000"]
                               + SMALL, out + ".log")
                held = key_value_lines(log, "cuboid_held")[0]
                sigma1, sigma3 = held["sigma1"], held["sigma3"]
                if boundary == "walls":
                    check(abs(sigma3 / P - 1) < 0.03, "seed %s walls held: sigma3 = %.0f Pa" %
                          (seed, sigma3))
                else:
                    check(abs(sigma1 / P - 1) < 0.10, "seed %s membrane held: sigma1 = %.0f Pa" %
                          (seed, sigma1))
                    check_frames(check, vtk_frames(out + "_membrane.pvd"), height)
                q = table(out + ".txt")["q[Pa]"]
                check(max(q) > 0.3 * P, "seed %s %s: q up to %.0f Pa" % (seed, boundary, max(q)))
        summary = run(["/usr/bin/python3", "compare_boundaries.py", tmp] + list(SEEDS),
                      os.path.join(tmp, "compare.log"), cwd=EXAMPLE)
        rows = [l for l in summary.splitlines() if l.startswith("| ") and "measure" not in l]
        check(len(rows) == 9 and all(l.count("±") == 3 for l in rows),
              "comparison table: %d rows with walls, membrane and their difference" % len(rows))
        check(os.path.getsize(os.path.join(tmp, "comparison.png")) > 10000, "comparison figure")
    if check.failures:
        sys.exit("FAIL: %d checks" % len(check.failures))


if __name__ == "__main__":
    main()

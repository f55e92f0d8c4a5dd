#!/usr/bin/python3
"""Resuming an interrupted shear (run.sh --paper) gives the output of an uninterrupted one.

A quarter-size sample (526 disks) is prepared and sheared to 0.2 % axial strain with
the paper preset's settings (local damping 0.7, side-wall servo without feed-forward,
restart files every 2 000 steps), once straight through and once stopped after 5 000
steps of the shear (the interruption: outputs written past the last restart file) and
resumed from the latest restart file with the splicing of liggghts_membrane.resume.
Checks, for each case:
- the spliced OUT table has the steps of the straight one, each once;
- every column equal to 1e-10 relative (the run goes in pieces that end on multiples of
  restartevery, each followed by write_restart, so the resumed run has the same piece
  ends, set-ups and servo-off first steps as the straight one: measured identical);
- the dump frames, rose blocks, ramp lines and membrane polylines of the spliced files
  are those of the straight run, byte for byte;
- the restart files are gone after clean.

    biaxial_resume.py EXE NP
"""
import os
import subprocess
import sys
import tempfile

import numpy as np

from example_run import Checks, ROOT, run
from liggghts_membrane import readers, resume

PAPER = ["-var", "damping", "1", "-var", "feedforward", "0", "-var", "restartevery", "2000",
         "-var", "eatarget", "0.002", "-var", "ndump", "2000"]
TOLERANCE = {"membrane": 1e-10, "rigid": 1e-10}



def main():
    exe, np_ = os.path.abspath(sys.argv[1]), sys.argv[2]
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe, "-log", "none"]
    check = Checks()
    failures = check.failures

    with tempfile.TemporaryDirectory() as tmp:
        data, restart = os.path.join(tmp, "sample.data"), os.path.join(tmp, "prepared.restart")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "generate_sample.py"), "--scale", "0.25",
                        "--seed", "12345", "--out", data], check=True, capture_output=True)
        run(mpi + ["-in", "in.prepare", "-var", "data", data, "-var", "out", restart], os.path.join(tmp, "prep"))
        for case in ("membrane", "rigid"):
            shear = mpi + ["-in", "in.shear_" + case] + PAPER
            straight = os.path.join(tmp, case + "_straight.txt")
            text = run(shear + ["-var", "restart", restart, "-var", "out", straight], straight + ".screen")
            check("SHEAR done" in text, "%s: the straight run finishes" % case)
            cut = os.path.join(tmp, case + "_cut.txt")
            text = run(shear + ["-var", "restart", restart, "-var", "out", cut, "-var", "interrupt", "5000"],
                       cut + ".screen")
            check("SHEAR done" not in text, "%s: the interrupted run stops early" % case)
            latest = resume.start_resume(cut, restart + ".walls")
            check(latest is not None and latest.endswith(".restart.%d" % max(resume.restart_steps(cut))),
                  "%s: resumes from the latest restart file (%s)" % (case, latest and os.path.basename(latest)))
            text = run(shear + ["-var", "restart", latest, "-var", "resume", "1", "-var", "start", cut + ".start",
                                "-var", "out", cut + ".part"], cut + ".part.screen")
            check("SHEAR done" in text, "%s: the resumed run finishes" % case)
            resume.finish_part(cut)

            a, b = readers.read_output(straight), readers.read_output(cut)
            check(np.array_equal(a["step"], b["step"]), "%s: same output steps (%d lines)" % (case, len(a["step"])))
            if np.array_equal(a["step"], b["step"]):
                worst, where = 0.0, ""
                for col in a.header:
                    x, y = a[col], b[col]
                    scale = np.maximum(np.abs(x), np.max(np.abs(x)) * 1e-6 + 1e-300)
                    d = float(np.max(np.abs(x - y) / scale))
                    if d > worst:
                        worst, where = d, col
                    if d > TOLERANCE[case]:
                        k = int(np.argmax(np.abs(x - y) / scale))
                        print("     %s %s: step %d straight %.12g resumed %.12g" % (case, col, a["step"][k], x[k], y[k]))
                check(worst <= TOLERANCE[case], "%s: resumed = straight to %.1e relative (worst %s, want <= %g)"
                      % (case, worst, where, TOLERANCE[case]))
            da = [s for s, _ in readers.dump_steps(straight + ".dump")]
            db = [s for s, _ in readers.dump_steps(cut + ".dump")]
            check(da == db, "%s: dump frames %s" % (case, db))
            ra = [s for s, _ in readers.read_rose(straight + ".rose")]
            rb = [s for s, _ in readers.read_rose(cut + ".rose")]
            check(ra == rb, "%s: rose blocks (%d)" % (case, len(rb)))
            for suffix in (".dump", ".rose", ".ramp") + ((".polyline",) if case == "membrane" else ()):
                with open(straight + suffix) as f1, open(cut + suffix) as f2:
                    same = f1.read() == f2.read()
                check(same, "%s: %s identical to the straight run's" % (case, suffix))
            resume.remove_restarts(cut)
            check(not resume.restart_steps(cut), "%s: restart files removed" % case)
    if failures:
        sys.exit("FAIL: %d check(s)" % len(failures))
    print("all checks passed")


if __name__ == "__main__":
    main()

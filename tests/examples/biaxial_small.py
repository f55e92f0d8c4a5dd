#!/usr/bin/python3
"""The biaxial examples, small: a quarter-size sample (526 disks) prepared and
sheared to 1 % axial strain with rigid walls and with fix membrane2d, on NP
ranks. Checks physical sanity that a broken example would fail:

- preparation reaches porosity 0.12 when grown and holds 100 kPa on the walls;
  the prepared sample meets the targets a quarter-size sample can meet
  (examples/biaxial/README.md): all four wall stresses within 1 % of 100 kPa,
  C_n >= 3.1 (rattlers included; 2.35 with the old procedure), rattlers
  <= 18 % (26 % before), and no wall stress fell below 0.9 sigma_3 during the
  consolidation (the printed minimum);
- both shear scripts start from the same holding phase (a START line each);
- the platen speed ramp: after it, sigma_1 from the platens and the Love-Weber
  sigma_yy with the wall contacts agree within 2 % (mean of the OUT.ramp lines
  after the ramp, against the difference at rest: 0 for rigid walls);
- no atom is lost in either shear run (thermo_modify lost error, and the count);
- the confining stress is held: rigid sigma_3 within 10 % of 100 kPa on every
  line after the first; membrane: the applied pressure is 100 kPa and the
  Love-Weber sigma_xx inside the membrane within 15 % of it on average;
- the stress ratio starts at 1 (+-0.1) and rises above 1.3;
- the rigid and the membrane runs of the same sample differ;
- the membrane run with 'every auto' (the default) and with a detection at
  every step give identical output tables;
- the stability guards stay quiet: no warning from fix stability/guard (time
  step, overlaps, inertial number) or from fix membrane2d (time step, chain
  speed, inertial number, lost chain) in any of the three runs;
- the ParaView files of both shears (-var vtkstrain, a frame every 0.5 % strain)
  read back with VTK's reader through their run.pvd agree with the run
  (paraview_checks.py), and the picture of the last frame shows them.

    biaxial_small.py EXE NP
"""
import os
import subprocess
import sys
import tempfile

from example_run import Checks, ROOT, run, table
import paraview_checks
from liggghts_membrane.readers import key_value_lines


def fields(screen):
    """The numbers of in.prepare's key=value line 'prepared ...' under this test's names."""
    lines = key_value_lines(screen, "prepared")
    keys = {"por": "porosity_grown", "cn": "cn_fabric", "zm": "zm", "rat": "rattlers",
            "lam_out": "lambda_out", "lam_in": "lambda_in", "R": "R", "minwall": "min_wall_ratio"}
    return {k: lines[0][name] for k, name in keys.items() if name in lines[0]} if lines else {}


def main():
    exe, np_ = os.path.abspath(sys.argv[1]), sys.argv[2]
    mpi = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe]
    check = Checks()
    failures = check.failures

    def check_quiet_guards(out, run_name):
        said = [l.strip() for l in out.splitlines()
                if l.startswith("WARNING: Fix stability/guard") or l.startswith("WARNING: Fix membrane2d")]
        check(not said, "%s: no guard warning%s" % (run_name, (" (got: %s)" % said[0]) if said else ""))

    with tempfile.TemporaryDirectory() as work:
        data, restart = os.path.join(work, "sample.data"), os.path.join(work, "prepared.restart")
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "scripts", "generate_sample.py"),
                        "--scale", "0.25", "--seed", "7", "--out", data], check=True,
                       stdout=subprocess.DEVNULL)
        out = run(mpi + ["-in", "in.prepare", "-var", "data", data, "-var", "out", restart,
                         "-log", "none"], os.path.join(work, "prepare.txt"))
        prepared = [l for l in out.splitlines() if l.startswith("PREPARED porosity")]
        check(len(prepared) == 1, "preparation finished")
        check_quiet_guards(out, "prepare")
        if prepared:
            f = fields(out)
            check(len(f) == 8, "prepared line has the porosity, C_n, Z_m, rattlers, lambda in/out, R, "
                  "min wall stress (%s)" % f)
            if len(f) == 8:
                check(abs(f["por"] - 0.12) < 1e-6, "porosity after growth %.6f = 0.12" % f["por"])
                check(f["cn"] >= 3.1, "prepared C_n %.3f >= 3.1 (rattlers included)" % f["cn"])
                check(f["rat"] <= 0.18, "prepared rattler fraction %.3f <= 0.18" % f["rat"])
                check(f["minwall"] >= 0.9, "min wall stress during consolidation %.3f sigma_3 >= 0.9" % f["minwall"])
                check(f["R"] < 1e-3, "unbalanced force ratio %.2e < 1e-3" % f["R"])
                check(f["zm"] > f["cn"] and f["lam_in"] > f["lam_out"], "Z_m > C_n and lambda with rattlers > without")
        walls = [l for l in out.splitlines() if l.startswith("PREPARED walls")]
        st = [float(x) for x in walls[0].split("stresses l r b t")[1].split()[:4]] if walls else []
        check(len(st) == 4 and all(abs(x / 1e5 - 1) < 0.01 for x in st),
              "prepared wall stresses l r b t %s within 1 %% of 100 kPa" % " ".join("%.0f" % x for x in st))

        runs = {}
        for case in ("rigid", "membrane"):
            table_path = os.path.join(work, "shear_%s.txt" % case)
            out = run(mpi + ["-in", "in.shear_%s" % case, "-var", "restart", restart,
                             "-var", "eatarget", "0.01", "-var", "out", table_path, "-var", "ndump", "100000",
                             "-var", "vtkstrain", "0.005", "-log", "none"], os.path.join(work, "%s.txt" % case))
            runs[case] = t = table(table_path)
            paraview_checks.check_run(check, case, table_path + ".paraview", t, 526,
                                      ["wb", "wt", "wl", "wr"] if case == "rigid" else ["wb", "wt"])
            paraview_checks.check_picture(check, case, table_path + ".paraview",
                                          os.path.join(work, "%s.png" % case))
            check_quiet_guards(out, case)
            start = [l for l in out.splitlines() if l.startswith("START of shear")]
            check(len(start) == 1, "%s: holding phase done (%s)" % (case, start[0][:120] if start else "no START line"))
            # the platen speed ramp: after it, the platen stress and the Love-Weber sigma_yy
            # with the wall contacts agree as well as at rest (first line, before the platens
            # move: exactly for rigid walls; the membrane case has a static offset, the
            # vertical part of the membrane forces on the chain disks, -5 % on this sample)
            ramp = table(table_path + ".ramp")
            with open(table_path + ".ramp") as fr:
                t_end = float(fr.readline().split("ends at t =")[1].split()[0])
            dev0 = ramp["s1/syy_w-1"][0]
            after = [d for t_, d in zip(ramp["t"], ramp["s1/syy_w-1"]) if t_ > t_end]
            mean_dev = sum(after) / max(len(after), 1)
            if case == "rigid":
                check(abs(dev0) < 0.005, "rigid: at rest sigma_1 = Love-Weber sigma_yy with the wall contacts (%+.4f)" % dev0)
            check(len(after) > 3 and abs(mean_dev - dev0) < 0.02,
                  "%s: after the platen ramp (t > %.3f s) sigma_1 / Love-Weber sigma_yy - 1 = %+.4f on average, "
                  "%+.4f at rest (difference < 0.02; worst line %+.4f)"
                  % (case, t_end, mean_dev, dev0, max(after, key=abs) if after else float("nan")))
            check(len(t["ea"]) > 5 and t["ea"][-1] > 0.0099, "%s: reached 1 %% axial strain" % case)
            atoms = [l for l in out.splitlines() if "Loop time" in l]
            check(bool(atoms) and all("with 526 atoms" in l for l in atoms), "%s: no atom lost (526 atoms)" % case)
            ratio = t["s1/s3"]
            check(abs(ratio[0] - 1.0) < 0.1, "%s: stress ratio starts at 1 (%.3f)" % (case, ratio[0]))
            check(max(ratio) > 1.3, "%s: stress ratio rises above 1.3 (max %.3f)" % (case, max(ratio)))
            if case == "rigid":
                s3 = t["s3"][1:]
                worst = max(abs(s / 1e5 - 1) for s in s3)
                check(worst < 0.10, "rigid: sigma_3 within 10 %% of 100 kPa (worst %.1f %%)" % (100 * worst))
            else:
                check(all(abs(s - 1e5) < 1e-6 for s in t["s3"]), "membrane: applied pressure 100 kPa")
                lw = t["sxx_lw"][1:]
                mean = sum(lw) / len(lw)
                check(abs(mean / 1e5 - 1) < 0.15,
                      "membrane: mean Love-Weber sigma_xx inside %.0f Pa within 15 %% of 100 kPa" % mean)
                counts = key_value_lines(out, "membrane_counts")
                check(bool(counts) and counts[0]["chain_failures"] == 0, "membrane: no chain failure")
        # every auto (the default) skips detections only when the chain cannot have changed:
        # the same run with a detection at every step must give the very same numbers
        table_every1 = os.path.join(work, "shear_membrane_every1.txt")
        out1 = run(mpi + ["-in", "in.shear_membrane", "-var", "restart", restart, "-var", "eatarget", "0.01",
                          "-var", "every", "1", "-var", "out", table_every1, "-var", "ndump", "100000",
                          "-log", "none"], os.path.join(work, "membrane_every1.txt"))
        rows_auto = [l for l in open(os.path.join(work, "shear_membrane.txt")) if not l.startswith("#")]
        rows_every1 = [l for l in open(table_every1) if not l.startswith("#")]
        check(len(rows_auto) > 5 and rows_auto == rows_every1,
              "membrane: every auto gives the same output, to the last digit, as a detection every step")
        done = [c for text in (out, out1) for c in key_value_lines(text, "membrane_counts")]
        check(len(done) == 2, "membrane: detections reported (auto / every 1: %s)"
              % " / ".join("%d changing the chain %d" % (c["detections"], c["chain_changes"]) for c in done))
        n = min(len(runs["rigid"]["s1"]), len(runs["membrane"]["s1"]))
        diff = max(abs(a - b) for a, b in zip(runs["rigid"]["s1"][1:n], runs["membrane"]["s1"][1:n]))
        check(diff > 1e3, "rigid and membrane runs differ (max |s1 difference| %.0f Pa)" % diff)

    if failures:
        print("FAILED:", "; ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

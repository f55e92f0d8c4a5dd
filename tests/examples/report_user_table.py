#!/usr/bin/python3
"""The minimal OUT table of doc/report.md ("A minimal table from a user's script"),
taken from the page itself, written by LIGGGHTS from variables whose answers are
known by hand, and reported by scripts/biaxial_report.py:

    ea = 1e-5 step, s1 = 1e5 (1 + 1e-4 step) Pa, s3 = 1e5 Pa, ev = -1e-6 step,
    el = -2e-6 step, printed every 500 steps to step 2000
    -> E = dq/d ea = 1e5 * 1e-4 / 1e-5 Pa = 1 MPa; nu = -d el/d ea = 0.2;
       s1/s3 at the end 1.2 at ea = 2 %; still rising: no peak;
       d ev/d ea = -0.1 -> sin psi = 0.1 / 2.1, psi = 2.729 deg.

    report_user_table.py LIGGGHTS_MEMBRANE
"""
import csv
import math
import os
import re
import sys
import tempfile

from example_run import ROOT, Checks, run

SETUP = """units si
atom_style granular
atom_modify sort 0 0.0
region box block 0 1 0 1 -0.5 0.5 units box
create_box 1 box
timestep 1e-5
variable ea equal step*1e-5
variable s1 equal 1e5*(1+step*1e-4)
variable s3 equal 1e5
variable ev equal -step*1e-6
variable el equal -step*2e-6
"""


def doc_snippet():
    """The LIGGGHTS lines of the page's minimal table."""
    with open(os.path.join(ROOT, "doc", "report.md")) as f:
        page = f.read()
    m = re.search(r"A minimal table from a\s+user's script.*?```\n(.*?)```", page, re.S)
    if not m:
        sys.exit("FAIL: doc/report.md has no minimal table snippet")
    return m.group(1)


def main():
    check = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "user.txt")
        script = os.path.join(tmp, "in.user")
        with open(script, "w") as f:
            f.write(SETUP + re.sub(r"\bOUT\b", out, doc_snippet()) + "run 2000\n")
        run([sys.argv[1], "-in", script, "-log", "none"], os.path.join(tmp, "run.log"), cwd=tmp)
        report = os.path.join(tmp, "report")
        run(["/usr/bin/python3", "-B", os.path.join(ROOT, "scripts", "biaxial_report.py"), out,
             "--outdir", report], os.path.join(tmp, "report.log"), cwd=tmp)
        with open(os.path.join(report, "summary.csv")) as f:
            cells = {r[0]: r[1] for r in csv.reader(f)}

    def near(row, value, tol):
        try:
            ok = abs(float(cells[row]) - value) <= tol
        except ValueError:
            ok = False
        check(ok, "%s: %s (by hand %g)" % (row, cells[row], value))

    check(cells["quantity"] == "user", "the run is named after its file: %s" % cells["quantity"])
    near("E, initial [MPa]", 1.0, 0.005)
    near("nu, initial", 0.2, 0.0005)
    near("s1/s3 at the end", 1.2, 5e-5)
    near("eps_11 at the end [%]", 2.0, 5e-4)
    near("psi, max dilation [deg]", math.degrees(math.asin(0.1 / 2.1)), 0.005)
    check(cells["peak s1/s3"].startswith("not measurable (s1/s3 still rising"),
          "no peak: %s" % cells["peak s1/s3"])
    if check.failures:
        sys.exit("FAIL: %d check(s)" % len(check.failures))
    print("all checks passed")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Time of the report command against the length of a run's table (issue 32, defect 5:
the sliding-window dilatancy fit was quadratic, 210 s for 150 000 lines).

    /usr/bin/python3 bench/report_rows.py [--rows 150000 500000] [--full]

For each row count: a synthetic OUT table (an elastic-plastic curve to 10 % axial
strain with noise, every column of the shear scripts) is written to a temporary folder,
and the times printed are those of reading it (readers.read_output), of the curve
analysis (curves.analyse_curves, the sliding fit included) and, with --full, of the
whole command (scripts/biaxial_report.py: the figures and the table too).
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from liggghts_membrane import curves, readers

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def write_table(path, n, seed=1):
    """An OUT table of n lines: q rises linearly then to a peak at 3 %, softens;
    eps_v contracts then dilates; noise on both (the DEM fluctuations)."""
    rng = np.random.default_rng(seed)
    ea = np.linspace(0.0, 0.10, n)
    s3 = np.full(n, 1e5)
    q = 2e5 * np.where(ea < 0.03, 1 - (1 - ea / 0.03) ** 2, 0.75 + 0.25 * np.exp(-((ea - 0.03) / 0.03) ** 2))
    q += rng.normal(0, 100.0, n)
    ev = 0.7 * ea - 25 * np.clip(ea - 0.005, 0, None) ** 2 + rng.normal(0, 1e-6, n)
    el = 1.0 - (1.0 - ev) / (1.0 - ea)
    s1 = s3 + q
    cols = {"step": np.arange(n) * 10.0, "t": ea / 0.0025, "ea": ea, "s1": s1, "s3": s3,
            "s1/s3": s1 / s3, "ev": ev, "el": el, "I": np.full(n, 7e-4),
            "a": 0.05 + 2 * ea, "an": 0.1 + 3 * ea, "at": 0.02 + ea, "f0": 30 * (1 + ea),
            "C_n": 2.3 - 3 * ea, "Zm": 3.2 - 4 * ea, "gsi": 0.15 + 0.5 * ea,
            "sxx_lw": 1.01 * s3, "syy_lw": 1.01 * s1}
    names = list(cols)
    data = np.column_stack([cols[c] for c in names])
    with open(path, "w") as f:
        f.write("# synthetic run of %d lines\n# %s\n" % (n, " ".join(names)))
        np.savetxt(f, data, fmt="%.10g")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rows", type=int, nargs="+", default=[150000, 500000])
    ap.add_argument("--full", action="store_true", help="also time the whole command")
    a = ap.parse_args()
    print("%10s %10s %12s %12s" % ("rows", "read [s]", "analyse [s]", "command [s]"))
    with tempfile.TemporaryDirectory() as d:
        for n in a.rows:
            path = os.path.join(d, "shear_%d.txt" % n)
            write_table(path, n)
            t0 = time.perf_counter()
            table = readers.read_output(path)
            t1 = time.perf_counter()
            res = curves.analyse_curves(table)
            t2 = time.perf_counter()
            full = float("nan")
            if a.full:
                subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "biaxial_report.py"),
                                path, "--outdir", os.path.join(d, "report_%d" % n)],
                               check=True, stdout=subprocess.DEVNULL)
                full = time.perf_counter() - t2
            print("%10d %10.2f %12.2f %12.2f   (psi %.2f deg)" % (n, t1 - t0, t2 - t1, full, res["psi"]),
                  flush=True)


if __name__ == "__main__":
    main()

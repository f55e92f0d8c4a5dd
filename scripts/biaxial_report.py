#!/usr/bin/python3
"""Report of the 2D DEM biaxial tests, rigid side walls vs fix membrane2d.

    biaxial_report.py --rigid OUT_R --membrane OUT_M --outdir DIR [--d50 1.75e-3]

OUT is the table the shear script writes; OUT.rose (polar histograms) and
OUT.dump (positions) are read when present. Either run may be left out.
Writes DIR/summary.md, DIR/summary.csv and the figures (stress_strain.png,
fabric.png, roses.png, field_<run>.png), and prints the Markdown table.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from biaxial import plots, summary  # noqa: E402
from biaxial.report import load_run  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("--rigid", help="OUT table of the rigid-wall run")
    p.add_argument("--membrane", help="OUT table of the membrane run")
    p.add_argument("--outdir", required=True)
    p.add_argument("--d50", type=float, default=1.75e-3,
                   help="D50 [m] used only when a run has no dump (default 1.75e-3)")
    args = p.parse_args(argv)
    if not args.rigid and not args.membrane:
        p.error("give --rigid and/or --membrane")
    return args


def make_report(runs, outdir):
    """Figures and tables of the loaded runs; returns the Markdown text."""
    os.makedirs(outdir, exist_ok=True)
    plots.stress_strain(runs, os.path.join(outdir, "stress_strain.png"))
    plots.fabric_evolution(runs, os.path.join(outdir, "fabric.png"))
    if any(r.roses for r in runs):
        plots.roses(runs, os.path.join(outdir, "roses.png"))
    for run in runs:
        if run.fields:
            plots.field(run, os.path.join(outdir, f"field_{run.name}.png"))
    header, rows = summary.build_table(runs)
    notes = [f"{r.name}: {n}" for r in runs for n in r.notes]
    text = summary.to_markdown(header, rows, notes)
    with open(os.path.join(outdir, "summary.md"), "w") as f:
        f.write(text)
    with open(os.path.join(outdir, "summary.csv"), "w") as f:
        f.write(summary.to_csv(header, rows))
    return text


def main(argv=None):
    args = parse_args(argv)
    runs = [load_run(name, path, args.d50)
            for name, path in (("rigid", args.rigid), ("membrane", args.membrane)) if path]
    print(make_report(runs, args.outdir))
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Report of the 2D DEM biaxial tests, rigid side walls vs fix membrane2d.

    biaxial_report.py --rigid OUT_R --membrane OUT_M --outdir DIR [--d50 1.75e-3]
    biaxial_report.py --samples SDIR [SDIR ...] --outdir DIR [--d50 1.75e-3]

OUT is the table the shear script writes; OUT.rose (polar histograms) and
OUT.dump (positions) are read when present. Either run may be left out.
Writes DIR/summary.md, DIR/summary.csv and the figures (stress_strain.png,
fabric.png, roses.png, field_<run>.png), and prints the Markdown table.

With --samples (replicates): each SDIR holds one sample's shear_rigid.txt and
shear_membrane.txt (with .rose, .dump) and gets the single-sample report above;
DIR gets the table over the samples (mean +- 95 % interval, paired rigid - membrane
difference: summary.md, summary.csv, samples.csv with every sample's values) and
stress_strain.png (mean curves and their 95 % band over the samples).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from biaxial import plots, replicates, summary  # noqa: E402
from biaxial.report import load_run  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("--rigid", help="OUT table of the rigid-wall run")
    p.add_argument("--membrane", help="OUT table of the membrane run")
    p.add_argument("--samples", nargs="+", metavar="SDIR",
                   help="one folder per replicate sample, each with shear_rigid.txt and "
                        "shear_membrane.txt (instead of --rigid/--membrane)")
    p.add_argument("--outdir", required=True)
    p.add_argument("--d50", type=float, default=1.75e-3,
                   help="D50 [m] used only when a run has no dump (default 1.75e-3)")
    args = p.parse_args(argv)
    if args.samples and (args.rigid or args.membrane):
        p.error("give --samples or --rigid/--membrane, not both")
    if not args.samples and not args.rigid and not args.membrane:
        p.error("give --rigid and/or --membrane, or --samples")
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


def load_sample(folder, d50):
    """{case: Run} of the shear outputs present in one sample's folder."""
    paths = {c: os.path.join(folder, f"shear_{c}.txt") for c in replicates.CASES}
    return {c: load_run(c, p, d50) for c, p in paths.items() if os.path.exists(p)}


def make_replicate_report(samples, names, outdir):
    """The table over the samples and the band plot in outdir; returns the Markdown."""
    os.makedirs(outdir, exist_ok=True)
    plots.stress_strain_band(samples, os.path.join(outdir, "stress_strain.png"))
    rows = replicates.aggregate(samples)
    notes = [f"{name} {r.name}: {n}" for name, s in zip(names, samples)
             for r in s.values() for n in r.notes]
    text = replicates.to_markdown(rows, names)
    text += ("\nMethods of each quantity: summary.md of a sample folder. Every sample's "
             "values: samples.csv.\n")
    if notes:
        text += "\nRun notes:\n" + "".join(f"- {n}\n" for n in notes)
    for name, content in (("summary.md", text), ("summary.csv", replicates.to_csv(rows)),
                          ("samples.csv", replicates.samples_csv(rows, names))):
        with open(os.path.join(outdir, name), "w") as f:
            f.write(content)
    return text


def main(argv=None):
    args = parse_args(argv)
    if args.samples:
        samples, names = [], []
        for folder in args.samples:
            sample = load_sample(folder, args.d50)
            if not sample:
                print(f"{folder}: no shear_rigid.txt or shear_membrane.txt", file=sys.stderr)
                return 1
            make_report(list(sample.values()), folder)
            samples.append(sample)
            names.append(os.path.basename(os.path.normpath(folder)))
        print(make_replicate_report(samples, names, args.outdir))
        return 0
    runs = [load_run(name, path, args.d50)
            for name, path in (("rigid", args.rigid), ("membrane", args.membrane)) if path]
    print(make_report(runs, args.outdir))
    return 0


if __name__ == "__main__":
    sys.exit(main())

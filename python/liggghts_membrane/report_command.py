#!/usr/bin/python3
"""Report of 2D DEM biaxial tests: the stress-strain analysis, fabric, roses and shear
band of one or more runs, side by side (doc/report.md).

    liggghts-membrane-report OUT [OUT ...] [--names NAME ...] [--outdir DIR] [--d50 D]
    liggghts-membrane-report --rigid OUT_R --membrane OUT_M [--outdir DIR] [--d50 D]
    liggghts-membrane-report --samples SDIR [SDIR ...] [--outdir DIR] [--d50 D]

(liggghts-membrane-report and scripts/biaxial_report.py run this module's command().)
OUT is the table a shear script writes (doc/report.md: a '#' header line naming the
columns, of which step ea s1 s3 ev el are needed); OUT.rose (polar histograms of
compute fabric) and OUT.dump (positions) are read when present. The runs are named
by --names, or by --rigid / --membrane, or else by their file names without the
extension. Writes DIR (default: report) /summary.md, summary.csv and the figures
(stress_strain.png, fabric.png, roses.png, field_<name>.png), and prints the Markdown
table.

With --samples (replicates): each SDIR holds one sample's shear_rigid.txt and
shear_membrane.txt (with .rose, .dump) and gets the single-sample report above;
DIR gets the table over the samples (mean +- 95 % interval, paired rigid - membrane
difference: summary.md, summary.csv, samples.csv with every sample's values) and
stress_strain.png (mean curves and their 95 % band over the samples).
"""
import argparse
import math
import os
import sys

from liggghts_membrane import replicates, summary
from liggghts_membrane.readers import InputError
from liggghts_membrane.report import load_run


def parse_args(argv):
    p = argparse.ArgumentParser(prog="liggghts-membrane-report", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="*", metavar="OUT", help="OUT table of a run")
    p.add_argument("--names", nargs="+", metavar="NAME",
                   help="the name of each OUT in the table and the figures (default: "
                        "the file names without the extension)")
    p.add_argument("--rigid", help="OUT table of the rigid-wall run")
    p.add_argument("--membrane", help="OUT table of the membrane run")
    p.add_argument("--samples", nargs="+", metavar="SDIR",
                   help="one folder per replicate sample, each with shear_rigid.txt and "
                        "shear_membrane.txt (instead of --rigid/--membrane)")
    p.add_argument("--outdir", default="report", help="where the report goes (default: report)")
    p.add_argument("--d50", type=float, default=1.75e-3,
                   help="D50 [m] used only when a run has no dump and no OUT.params naming d50 "
                        "(default 1.75e-3)")
    args = p.parse_args(argv)
    ways = [w for w, given in (("OUT", args.runs), ("--rigid/--membrane", args.rigid or args.membrane),
                               ("--samples", args.samples)) if given]
    if len(ways) != 1:
        p.error("give OUT tables, --rigid and/or --membrane, or --samples: " +
                ("not both " + " and ".join(ways) if ways else "none was given"))
    if args.names and len(args.names) != len(args.runs):
        p.error(f"--names gives {len(args.names)} names for {len(args.runs)} OUT tables")
    args.named = list(zip(args.names or [run_name(path) for path in args.runs], args.runs))
    args.named += [(name, path) for name, path in (("rigid", args.rigid), ("membrane", args.membrane)) if path]
    names = [name for name, _ in args.named]
    if len(set(names)) != len(names):
        p.error("two runs are named alike (%s): name them with --names" % " ".join(names))
    for _, path in args.named:
        if not os.path.isfile(path):
            p.error(f"no OUT table {path}" + (" (a folder: give the table in it, or the folder "
                                              "with --samples)" if os.path.isdir(path) else ""))
    twice(p, [path for _, path in args.named], "OUT table")
    for folder in args.samples or []:
        if not os.path.isdir(folder):
            p.error(f"--samples: no folder {folder}")
    twice(p, args.samples or [], "--samples folder")
    if not (math.isfinite(args.d50) and args.d50 > 0):
        p.error(f"--d50 = {args.d50}: needs a positive diameter [length], e.g. 1.75e-3")
    return args


def twice(p, paths, what):
    """Refuse a file or folder given twice (under the same or another name)."""
    seen = {}
    for path in paths:
        key = os.path.realpath(path)
        if key in seen:
            same = "" if seen[key] == path else f" (as {seen[key]})"
            p.error(f"the {what} {path} is given twice{same}: each run or sample once")
        seen[key] = path


def run_name(path):
    """A run's default name: its file name without the extension."""
    return os.path.splitext(os.path.basename(path))[0]


def make_report(runs, outdir):
    """Figures and tables of the loaded runs; returns the Markdown text."""
    from liggghts_membrane import plots   # matplotlib: only once the runs are read (a refused file is quick)
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
    from liggghts_membrane import plots
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
    runs = [load_run(name, path, args.d50) for name, path in args.named]
    from liggghts_membrane import plots
    plots.assign_colours(runs)
    print(make_report(runs, args.outdir))
    return 0


def command():
    """The command line: main() with a refused file as a message, not a traceback."""
    try:
        sys.exit(main())
    except (InputError, OSError) as e:   # a file it cannot use: the message, not a traceback
        print(f"liggghts-membrane-report: {e}", file=sys.stderr)
        sys.exit(2)
    except BrokenPipeError:  # the table piped into head: the files are written, stop quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(0)


if __name__ == "__main__":
    command()

"""The rigid-boundary comparison of run_comparison.sh: for each seed the same cuboid
sample sheared with servo-controlled side walls and with fix membrane3d.

Writes OUT/comparison.md (a table: mean and sample-to-sample standard deviation over
the seeds for each boundary, and the paired difference membrane - walls with its
standard deviation over the seeds) and OUT/comparison.png (q/p, volumetric strain,
fabric and normal-force anisotropy and Z_m against the axial strain for every run,
and the membrane's profile, its half-width against z, at the start and end of one
shear).

A difference is called a finding only when it exceeds both the sample-to-sample
scatter (the larger standard deviation of the two boundaries) and twice the
standard error of the paired differences.

Usage: compare_boundaries.py OUT SEED [SEED ...]"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from liggghts_membrane.pvd import collection_frames  # noqa: E402
from liggghts_membrane.readers import read_columns  # noqa: E402
from liggghts_membrane.vtk_files import polydata_points  # noqa: E402

BOUNDARIES = ("walls", "membrane")


def read_run(path):
    """{column: array} of one shear's table (readers.read_columns)."""
    return read_columns(path)[0]


def measures(run):
    """The numbers of the table for one shear."""
    stress_ratio = run["q[Pa]"] / run["p[Pa]"]
    peak = int(np.argmax(run["q[Pa]"]))
    return {
        "peak q/p": stress_ratio[peak],
        "ε₁ at peak [%]": 100 * run["e1"][peak],
        "q/p at the end": stress_ratio[-1],
        "largest contraction ε_v [%]": 100 * run["ev"].max(),
        "ε_v at the end [%]": 100 * run["ev"][-1],
        "fabric a at peak": run["a"][peak],
        "normal-force a_n at peak": run["a_n"][peak],
        "Z_m at the start": run["Zm"][0],
        "Z_m at the end": run["Zm"][-1],
    }


def finding(diff, sd_diff, scatter, n):
    if n < 2:
        return "one sample: no finding"
    if abs(diff) > scatter and abs(diff) > 2 * sd_diff / math.sqrt(n):
        return "yes"
    return "no (within the scatter)"


def table(runs, seeds):
    names = list(measures(runs[BOUNDARIES[0]][seeds[0]]).keys())
    values = {b: [measures(runs[b][s]) for s in seeds] for b in BOUNDARIES}
    n = len(seeds)
    lines = [
        "| measure | walls (mean ± sd) | membrane (mean ± sd) | membrane − walls (mean ± sd) | a finding? |",
        "|---|---|---|---|---|",
    ]
    for name in names:
        w = np.array([v[name] for v in values["walls"]])
        m = np.array([v[name] for v in values["membrane"]])
        d = m - w
        sd = (lambda x: x.std(ddof=1) if n > 1 else float("nan"))
        scatter = max(sd(w), sd(m))
        lines.append("| %s | %.3g ± %.2g | %.3g ± %.2g | %+.3g ± %.2g | %s |" % (
            name, w.mean(), sd(w), m.mean(), sd(m), d.mean(), sd(d),
            finding(d.mean(), sd(d), scatter, n)))
    return "\n".join(lines)


def half_width_profile(points, bin_width=0.002):
    """(z, half-width in x) of the membrane's corners in the slice through the axis
    |y - y_mid| < width / 6, in bins of z: half the x extent of each bin."""
    y_mid = 0.5 * (points[:, 1].max() + points[:, 1].min())
    slab = points[np.abs(points[:, 1] - y_mid) < np.ptp(points[:, 1]) / 6]
    edges = np.arange(slab[:, 2].min(), slab[:, 2].max() + bin_width, bin_width)
    z, half = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        x = slab[(slab[:, 2] >= lo) & (slab[:, 2] < hi), 0]
        if len(x) >= 2:
            z.append(0.5 * (lo + hi))
            half.append(0.5 * np.ptp(x))
    return np.array(z), np.array(half)


def membrane_frames(out, seed):
    return collection_frames(os.path.join(out, "membrane_%s_membrane.pvd" % seed))


def plot(runs, seeds, out, png):
    fig, ax = plt.subplots(2, 3, figsize=(15, 8.5))
    colours = {"walls": "tab:blue", "membrane": "tab:red"}
    panels = [
        (ax[0, 0], lambda r: r["q[Pa]"] / r["p[Pa]"], "q / p", "stress ratio"),
        (ax[0, 1], lambda r: 100 * r["ev"], "ε_v [%] (compression > 0)", "volumetric strain"),
        (ax[0, 2], lambda r: r["a"], "a = √(3/2 a:a)", "contact-normal fabric anisotropy"),
        (ax[1, 0], lambda r: r["a_n"], "a_n", "normal-force anisotropy"),
        (ax[1, 1], lambda r: r["Zm"], "Z_m", "mechanical coordination number"),
    ]
    for a, value, ylabel, title in panels:
        for b in BOUNDARIES:
            for k, s in enumerate(seeds):
                r = runs[b][s]
                a.plot(100 * r["e1"], value(r), color=colours[b], alpha=0.8, lw=1.2,
                       label=b if k == 0 else None)
        a.set(xlabel="axial strain ε₁ [%]", ylabel=ylabel, title=title)
        a.grid(alpha=0.3)
        a.legend()
    frames = membrane_frames(out, seeds[0])
    shape = ax[1, 2]
    if frames:
        for (step, path), colour, label in ((frames[0], "0.5", "start of the shear"),
                                            (frames[-1], "tab:red", "end")):
            z, half_width = half_width_profile(polydata_points(path))
            shape.plot(1000 * half_width, 1000 * z, "-o", ms=3, color=colour,
                       label="%s (step %d)" % (label, step))
        shape.set(xlabel="half-width (x) of the membrane [mm]", ylabel="z [mm]",
                  title="bulging: the membrane's profile, seed %s" % seeds[0])
        shape.grid(alpha=0.3)
        shape.legend(fontsize=8)
    else:
        shape.set_axis_off()
        shape.text(0.5, 0.5, "no membrane frames (vtkevery 0)", ha="center", transform=shape.transAxes)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    if len(sys.argv) < 3 or sys.argv[1] in ("-h", "--help"):
        print(__doc__, file=sys.stdout if len(sys.argv) == 2 else sys.stderr)
        sys.exit(0 if len(sys.argv) == 2 else 2)
    out, seeds = sys.argv[1], sys.argv[2:]
    runs = {b: {s: read_run(os.path.join(out, "%s_%s.txt" % (b, s))) for s in seeds}
            for b in BOUNDARIES}
    text = ("# Rigid side walls against fix membrane3d: %d cuboid samples (seeds %s)\n\n"
            % (len(seeds), ", ".join(seeds)) + table(runs, seeds) + "\n")
    with open(os.path.join(out, "comparison.md"), "w") as f:
        f.write(text)
    print(text)
    png = os.path.join(out, "comparison.png")
    plot(runs, seeds, out, png)
    print("wrote", png)


if __name__ == "__main__":
    main()

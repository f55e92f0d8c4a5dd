#!/usr/bin/python3
"""Plot a triaxial run of in.triaxial: q/p and the volumetric strain against the
axial strain, and the membrane's spheres and equivalent outer radius.

Usage: plot_triaxial.py OUT.txt [PNG]   (PNG defaults to OUT.png beside OUT.txt)

The table may still be growing: an incomplete last line is left out. Values that are
not finite (and q/p where p = 0) leave gaps in the curves, with a warning."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from biaxial.readers import read_columns  # noqa: E402

USAGE = ("usage: plot_triaxial.py OUT.txt [PNG]   (OUT.txt: the table of in.triaxial, "
         "out/triaxial/triaxial.txt of run_triaxial.sh; PNG: default OUT.png)")
COLUMNS = ["e1", "q[Pa]", "p[Pa]", "ev", "membrane_spheres", "escaped"]


class Refused(Exception):
    """What stops the plot, said in one line."""


def png_path(table, given):
    """The PNG to write: the one given, else the table's name with .png for .txt."""
    if given:
        return given
    root, ext = os.path.splitext(table)
    return (root if ext == ".txt" else table) + ".png"


def read_table(path):
    """The columns of in.triaxial's table, at least one complete row."""
    try:
        columns, _ = read_columns(path)
    except FileNotFoundError:
        raise Refused(f"no file {path}: run examples/triaxial/run_triaxial.sh first")
    except (ValueError, OSError) as e:
        raise Refused(f"{e} (is it the table of in.triaxial?)")
    missing = [c for c in COLUMNS if c not in columns]
    if missing:
        raise Refused(f"{path}: the header lacks {' '.join(missing)} (is it the table of "
                      "in.triaxial?)")
    if len(columns["e1"]) == 0:
        raise Refused(f"{path}: no complete data row yet")
    return columns


def rows_with_gaps(columns, ratio):
    """How many rows leave a gap in some curve."""
    plotted = [ratio] + [columns[c] for c in COLUMNS if c not in ("q[Pa]", "p[Pa]")]
    return int((~np.isfinite(np.vstack(plotted))).any(axis=0).sum())


def plot(c, png):
    e1 = 100 * c["e1"]
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = c["q[Pa]"] / c["p[Pa]"]
    ratio[~np.isfinite(ratio)] = np.nan
    gaps = rows_with_gaps(c, ratio)
    if gaps:
        print(f"plot_triaxial.py: warning: {gaps} rows have values that are not finite (or "
              "p = 0): gaps in the curves", file=sys.stderr)
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    ax[0].plot(e1, ratio)
    ax[0].set(xlabel="axial strain ε₁ [%]", ylabel="q / p", title="stress ratio")
    ax[1].plot(e1, 100 * c["ev"])
    ax[1].set(xlabel="axial strain ε₁ [%]", ylabel="volumetric strain ε_v [%] (compression > 0)",
              title="volume (membrane, to the outer faces)")
    ax[2].plot(e1, c["membrane_spheres"], label="membrane spheres")
    ax[2].plot(e1, c["escaped"], label="escaped")
    ax[2].set(xlabel="axial strain ε₁ [%]", ylabel="spheres", title="the membrane")
    ax[2].legend()
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv):
    if len(argv) in (2, 3) and argv[1] in ("-h", "--help"):
        print(USAGE)
        return 0
    if len(argv) not in (2, 3):
        print(USAGE, file=sys.stderr)
        return 2
    table = argv[1]
    png = png_path(table, argv[2] if len(argv) > 2 else None)
    try:
        if os.path.abspath(png) == os.path.abspath(table):
            raise Refused(f"the plot {png} would overwrite the table: give another PNG name")
        folder = os.path.dirname(os.path.abspath(png))
        if not os.path.isdir(folder):
            raise Refused(f"no folder {folder} to write {png} in")
        plot(read_table(table), png)
    except Refused as e:
        print(f"plot_triaxial.py: {e}", file=sys.stderr)
        return 1
    print("wrote", png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

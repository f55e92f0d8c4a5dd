#!/usr/bin/python3
"""Plot a triaxial run of in.triaxial: against the axial strain ε₁, q/p (from the platen
and the membrane, and from the contacts: Love–Weber), the volumetric strain, the
membrane's spheres, the fabric and force anisotropies and the coordination numbers;
and the bulged shape: the membrane's radius R(z) at the start of the shear, at the
peak of q and at the end, from its VTK frames.

Usage: plot_triaxial.py OUT.txt [PNG]   (PNG defaults to OUT.png beside OUT.txt)

The frames are those of OUT.paraview/membrane.pvd (in.triaxial's -var vtkdir); without
them, or with a table of a run before the fabric was logged, those panels say so.
The table may still be growing: an incomplete last line is left out. Values that are
not finite (and q/p where p = 0) leave gaps in the curves, with a warning."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from liggghts_membrane.curves import find_peak, measured  # noqa: E402
from liggghts_membrane.readers import read_columns  # noqa: E402
from liggghts_membrane.pvd import collection_frames  # noqa: E402
from liggghts_membrane.vtk_files import polydata_points  # noqa: E402

USAGE = ("usage: plot_triaxial.py OUT.txt [PNG]   (OUT.txt: the table of in.triaxial, "
         "out/triaxial/triaxial.txt of run_triaxial.sh; PNG: default OUT.png)")
COLUMNS = ["step", "e1", "q[Pa]", "p[Pa]", "ev", "membrane_spheres", "escaped"]
# the fabric of compute fabric and the Love-Weber stress (tables from before lack them)
FABRIC = ["a", "a_n", "a_t", "Zm", "Cn"]
LOVE_WEBER = ["sLW_zz[Pa]", "sLW_xx[Pa]", "sLW_yy[Pa]"]


class Refused(Exception):
    """What stops the plot, said in one line."""


def png_path(table, given):
    """The PNG to write: the one given, else the table's name with .png for .txt."""
    if given:
        return given
    root, ext = os.path.splitext(table)
    return (root if ext == ".txt" else table) + ".png"


def frames_path(table):
    """The membrane's frames of the run whose table is `table`: OUT.paraview/membrane.pvd."""
    root, ext = os.path.splitext(table)
    return os.path.join((root if ext == ".txt" else table) + ".paraview", "membrane.pvd")


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


def has(columns, names):
    return all(n in columns for n in names)


def ratio(num, den):
    """num / den with NaN where it is not finite (den = 0)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.asarray(num, dtype=float) / den
    r[~np.isfinite(r)] = np.nan
    return r


def love_weber_ratio(c):
    """q/p of the Love–Weber stress: q = σ_zz − (σ_xx + σ_yy)/2, p = (σ_zz + σ_xx + σ_yy)/3."""
    zz, xx, yy = (c[n] for n in LOVE_WEBER)
    return ratio(zz - 0.5 * (xx + yy), (zz + xx + yy) / 3)


def rows_with_gaps(columns, stress_ratio):
    """How many rows leave a gap in some curve."""
    names = [c for c in COLUMNS if c not in ("step", "q[Pa]", "p[Pa]")]
    names += [c for c in FABRIC + LOVE_WEBER if c in columns]
    plotted = [stress_ratio] + [columns[c] for c in names]
    return int((~np.isfinite(np.vstack(plotted))).any(axis=0).sum())


# ---------------------------------------------------------------- the bulged shape
def axis_centre(points):
    """(x, y) of the sample's axis: the centre of the least-squares circle through the
    points' (x, y) (Kåsa: x² + y² = 2 a x + 2 b y + c), however the points are spread
    around it (every slice of a bulged cylinder has this centre)."""
    x, y = points[:, 0], points[:, 1]
    design = np.column_stack([2 * x, 2 * y, np.ones_like(x)])
    (a, b, _), *_ = np.linalg.lstsq(design, x * x + y * y, rcond=None)
    return a, b


def radius_profile(points, bin_width=0.002):
    """(z, R): the mean distance from the axis (axis_centre) of the membrane's corners in
    each of equal bins of z about bin_width tall, from the lowest corner to the highest
    (the platens); z the bin's centre, bins with fewer than 3 corners left out."""
    if len(points) < 3:
        raise ValueError(f"{len(points)} corners")
    cx, cy = axis_centre(points)
    r = np.hypot(points[:, 0] - cx, points[:, 1] - cy)
    z = points[:, 2]
    n = max(1, int(round(np.ptp(z) / bin_width)))
    edges = np.linspace(z.min(), z.max(), n + 1)
    k = np.clip(np.searchsorted(edges, z, side="right") - 1, 0, n - 1)
    zs, rs = [], []
    for b in range(n):
        inside = k == b
        if inside.sum() >= 3:
            zs.append(0.5 * (edges[b] + edges[b + 1]))
            rs.append(r[inside].mean())
    return np.array(zs), np.array(rs)


def frame_strains(steps, e1, frame_steps):
    """ε₁ at each frame's step. In shear ε₁ is linear in the step (the platen moves at
    constant speed): along the line through the table's first and last rows, which
    gives the frames before the shear (the isotropic stage) ε₁ < 0. NaN for all when
    the table has no two rows of different steps."""
    frame_steps = np.asarray(frame_steps, dtype=float)
    if len(steps) < 2 or steps[-1] == steps[0]:
        return np.full(len(frame_steps), np.nan)
    slope = (e1[-1] - e1[0]) / (steps[-1] - steps[0])
    return e1[0] + slope * (frame_steps - steps[0])


def choose_frames(steps, e1, stress_ratio, frame_steps):
    """The frames drawn, as [(label, frame index)]: the start of the shear (the last frame
    at ε₁ <= 0, else the first), the peak of q/p (the frame nearest its row, when the
    table has a peak: curves.find_peak) and the end (the last frame); each once."""
    eps = frame_strains(steps, e1, frame_steps)
    before = np.flatnonzero(eps <= 0)
    start = int(before[-1]) if len(before) else 0
    end = len(frame_steps) - 1
    chosen = [("start of shear", start)]
    peak = find_peak(e1, stress_ratio)
    if measured(peak):
        k = int(np.argmin(np.abs(np.asarray(frame_steps, dtype=float) - steps[peak])))
        chosen.append(("peak of q/p", k))
    chosen.append(("end", end))
    drawn, seen = [], set()
    for label, k in chosen:
        if k not in seen and (label != "peak of q/p" or start < k < end):
            drawn.append((label, k))
            seen.add(k)
    return drawn, eps


def profiles(c, stress_ratio, pvd):
    """[(label, step, ε₁, z, R)] of the frames drawn, or a reason (str) why none are."""
    frames = collection_frames(pvd)
    if not frames:
        return f"no membrane frames {pvd} (in.triaxial -var vtkstrain 0?)"
    steps = [s for s, _ in frames]
    drawn, eps = choose_frames(c["step"], c["e1"], stress_ratio, steps)
    out = []
    for label, k in drawn:
        step, path = frames[k]
        try:
            z, r = radius_profile(polydata_points(path, corners_only=True))
        except (OSError, AttributeError, ValueError) as e:
            print(f"plot_triaxial.py: warning: frame {path} left out ({e})", file=sys.stderr)
            continue
        out.append((label, step, eps[k], z, r))
    return out or f"no readable membrane frame in {pvd}"


def describe(label, step, eps, z, r):
    """One line on a profile: R at the platens' bins, at mid-height and the largest."""
    mid = int(np.argmin(np.abs(z - 0.5 * (z.min() + z.max()))))
    big = int(np.argmax(r))
    strain = "ε₁ = ?" if not np.isfinite(eps) else f"ε₁ = {100 * max(eps, 0.0):.2f} %"
    return (f"membrane at the {label} (step {step}, {strain}): R = {1000 * r[0]:.2f} and "
            f"{1000 * r[-1]:.2f} mm at the platens, {1000 * r[mid]:.2f} mm at mid-height, "
            f"largest {1000 * r[big]:.2f} mm at z = {1000 * z[big]:.1f} mm")


# ---------------------------------------------------------------- the figure
def note(a, text):
    a.text(0.5, 0.5, text, ha="center", va="center", wrap=True, transform=a.transAxes,
           fontsize=9)


def plot(c, png, pvd):
    e1 = 100 * c["e1"]
    stress_ratio = ratio(c["q[Pa]"], c["p[Pa]"])
    gaps = rows_with_gaps(c, stress_ratio)
    if gaps:
        print(f"plot_triaxial.py: warning: {gaps} rows have values that are not finite (or "
              "p = 0): gaps in the curves", file=sys.stderr)
    fig, ax = plt.subplots(2, 3, figsize=(14, 8.5))
    strain = "axial strain ε₁ [%]"
    a = ax[0, 0]
    a.plot(e1, stress_ratio, label="platen, membrane at p")
    if has(c, LOVE_WEBER):
        a.plot(e1, love_weber_ratio(c), "--", label="Love–Weber (contacts in V_out)")
    a.set(xlabel=strain, ylabel="q / p", title="stress ratio")
    a.legend(fontsize=8)
    a = ax[0, 1]
    a.plot(e1, 100 * c["ev"])
    a.set(xlabel=strain, ylabel="volumetric strain ε_v [%] (compression > 0)",
          title="volume (membrane, to the outer faces)")
    a = ax[0, 2]
    a.plot(e1, c["membrane_spheres"], label="membrane spheres")
    a.plot(e1, c["escaped"], label="escaped")
    a.set(xlabel=strain, ylabel="spheres", title="the membrane")
    a.legend(fontsize=8)
    fabric = has(c, FABRIC)
    if not fabric:
        print("plot_triaxial.py: note: the table has no fabric columns (" + " ".join(FABRIC)
              + "): a run before they were logged; those panels are left empty", file=sys.stderr)
    a = ax[1, 0]
    if fabric:
        for name, label in (("a", "a, contact normals"), ("a_n", "a_n, normal forces"),
                            ("a_t", "a_t, tangential forces")):
            a.plot(e1, c[name], label=label)
        a.legend(fontsize=8)
    else:
        note(a, "no fabric columns in this table")
    a.set(xlabel=strain, ylabel="anisotropy (magnitude)", title="fabric and force anisotropy")
    a = ax[1, 1]
    if fabric:
        a.plot(e1, c["Zm"], label="Z_m, mechanical")
        a.plot(e1, c["Cn"], label="C_n = 2 N_c / N_p")
        a.legend(fontsize=8)
    else:
        note(a, "no fabric columns in this table")
    a.set(xlabel=strain, ylabel="contacts per sphere", title="coordination number")
    shape = ax[1, 2]
    drawn = profiles(c, stress_ratio, pvd)
    if isinstance(drawn, str):
        print(f"plot_triaxial.py: note: {drawn}: no bulged shape", file=sys.stderr)
        note(shape, drawn)
    else:
        colours = {"start of shear": "0.5", "peak of q/p": "tab:orange", "end": "tab:red"}
        for label, step, eps, z, r in drawn:
            strain_text = "" if not np.isfinite(eps) else ", ε₁ = %.1f %%" % (100 * max(eps, 0.0))
            shape.plot(1000 * r, 1000 * z, "-o", ms=3, color=colours[label],
                       label=f"{label} (step {step}{strain_text})")
            print(describe(label, step, eps, z, r))
        shape.legend(fontsize=8)
    shape.set(xlabel="radius R of the membrane [mm] (its corners' mean)", ylabel="z [mm]",
              title="bulging: the membrane's profile R(z)")
    for a in ax.flat:
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
        plot(read_table(table), png, frames_path(table))
    except Refused as e:
        print(f"plot_triaxial.py: {e}", file=sys.stderr)
        return 1
    print("wrote", png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

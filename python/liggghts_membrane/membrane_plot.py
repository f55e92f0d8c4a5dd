#!/usr/bin/python3
"""Draw the membrane of fix membrane2d: disks, chain disks, polyline and forces.

Inputs: a LIGGGHTS dump with the columns id x y radius and the fix's per-atom
flag (dump custom ... id x y radius f_ID), and the fix's polyline file
(keyword `polyline N file`). The figure shows the snapshot at the timestep
given (default: the last one present in both files).

    plot_membrane.py --dump dump.membrane --polyline membrane.polyline --out chain.png
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402

from liggghts_membrane.readers import read_dump, read_polylines  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dump", required=True)
    ap.add_argument("--polyline", required=True)
    ap.add_argument("--step", type=int)
    ap.add_argument("--flag", default=None, help="dump column of the membrane flag (default: the last column)")
    ap.add_argument("--zoom", type=float, nargs=4, metavar=("XLO", "XHI", "YLO", "YHI"),
                    help="show only this window (m)")
    ap.add_argument("--out", default="membrane_chain.png")
    a = ap.parse_args()

    dumps, polys = read_dump(a.dump), read_polylines(a.polyline)
    steps = sorted(set(dumps) & set(polys))
    if not steps:
        sys.exit("no timestep is present in both the dump and the polyline file")
    step = a.step if a.step is not None else steps[-1]
    if step not in steps:
        sys.exit("timestep %d is not in both files (have %s)" % (step, steps))
    d, p = dumps[step], polys[step]
    flag = d[a.flag] if a.flag else d[[c for c in d if c != "step"][-1]]   # the last dump column

    colours = {0: "#d9d9d9", 1: "#4c72b0", 2: "#dd8452", 3: "#c44e52"}
    fmax = max((np.hypot(s["chain"][:, 4], s["chain"][:, 5]).max() for s in p.values()
                if len(s.get("chain", [])) > 0), default=1.0)
    rmean = float(np.mean(d["radius"]))

    def draw(ax, arrows):
        patches = [Circle((x, y), r) for x, y, r in zip(d["x"], d["y"], d["radius"])]
        ax.add_collection(PatchCollection(patches, facecolor=[colours.get(int(f), "k") for f in flag],
                                          edgecolor="#666666", linewidth=0.3))
        for s in p.values():
            poly = s["polyline"]
            ax.plot(poly[:, 0], poly[:, 1], "k-", lw=1.0)
            c = s["chain"]
            if arrows:
                scale = 4 * rmean / fmax
                ax.quiver(c[:, 1], c[:, 2], c[:, 4] * scale, c[:, 5] * scale, angles="xy",
                          scale_units="xy", scale=1, color="k", width=0.003)
        ax.set_aspect("equal")
        ax.autoscale_view()
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")

    if a.zoom:
        fig, (ax, axz) = plt.subplots(1, 2, figsize=(10, 8), gridspec_kw={"width_ratios": [1, 1.3]})
        draw(ax, arrows=False)
        ax.add_patch(plt.Rectangle((a.zoom[0], a.zoom[2]), a.zoom[1] - a.zoom[0], a.zoom[3] - a.zoom[2],
                                   fill=False, ec="k", lw=1.2))
        draw(axz, arrows=True)
        axz.set_xlim(a.zoom[0], a.zoom[1])
        axz.set_ylim(a.zoom[2], a.zoom[3])
    else:
        fig, ax = plt.subplots(figsize=(6, 9))
        draw(ax, arrows=True)
    fig.suptitle("fix membrane2d at step %d: chain disks (blue left, orange right), escaped (red),\n"
                 "contact-point polyline and chain forces (arrows, length ~ force)" % step, fontsize=9)
    fig.tight_layout()
    fig.savefig(a.out, dpi=150)
    print("wrote", a.out)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Draw the membrane of fix membrane2d: disks, chain disks, polyline and forces.

Inputs: a LIGGGHTS dump with the columns id x y radius and the fix's per-atom
flag (dump custom ... id x y radius f_ID), and the fix's polyline file
(keyword `polyline N file`). The figure shows the snapshot at the timestep
given (default: the last one present in both files).

    plot_membrane.py --dump dump.membrane --polyline membrane.polyline --out chain.png
"""
import argparse
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.patches import Circle  # noqa: E402


def read_dump(path):
    """{timestep: structured rows} from a LIGGGHTS text dump."""
    frames = {}
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            data = np.array([list(map(float, l.split())) for l in lines[i + 9:i + 9 + n]])
            frames[step] = {c: data[:, k] for k, c in enumerate(cols)}
            i += 9 + n
        else:
            i += 1
    return frames


def read_polylines(path):
    """{timestep: {side: {'polyline': (n,2), 'chain': (m,6) tag x y r fx fy}}}."""
    frames, step = {}, None
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        w = lines[i].split()
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            frames[step] = {}
            i += 2
        elif w[:2] == ["ITEM:", "POLYLINE"]:
            side, n = w[2], int(w[3])
            pts = np.array([list(map(float, l.split())) for l in lines[i + 1:i + 1 + n]])
            frames[step].setdefault(side, {})["polyline"] = pts
            i += 1 + n
        elif w[:2] == ["ITEM:", "CHAIN"]:
            side, n = w[2], int(w[3])
            rows = np.array([list(map(float, l.split())) for l in lines[i + 1:i + 1 + n]])
            frames[step].setdefault(side, {})["chain"] = rows
            i += 1 + n
        else:
            i += 1
    return frames


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
    flag = d[a.flag] if a.flag else d[list(d)[-1]]

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

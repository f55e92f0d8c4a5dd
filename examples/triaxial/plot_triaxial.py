#!/usr/bin/python3
"""Plot a triaxial run of in.triaxial: q/p and the volumetric strain against the
axial strain, and the membrane's spheres and equivalent outer radius.

Usage: plot_triaxial.py OUT.txt [PNG]   (PNG defaults to OUT.png)"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    path = sys.argv[1]
    png = sys.argv[2] if len(sys.argv) > 2 else path.rsplit(".", 1)[0] + ".png"
    with open(path) as f:
        cols = [l for l in f if l.startswith("#")][-1].lstrip("#").split()
    data = np.loadtxt(path, comments="#")
    c = {name: data[:, k] for k, name in enumerate(cols)}
    e1 = 100 * c["e1"]
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    ax[0].plot(e1, c["q[Pa]"] / c["p[Pa]"])
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
    print("wrote", png)


if __name__ == "__main__":
    main()

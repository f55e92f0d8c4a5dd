"""Polar histograms of contact normals and mean normal forces, and their fitted curves.

The fitted parameters are NOT refitted here: a, theta_a, an, theta_n and f0 come
from the OUT line nearest in step to the histogram (compute fabric computed them
from all contacts). The histogram estimate of a (fabric.md, unbiased form) is
computed only as a cross-check shown in the legend.
"""
import math

import numpy as np


def nearest_line(table, step):
    """Index of the OUT line nearest in step to `step`."""
    return int(np.argmin(np.abs(table["step"] - step)))


def fit_parameters(table, step):
    """The fitted rose parameters of the OUT line nearest to `step`:
    {'a', 'theta_a', 'an', 'theta_n', 'f0', 'step'}; a name is absent when its column is."""
    k = nearest_line(table, step)
    params = {"step": int(table["step"][k])}
    for name in ("a", "theta_a", "an", "theta_n", "f0"):
        if table.has(name):
            params[name] = float(table[name][k])
    return params


def normal_density(counts, centres_deg):
    """Histogram counts -> probability density E_g over 0-2 pi (each contact is
    counted twice, n and -n, so the counts sum to 2 N_c and the density to 1)."""
    width = 2.0 * math.pi / len(centres_deg)
    total = counts.sum()
    return counts / (total * width) if total > 0 else np.zeros_like(counts)


def model_normal_density(theta_deg, a, theta_a_deg):
    """E(theta) = (1/2 pi) [1 + a cos 2(theta - theta_a)]."""
    return (1.0 + a * np.cos(2.0 * np.radians(theta_deg - theta_a_deg))) / (2.0 * math.pi)


def model_mean_force(theta_deg, f0, an, theta_n_deg):
    """f_n(theta) = f0 [1 + a_n cos 2(theta - theta_n)]."""
    return f0 * (1.0 + an * np.cos(2.0 * np.radians(theta_deg - theta_n_deg)))


def histogram_anisotropy(centres_deg, counts):
    """(a, theta_a [deg, 0-180)) from binned counts, the unbiased estimate of
    fabric.md: a cos 2 theta_a = (2 dtheta / (N sin dtheta)) sum N_g cos 2 theta_g,
    N = sum N_g (the N of the formula counts every n and -n entry)."""
    width = 2.0 * math.pi / len(centres_deg)
    two = 2.0 * np.radians(centres_deg)
    scale = 2.0 * width / (counts.sum() * math.sin(width))
    c, s = scale * (counts * np.cos(two)).sum(), scale * (counts * np.sin(two)).sum()
    return math.hypot(c, s), math.degrees(0.5 * math.atan2(s, c)) % 180.0


def select_blocks(blocks, steps):
    """For each wanted step, the (step, block) of the rose file nearest to it."""
    have = np.array([b[0] for b in blocks])
    return [blocks[int(np.argmin(np.abs(have - s)))] for s in steps]

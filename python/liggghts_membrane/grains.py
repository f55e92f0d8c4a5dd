"""D50: the median grain diameter by mass, as the C++ styles define it.

The step definition of grains::d50_by_mass (common/grain_size.cpp, used by
common/contact_scales.h group_grain_scales for the default tolerances of fix
membrane2d and fix membrane3d): the smallest diameter d such that the grains of
diameter <= d hold at least half of the mass, a grain of diameter d weighing d^2
(disks, 2D) or d^3 (spheres, 3D) for one density. It is one of the diameters of the
grains, never a value interpolated between two of them.
"""
import numpy as np


def d50_by_mass(diameters, dimension=2):
    """D50 by mass of grains of one density (dimension 2: disks, 3: spheres); nan for no
    grain."""
    if dimension not in (2, 3):
        raise ValueError(f"d50_by_mass: dimension {dimension} is not 2 or 3")
    d = np.sort(np.asarray(diameters, dtype=float).ravel())
    if len(d) == 0:
        return float("nan")
    mass = np.cumsum(d ** dimension)
    return float(d[np.searchsorted(mass, 0.5 * mass[-1], side="left")])

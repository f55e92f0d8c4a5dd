"""Strain measured on the particles: the best-fit affine deformation of the interior
disks between two dump frames, to set against the strain of the boundaries (platens,
walls, membrane) and with the Love-Weber stress inside give moduli that do not depend
on how the boundary is measured."""
import numpy as np

from . import field
from .curves import NotMeasurable, measured


def affine_strain(x0, du):
    """(eps_xx, eps_yy), compression > 0, of the least-squares fit du = a + G (x0 - mean x0):
    the small-strain part -G_xx, -G_yy of the best-fit displacement gradient."""
    X = np.column_stack([np.ones(len(x0)), x0 - x0.mean(axis=0)])
    coef, *_ = np.linalg.lstsq(X, du, rcond=None)
    G = coef[1:].T                 # G[i, j] = d u_i / d x_j
    return -float(G[0, 0]), -float(G[1, 1])


def strain_at(frames, frame_ea, ea_target, margin):
    """(eps_xx, eps_yy) of the interior soil disks from the first frame to eps_11 =
    ea_target, interpolated between the two frames around it (frames: a function
    i -> dump frame; frame_ea: eps_11 of each frame)."""
    if not measured(ea_target):
        return ea_target, ea_target
    k = int(np.searchsorted(frame_ea, ea_target))
    if k >= len(frame_ea):
        return (NotMeasurable("no dump frame after eps_11 = %.3g %%" % (100 * ea_target)),) * 2
    points = []
    for i in (max(k - 1, 0), k):
        if i == 0:
            points.append((frame_ea[0], 0.0, 0.0))
            continue
        _, x0, du = field.increment(frames(0), frames(i))
        inside = field.interior_mask(x0, margin)
        points.append((frame_ea[i],) + affine_strain(x0[inside], du[inside]))
    (a0, xx0, yy0), (a1, xx1, yy1) = points
    t = 0.0 if a1 == a0 else (ea_target - a0) / (a1 - a0)
    return xx0 + t * (xx1 - xx0), yy0 + t * (yy1 - yy0)


def particle_secant(table, curves, frames, frame_ea, d50, margin_d50=2.0):
    """(E50 [Pa], nu50) from the Love-Weber deviator inside against the particle strain,
    over the secant window of the boundary E50 (first dump frame to eps_11 = ea50)."""
    ea50 = curves.get("ea50", NotMeasurable("not computed"))
    if not table.has("syy_lw"):
        return (NotMeasurable("no syy_lw column"),) * 2
    exx, eyy = strain_at(frames, frame_ea, ea50, margin_d50 * d50)
    if not measured(eyy):
        return eyy, eyy
    if eyy <= 0:
        return (NotMeasurable("no axial compression of the particles"),) * 2
    q = table["syy_lw"] - table["sxx_lw"]
    dq = float(np.interp(ea50, table["ea"], q) - np.interp(frame_ea[0], table["ea"], q))
    return dq / eyy, -exx / eyy

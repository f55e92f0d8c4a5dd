#!/usr/bin/python3
"""Independent values of compute fabric's 3D outputs (doc/compute_fabric.md, "In 3D")
for the D_degenerate3d / F_topology3d cases, from sphere positions and the linear
normal contact law f_n = k_n * overlap (no tangential force: a sample at rest).
numpy only, written from the doc's formulas, not from the C++ code.

    reference_fabric3d.py CASE     prints NAME VALUE lines (the case's RESULT names)
    reference_fabric3d.py --list   the set-ups it knows
"""
import sys
import numpy as np

KN = 1e4  # setups/materials3d.inc


def lattice(nx, ny, nz, a):
    return np.array([(i * a, j * a, k * a) for k in range(nz) for j in range(ny) for i in range(nx)],
                    dtype=float)


def outputs(x, r, volume=None, ids=None, period_x=None):
    """Every value of fabric3d_print.inc for spheres at x with radii r (IDs 1..N in order);
    period_x: the box length of a periodic x (minimum image)."""
    n = len(x)
    ids = np.arange(1, n + 1) if ids is None else np.asarray(ids)
    normals, fns, branches, counts = [], [], [], np.zeros(n)
    nc = nc0 = 0
    for i in range(n):
        for j in range(i + 1, n):
            a, b = (i, j) if ids[i] < ids[j] else (j, i)
            l = x[b] - x[a]
            if period_x:
                l[0] -= period_x * round(l[0] / period_x)
            dist = np.linalg.norm(l)
            overlap = r[a] + r[b] - dist
            if overlap <= 0:
                continue
            nc += 1
            counts[a] += 1
            counts[b] += 1
            if dist <= 1e-12 * (r[a] + r[b]):
                nc0 += 1
                continue
            normals.append(l / dist)
            fns.append(KN * overlap)
            branches.append(l)
    out = {"nc": nc, "np": n, "nc0": nc0, "skipped": 0, "count_sum": counts.sum()}
    out["cn"] = 2 * nc / n if n else 0.0
    n0, n1 = np.sum(counts == 0), np.sum(counts == 1)
    out["zm"] = (2 * nc - n1) / (n - n0 - n1) if n - n0 - n1 > 0 else 0.0
    comps = [("xx", 0, 0), ("yy", 1, 1), ("zz", 2, 2), ("xy", 0, 1), ("xz", 0, 2), ("yz", 1, 2)]
    a = an = at = np.zeros((3, 3))
    f0 = 0.0
    stress = np.zeros((3, 3))
    if normals:
        N = np.array(normals)
        fn = np.array(fns)
        phi = N.T @ N / len(N)
        dev = lambda t: t - np.trace(t) / 3 * np.eye(3)
        a = 7.5 * dev(phi)
        w = 1 + np.einsum("ci,ij,cj->c", N, a, N)
        ok = w > 1e-12  # w = 0 in exact arithmetic is ~2e-16 here: outside the model
        out["skipped"] = int(np.sum(~ok))
        chi = (N[ok].T * (fn[ok] / w[ok])) @ N[ok] / len(N)
        f0 = np.trace(chi)
        an = 7.5 * dev(chi) / f0 if f0 != 0 else np.zeros((3, 3))
        # force on b from a is f_n n (repulsive), branch a -> b
        if volume:
            stress = sum(f * np.outer(nn, l) for f, nn, l in zip(fn, N, branches)) / volume
    mag = lambda t: np.sqrt(1.5 * np.sum(t * t))
    out.update(a=mag(a), an=mag(an), at=mag(at), f0=f0)
    for name, t in (("a", a), ("an", an), ("at", at), ("s", stress)):
        for c, i, j in comps:
            out["%s_%s" % (name, c)] = 0.5 * (t[i, j] + t[j, i])
    return out


def cases():
    d = 0.00101  # overlapping spheres on a 1 mm lattice: overlap 10 um, f_n = 0.1 N
    r3 = lambda m: np.full(m, d / 2)
    c = {}
    x = lattice(3, 3, 3, 0.001)
    c["cube"] = (x, r3(27), 2.7e-8)
    x = lattice(1, 1, 5, 0.001)
    c["column"] = (x, r3(5), 5e-9)
    x = lattice(3, 3, 1, 0.001)
    c["layer"] = (x, r3(9), 9e-9)
    x = lattice(3, 3, 2, 0.001)
    c["cube_top_deleted"] = (x, r3(18), 1.8e-8)
    # a column of 5 along z and a sphere beside its lowest: a_xx = -1, w = 0 for that contact
    x = np.vstack([lattice(1, 1, 5, 0.001), [(0.001, 0, 0)]])
    c["column_side"] = (x, r3(6), 6e-9)
    # the cube in a box periodic in x of length 3 mm: a ring of contacts along x
    c["cube_periodic_x"] = (lattice(3, 3, 3, 0.001), r3(27), 2.7e-8, 0.003)
    # 1:20 grading: a 20 mm ball at the origin, six 1 mm spheres on its axes, 10 um overlap
    big = 0.01
    s = big + 0.0005 - 1e-5
    x = np.array([(0, 0, 0), (s, 0, 0), (-s, 0, 0), (0, s, 0), (0, -s, 0), (0, 0, s), (0, 0, -s)])
    r = np.array([big] + [0.0005] * 6)
    c["grading"] = (x, r, 8e-6)
    # two clusters: a pair along x at the origin, a column of 3 along z 5 mm away
    x = np.array([(0, 0, 0), (0.001, 0, 0), (0.005, 0, 0), (0.005, 0, 0.001), (0.005, 0, 0.002)])
    c["clusters"] = (x, r3(5), 5e-9)
    return c


if __name__ == "__main__":
    known = cases()
    if len(sys.argv) != 2 or sys.argv[1] not in known:
        print("usage: reference_fabric3d.py CASE; CASE = " + ", ".join(known))
        sys.exit(0 if sys.argv[1:] == ["--list"] else 1)
    x, r, vol, *period = known[sys.argv[1]]
    for k, v in outputs(x, r, vol, period_x=period[0] if period else None).items():
        print("%-10s %.17g" % (k, v))

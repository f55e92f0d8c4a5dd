"""The triaxial example (examples/triaxial/in.triaxial) on a small sample (R = 10 mm,
about 290 spheres): physical sanity of each stage and of the membrane.

  compressed in the rigid cylinder: the platen stress within 5 % of p;
  isotropic with the membrane: membrane spheres found, none escaped, the platen
    stress still within 10 % of p;
  shear to 10 % axial strain: every output row has membrane spheres, the membrane
    reaches both platens (no warning), escapees stay below 2 % of the spheres, q
    rises above 0.3 p by 5 % strain, the volume changes by less than 10 %, and the
    detections follow 'every';
  the fabric in shear (compute fabric): the anisotropies >= 0, Z_m from 3 to 8 and
    C_n <= Z_m in every row, the contact normals' anisotropy a growing and along the
    axis (a_zz > 0) at the end; the Love-Weber stresses within 0.7-1.1 of the
    platen's sigma_1 and of p (the contacts with the platens and the membrane's
    loads are not in its sum);
  the ParaView files by default (vtkstrain 0.01): the membrane's frames from the
    isotropic stage to the end of the shear, on table rows, closed, between the
    platens; the spheres' files at the frames' steps in shear; the radius profile of
    each frame on a row (plot_triaxial.py) giving R_out to 2 %, and the end's bulge
    (mid-height against the platens) larger than the start's.

Usage: triaxial_small.py EXE NP"""
import os
import sys
import tempfile

import numpy as np

from example_run import ROOT, Checks, run, table

EXAMPLE = os.path.join(ROOT, "examples", "triaxial")
from liggghts_membrane import vtk_files
from liggghts_membrane.readers import key_value_lines
from liggghts_membrane.pvd import collection_frames
from liggghts_membrane.triaxial_plot import polydata_points, radius_profile

P = 1e5


def vtk_frames(pvd):
    """(step, points, polys, verts, load sum) of each frame of the membrane's collection,
    read with the package's readers (pvd: the collection, vtk_files: VTK's own reader)."""
    frames = []
    for step, path in collection_frames(pvd):
        poly = vtk_files.read_polydata(path)
        load = vtk_files.point_array(poly, "load")
        frames.append((step, vtk_files.points(poly), poly.GetNumberOfPolys(), poly.GetNumberOfVerts(),
                       load.sum(axis=0)))
    return frames


def check_frames(check, frames, height):
    """The membrane's frames: one at least per stage, facets in each, every corner
    between the platens (z in [0, H0]), and the lateral loads summing to zero."""
    check(len(frames) >= 3, "%d membrane frames" % len(frames))
    for step, points, polys, verts, load in frames:
        check(polys > 100 and verts == 0, "frame %d: %d facets, %d escapees" % (step, polys, verts))
        check(points[:, 2].min() >= 0 and points[:, 2].max() <= height * 1.0001,
              "frame %d: corners from z = %.4g to %.4g" % (step, points[:, 2].min(), points[:, 2].max()))
        check(abs(load[0]) + abs(load[1]) < 1e-9 * abs(load).sum() + 1e-12,
              "frame %d: lateral load sum %.2g, %.2g N" % (step, load[0], load[1]))


def check_fabric(check, t):
    """compute fabric's columns in shear: sane values, the expected trends."""
    for name in ("a", "a_n", "a_t"):
        check(min(t[name]) >= 0, "%s >= 0 in every row (min %.3g)" % (name, min(t[name])))
    check(3 <= min(t["Zm"]) and max(t["Zm"]) <= 8,
          "Z_m from %.3g to %.3g (3 to 8)" % (min(t["Zm"]), max(t["Zm"])))
    check(all(0 < cn <= zm for cn, zm in zip(t["Cn"], t["Zm"])), "0 < C_n <= Z_m in every row")
    check(t["a"][-1] > t["a"][0] and t["a_zz"][-1] > 0,
          "a from %.3g to %.3g, a_zz %.3g at the end (normals along the axis)"
          % (t["a"][0], t["a"][-1], t["a_zz"][-1]))
    s1 = [q + P for q in t["q[Pa]"]]
    zz = [lw / s for lw, s in zip(t["sLW_zz[Pa]"], s1)]
    check(0.7 < min(zz) and max(zz) < 1.1,
          "Love-Weber sigma_zz / platen sigma_1 from %.3f to %.3f" % (min(zz), max(zz)))
    lateral = [v / P for v in t["sLW_xx[Pa]"] + t["sLW_yy[Pa]"]]
    check(0.7 < min(lateral) and max(lateral) < 1.1,
          "Love-Weber sigma_xx, sigma_yy / p from %.3f to %.3f" % (min(lateral), max(lateral)))


def check_paraview(check, folder, t, frames):
    """The ParaView files written by default: the membrane's frames on table rows, from
    the isotropic stage to the end, the spheres' beside them in shear; the radius
    profile of each frame on a row gives R_out, and the membrane bulges."""
    steps = [f[0] for f in frames]
    rows = dict(zip(t["step"], range(len(t["step"]))))
    shear = [s for s in steps if s >= t["step"][0]]
    check(len(frames) - len(shear) >= 1 and len(shear) >= 8 and steps[-1] == t["step"][-1],
          "membrane frames: %d before the shear, %d in it, the last at step %d (last row %d)"
          % (len(frames) - len(shear), len(shear), steps[-1], t["step"][-1]))
    missing = [s for s in shear if not os.path.exists(os.path.join(folder, "particles_%d.vtp" % s))]
    check(not missing, "the spheres' files at the %d frames in shear (missing: %s)"
          % (len(shear), missing))
    worst, bulge = 0.0, {}
    for step in steps:
        z, r = radius_profile(polydata_points(os.path.join(folder, "membrane_%d.vtp" % step),
                                              corners_only=True))
        if step in rows:
            worst = max(worst, abs(np.sqrt(np.mean(r ** 2)) / t["R_out[m]"][rows[step]] - 1))
        middle = np.abs(z - 0.5 * (z.min() + z.max())) < (z.max() - z.min()) / 6
        bulge[step] = r[middle].mean() - 0.5 * (r[0] + r[-1])
    check(worst < 0.02, "the profiles' sqrt(mean R^2) is R_out to %.2f %% (within 2 %%)" % (100 * worst))
    start = max((s for s in steps if s < t["step"][0]), default=steps[0])
    check(bulge[steps[-1]] > bulge[start] and bulge[steps[-1]] > 0,
          "bulge (mid-height R - the platens' R): %.3f mm at the start, %.3f mm at the end"
          % (1000 * bulge[start], 1000 * bulge[steps[-1]]))


def main():
    exe, np_ = sys.argv[1], sys.argv[2]
    check = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "small")
        log = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe,
                   "-in", "in.triaxial", "-var", "R", "0.01", "-var", "hfill", "0.06",
                   "-var", "nsettle", "8000", "-var", "ncompress", "10000",
                   "-var", "nhold", "4000", "-var", "out", out],
                  out + ".log", cwd=EXAMPLE)
        # in.triaxial's key=value lines
        compressed = key_value_lines(log, "triaxial_compressed")[0]
        iso = key_value_lines(log, "triaxial_isotropic")[0]
        atoms = int(compressed["atoms"])
        e1_end = key_value_lines(log, "triaxial_done")[0]["e1"]
        t = table(out + ".txt")
        frames = vtk_frames(os.path.join(out + ".paraview", "membrane.pvd"))
        check_paraview(check, out + ".paraview", t, frames)
        rows, detections = {}, {}
        for every in ("auto", "1"):
            o = os.path.join(tmp, "every_" + every)
            run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe,
                 "-in", "in.triaxial", "-var", "R", "0.01", "-var", "hfill", "0.06",
                 "-var", "nsettle", "8000", "-var", "ncompress", "10000", "-var", "nhold", "2000",
                 "-var", "strain", "0.03", "-var", "every", every, "-var", "vtkstrain", "0",
                 "-var", "out", o],
                o + ".log", cwd=EXAMPLE)
            with open(o + ".txt") as f:
                lines = f.read().splitlines()
            names = lines[0].lstrip("#").split()
            kept = [k for k, n in enumerate(names) if n != "detections"]
            body = [l.split() for l in lines[1:] if l and not l.startswith("#")]
            rows[every] = [[l[k] for k in kept] for l in body]  # all but the detection counter
            detections[every] = float(body[-1][names.index("detections")]) if body else 0.0
    check(abs(compressed["sigma1"] / P - 1) < 0.05,
          "compressed in the cylinder: sigma1 = %.0f Pa" % compressed["sigma1"])
    sigma1, spheres, escaped = iso["sigma1"], iso["membrane_spheres"], iso["escaped"]
    check(abs(sigma1 / P - 1) < 0.10, "isotropic with the membrane: sigma1 = %.0f Pa" % sigma1)
    check(spheres > 0.2 * atoms, "isotropic: %d of %d spheres on the membrane" % (spheres, atoms))
    check(escaped == 0, "isotropic: %d escaped" % escaped)
    e1, q, ev = t["e1"], t["q[Pa]"], t["ev"]
    check(e1_end > 0.0999, "sheared to e1 = %.4f" % e1_end)
    check(min(t["membrane_spheres"]) > 0, "membrane spheres in every row (min %d)" % min(t["membrane_spheres"]))
    check(max(t["escaped"]) < 0.02 * atoms, "escaped at most %d of %d" % (max(t["escaped"]), atoms))
    q5 = [qq for ee, qq in zip(e1, q) if ee > 0.05]
    check(q5 and max(q5) > 0.3 * P, "q beyond 5 %% strain up to %.0f Pa" % (max(q5) if q5 else 0))
    check(max(abs(v) for v in ev) < 0.10, "|ev| at most %.4f" % max(abs(v) for v in ev))
    check("found different membranes" not in log, "the ranks found the same membranes")
    check(log.count("differs between the ranks") <= 1, "a rank-dependent input warned about once at most")
    shear_log = log[log.index("TRIAXIAL isotropic"):]
    check("does not reach" not in shear_log, "the membrane reaches both platens in shear")
    steps = t["step"][-1] - t["step"][0]
    dets = t["detections"][-1] - t["detections"][0]
    check(abs(dets - steps / 50) <= 1, "%d detections in %d steps (every 50)" % (dets, steps))
    check(len(rows["1"]) >= 4 and rows["auto"] == rows["1"],
          "every auto gives the table of every 1 to the last digit (%d rows)" % len(rows["1"]))
    check(0 < detections["auto"] < detections["1"],
          "every auto detects less: %d against %d" % (detections["auto"], detections["1"]))
    check_fabric(check, t)
    check_frames(check, frames, compressed["H"])
    if check.failures:
        sys.exit("FAIL: %d checks" % len(check.failures))


if __name__ == "__main__":
    main()

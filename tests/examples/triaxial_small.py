"""The triaxial example (examples/triaxial/in.triaxial) on a small sample (R = 10 mm,
about 290 spheres): physical sanity of each stage and of the membrane.

  compressed in the rigid cylinder: the platen stress within 5 % of p;
  isotropic with the membrane: membrane spheres found, none escaped, the platen
    stress still within 10 % of p;
  shear to 10 % axial strain: every output row has membrane spheres, the membrane
    reaches both platens (no warning), escapees stay below 2 % of the spheres, q
    rises above 0.3 p by 5 % strain, the volume changes by less than 10 %, and the
    detections follow 'every'.

Usage: triaxial_small.py EXE NP"""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from example_run import ROOT, Checks, run, table  # noqa: E402

EXAMPLE = os.path.join(ROOT, "examples", "triaxial")
P = 1e5


def vtk_frames(pvd):
    """(step, points, polys, verts, load sum) of each frame of the membrane's collection,
    read with VTK's own readers."""
    import vtk  # Debian's python3-vtk9
    from vtk.util.numpy_support import vtk_to_numpy

    folder = os.path.dirname(pvd)
    with open(pvd) as f:
        entries = re.findall(r'timestep="(\d+)" part="0" file="([^"]+)"', f.read())
    frames = []
    for step, name in entries:
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(folder, name))
        reader.Update()
        poly = reader.GetOutput()
        points = vtk_to_numpy(poly.GetPoints().GetData())
        load = vtk_to_numpy(poly.GetPointData().GetArray("load"))
        frames.append((int(step), points, poly.GetNumberOfPolys(), poly.GetNumberOfVerts(),
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


def main():
    exe, np_ = sys.argv[1], sys.argv[2]
    check = Checks()
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "small")
        log = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe,
                   "-in", "in.triaxial", "-var", "R", "0.01", "-var", "hfill", "0.06",
                   "-var", "nsettle", "8000", "-var", "ncompress", "10000",
                   "-var", "nhold", "4000", "-var", "vtkevery", "4000", "-var", "out", out],
                  out + ".log", cwd=EXAMPLE)
        compressed = float(re.search(r"TRIAXIAL compressed: sigma1 = (\S+) Pa", log).group(1))
        iso = re.search(r"TRIAXIAL isotropic: sigma1 = (\S+) Pa, V_out = (\S+) m3, R_out = (\S+) m, "
                        r"membrane spheres (\S+), escaped (\S+)", log)
        atoms = int(re.search(r"^ +1 +(\d+) ", log, re.M).group(1))
        e1_end = float(re.search(r"TRIAXIAL done: e1 = (\S+),", log).group(1))
        t = table(out + ".txt")
        frames = vtk_frames(out + "_membrane.pvd")
        rows, detections = {}, {}
        for every in ("auto", "1"):
            o = os.path.join(tmp, "every_" + every)
            run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", np_, exe,
                 "-in", "in.triaxial", "-var", "R", "0.01", "-var", "hfill", "0.06",
                 "-var", "nsettle", "8000", "-var", "ncompress", "10000", "-var", "nhold", "2000",
                 "-var", "strain", "0.03", "-var", "every", every, "-var", "out", o],
                o + ".log", cwd=EXAMPLE)
            with open(o + ".txt") as f:
                lines = [l.split() for l in f if not l.startswith("#")]
            rows[every] = [l[:-1] for l in lines]  # all but the detection counter
            detections[every] = float(lines[-1][-1]) if lines else 0.0
    check(abs(compressed / P - 1) < 0.05, "compressed in the cylinder: sigma1 = %.0f Pa" % compressed)
    sigma1, spheres, escaped = float(iso.group(1)), float(iso.group(4)), float(iso.group(5))
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
    check_frames(check, frames, float(re.search(r"TRIAXIAL compressed: sigma1 = \S+ Pa at H = (\S+) m",
                                                log).group(1)))
    if check.failures:
        sys.exit("FAIL: %d checks" % len(check.failures))


if __name__ == "__main__":
    main()

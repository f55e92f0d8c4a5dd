#!/usr/bin/env python3
"""The extent of the membrane in a fix membrane3d VTK frame (FILE_<step>.vtp).

    shell python3 ${testdir}/membrane3d_vtp_extent.py m_0.vtp

prints RESULT vtp_xmin, vtp_xmax, vtp_ymin, ... vtp_zmax over the points of its
facets (Polys; the escaped spheres' Verts left out), and vtp_points, their count,
for the adversarial cases (run_cases.py reads RESULT lines). The file is read by
liggghts_membrane.vtk_files (VTK's own reader).
"""
import sys

from liggghts_membrane import vtk_files


def main(path):
    poly = vtk_files.read_polydata(path)
    xyz = vtk_files.points(poly)
    used = vtk_files.polygon_point_ids(poly)
    names = ("x", "y", "z")
    for axis in range(3):
        vals = list(xyz[used, axis]) or [float("nan")]
        print("RESULT vtp_%smin %.17g" % (names[axis], min(vals)))
        print("RESULT vtp_%smax %.17g" % (names[axis], max(vals)))
    print("RESULT vtp_points %d" % len(used))
    sys.stdout.flush()


if __name__ == "__main__":
    main(sys.argv[1])

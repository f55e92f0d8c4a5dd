#!/usr/bin/env python3
"""The extent of the membrane in a fix membrane3d VTK frame (FILE_<step>.vtp).

    shell python3 ${testdir}/membrane3d_vtp_extent.py m_0.vtp

prints RESULT vtp_xmin, vtp_xmax, vtp_ymin, ... vtp_zmax over the points of its
facets (Polys; the escaped spheres' Verts left out), and vtp_points, their count,
for the adversarial cases (run_cases.py reads RESULT lines).
"""
import sys
import xml.etree.ElementTree as ET


def arrays(piece, section):
    out = {}
    node = piece.find(section)
    if node is None:
        return out
    for da in node.iter("DataArray"):
        out[da.attrib.get("Name")] = (da.text or "").split()
    return out


def main(path):
    root = ET.parse(path).getroot()
    piece = root.find("PolyData/Piece")
    xyz = [float(v) for v in arrays(piece, "Points")["Points"]]
    polys = arrays(piece, "Polys").get("connectivity", [])
    used = sorted({int(i) for i in polys})
    names = ("x", "y", "z")
    for axis in range(3):
        vals = [xyz[3 * i + axis] for i in used] or [float("nan")]
        print("RESULT vtp_%smin %.17g" % (names[axis], min(vals)))
        print("RESULT vtp_%smax %.17g" % (names[axis], max(vals)))
    print("RESULT vtp_points %d" % len(used))
    sys.stdout.flush()


if __name__ == "__main__":
    main(sys.argv[1])

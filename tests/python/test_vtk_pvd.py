"""The readers of the VTK formats: liggghts_membrane.vtk_files (.vtp XML, .vtk legacy,
read by VTK's own readers) and liggghts_membrane.pvd.read_collection (.pvd), on
hand-written files whose contents are known."""
import locale
import os
import tempfile
import unittest

import numpy as np

from liggghts_membrane import pvd, vtk_files

VTP = """<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0">
      <PointData>
        <DataArray type="Int32" Name="escaped" format="ascii">0 1 0</DataArray>
      </PointData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">1 2 3 4 5 6 7 8 9.5</DataArray>
      </Points>
    </Piece>
  </PolyData>
</VTKFile>
"""

LEGACY = """# vtk DataFile Version 3.0
two points
ASCII
DATASET POLYDATA
POINTS 2 double
0.5 0 0
1 2 3
POINT_DATA 2
SCALARS radius double 1
LOOKUP_TABLE default
0.25 0.75
"""

PVD = """<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1">
  <Collection>
    <DataSet timestep="100" part="0" name="particles" file="particles_100.vtp"/>
    <DataSet timestep="100" part="3" name="membrane" file="membrane_100.vtp"/>
    <DataSet timestep="200" part="0" file="sub/particles_200.vtp"/>
  </Collection>
</VTKFile>
"""


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def write(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path


class VtkFiles(Files):
    def test_xml_points_and_arrays(self):
        poly = vtk_files.read_polydata(self.write("m.vtp", VTP))
        np.testing.assert_array_equal(vtk_files.points(poly), [[1, 2, 3], [4, 5, 6], [7, 8, 9.5]])
        np.testing.assert_array_equal(vtk_files.point_array(poly, "escaped"), [0, 1, 0])
        self.assertFalse(vtk_files.has_point_array(poly, "radius"))
        with self.assertRaises(KeyError):
            vtk_files.point_array(poly, "radius")

    def test_corners_leave_the_escaped_out(self):
        path = self.write("m.vtp", VTP)
        np.testing.assert_array_equal(vtk_files.polydata_points(path, corners_only=True),
                                      [[1, 2, 3], [7, 8, 9.5]])
        self.assertEqual(len(vtk_files.polydata_points(path)), 3)

    def test_legacy_vtk(self):
        kept = locale.setlocale(locale.LC_ALL)
        poly = vtk_files.read_polydata(self.write("p.vtk", LEGACY))
        self.assertEqual(locale.setlocale(locale.LC_ALL), kept)   # VTK's reader sets "C"
        np.testing.assert_array_equal(vtk_files.points(poly), [[0.5, 0, 0], [1, 2, 3]])
        np.testing.assert_array_equal(vtk_files.point_array(poly, "radius"), [0.25, 0.75])

    def test_refused(self):
        with self.assertRaises(FileNotFoundError):
            vtk_files.read_polydata(os.path.join(self.dir.name, "none.vtp"))
        for name, text in (("cut.vtp", VTP[:200]), ("empty.vtp", ""), ("words.vtk", "nonsense\n")):
            with self.subTest(name=name), self.assertRaises(ValueError):
                vtk_files.read_polydata(self.write(name, text))
        with self.assertRaises(ValueError):
            vtk_files.read_polydata(self.write("m.vtu", VTP))


class Collections(Files):
    def test_read(self):
        path = self.write("run.pvd", PVD)
        sets = pvd.read_collection(path)
        self.assertEqual([(d.timestep, d.part, d.name) for d in sets],
                         [(100.0, 0, "particles"), (100.0, 3, "membrane"), (200.0, 0, "")])
        self.assertEqual(sets[2].path, os.path.join(self.dir.name, "sub", "particles_200.vtp"))
        self.assertEqual(pvd.collection_frames(path),
                         [(100, os.path.join(self.dir.name, "particles_100.vtp")),
                          (200, os.path.join(self.dir.name, "sub", "particles_200.vtp"))])
        self.assertEqual(pvd.collection_frames(path, part=3)[0][0], 100)
        self.assertEqual(pvd.collection_frames(os.path.join(self.dir.name, "none.pvd")), [])

    def test_written_collection_reads_back(self):
        names = ["particles_5.vtp", "membrane_5.vtp", "particles_10.vtp"]
        path = self.write("run.pvd", pvd.collection(names))
        self.assertEqual([(d.timestep, d.part, d.name, os.path.basename(d.path))
                          for d in pvd.read_collection(path)],
                         [(5.0, 0, "particles", "particles_5.vtp"), (5.0, 3, "membrane", "membrane_5.vtp"),
                          (10.0, 0, "particles", "particles_10.vtp")])

    def test_refused(self):
        with self.assertRaises(ValueError):
            pvd.read_collection(self.write("a.pvd", "<VTKFile type=\"PolyData\"/>"))
        with self.assertRaises(ValueError):
            pvd.read_collection(self.write("b.pvd", "<VTKFile"))


if __name__ == "__main__":
    unittest.main()

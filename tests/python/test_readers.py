"""The file readers on small hand-written files."""
import os
import tempfile
import textwrap
import unittest

import numpy as np

from liggghts_membrane import readers

OUT = """\
# biaxial test, rigid walls: hand-written
# step t ea s1 s3 s1/s3 ev el I sxx_int syy_int C_n W H KE a theta_a extra_col
0 0 0 100000 100000 1 0 0 7e-4 99000 99000 2.3 0.075 0.15 0 0.05 90 7
0 0 0 111111 100000 1.1 0 0 7e-4 99000 99000 2.3 0.075 0.15 0 0.05 90 7
500 0.05 0.0005 130000 100000 1.3 0.0003 -0.0002 7e-4 99000 129000 2.3 0.075 0.149 0 0.06 91 7
1000 0.1 0.001 150000 100100 1.4985 0.0005 -0.0005 7e-4 99000 149000 2.29 0.075 0.148 0 nan 92 7
1500 0.15 0.0015 1600
"""

ROSE = """\
# Time-averaged data for fix rose
# TimeStep Number-of-rows
# Row c_fab[1] c_fab[2] c_fab[3] c_fab[4]
1000 4
1 45 10 2.5 0.1
2 135 6 1.5 -0.1
3 225 10 2.5 0.1
4 315 6 1.5 -0.1
1500 4
1 45 11 2.6 0.2
2 135 5 1.4 -0.2
3 225 11 2.6 0.2
4 315 5 1.4 -0.2
2000 4
1 45 11 2.6 0.2
"""

DUMP = """\
ITEM: TIMESTEP
0
ITEM: NUMBER OF ATOMS
3
ITEM: BOX BOUNDS ff ff pp
0 0.075
0 0.15
-0.5 0.5
ITEM: ATOMS id x y radius f_mem
3 0.03 0.01 0.001 1
1 0.01 0.01 0.0005 0
2 0.02 0.01 0.0015 0
ITEM: TIMESTEP
5000
ITEM: NUMBER OF ATOMS
2
ITEM: BOX BOUNDS ff ff pp
0 0.075
0 0.15
-0.5 0.5
ITEM: ATOMS id x y radius f_mem
2 0.021 0.011 0.0015 3
1 0.011 0.009 0.0005 0
"""

POLYLINE = """\
ITEM: TIMESTEP
100
ITEM: POLYLINE left 3
0.0 0.0
0.001 0.05
0.0 0.1
ITEM: CHAIN left 2
7 0.001 0.0 0.0005 -1.5 0.0
9 0.001 0.1 0.0005 -2.5 0.25
ITEM: TIMESTEP
200
ITEM: POLYLINE right 2
0.075 0.0
0.075 0.1
"""

DATA = """\
LIGGGHTS data: 3 disks at HALF size

3 atoms
1 atom types

-0.02 0.095 xlo xhi

Atoms

1 1 0.001 2e8 0.01 0.01 0
2 1 0.0015 2e8 0.02 0.01 0
3 1 0.0005 2e8 0.03 0.01 0

Velocities
1 0 0 0
"""


class Readers(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        for name, text in (("out", OUT), ("out.rose", ROSE), ("out.dump", DUMP),
                           ("out.polyline", POLYLINE), ("sample.data", DATA)):
            with open(os.path.join(self.dir, name), "w") as f:
                f.write(textwrap.dedent(text))

    def tearDown(self):
        self.tmp.cleanup()

    def test_output_table(self):
        t = readers.read_output(os.path.join(self.dir, "out"))
        self.assertEqual(len(t), 3)                       # duplicate step and short line dropped
        np.testing.assert_array_equal(t["step"], [0, 500, 1000])
        self.assertEqual(t["s1"][0], 100000)             # the first line of a repeated step
        self.assertAlmostEqual(t["el"][2], -0.0005)
        self.assertEqual(t.missing, ["an", "theta_n", "f0", "at", "Zm", "gsi", "sxx_lw", "syy_lw"])
        self.assertEqual(t.extra, ["extra_col"])
        self.assertTrue(t.has("a"))
        self.assertTrue(np.isnan(t["a"][2]))
        self.assertFalse(t.has("f0"))

    def test_output_without_mechanical_column_is_an_error(self):
        path = os.path.join(self.dir, "bad")
        with open(path, "w") as f:
            f.write("# step ea s1\n0 0 1\n")
        with self.assertRaises(ValueError):
            readers.read_output(path)

    def test_rose(self):
        blocks = readers.read_rose(os.path.join(self.dir, "out.rose"))
        self.assertEqual([s for s, _ in blocks], [1000, 1500])   # truncated block dropped
        step, b = blocks[1]
        np.testing.assert_array_equal(b["centre_deg"], [45, 135, 225, 315])
        np.testing.assert_array_equal(b["count"], [11, 5, 11, 5])
        np.testing.assert_array_equal(b["mean_fn"], [2.6, 1.4, 2.6, 1.4])
        np.testing.assert_array_equal(b["mean_ft"], [0.2, -0.2, 0.2, -0.2])

    def test_dump(self):
        path = os.path.join(self.dir, "out.dump")
        index = readers.dump_steps(path)
        self.assertEqual([s for s, _ in index], [0, 5000])
        frames = readers.read_dump(path)
        f0, f1 = frames[0], frames[5000]
        np.testing.assert_array_equal(f0["id"], [1, 2, 3])           # sorted by id
        np.testing.assert_array_equal(f0["x"], [0.01, 0.02, 0.03])
        np.testing.assert_array_equal(f0["f_mem"], [0, 0, 1])
        self.assertEqual(f1["step"], 5000)
        self.assertEqual(len(f1["id"]), 2)

    def test_columns_keep_repeated_steps(self):
        columns, header = readers.read_columns(os.path.join(self.dir, "out"))
        self.assertEqual(header[-1], "extra_col")
        np.testing.assert_array_equal(columns["step"], [0, 0, 500, 1000])   # no dedup here
        self.assertEqual(columns["s1"][1], 111111)

    def test_polylines(self):
        frames = readers.read_polylines(os.path.join(self.dir, "out.polyline"))
        self.assertEqual(sorted(frames), [100, 200])
        left = frames[100]["left"]
        np.testing.assert_array_equal(left["polyline"][:, 1], [0.0, 0.05, 0.1])
        np.testing.assert_array_equal(left["chain"][:, 0], [7, 9])
        self.assertEqual(left["chain"][1, 5], 0.25)
        self.assertEqual(list(frames[200]), ["right"])
        self.assertNotIn("chain", frames[200]["right"])

    def test_data_diameters(self):
        d = readers.read_data_diameters(os.path.join(self.dir, "sample.data"))
        np.testing.assert_array_equal(d, [0.001, 0.0015, 0.0005])

    def test_increment_keeps_soil_present_in_both(self):
        from liggghts_membrane import field
        frames = readers.read_dump(os.path.join(self.dir, "out.dump"))
        ids, x0, du = field.increment(frames[0], frames[5000])
        # 3 is a chain disk, 2 escaped in the second frame: only 1 is left
        np.testing.assert_array_equal(ids, [1])
        np.testing.assert_allclose(du, [[0.001, -0.001]])


class KeyValueLines(unittest.TestCase):
    """The key=value lines printed for programs: fix membrane2d's membrane2d_traffic,
    in.shear_membrane's membrane_counts, in.prepare's prepared, OUT.params."""

    def test_lines_of_one_tag(self):
        text = ("fix mem: each rank received 1.97 kB per step ...\n"
                "membrane2d_traffic id=mem kb_per_step=1.97172 kb_per_detection=8.72 steps=100 "
                "detections=10 full_passes=3 fix_seconds=0.25 search_seconds=0.0125\n"
                "membrane2d_trafficx kb_per_step=5\n"
                "  membrane2d_traffic id=m2 steps=7 loose\n")
        lines = readers.key_value_lines(text, "membrane2d_traffic")
        self.assertEqual(lines, [dict(id="mem", kb_per_step=1.97172, kb_per_detection=8.72, steps=100.0,
                                      detections=10.0, full_passes=3.0, fix_seconds=0.25,
                                      search_seconds=0.0125),
                                 dict(id="m2", steps=7.0)])
        self.assertEqual(readers.key_value_lines(text, "prepared"), [])

    def test_params_file(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "out.txt.params")
            self.assertEqual(readers.read_params(path), {})
            with open(path, "w") as f:
                f.write("shear rate=0.0025 nramp=9200 d50=0.00175 atoms=526\nother nramp=9300\n")
            self.assertEqual(readers.read_params(path),
                             dict(rate=0.0025, nramp=9300.0, d50=0.00175, atoms=526.0))

    def test_data_atoms(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "s.data")
            with open(path, "w") as f:
                f.write("LIGGGHTS data\n\n2 atoms\n3 atom types\n\nAtoms\n\n"
                        "1 1 0.001 2500 0.1 0.2 0\n2 2 0.002 2500 0.3 0.4 0  # a comment\n\n"
                        "Velocities\n\n1 0 0 0 0 0 0\n")
            a = readers.read_data_atoms(path)
            np.testing.assert_array_equal(a["type"], [1, 2])
            np.testing.assert_array_equal(a["diameter"], [0.001, 0.002])
            np.testing.assert_array_equal(a["y"], [0.2, 0.4])


if __name__ == "__main__":
    unittest.main()

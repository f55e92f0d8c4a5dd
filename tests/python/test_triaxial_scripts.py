"""The triaxial example's scripts: plot_triaxial.py on hand-written tables (a plot from a
table still being written, one clear line, no traceback, for each table it cannot
plot), its computations on hand-made inputs (the Love-Weber stress ratio, the axis and
radius profile of the membrane's corners, the frames drawn and their strains), and
run_triaxial.sh's options refused before anything runs."""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

EXAMPLE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "triaxial")
SCRIPT = os.path.join(EXAMPLE, "plot_triaxial.py")
from liggghts_membrane import triaxial_plot

OLD_HEADER = "# step e1 q[Pa] p[Pa] ev R_out[m] membrane_spheres escaped detections\n"
HEADER = ("# step e1 q[Pa] p[Pa] ev R_out[m] membrane_spheres escaped detections a a_n a_t "
          "a_zz an_zz at_zz Zm Cn sLW_zz[Pa] sLW_xx[Pa] sLW_yy[Pa]\n")
OLD_ROWS = ("60500 0.0015 6000 102000 0.001 0.0244 1575 0 210\n"
            "61000 0.0031 15000 105000 0.002 0.0245 1575 0 220\n")
FABRIC = (" 0.25 0.5 0.16 0.14 0.32 0.10 5.13 5.05 101000 92000 93000\n",
          " 0.26 0.8 0.30 0.13 0.53 0.20 5.14 5.05 110000 93000 94000\n")
ROWS = "".join(r.rstrip("\n") + f for r, f in zip(OLD_ROWS.splitlines(), FABRIC))


def run(*args):
    done = subprocess.run(["/usr/bin/python3", SCRIPT, *args], capture_output=True, text=True)
    return done.returncode, done.stdout + done.stderr


class PlotTriaxial(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)

    def table(self, name, text):
        path = os.path.join(self.dir.name, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_a_growing_table_is_plotted_beside_it(self):
        path = self.table("t.txt", HEADER + ROWS + "61500 0.0046 2")  # the last line cut
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertTrue(os.path.getsize(os.path.join(self.dir.name, "t.png")) > 1000)

    def test_gaps_are_warned(self):
        path = self.table("t.txt", HEADER + ROWS.replace("102000", "0").replace("15000", "nan"))
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertIn("warning: 2 rows have values that are not finite (or p = 0)", out)

    def test_what_cannot_be_plotted_is_said_in_one_line(self):
        cases = [
            ((os.path.join(self.dir.name, "none.txt"),), "no file"),
            ((self.table("empty.txt", ""),), "no header line"),
            ((self.table("header.txt", HEADER),), "no complete data row yet"),
            ((self.table("other.txt", "# step e1 q\n1 2 3\n"),), "the header lacks q[Pa] p[Pa] ev"),
            ((self.table("rows.txt", ROWS),), "data before any '#' header line"),
            ((self.table("same.txt", HEADER + ROWS), os.path.join(self.dir.name, "same.txt")),
             "would overwrite the table"),
            ((self.table("t.txt", HEADER + ROWS), "/nonexistent_dir/x.png"), "no folder"),
        ]
        for args, said in cases:
            rc, out = run(*args)
            self.assertEqual(rc, 1, out)
            self.assertIn(said, out)
            self.assertNotIn("Traceback", out)

    def test_a_png_named_table_is_not_overwritten(self):
        path = self.table("same.png", HEADER + ROWS)
        rc, out = run(path)
        self.assertEqual(rc, 0, out)
        self.assertIn("same.png.png", out)
        with open(path) as f:
            self.assertEqual(f.read(), HEADER + ROWS)

    def test_usage(self):
        self.assertEqual(run()[0], 2)
        rc, out = run("--help")
        self.assertEqual(rc, 0)
        self.assertIn("usage: plot_triaxial.py OUT.txt [PNG]", out)


def vtp(points, escaped):
    """An ascii VTK PolyData file as fix membrane3d writes it (the arrays the report reads)."""
    flags = " ".join(str(int(e)) for e in escaped)
    xyz = " ".join(repr(float(v)) for v in np.asarray(points).ravel())
    return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n  <PolyData>\n'
            f'    <Piece NumberOfPoints="{len(points)}" NumberOfPolys="0">\n      <PointData>\n'
            f'        <DataArray type="Int32" Name="escaped" NumberOfComponents="1" format="ascii">\n'
            f'          {flags}\n        </DataArray>\n      </PointData>\n      <Points>\n'
            '        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">\n'
            f'          {xyz}\n        </DataArray>\n      </Points>\n    </Piece>\n'
            '  </PolyData>\n</VTKFile>\n')


def bulged(centre, height, r0, bulge, levels=10, per_level=12):
    """Corners of a bulged cylinder: R(z) = r0 + bulge sin(pi z / H) at `levels` heights
    (the centres of the 2 mm bins when H = 20 mm), `per_level` equally spaced angles at
    each, turned from level to level, and at each platen (z = 0, H) the rim: 4 corners
    at r0 on opposite sides (so that the axis is exactly the centre). Returns the
    points, the levels' z and each bin's mean R: R(z) of its level, and in the first and
    last bin (per_level R(z) + 4 r0) / (per_level + 4)."""
    z = (np.arange(levels) + 0.5) * height / levels
    radius = r0 + bulge * np.sin(math.pi * z / height)
    pts = []
    for k, (zk, rk) in enumerate(zip(z, radius)):
        for j in range(per_level):
            phi = 2 * math.pi * j / per_level + 0.37 * k
            pts.append((centre[0] + rk * math.cos(phi), centre[1] + rk * math.sin(phi), zk))
    for zk in (0.0, height):
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            pts.append((centre[0] + r0 * dx, centre[1] + r0 * dy, zk))
    binned = radius.copy()
    for end in (0, -1):
        binned[end] = (per_level * radius[end] + 4 * r0) / (per_level + 4)
    return np.array(pts), z, binned


class Computations(unittest.TestCase):
    """plot_triaxial's numbers, against values worked by hand."""

    def test_love_weber_ratio(self):
        # q = zz - (xx + yy)/2, p = (zz + xx + yy)/3: (250, 100, 100) -> 150/150;
        # (200, 80, 120) -> 100/(400/3) = 0.75; a zero mean stress is a gap
        c = {"sLW_zz[Pa]": np.array([250.0, 200.0, 0.0]), "sLW_xx[Pa]": np.array([100.0, 80.0, 0.0]),
             "sLW_yy[Pa]": np.array([100.0, 120.0, 0.0])}
        r = triaxial_plot.love_weber_ratio(c)
        self.assertAlmostEqual(r[0], 1.0, places=14)
        self.assertAlmostEqual(r[1], 0.75, places=14)
        self.assertTrue(math.isnan(r[2]))

    def test_axis_from_points_on_one_side(self):
        # seven points on a quarter of a circle about (3, -2) mm: the fit finds the
        # centre, which their mean (far inside the arc) would not
        phi = np.linspace(0.1, 1.5, 7)
        pts = np.column_stack([0.003 + 0.01 * np.cos(phi), -0.002 + 0.01 * np.sin(phi),
                               np.zeros(7)])
        cx, cy = triaxial_plot.axis_centre(pts)
        self.assertAlmostEqual(cx, 0.003, delta=1e-12)
        self.assertAlmostEqual(cy, -0.002, delta=1e-12)

    def test_radius_profile_of_a_bulged_cylinder(self):
        # 20 mm high, the axis at (4, 1) mm: 10 bins of 2 mm, one level in each, 10 mm
        # at the platens to 11 mm at mid-height
        pts, z, binned = bulged((0.004, 0.001), 0.02, 0.010, 0.001)
        zb, rb = triaxial_plot.radius_profile(pts, bin_width=0.002)
        np.testing.assert_allclose(zb, z, atol=1e-15)
        np.testing.assert_allclose(rb, binned, rtol=1e-12)
        self.assertAlmostEqual(rb[4], 0.010 + 0.001 * math.sin(math.pi * 0.45), delta=1e-14)
        self.assertAlmostEqual(rb[0], (12 * (0.010 + 0.001 * math.sin(math.pi * 0.05)) + 4 * 0.010)
                               / 16, delta=1e-14)

    def test_sparse_bins_are_left_out(self):
        pts, _, _ = bulged((0.0, 0.0), 0.02, 0.01, 0.0)
        pts = pts[(pts[:, 2] < 0.006) | (pts[:, 2] > 0.008)]    # empties the 4th level
        pts = np.vstack([pts, [[0.01, 0.0, 0.007], [-0.01, 0.0, 0.007]]])  # 2 corners there
        zb, rb = triaxial_plot.radius_profile(pts, bin_width=0.002)
        self.assertEqual(len(zb), 9)
        np.testing.assert_allclose(zb, [0.001, 0.003, 0.005, 0.009, 0.011, 0.013, 0.015, 0.017,
                                        0.019], atol=1e-15)
        np.testing.assert_allclose(rb, 0.01, rtol=1e-12)
        with self.assertRaises(ValueError):
            triaxial_plot.radius_profile(pts[:2])

    def test_frame_strains(self):
        # 1.2e-5 per step from the rows (22500, 0.6 %) to (23500, 1.8 %): the shear
        # starts at step 22000; a frame of the isotropic stage at 21000 gets -1.2 %
        steps = np.array([22500.0, 23000.0, 23500.0])
        e1 = np.array([0.006, 0.012, 0.018])
        eps = triaxial_plot.frame_strains(steps, e1, [21000, 22000, 23000, 24000])
        np.testing.assert_allclose(eps, [-0.012, 0.0, 0.012, 0.024], atol=1e-15)
        self.assertTrue(np.isnan(triaxial_plot.frame_strains(steps[:1], e1[:1], [22000])).all())

    def test_frames_drawn(self):
        steps = 22000.0 + 500 * np.arange(1, 11)              # rows at 22500 ... 27000
        e1 = 0.006 * np.arange(1, 11)
        ratio = np.array([0.3, 0.5, 0.7, 0.9, 1.0, 0.95, 0.9, 0.88, 0.87, 0.86])  # peak at row 4
        frames = [20000, 21000, 22000, 23000, 24000, 25000, 26000, 27000]
        drawn, _ = triaxial_plot.choose_frames(steps, e1, ratio, frames)
        # start: 22000 (the last at e1 <= 0); peak: row 24500 -> the frame at 24000 or
        # 25000, the nearer first (24000); end: 27000
        self.assertEqual(drawn, [("start of shear", 2), ("peak of q/p", 4), ("end", 7)])
        rising = np.linspace(0.3, 1.2, 10)                     # no peak: start and end
        self.assertEqual(triaxial_plot.choose_frames(steps, e1, rising, frames)[0],
                         [("start of shear", 2), ("end", 7)])
        # frames from the shear on only: the first is the start; one frame: drawn once
        self.assertEqual(triaxial_plot.choose_frames(steps, e1, rising, [23000, 27000])[0],
                         [("start of shear", 0), ("end", 1)])
        self.assertEqual(triaxial_plot.choose_frames(steps, e1, ratio, [27000])[0],
                         [("start of shear", 0)])

    def test_escaped_spheres_are_not_corners(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "m.vtp")
            with open(path, "w") as f:
                f.write(vtp([[1, 2, 3], [4, 5, 6], [7, 8, 9]], [0, 1, 0]))
            np.testing.assert_array_equal(triaxial_plot.polydata_points(path, corners_only=True),
                                          [[1, 2, 3], [7, 8, 9]])
            self.assertEqual(len(triaxial_plot.polydata_points(path)), 3)


class PlotWithFrames(unittest.TestCase):
    """plot_triaxial.py on a table and membrane frames beside it (OUT.paraview/membrane.pvd)."""

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.addCleanup(self.dir.cleanup)
        self.table = os.path.join(self.dir.name, "t.txt")
        with open(self.table, "w") as f:
            f.write(HEADER + ROWS)
        self.frames = os.path.join(self.dir.name, "t.paraview")
        os.mkdir(self.frames)

    def write_frames(self, frames):
        """frames: {step: file text}; writes them and membrane.pvd."""
        rows = []
        for step, text in frames.items():
            name = "membrane_%d.vtp" % step
            with open(os.path.join(self.frames, name), "w") as f:
                f.write(text)
            rows.append('    <DataSet timestep="%d" part="0" file="%s"/>\n' % (step, name))
        with open(os.path.join(self.frames, "membrane.pvd"), "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                    "  <Collection>\n" + "".join(rows) + "  </Collection>\n</VTKFile>\n")

    def test_the_profiles_are_drawn_and_described(self):
        # the rows (60500, 0.15 %) and (61000, 0.31 %): the shear starts at step 60031;
        # a frame of the isotropic stage (59000), the start (59500: a straight 10 mm
        # cylinder) and the end (61000: bulged by 1 mm at mid-height, its axis at x = 1 mm)
        # with an escaped sphere far out, which is no corner
        straight, _, _ = bulged((0.0, 0.0), 0.02, 0.010, 0.0)
        bulge, _, binned = bulged((0.001, 0.0), 0.02, 0.010, 0.001)
        out = np.vstack([bulge, [[0.05, 0.0, 0.01]]])
        self.write_frames({59000: vtp(straight, [0] * len(straight)),
                           59500: vtp(straight, [0] * len(straight)),
                           61000: vtp(out, [0] * len(bulge) + [1])})
        rc, said = run(self.table)
        self.assertEqual(rc, 0, said)
        self.assertTrue(os.path.getsize(os.path.join(self.dir.name, "t.png")) > 1000)
        self.assertNotIn("note:", said)
        lines = [l for l in said.splitlines() if l.startswith("membrane at")]
        self.assertEqual(len(lines), 2, said)
        self.assertIn("start of shear (step 59500, ε₁ = 0.00 %): R = 10.00 and 10.00 mm at "
                      "the platens, 10.00 mm at mid-height", lines[0])
        # the end: 10.12 mm in the end bins ((12 x 10.156 + 4 x 10) / 16), 10.99 mm in
        # those at z = 9 and 11 mm (mid-height: the lower, 9 mm; the largest: either)
        self.assertIn("end (step 61000, ε₁ = 0.31 %%): R = %.2f and %.2f mm at the platens, "
                      "%.2f mm at mid-height, largest %.2f mm at z = "
                      % tuple(1000 * binned[[0, -1, 4, 4]]), lines[1])
        self.assertRegex(lines[1], r"at z = (9\.0|11\.0) mm$")   # the two bins tie
        self.assertIn("R = 10.12 and 10.12 mm at the platens, 10.99 mm at mid-height", lines[1])

    def test_unreadable_frames_are_left_out(self):
        straight, _, _ = bulged((0.0, 0.0), 0.02, 0.010, 0.0)
        self.write_frames({59500: vtp(straight, [0] * len(straight)),
                           61000: "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\""})  # cut
        rc, said = run(self.table)
        self.assertEqual(rc, 0, said)
        self.assertIn("warning: frame", said)
        self.assertIn("membrane_61000.vtp left out", said)
        self.assertIn("membrane at the start of shear (step 59500", said)
        self.assertNotIn("Traceback", said)

    def test_without_frames_or_fabric_the_panels_say_so(self):
        rc, said = run(self.table)
        self.assertEqual(rc, 0, said)
        self.assertIn("note: no membrane frames", said)
        self.assertIn("vtkstrain 0", said)
        with open(self.table, "w") as f:
            f.write(OLD_HEADER + OLD_ROWS)
        rc, said = run(self.table)
        self.assertEqual(rc, 0, said)
        self.assertIn("note: the table has no fabric columns (a a_n a_t Zm Cn)", said)
        self.assertNotIn("Traceback", said)


class RunTriaxialOptions(unittest.TestCase):
    def test_bad_options_stop_before_any_run(self):
        # --np 0 would run on every slot (Open MPI), the full-size sample
        for args in (["--np"], ["--np", "0"], ["--np", "-1"], ["--np", "1.5"], ["--quick", "--np"],
                     ["--bogus"]):
            done = subprocess.run(["bash", os.path.join(EXAMPLE, "run_triaxial.sh"), *args],
                                  capture_output=True, text=True, timeout=20)
            self.assertEqual(done.returncode, 2, args)
            self.assertIn("usage:" if args == ["--bogus"] else "--np needs an integer >= 1",
                          done.stderr)
            self.assertNotIn("mpirun", done.stdout + done.stderr)


if __name__ == "__main__":
    unittest.main()

"""Pure functions of bench/scaling3d.py (liggghts_membrane.bench.scaling3d) and the
model it shares with bench/scaling.py, on hand-made input with hand-worked values."""
import argparse
import math
import os
import tempfile
import unittest

import numpy as np

from liggghts_membrane import readers
from liggghts_membrane.bench import scaling, scaling3d

# a process of in.membrane3d_cuboid_cost with the membrane and 2 timed runs: the hold,
# the run 0 of the timed fix's first detection, the timed runs
SCREEN = """\
Loop time of 0.5 on 1 procs for 100 steps with 3981 atoms
membrane3d_traffic id=mem kb_per_step=1 kb_per_detection=190 steps=100 detections=2 fix_seconds=0.1 detection_seconds=0.05
Nghost: 10 ave 10 max 10 min
Loop time of 0.02 on 1 procs for 0 steps with 3981 atoms
membrane3d_traffic id=mem kb_per_step=0 kb_per_detection=191 steps=0 detections=1 fix_seconds=0.03 detection_seconds=0.03
BENCH_CPU start1 100 20 100
Loop time of 2.0 on 1 procs for 200 steps with 3981 atoms
membrane3d_traffic id=mem kb_per_step=2.5 kb_per_detection=192 steps=200 detections=4 fix_seconds=0.5 detection_seconds=0.2
BENCH_CPU end1 250 30 100
BENCH_CPU start2 250 30 100
Loop time of 1.6 on 1 procs for 200 steps with 3981 atoms
Nghost: 12.5 ave 13 max 12 min
membrane3d_traffic id=mem kb_per_step=2.4 kb_per_detection=192 steps=200 detections=4 fix_seconds=0.4 detection_seconds=0.16
BENCH_CPU end2 300 40 100
BENCH contacts per sphere 6.25
BENCH membrane spheres 1131
"""


class Parsing(unittest.TestCase):
    def test_tiles(self):
        self.assertEqual(scaling3d.tiles_list("1x1x1, 2X2x1"), [(1, 1, 1), (2, 2, 1)])
        self.assertEqual(scaling3d.tag((8, 8, 2)), "8x8x2")
        with self.assertRaises(argparse.ArgumentTypeError):
            scaling3d.tiles_list("2x2")
        with self.assertRaises(argparse.ArgumentTypeError):
            scaling3d.tiles_list("0x1x1")

    def test_quick_keeps_the_two_smallest(self):
        args = scaling3d.parse_args(["--quick", "--tiles", "4x4x2,1x1x1,2x2x1"])
        self.assertEqual(args.tiles, [(1, 1, 1), (2, 2, 1)])
        self.assertEqual(scaling3d.steps_for((2, 2, 2), 1000, 100), 125)
        self.assertEqual(scaling3d.steps_for((8, 8, 2), 1000, 100), 100)

    def test_cpu_seconds_of_each_timed_run(self):
        # (250 + 30 - 100 - 20) / 100 and (300 + 40 - 250 - 30) / 100
        self.assertEqual(scaling3d.cpu_seconds(SCREEN), [1.6, 0.6])

    def test_run_figures_take_the_fastest_timed_run(self):
        r = scaling3d.run_figures(SCREEN, 2, True)
        self.assertEqual(r["steps"], 200)
        self.assertAlmostEqual(r["wall_ms"], 8.0)              # 1.6 s / 200 steps
        self.assertAlmostEqual(r["cpu_ms"], 3.0)               # 0.6 s / 200 steps
        self.assertAlmostEqual(r["detections_per_1000"], 20.0)  # 8 in 400 steps
        self.assertAlmostEqual(r["detection_ms"], 40.0)        # 0.16 s / 4, the smaller
        self.assertAlmostEqual(r["first_detection_ms"], 30.0)  # run 0
        self.assertAlmostEqual(r["fix_ms_per_step"], 2.0)      # 0.4 s / 200
        self.assertEqual(r["kb_per_step"], 2.4)                # of the fastest run
        self.assertEqual(r["kb_per_detection"], 192)
        self.assertEqual(r["ghosts_per_rank"], 12.5)
        self.assertEqual(r["contacts_per_sphere"], 6.25)
        self.assertEqual(r["membrane_spheres"], 1131)

    def test_run_figures_of_the_walls_and_of_a_short_output(self):
        r = scaling3d.run_figures(SCREEN, 1, False)
        self.assertAlmostEqual(r["wall_ms"], 8.0)
        self.assertNotIn("kb_per_step", r)
        with self.assertRaises(ValueError):
            scaling3d.run_figures(SCREEN, 5, False)


class Tiling(unittest.TestCase):
    def test_tiles_about_the_axis_and_layers_a_platen_apart(self):
        atoms = {k: np.array(v, dtype=float) for k, v in dict(
            id=[1, 2], type=[1, 1], diameter=[0.002, 0.003], density=[2650, 2650],
            x=[0.001, -0.002], y=[0.0, 0.004], z=[0.005, 0.02]).items()}
        walls = dict(top0=0.03, xlo0=-0.01, xhi0=0.01, ylo0=-0.01, yhi0=0.01)
        with tempfile.TemporaryDirectory() as d:
            data, wfile = os.path.join(d, "t.data"), os.path.join(d, "t.walls")
            self.assertEqual(scaling3d.tile_data(atoms, walls, (2, 1, 2), 0.072, data, wfile), 8)
            t = readers.read_data_atoms(data)
            w = scaling3d.read_walls(wfile)
        self.assertEqual(list(t["id"]), list(range(1, 9)))
        # tile (0, 0, 0): x - 0.01; (0, 0, 1): z + 0.03; (1, 0, 0): x + 0.01
        self.assertAlmostEqual(t["x"][0], -0.009)
        self.assertAlmostEqual(t["z"][2], 0.035)
        self.assertAlmostEqual(t["x"][5], 0.008)
        self.assertAlmostEqual(t["y"][5], 0.004)
        self.assertAlmostEqual(t["diameter"][7], 0.003)
        self.assertEqual(w, dict(top0=0.06, xlo0=-0.02, xhi0=0.02, ylo0=-0.01, yhi0=0.01))

    def test_fastest_of_the_rounds(self):
        rounds = [dict(wall_ms=9.0, cpu_ms=4.0, detection_ms=30.0, kb_per_step=1.0, peak_mb_per_rank=50.0, run_s=10.0),
                  dict(wall_ms=8.0, cpu_ms=5.0, detection_ms=float("nan"), kb_per_step=2.0, peak_mb_per_rank=40.0,
                       run_s=20.0)]
        self.assertEqual(scaling3d.fastest(rounds), dict(wall_ms=8.0, cpu_ms=4.0, detection_ms=30.0, kb_per_step=2.0,
                                                         peak_mb_per_rank=50.0, run_s=15.0))


def rows_one_size():
    """The rows of one size (4000 spheres) on 1 and 2 ranks, every case alike."""
    rows = []
    for np_ in (1, 2):
        for case, _, _ in scaling3d.CASES:
            rows.append(dict(spheres=4000, ranks=np_, case=case, cpu_ms=10.0, wall_ms=11.0,
                             ghosts_per_rank=500.0, lx_m=0.04, ly_m=0.04, h_m=0.05,
                             fix_ms_per_step=2.0 if np_ == 1 else 1.5, kb_per_step=2.0,
                             kb_per_detection=100.0, detections_per_1000=20.0))
    return rows


class Model(unittest.TestCase):
    def test_power_law_and_the_split_of_the_membrane_time(self):
        self.assertEqual(scaling3d.power_law([(1000, 2.0), (8000, 16.0)], 64000), (128.0, 1.0))
        y, k = scaling3d.power_law([(1000, 1.0), (4000, 2.0)], 16000)
        self.assertAlmostEqual(y, 4.0)
        self.assertAlmostEqual(k, 0.5)
        self.assertEqual(scaling3d.power_law([(4000, 3.0)], 8000), (6.0, 1.0))
        self.assertEqual(scaling3d.amdahl(10.0, 6.0), (2.0, 8.0))   # 2 + 8 / 2 = 6
        self.assertEqual(scaling3d.amdahl(10.0, 12.0), (10.0, 0.0))
        self.assertEqual(scaling3d.amdahl(10.0, 4.0), (0.0, 10.0))

    def test_efficiency_hand_worked(self):
        # 16 ranks, 2 us / 10 GB/s: compute 1.6 / 16 = 0.1 s; halo 6 x 2 us + 72 x 1000 B /
        # 1e10 = 1.92e-5 s; LIGGGHTS' 6 allreduces 6 x 2 x 4 x 2 us = 9.6e-5 s; membrane
        # 0.01 + 3 x 4 x 2 us + 1e6 B / 1e10 = 0.010124 s
        t_calc, t_halo, t_coll, t_mem, e_walls, e_mem = scaling.efficiency(
            16, (2e-6, 10e9), 1.6, 1000.0, 6, 0.01, 1e6, 3)
        self.assertAlmostEqual(t_calc, 0.1)
        self.assertAlmostEqual(t_halo, 1.92e-5)
        self.assertAlmostEqual(t_coll, 9.6e-5)
        self.assertAlmostEqual(t_mem, 0.010124)
        self.assertAlmostEqual(e_walls, 0.1 / 0.1001152)
        self.assertAlmostEqual(e_mem, 0.1 / 0.1102392)

    def test_model_inputs_extrapolate_one_size_in_proportion(self):
        m = scaling3d.model_inputs(rows_one_size(), 1e6)
        self.assertAlmostEqual(m["work_s"], 2.5)              # 10 ms / 4000 x 1e6
        self.assertAlmostEqual(m["ghosts_per_m2"], 250000.0)  # 500 / (0.04 x 0.05)
        self.assertAlmostEqual(m["volume_per_sphere"], 2e-8)
        c = m["cases"]["every50"]
        # 2 and 1.5 ms x 250 -> 0.5 and 0.375 s: s = 0.25, q = 0.25
        self.assertAlmostEqual(c["s"], 0.25)
        self.assertAlmostEqual(c["q"], 0.25)
        # 2 kB x 250 per step + 20 / 1000 x 100 kB x 250 per detection
        self.assertAlmostEqual(c["bytes"], 1e6)
        lines, text = scaling3d.model(rows_one_size(), 1e6)
        self.assertEqual(len(lines), 2 + 3 * len(scaling.NETWORKS))
        self.assertIn("proportional to N", text)

    def test_the_split_grows_as_the_time_on_one_rank(self):
        rows = rows_one_size()
        for r in rows_one_size():
            rows.append(dict(r, spheres=16000, fix_ms_per_step=2 * r["fix_ms_per_step"]))
        c = scaling3d.model_inputs(rows, 1e6)["cases"]["placed"]
        # 2 -> 4 ms from 4000 to 16000 spheres: N^0.5, 4 ms x 62.5^0.5 = 31.62 ms at 1e6;
        # at 16000, 4 ms on 1 rank and 3 on 2: s = 2 x 3 - 4 = 2 ms, q = 2 ms
        self.assertAlmostEqual(c["k"], 0.5)
        self.assertAlmostEqual(c["s"], 2e-3 * math.sqrt(62.5))
        self.assertAlmostEqual(c["q"], 2e-3 * math.sqrt(62.5))

    def test_model_needs_both_rank_counts(self):
        self.assertIsNone(scaling3d.model_inputs([r for r in rows_one_size() if r["ranks"] == 1], 1e6))


if __name__ == "__main__":
    unittest.main()

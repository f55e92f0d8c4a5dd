"""Pure functions of the benchmark drivers (liggghts_membrane.bench.common, bench/accuracy_sweep.py,
bench/accuracy_report.py) on hand-made input."""
import os
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))

from liggghts_membrane.bench import accuracy_report
from liggghts_membrane.bench import accuracy_sweep
from liggghts_membrane.bench import common

LOG = """\
Loop time of 0.5 on 2 procs for 100 steps with 526 atoms

Pair  time (%) = 0.3 (60)
Neigh time (%) = 0.05 (10)
Comm  time (%) = 0.05 (10)
Outpt time (%) = 0 (0)
Other time (%) = 0.1 (20)

Loop time of 4.0 on 2 procs for 1000 steps with 526 atoms

Pair  time (%) = 1.6 (40)
Neigh time (%) = 0.2 (5)
Comm  time (%) = 0.2 (5)
Outpt time (%) = 0 (0)
Other time (%) = 2.0 (50)

Loop time of 0.01 on 2 procs for 1 steps with 526 atoms

Pair  time (%) = 0.01 (100)
"""


class LogParsing(unittest.TestCase):
    def setUp(self):
        fd, self.path = tempfile.mkstemp(suffix=".log")
        with os.fdopen(fd, "w") as f:
            f.write(textwrap.dedent(LOG))

    def tearDown(self):
        os.remove(self.path)

    def test_loop_times_sum_every_run(self):
        t, n = common.loop_times(self.path)
        self.assertAlmostEqual(t, 4.51)
        self.assertEqual(n, 1101)

    def test_time_split_is_that_of_the_longest_run(self):
        split = common.time_split(self.path)
        self.assertEqual(split, {"Pair": 40.0, "Neigh": 5.0, "Comm": 5.0, "Outpt": 0.0, "Other": 50.0})

    def test_missing_log(self):
        self.assertEqual(common.time_split(self.path + ".none"), {})


class Settings(unittest.TestCase):
    def test_everys_parse_auto_and_intervals(self):
        self.assertEqual(accuracy_sweep.everys("auto, 1,10"), ["auto", 1, 10])
        self.assertEqual(sorted(["auto", 50, 1, 5], key=accuracy_report.every_key), ["auto", 1, 5, 50])

    def test_pareto_front(self):
        # (time, error): (1, 5) and (2, 3) and (4, 1) are on the front; (3, 4) is dominated by (2, 3)
        pts = [(3, 4), (1, 5), (4, 1), (2, 3)]
        self.assertEqual(sorted(accuracy_report.pareto(pts)), [1, 2, 3])

    def test_cached_meta(self):
        with tempfile.TemporaryDirectory() as d:
            f = os.path.join(d, "meta.json")
            self.assertIsNone(common.cached_meta(f, {"a": 1}, "ok", False))
            with open(f, "w") as out:
                out.write('{"params": {"a": 1}, "status": "failed"}')
            self.assertIsNotNone(common.cached_meta(f, {"a": 1}, "ok", False))   # failed runs are kept
            self.assertIsNone(common.cached_meta(f, {"a": 1}, "ok", True))       # unless retried
            self.assertIsNone(common.cached_meta(f, {"a": 2}, "ok", False))      # other parameters


if __name__ == "__main__":
    unittest.main()

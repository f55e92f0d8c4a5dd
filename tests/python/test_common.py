"""liggghts_membrane.bench.common (the module every benchmark uses) and the row functions of
bench/accuracy_report.py, on hand-made input."""
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))

from liggghts_membrane.bench import accuracy_report as rep
from liggghts_membrane.bench import common

SCREEN = """\
LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0)
WARNING: Mesh for fix mesh/surface/stress has been scaled
WARNING: Fix membrane2d: chain disk 12 moved 0.2 of its radius in one step at step 40
WARNING: Fix membrane2d: chain disk 12 moved 0.2 of its radius in one step at step 40
ERROR: Fix stability/guard (id guard): atom 3 moved 0.07 of its radius in one step at step 41
ERROR: a second error
"""


class Helpers(unittest.TestCase):
    def test_sci_writes_numbers_as_the_scripts_do(self):
        self.assertEqual(common.sci(8.45e7), "8.45e7")
        self.assertEqual(common.sci(1e-4), "1e-4")
        self.assertEqual(common.sci(1e5), "1e5")
        self.assertEqual(common.sci(2.5), "2.5e0")

    def test_fmt(self):
        self.assertEqual(common.fmt(""), "")
        self.assertEqual(common.fmt(float("nan")), "—")
        self.assertEqual(common.fmt(0.123456), "0.123")
        self.assertEqual(common.fmt(0.0123, "{:.2f}", 100), "1.23")
        self.assertEqual(common.fmt("text"), "text")

    def test_done_counts(self):
        # the last membrane_counts line of a screen (in.shear_membrane prints one per run)
        text = ("SHEAR done: escaped 9 chain failures 9\n"
                "membrane_counts escaped=1 chain_failures=3\n"
                "membrane_counts escaped=2 chain_failures=0 detections=1000 chain_changes=37\n"
                "membrane_countsx escaped=5\n")
        self.assertEqual(common.done_counts(text), dict(escaped=2.0, chain_failures=0.0,
                                                        detections=1000.0, chain_changes=37.0))
        self.assertEqual(common.done_counts("SHEAR done: escaped 2 chain failures 0"), {})

    def test_messages_and_symptom(self):
        with tempfile.TemporaryDirectory() as d:
            screen = os.path.join(d, "screen.txt")
            with open(screen, "w") as f:
                f.write(SCREEN)
            err, warns = common.messages(screen, benign=("has been scaled",))
            self.assertTrue(err.startswith("ERROR: Fix stability/guard (id guard): atom 3"))
            self.assertEqual(len(warns), 1)           # deduplicated, the benign one left out
            self.assertIn("chain disk 12", warns[0])
            self.assertEqual(common.symptom(screen), err)
            self.assertEqual(common.symptom(screen + ".none"), "no output")

    def test_rows_round_trip(self):
        rows = [dict(case="rigid", seed=12345, x=0.1234567891, every="", steps=400001, note="a, b"),
                dict(case="membrane", seed=54321, x=float("nan"), every="auto", steps="", note="")]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "t.csv")
            common.write_rows(path, rows, ["case", "seed", "x", "every", "steps", "note"])
            with open(path) as f:
                self.assertEqual(f.readline().strip(), "case,seed,x,every,steps,note")
                self.assertEqual(f.readline().strip(), 'rigid,12345,0.123457,,400001,"a, b"')
            back = common.read_rows(path, int_keys=("seed", "steps"), text_keys=("every",))
        self.assertEqual(back[0]["seed"], 12345)
        self.assertEqual(back[0]["steps"], 400001)
        self.assertEqual(back[0]["x"], 0.123457)                 # 6 significant digits
        self.assertEqual(back[0]["every"], "")
        self.assertTrue(math.isnan(back[1]["x"]))
        self.assertEqual(back[1]["every"], "auto")
        self.assertEqual(back[1]["steps"], "")

    def test_freeze_script_and_cache(self):
        with tempfile.TemporaryDirectory() as d:
            src = os.path.join(d, "in.test")
            with open(src, "w") as f:
                f.write("include a.inc\n")
            with open(os.path.join(d, "a.inc"), "w") as f:
                f.write("variable kn index 1\n")
            copy, h = common.freeze_script(src, os.path.join(d, "inputs"))
            self.assertEqual(copy, os.path.join(d, "inputs", "in.test." + h, "in.test"))
            self.assertEqual(h, common.sha_text("in.test\0include a.inc\na.inc\0variable kn index 1\n"))
            self.assertTrue(os.path.exists(os.path.join(os.path.dirname(copy), "a.inc")))
            with open(os.path.join(d, "a.inc"), "w") as f:          # an include changed: another copy
                f.write("variable kn index 2\n")
            self.assertNotEqual(common.freeze_script(src, os.path.join(d, "inputs"))[1], h)
            run = os.path.join(d, "run")
            os.makedirs(run)
            self.assertIsNone(common.known_meta(run, {"a": 1}, "ok", False, False))
            placeholder = common.known_meta(run, {"a": 1}, "ok", False, True, steps=0)
            self.assertEqual((placeholder["status"], placeholder["steps"]), ("not run", 0))
            common.write_context(os.path.join(run, "meta.json"), {"params": {"a": 1}, "status": "ok"})
            self.assertEqual(common.known_meta(run, {"a": 1}, "ok", True, False)["status"], "ok")

    def test_markdown_table(self):
        t = common.markdown_table([{"a": 1, "b": "x|y"}], [("A", lambda r: r["a"]), ("B", lambda r: r["b"])])
        self.assertEqual(t, "| A | B |\n|---|---|\n| 1 | x/y |")


class AccuracyRows(unittest.TestCase):
    @staticmethod
    def row(sweep, case, rms_ratio, rms_ev=0.001, d_peak=0.01, is_reference=0, status="ok"):
        r = dict(sweep=sweep, case=case, is_reference=is_reference, status=status,
                 rms_ratio=rms_ratio, rms_ev=rms_ev, d_peak=d_peak)
        r.update({k: r.get(k, 0.0) for k in rep.ERR_KEYS + ["mean_ratio"]})
        return r

    def test_scatter_and_within(self):
        rows = [self.row("rate", "rigid", 0.0, is_reference=1),
                self.row("rate", "rigid", 0.2),
                self.row("rate", "rigid", 0.5),
                self.row("seed", "rigid", 0.3, d_peak=-0.1),
                self.row("seed@rate", "rigid", 0.4, d_peak=0.1)]
        rows = rep.judge(rows)
        scatter = [r for r in rows if r["sweep"] == "scatter"]
        self.assertEqual(len(scatter), 1)                       # no membrane seed rows
        self.assertAlmostEqual(scatter[0]["rms_ratio"], math.sqrt((0.09 + 0.16) / 2))   # 0.35355
        self.assertAlmostEqual(scatter[0]["d_peak"], 0.1)       # RMS of -0.1 and 0.1
        self.assertEqual(rep.scatter_of(rows)["rigid"]["n"], 2)
        self.assertEqual([r["within_scatter"] for r in rows[:5]], ["", "yes", "no: rms_ratio", "", ""])

    def test_run_names(self):
        dflt = ("viscous", 500.0)
        self.assertEqual(rep.run_name("rigid", 1, 0.01, 1e-4, 0, dflt, dflt, 1),
                         "rigid_seed1_rate0.01_dt0.0001")
        self.assertEqual(rep.run_name("membrane", 1, 0.01, 1e-4, "auto", ("local", 0.7), dflt, 2),
                         "membrane_seed1_rate0.01_dt0.0001_everyauto_local0.7_np2")
        self.assertEqual(rep.damping_spec(rep.damping("visc:500")), "viscous:500")
        self.assertEqual(rep.damping_text(("local", 0.3)), "damping local α 0.3")


if __name__ == "__main__":
    unittest.main()

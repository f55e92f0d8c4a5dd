#!/usr/bin/env python3
"""run_script.py's restart mode without LIGGGHTS: the split-run copy of a script (also
reading the files of a run on other ranks, --write-np), the comparison of the two
outputs and its tolerance (CTest: script.run_script.selftest)."""
import unittest

from liggghts_membrane import run_script

SCRIPT = """#@ restart
create_box 1 box
#@ begin-definitions
pair_style gran
fix g all stability/guard
#@ end-definitions
run 10
#@ split
run 10
print "RESULT x $(x[1])"
clear
create_box 1 box
#@ begin-definitions
fix d all damping/local alpha 0.7
#@ end-definitions
run 5
#@ split
run 5
"""


def split(text, dirs=()):
    return run_script.split_script(text, list(dirs)).splitlines()


class SplitScript(unittest.TestCase):
    def test_split_replaced_and_definitions_repeated(self):
        lines = split(SCRIPT)
        i = lines.index("write_restart   split1.restart")
        self.assertEqual(lines[i + 1:i + 6], [
            "clear", "atom_modify map array", "communicate single vel yes",
            "read_restart    split1.restart", "pair_style gran"])
        self.assertEqual(lines[i + 6], "fix g all stability/guard")
        self.assertEqual(lines[i + 8], "run 10")
        # the straight part is kept as it is, the definitions run once before the split too
        self.assertEqual(lines[:i].count("pair_style gran"), 1)

    def test_clear_starts_a_new_case(self):
        lines = split(SCRIPT)
        i = lines.index("read_restart    split2.restart")
        self.assertEqual(lines[i + 1], "fix d all damping/local alpha 0.7")
        self.assertNotIn("pair_style gran", lines[i:])

    def test_restart_pre_replaces_the_default(self):
        lines = split(SCRIPT, ["restart-pre atom_modify map hash"])
        i = lines.index("write_restart   split1.restart")
        self.assertEqual(lines[i + 2:i + 4], ["atom_modify map hash", "read_restart    split1.restart"])

    def test_malformed(self):
        for text in ("run 1\n",                                              # no split
                     "#@ split\n",                                           # no definitions
                     "#@ begin-definitions\nfix a\n#@ split\n#@ end-definitions\n",
                     "#@ begin-definitions\nfix a\n#@ split\n",
                     "#@ end-definitions\n#@ split\n"):
            with self.assertRaises(ValueError, msg=text):
                run_script.split_script(text, [])


class RestartOnOtherRanks(unittest.TestCase):
    """--write-np: the split run reads the restart files a run on other ranks wrote."""

    def test_read_from_the_writer(self):
        lines = split(SCRIPT)
        other = run_script.split_script(SCRIPT, [], "/w/write").splitlines()
        # the same copy but for the files read: its own still written, the writer's read
        self.assertEqual(len(other), len(lines))
        self.assertIn("write_restart   split1.restart", other)
        self.assertIn("read_restart    /w/write/split1.restart", other)
        self.assertIn("read_restart    /w/write/split2.restart", other)
        self.assertNotIn("read_restart    split1.restart", other)
        self.assertEqual([a for a, b in zip(lines, other) if a != b],
                         ["read_restart    split1.restart", "read_restart    split2.restart"])

    def test_tolerance(self):
        dirs = ["restart", "restart-tolerance 1e-15 0", "tolerance 1e-9 1e-12"]
        self.assertEqual(run_script.restart_tolerance(dirs), (1e-15, 0.0))
        self.assertEqual(run_script.restart_tolerance(dirs, cross_ranks=True), (1e-9, 1e-12))
        self.assertEqual(run_script.restart_tolerance(["restart"]), (0.0, 0.0))
        self.assertEqual(run_script.restart_tolerance(["restart"], cross_ranks=True), (1e-12, 0.0))

    def test_needs_restart_mode(self):
        import io
        import sys
        from unittest import mock
        for argv in (["--write-np", "2", "x.in"], ["--restart", "--write-np", "0", "x.in"]):
            with mock.patch.object(sys, "argv", ["run_script.py", "--exe", "e"] + argv), \
                 mock.patch("sys.stderr", io.StringIO()), self.assertRaises(SystemExit):
                run_script.main()


class Compare(unittest.TestCase):
    def test_identical(self):
        out = "RESULT a 1.5\nRESULT b 2\nRESULT b 3\n"
        self.assertEqual(run_script.compare_restart(out, out + "RESULT extra 1\n", 0, 0), (3, []))

    def test_different_value_fails(self):
        n, bad = run_script.compare_restart("RESULT a 1.5\n", "RESULT a 1.5000000000000002\n", 0, 0)
        self.assertEqual(n, 1)
        self.assertEqual(len(bad), 1)
        self.assertEqual(run_script.compare_restart("RESULT a 1.5\n", "RESULT a 1.5000000000000002\n",
                                                    1e-15, 0)[1], [])

    def test_missing_or_repeated_fails(self):
        self.assertEqual(len(run_script.compare_restart("RESULT a 1\n", "", 0, 0)[1]), 1)
        self.assertEqual(len(run_script.compare_restart("RESULT a 1\n", "RESULT a 1\nRESULT a 1\n", 0, 0)[1]), 1)

    def test_nan_fails(self):
        self.assertEqual(len(run_script.compare_restart("RESULT a nan\n", "RESULT a nan\n", 0, 0)[1]), 1)


if __name__ == "__main__":
    unittest.main()

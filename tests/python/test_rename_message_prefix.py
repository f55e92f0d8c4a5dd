"""tools/rename_message_prefix.py on hand-made tests: the ID of each expected message
comes from the case's or script's own line of the style, other styles stay as they are."""
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(os.path.dirname(os.path.dirname(HERE)), "tools", "rename_message_prefix.py")

CASES = textwrap.dedent("""\
    # head: Fix stability/guard: stays (no case, no ID)

    case one
      setup  block
      error  Fix stability/guard: keyword 'every' needs a value
      output Fix membrane2d: keyword 'band' = 1: stays
      | fix g1 all stability/guard every

    case two
      setup  guarded
      error  Fix stability/guard:
      | run 10

    case three
      error  Fix stability/guard: several
      | fix first all stability/guard
      | fix second all stability/guard every 5
    """)

SETUP = "fix fromsetup all stability/guard every 10\n"

SCRIPT = textwrap.dedent("""\
    #@ output Fix stability/guard: atoms 1 and 2 overlap
    #@ error Fix stability/guard: keyword 'move' = 2: ::: fix bad all stability/guard move 2
    #@ error Fix stability/guard: the restart ::: run 0
    # a comment: Fix stability/guard: also renamed
    fix guard all stability/guard every 10
    fix guarded all stability/guardian
    """)


class RenameMessagePrefix(unittest.TestCase):
    def run_tool(self, files, *options):
        return subprocess.run([sys.executable, TOOL, "--style", "Fix stability/guard"] +
                              list(options) + files, capture_output=True, text=True)

    def test_cases_and_scripts(self):
        with tempfile.TemporaryDirectory() as d:
            os.makedirs(os.path.join(d, "cases"))
            os.makedirs(os.path.join(d, "setups"))
            cases = os.path.join(d, "cases", "A.cases")
            script = os.path.join(d, "s.in")
            for path, text in ((cases, CASES), (script, SCRIPT),
                               (os.path.join(d, "setups", "guarded.inc"), SETUP)):
                with open(path, "w") as f:
                    f.write(text)
            result = self.run_tool([cases, script])
            self.assertEqual(result.returncode, 1)  # a line left, one ambiguous
            self.assertIn("1 ambiguous, 1 left", result.stdout)
            with open(cases) as f:
                out = f.read().splitlines()
            self.assertEqual(out[0], "# head: Fix stability/guard: stays (no case, no ID)")
            self.assertIn("  error  Fix stability/guard (id g1): keyword 'every' needs a value", out)
            self.assertIn("  output Fix membrane2d: keyword 'band' = 1: stays", out)
            self.assertIn("  | fix g1 all stability/guard every", out)  # input untouched
            self.assertIn("  error  Fix stability/guard (id fromsetup):", out)  # end of line
            self.assertIn("  error  Fix stability/guard (id first): several", out)
            with open(script) as f:
                out = f.read().splitlines()
            self.assertEqual(out[0], "#@ output Fix stability/guard (id guard): atoms 1 and 2 overlap")
            self.assertEqual(out[1], "#@ error Fix stability/guard (id bad): keyword 'move' = 2: "
                                     "::: fix bad all stability/guard move 2")
            self.assertEqual(out[2], "#@ error Fix stability/guard (id guard): the restart ::: run 0")
            self.assertEqual(out[3], "# a comment: Fix stability/guard (id guard): also renamed")
            # a second run finds nothing left to do
            again = self.run_tool([cases, script])
            self.assertIn(": 0 line(s)", again.stdout)

    def test_dry_run_and_fallback_id(self):
        with tempfile.TemporaryDirectory() as d:
            fixture = os.path.join(d, "t.py")
            with open(fixture, "w") as f:
                f.write('SCREEN = "ERROR: Fix stability/guard: atom 3 moved"\n')
            self.assertEqual(self.run_tool([fixture, "--dry-run"]).returncode, 1)  # no ID
            result = self.run_tool([fixture], "--id", "guard", "--dry-run")
            self.assertEqual(result.returncode, 0)
            with open(fixture) as f:
                self.assertIn("Fix stability/guard: atom", f.read())  # dry run: unchanged
            self.run_tool([fixture], "--id", "guard")
            with open(fixture) as f:
                self.assertIn("Fix stability/guard (id guard): atom 3", f.read())

    def test_style_must_name_fix_or_compute(self):
        result = subprocess.run([sys.executable, TOOL, "--style", "stability/guard"],
                                capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("Fix NAME", result.stderr)


if __name__ == "__main__":
    unittest.main()

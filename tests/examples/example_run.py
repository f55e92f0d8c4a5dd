"""Running the biaxial example scripts from the tests: the folder and one run."""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(ROOT, "examples", "biaxial")
from liggghts_membrane.run_script import mpi_env


def run(cmd, log, cwd=EXAMPLE):
    """Run `cmd` in `cwd` (examples/biaxial) with its output in `log`; the test fails with
    the end of the log when it exits non-zero. Returns the output."""
    with open(log, "w") as f, mpi_env() as env:
        p = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, timeout=900,
                           env=env)
    if p.returncode != 0:
        with open(log, errors="replace") as f:  # see error_visible.py
            sys.exit("FAIL: %s exited %d\n%s" % (" ".join(cmd[:8]), p.returncode, f.read()[-3000:]))
    with open(log) as f:
        return f.read()


def table(path):
    """{column: values} of an OUT table (its last '#' line names the columns); a row
    that is not all numbers fails the test."""
    with open(path) as f:
        lines = f.read().splitlines()
    cols = [l for l in lines if l.startswith("#")][-1].lstrip("#").split()
    rows = [list(map(float, l.split())) for l in lines if l and not l.startswith("#")]
    return {c: [r[k] for r in rows] for k, c in enumerate(cols)}


class Checks:
    """check(ok, what) prints ok/FAIL per check and keeps the failures."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print("%s %s" % ("ok  " if ok else "FAIL", what))
        if not ok:
            self.failures.append(what)

"""Running the biaxial example scripts from the tests: the folder and one run."""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(ROOT, "examples", "biaxial")


def run(cmd, log):
    """Run `cmd` in examples/biaxial with its output in `log`; the test fails with the
    end of the log when it exits non-zero. Returns the output."""
    with open(log, "w") as f:
        p = subprocess.run(cmd, cwd=EXAMPLE, stdout=f, stderr=subprocess.STDOUT, timeout=900)
    if p.returncode != 0:
        with open(log) as f:
            sys.exit("FAIL: %s exited %d\n%s" % (" ".join(cmd[:8]), p.returncode, f.read()[-3000:]))
    with open(log) as f:
        return f.read()

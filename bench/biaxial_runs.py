"""Preparing and shearing biaxial samples for the benchmarks: the example scripts of
examples/biaxial run through build/app/liggghts-membrane, each run kept in a folder
and reused when it finished (its screen output has the script's final line)."""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
EXAMPLES = os.path.join(ROOT, "examples", "biaxial")
EXE = os.path.join(ROOT, "build", "app", "liggghts-membrane")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from biaxial.readers import read_output  # noqa: E402


def _run(args, screen, done_marker, np_):
    """Run the executable with `args` in examples/biaxial unless `screen` already holds
    `done_marker`; return the screen text."""
    if os.path.exists(screen) and done_marker in open(screen).read():
        return open(screen).read()
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np_), EXE] + args + ["-log", "none"]
    with open(screen + ".tmp", "w") as f:
        p = subprocess.run(cmd, cwd=EXAMPLES, stdout=f, stderr=subprocess.STDOUT)
    text = open(screen + ".tmp").read()
    if p.returncode != 0 or done_marker not in text:
        raise RuntimeError("%s failed: see %s" % (" ".join(args[:2]), os.path.relpath(screen + ".tmp", ROOT)))
    os.replace(screen + ".tmp", screen)
    return text


def _vars(settings):
    out = []
    for key, value in settings.items():
        out += ["-var", key, str(value)]
    return out


def prepare(scale, seed, folder, settings=None, np_=1):
    """Generate and prepare one sample in `folder`; returns its restart file."""
    os.makedirs(folder, exist_ok=True)
    data = os.path.join(folder, "sample.data")
    restart = os.path.join(folder, "prepared.restart")
    if not os.path.exists(data):
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "generate_sample.py"), "--scale", str(scale),
                        "--seed", str(seed), "--out", data], check=True, capture_output=True)
    _run(["-in", "in.prepare", "-var", "data", data, "-var", "out", restart] + _vars(settings or {}),
         os.path.join(folder, "screen.prepare"), "PREPARED porosity", np_)
    return restart


class Shear:
    """One finished shear: its OUT table, its screen text and the numbers the scripts print."""

    def __init__(self, out, text):
        self.table = read_output(out)
        self.text = text
        self.nramp = int(re.search(r"after a ramp of (\d+) steps", text).group(1))
        self.atoms = int(re.search(r"for \d+ steps with (\d+) atoms", text).group(1))

    def after_ramp(self):
        """Mask of the OUT rows after the platen speed ramp."""
        step = self.table["step"]
        return step >= step[0] + self.nramp


def shear(case, restart, out, settings=None, np_=1):
    """Shear `restart` with in.shear_<case> (rigid or membrane), OUT table `out`."""
    args = ["-in", "in.shear_" + case, "-var", "restart", restart, "-var", "out", out] + _vars(settings or {})
    text = _run(args, out + ".screen", "SHEAR done", np_)
    return Shear(out, text)

"""The repository stands alone: no file of it names a path outside it.

A clone has only what is committed: a file that cites a working note of the team
(the spec and notes folders beside the checkout), a relative path climbing above the
repository root, or an absolute path into a machine's own folders (work, home, ...)
points a user at something they do not have. Checked over every file git tracks
(every file below the root, build and output folders aside, where git is missing).
"""
import os
import re
import subprocess
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# a path of the team's working notes, wherever it is written from
NOTES = re.compile(r"shared/(spec|notes)\b")
# an absolute path in a folder that exists on one machine only (system paths such
# as /usr/bin/python3 or /dev/null are the same on every Debian machine)
MACHINE = re.compile(r"(?<![\w.~-])/(work|home|root|check|mnt|scratch|Users|media|srv)/[\w.-]")
# a relative path that climbs: ../a, ../../a/b, ...
CLIMB = re.compile(r"(?<![\w.])((?:\.\./)+)([\w-][\w.-]*)")
BINARY = (".png", ".jpg", ".pdf", ".stl", ".gz", ".restart")
SKIP_DIRS = {".git", "build", "out", "__pycache__"}


def tracked_files():
    try:
        out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True)
        names = [n for n in out.stdout.decode().split("\0") if n]
    except (OSError, subprocess.CalledProcessError):
        names = []
        for folder, dirs, files in os.walk(ROOT):
            dirs[:] = [d for d in dirs if d not in SKIP_DIRS]
            names += [os.path.relpath(os.path.join(folder, f), ROOT) for f in files]
    return [n for n in names if not n.endswith(BINARY)]


def outside_paths(relname, text):
    """(line number, what) of each path of `text` that leaves the repository."""
    found = []
    here = os.path.dirname(os.path.join(ROOT, relname))
    for lineno, line in enumerate(text.splitlines(), 1):
        for m in NOTES.finditer(line):
            found.append((lineno, m.group(0)))
        for m in MACHINE.finditer(line):
            found.append((lineno, line[m.start():m.start() + 40].split()[0]))
        for m in CLIMB.finditer(line):
            target = os.path.normpath(os.path.join(here, m.group(1), m.group(2)))
            if os.path.relpath(target, ROOT).startswith(".."):
                found.append((lineno, m.group(0)))
    return found


class RepositoryStandsAlone(unittest.TestCase):
    def test_no_file_names_a_path_outside_the_repository(self):
        problems = []
        for name in tracked_files():
            try:
                with open(os.path.join(ROOT, name), encoding="utf-8") as f:
                    text = f.read()
            except (UnicodeDecodeError, FileNotFoundError, IsADirectoryError):
                continue
            problems += ["%s:%d: %s" % (name, n, what) for n, what in outside_paths(name, text)]
        self.assertEqual(problems, [], "paths outside the repository:\n" + "\n".join(problems))

    def test_the_check_finds_each_kind(self):
        # the patterns above catch what they are for, and leave system paths alone
        # (put together here, so that this file names none of them itself)
        text = ("see " + "shared/" + "spec/fabric.md\n"
                "data in " + "/" + "work/main/out\n"
                "read " + "../" * 3 + "elsewhere/file.md\n"
                "python is /usr/bin/python3, meshes in ../examples/biaxial/meshes\n")
        found = outside_paths("bench/README.md", text)
        self.assertEqual([n for n, _ in found], [1, 2, 3])
        self.assertEqual(found[2][1], "../" * 3 + "elsewhere")


if __name__ == "__main__":
    unittest.main()

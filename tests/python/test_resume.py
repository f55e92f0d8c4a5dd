"""Splicing a resumed shear's outputs: the result must be the uninterrupted file."""
import os
import tempfile
import unittest

from liggghts_membrane import resume


def rows(steps):
    return "# title\n# step x\n" + "".join("%d %g\n" % (s, 0.5 * s) for s in steps)


def blocks(steps):
    return "# a\n# b\n# c\n" + "".join("%d 2\n1 %d\n2 %d\n" % (s, s, -s) for s in steps)


def frames(steps):
    return "".join("ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n1\n1 %d\n" % (s, s) for s in steps)


MAKERS = {"rows": rows, "blocks": blocks, "frames": frames}


class Splice(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_every_kind(self):
        straight = range(0, 1001, 100)
        for kind, make in MAKERS.items():
            # interrupted after step 700 in the middle of a record; restart at 500;
            # the part repeats 500 (its first output) and goes on to the end
            cut = make(range(0, 701, 100))
            cut += {"rows": "800 4", "blocks": "800 2\n1 800\n", "frames": "ITEM: TIMESTEP\n800\nITEM: NU"}[kind]
            path = self.write("out_" + kind, cut)
            part = self.write("part_" + kind, make(range(500, 1001, 100)))
            resume.splice(path, part, 500, kind)
            with open(path) as f:
                self.assertEqual(f.read(), make(straight), kind)

    def test_records_of_a_partial_file(self):
        header, recs = resume.split_records(blocks([10, 20]).splitlines(True)[:-1], "blocks")
        self.assertEqual(len(header), 3)
        self.assertEqual([s for s, _ in recs], [10])

    def test_start_and_finish(self):
        out = os.path.join(self.dir, "shear.txt")
        self.write("shear.txt", rows(range(0, 701, 100)) + "800 4")
        self.write("shear.txt.dump", frames(range(0, 701, 100)))
        for s in (200, 400):
            self.write("shear.txt.restart.%d" % s, "R")
        walls = self.write("prepared.walls", "variable W0 equal 1\n")
        restart = resume.start_resume(out, walls)
        self.assertEqual(restart, out + ".restart.400")
        with open(restart + ".walls") as f:
            self.assertEqual(f.read(), "variable W0 equal 1\n")
        with open(out) as f:
            self.assertEqual(f.read(), rows(range(0, 401, 100)))
        # the resumed part, with a restart of its own
        self.write("shear.txt.part", rows(range(400, 1001, 100)))
        self.write("shear.txt.part.dump", frames(range(400, 1001, 100)))
        self.write("shear.txt.part.restart.800", "R")
        resume.finish_part(out)
        with open(out) as f:
            self.assertEqual(f.read(), rows(range(0, 1001, 100)))
        with open(out + ".dump") as f:
            self.assertEqual(f.read(), frames(range(0, 1001, 100)))
        self.assertEqual(sorted(resume.restart_steps(out)), [200, 400, 800])
        self.assertFalse(os.path.exists(out + ".part"))
        resume.remove_restarts(out)
        self.assertEqual(resume.restart_steps(out), {})

    def test_nothing_to_resume(self):
        out = os.path.join(self.dir, "none.txt")
        self.assertIsNone(resume.start_resume(out, os.path.join(self.dir, "w")))


if __name__ == "__main__":
    unittest.main()

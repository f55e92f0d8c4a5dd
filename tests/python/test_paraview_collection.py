"""liggghts_membrane.pvd (scripts/paraview_collection.py): which files of a folder enter run.pvd, as what."""
import contextlib
import io
import os
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

from liggghts_membrane import pvd


class Collection(unittest.TestCase):
    def data_sets(self, names):
        root = ET.fromstring(pvd.collection(names))
        return [(int(d.get("timestep")), int(d.get("part")), d.get("name"), d.get("file"))
                for d in root.find("Collection").findall("DataSet")]

    def test_steps_of_the_particles_with_the_kinds_present(self):
        names = ["particles_200.vtp", "particles_1000.vtp", "contacts_1000.vtp", "contacts_200.vtp",
                 "walls_200.vtp", "membrane_100.vtp", "membrane_200.vtp",   # 100: before shear
                 "particles_boundingBox_200.vtr", "membrane.pvd", "particles_x.vtp", "run.pvd"]
        self.assertEqual(self.data_sets(names), [
            (200, 0, "particles", "particles_200.vtp"), (200, 1, "contacts", "contacts_200.vtp"),
            (200, 2, "walls", "walls_200.vtp"), (200, 3, "membrane", "membrane_200.vtp"),
            (1000, 0, "particles", "particles_1000.vtp"), (1000, 1, "contacts", "contacts_1000.vtp")])

    def test_no_particles_is_a_note_and_no_file(self):
        # a shear shorter than its frame interval: not an error (run.sh goes on, issue 32)
        with tempfile.TemporaryDirectory() as d:
            open(os.path.join(d, "walls_5.vtp"), "w").close()
            with contextlib.redirect_stderr(io.StringIO()):
                self.assertEqual(pvd.main(["paraview_collection.py", d]), 0)
            self.assertFalse(os.path.exists(os.path.join(d, "run.pvd")))
            open(os.path.join(d, "particles_5.vtp"), "w").close()
            self.assertEqual(pvd.main(["paraview_collection.py", d]), 0)
            self.assertEqual(len(ET.parse(os.path.join(d, "run.pvd")).getroot().find("Collection")), 2)


if __name__ == "__main__":
    unittest.main()

#!/usr/bin/python3
"""paraview_collection.py FOLDER: the run.pvd of a shear's ParaView folder
(liggghts_membrane.pvd). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.pvd import main

sys.exit(main(sys.argv))

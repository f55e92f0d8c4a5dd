#!/usr/bin/python3
"""Pictures of a run's ParaView files (liggghts_membrane.render_paraview). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.render_paraview import main

sys.exit(main(sys.argv))

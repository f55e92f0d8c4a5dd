#!/usr/bin/python3
"""The membrane chains over the disks of a run (liggghts_membrane.membrane_plot). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.membrane_plot import main

main()

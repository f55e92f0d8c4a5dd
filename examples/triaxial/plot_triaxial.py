#!/usr/bin/python3
"""plot_triaxial.py TABLE [PNG]: the figure of a triaxial run
(liggghts_membrane.triaxial_plot). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.triaxial_plot import main

sys.exit(main(sys.argv))

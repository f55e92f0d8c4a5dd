#!/usr/bin/python3
"""progress.py OUT TARGET PID LABEL: the progress of a shear (liggghts_membrane.progress). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.progress import main

main()

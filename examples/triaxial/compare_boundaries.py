#!/usr/bin/python3
"""compare_boundaries.py OUT SEED [SEED ...]: the rigid-boundary comparison of the
triaxial example (liggghts_membrane.triaxial_compare). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.triaxial_compare import main

main()

#!/usr/bin/python3
"""bench/scaling3d.py: the 3D scaling benchmark (liggghts_membrane.bench.scaling3d; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.bench.scaling3d import main

sys.exit(main(sys.argv[1:]))

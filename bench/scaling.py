#!/usr/bin/python3
"""bench/scaling.py: the scaling benchmark (liggghts_membrane.bench.scaling; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.bench.scaling import main

sys.exit(main(sys.argv[1:]))

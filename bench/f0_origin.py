#!/usr/bin/python3
"""bench/f0_origin.py: the origin of f0 (liggghts_membrane.bench.f0_origin; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.bench.f0_origin import main

main()

#!/usr/bin/python3
"""bench/density_scaling.py: the density scaling (liggghts_membrane.bench.density_scaling; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.bench.density_scaling import main

main()

#!/usr/bin/python3
"""bench/porosity_coordination.py: porosity and coordination (liggghts_membrane.bench.porosity_coordination; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.bench.porosity_coordination import main

main()

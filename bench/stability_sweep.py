#!/usr/bin/python3
"""bench/stability_sweep.py: the stability sweep (liggghts_membrane.bench.stability_sweep; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.bench.stability_sweep import main

sys.exit(main(sys.argv[1:]))

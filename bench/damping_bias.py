#!/usr/bin/python3
"""bench/damping_bias.py: the damping bias (liggghts_membrane.bench.damping_bias; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.bench.damping_bias import main

main()

#!/usr/bin/python3
"""The sample command (liggghts-membrane-sample): liggghts_membrane.sample. The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.sample import main

main()

#!/usr/bin/python3
"""Runs an input script and checks its '#@' expectations (liggghts_membrane.run_script). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
import sys

from liggghts_membrane.run_script import main

sys.exit(main())

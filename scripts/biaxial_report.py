#!/usr/bin/python3
"""The report command (liggghts-membrane-report): liggghts_membrane.report_command. The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.report_command import command

command()

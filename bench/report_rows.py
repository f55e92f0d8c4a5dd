#!/usr/bin/python3
"""bench/report_rows.py: the report time against the table length (liggghts_membrane.bench.report_rows; its --help). The package is found on PYTHONPATH (run.sh, test.sh and CTest set it to the
repository's python/) or where the Debian package installs it (doc/install.md).
"""
from liggghts_membrane.bench.report_rows import main

main()

#!/usr/bin/env bash
# Install what is missing, build, and run every test (unit and input-script,
# on 1, 2 and 4 MPI ranks).
set -euo pipefail
cd "$(dirname "$0")"
export PYTHONPATH="$(pwd)/python${PYTHONPATH:+:$PYTHONPATH}"   # the package python/liggghts_membrane
tools/install-deps.sh
tools/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"

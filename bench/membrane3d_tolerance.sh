#!/usr/bin/env bash
# fix membrane3d's surface against its tolerance on the compressed triaxial sample
# (examples/triaxial/run_triaxial.sh writes it): prints the table of
# bench/README.md (membrane spheres, leaks, escapees, volume, detection time).
#   bench/membrane3d_tolerance.sh [RESTART]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
restart=$(readlink -f "${1:-$here/../out/triaxial/triaxial.compressed.restart}")  # before cd: a path given from anywhere
cd "$here"
[ -f "$restart" ] || { echo "no compressed sample $restart: run examples/triaxial/run_triaxial.sh first"; exit 1; }
platen=${restart%.restart}.platen
ztop=$(awk '{print $4}' "$platen")
dump=$(mktemp --suffix=.dump)
trap 'rm -f "$dump"' EXIT
../build/app/liggghts-membrane -in in.membrane3d_dump -log none -var restart "$restart" -var dump "$dump" > /dev/null
../build/bench/membrane3d_tolerance "$dump" 0.025 0 "$ztop"

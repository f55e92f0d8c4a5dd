#!/usr/bin/env bash
# How much of fix membrane3d's surface changes per step on the compressed triaxial
# sample (examples/triaxial/run_triaxial.sh writes it), platens still, the membrane
# found at every step: the spheres dumped at each of NSTEPS steps after the settling
# of bench/membrane3d_cost.sh, and their membranes compared (membrane3d_steps.cpp):
# what a kinetic repair would redo per step against a detection from scratch.
#   bench/membrane3d_steps.sh [RESTART] [NSTEPS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
restart=$(readlink -f "${1:-$here/../out/triaxial/triaxial.compressed.restart}")  # before cd: a path given from anywhere
cd "$here"
nsteps=${2:-20}
[ -f "$restart" ] || { echo "no compressed sample $restart: run examples/triaxial/run_triaxial.sh first"; exit 1; }
platen=${restart%.restart}.platen
ztop=$(awk '{print $4}' "$platen")
dump=$(mktemp --suffix=.dump)
trap 'rm -f "$dump"' EXIT
../build/app/liggghts-membrane -in in.membrane3d_cost -log none -var restart "$restart" \
  -var platen "$platen" -var meshdir "$(readlink -f ../examples/triaxial/meshes)" -var every 1 \
  -var nsteps "$nsteps" -var dumpevery 1 -var dump "$dump" > /dev/null
# the fix's default tolerance: 0.7 mean diameters (doc/fix_membrane3d.md)
../build/bench/membrane3d_steps "$dump" 0 "$ztop" 0.7

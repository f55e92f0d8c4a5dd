#!/usr/bin/env bash
# The triaxial example in one command: prepare, shear with the membrane, plot.
#   examples/triaxial/run_triaxial.sh [--quick] [--np N]
# --quick: a 20 mm cylinder (about 290 spheres, under a minute); default the 50 mm
# cylinder (about 7 700 spheres, about 6 minutes on 2 cores). Writes
# out/triaxial/triaxial.txt, .png, .log, the compressed sample's restart and the
# ParaView files in triaxial.paraview/ (run.pvd: the spheres and the membrane in shear;
# membrane.pvd: the membrane from the isotropic stage on).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
export PYTHONPATH="$root/python${PYTHONPATH:+:$PYTHONPATH}"   # the package python/liggghts_membrane
. "$root/tools/run_options.sh"
np=2
vars=()
usage="usage: $0 [--quick] [--np N]   (N: MPI ranks, an integer >= 1, default 2)"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) vars+=(-var R 0.01 -var hfill 0.06 -var nsettle 8000 -var ncompress 10000 -var nhold 4000) ;;
    --np) np=${2-}; ranks_or_exit "$np"; shift ;;
    -h|--help) echo "$usage"; exit 0 ;;
    *) echo "$0: unknown option '$1'" >&2; echo "$usage" >&2; exit 2 ;;
  esac
  shift
done
out=$root/out/triaxial
mkdir -p "$out"
rm -rf "$out/triaxial.paraview"   # the frames of an earlier run (another size) would mix in
cd "$here"
mpirun --allow-run-as-root --oversubscribe -np "$np" "$root/build/app/liggghts-membrane" \
  -in in.triaxial -log "$out/triaxial.log" -var out "$out/triaxial" "${vars[@]}"
if [ -d "$out/triaxial.paraview" ]; then
  /usr/bin/python3 "$root/scripts/paraview_collection.py" "$out/triaxial.paraview"
fi
/usr/bin/python3 plot_triaxial.py "$out/triaxial.txt"

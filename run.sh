#!/usr/bin/env bash
# The main job: install what is missing, build, prepare one biaxial sample, shear
# it with rigid servo-controlled side walls and with fix membrane2d, and write the
# comparison (plots and table) to out/biaxial/.
#
#   ./run.sh                 published size (75 x 150 mm, 8 404 disks), 10 % axial strain
#   ./run.sh --quick         a quarter-size sample (526 disks), 2 % strain: about a minute
#   ./run.sh --np N          MPI ranks (default: the number of cores)
#   ./run.sh --rate R        axial strain rate [1/s] (default 0.0025: the fastest within the
#                            sample scatter for the membrane, bench/accuracy_sweep.md)
#   ./run.sh --strain E      final axial strain (default 0.10)
set -euo pipefail
cd "$(dirname "$0")"
root=$(pwd)

scale=1; strain=0.10; rate=0.0025; np=$(nproc); seed=12345
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) scale=0.25; strain=0.02 ;;
    --full) scale=1 ;;
    --np) np=$2; shift ;;
    --rate) rate=$2; shift ;;
    --strain) strain=$2; shift ;;
    --seed) seed=$2; shift ;;
    *) echo "unknown option $1 (see the comments at the top of run.sh)"; exit 2 ;;
  esac
  shift
done

tools/install-deps.sh
tools/build.sh >/dev/null
exe=$root/build/app/liggghts-membrane
out=$root/out/biaxial
mkdir -p "$out"
cd examples/biaxial
mpi=(mpirun --allow-run-as-root --oversubscribe -np "$np")
t0=$(date +%s)

echo "== sample: scale $scale, seed $seed"
/usr/bin/python3 "$root/scripts/generate_sample.py" --scale "$scale" --seed "$seed" --out "$out/sample.data"
"${mpi[@]}" "$exe" -in in.prepare -var data "$out/sample.data" -var out "$out/prepared.restart" \
    -log "$out/log.prepare" > "$out/screen.prepare"
grep -E "^PREPARED porosity" "$out/screen.prepare" || { tail -20 "$out/screen.prepare"; exit 1; }

for case in rigid membrane; do
  echo "== shear, $case: rate $rate 1/s to axial strain $strain on $np ranks"
  "${mpi[@]}" "$exe" -in in.shear_$case -var restart "$out/prepared.restart" -var rate "$rate" \
      -var eatarget "$strain" -var out "$out/shear_$case.txt" -log "$out/log.shear_$case" \
      > "$out/screen.shear_$case" &
  pid=$!
  /usr/bin/python3 "$root/scripts/progress.py" "$out/shear_$case.txt" "$strain" "$pid" "$case" &
  mon=$!
  wait "$pid" || { kill "$mon" 2>/dev/null; tail -20 "$out/screen.shear_$case"; exit 1; }
  kill "$mon" 2>/dev/null || true
  grep -E "^SHEAR done" "$out/screen.shear_$case"
done

echo "== report"
/usr/bin/python3 "$root/scripts/biaxial_report.py" --rigid "$out/shear_rigid.txt" \
    --membrane "$out/shear_membrane.txt" --outdir "$out"
echo "== done in $(( $(date +%s) - t0 )) s; plots and summary.md in out/biaxial/"

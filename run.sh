#!/usr/bin/env bash
# The main job: install what is missing, build, prepare one biaxial sample (or N),
# shear it with rigid servo-controlled side walls and with fix membrane2d, and write
# the comparison (plots and table) to out/biaxial/.
#
#   ./run.sh                 published size (75 x 150 mm, 8 404 disks), 10 % axial strain
#   ./run.sh --quick         a quarter-size sample (526 disks), 2 % strain: about a minute
#   ./run.sh --np N          MPI ranks (default: the number of cores)
#   ./run.sh --rate R        axial strain rate [1/s] (default 0.0025: the fastest within the
#                            sample scatter for the membrane, bench/accuracy_sweep.md)
#   ./run.sh --strain E      final axial strain (default 0.10)
#   ./run.sh --seed S        seed of the (first) sample (default 12345)
#   ./run.sh --samples N     N independent samples, seeds S, S + 1000, ..., S + 1000 (N - 1),
#                            each sheared with both boundaries; the table gives means with
#                            95 % intervals and paired rigid - membrane differences (default 1)
#
# Each sample keeps its files in out/biaxial/scale<scale>_seed<seed>/ (and its own
# report); out/biaxial/prepared.restart and .walls link to the first sample's, for
# bench/. A re-run reuses a sample's preparation and each of its shears when they
# finished with the same scale, seed, rank count and scripts (and rate and strain, for
# a shear): stamps prepare.key and shear_<case>.key in the folder.
set -euo pipefail
cd "$(dirname "$0")"
root=$(pwd)

scale=1; strain=0.10; rate=0.0025; np=$(nproc); seed=12345; samples=1
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) scale=0.25; strain=0.02 ;;
    --full) scale=1 ;;
    --np) np=$2; shift ;;
    --rate) rate=$2; shift ;;
    --strain) strain=$2; shift ;;
    --seed) seed=$2; shift ;;
    --samples) samples=$2; shift ;;
    *) echo "unknown option $1 (see the comments at the top of run.sh)"; exit 2 ;;
  esac
  shift
done
[[ "$samples" =~ ^[1-9][0-9]*$ ]] || { echo "--samples needs a positive integer, not '$samples'"; exit 2; }

tools/install-deps.sh
tools/build.sh >/dev/null
exe=$root/build/app/liggghts-membrane
out=$root/out/biaxial
mkdir -p "$out"
cd examples/biaxial
mpi=(mpirun --allow-run-as-root --oversubscribe -np "$np")
t0=$(date +%s)

script_hash() { cat "$@" | sha1sum | cut -c1-12; }   # a changed script invalidates its results

dirs=()
for k in $(seq 1 "$samples"); do
  s=$(( seed + 1000 * (k - 1) ))
  dir=$out/scale${scale}_seed$s
  dirs+=("$dir")
  mkdir -p "$dir"
  prep_key="scale $scale seed $s np $np scripts $(script_hash in.prepare "$root/scripts/generate_sample.py")"
  if [ "$(cat "$dir/prepare.key" 2>/dev/null)" = "$prep_key" ] \
      && grep -qE "^PREPARED porosity" "$dir/screen.prepare" 2>/dev/null; then
    echo "== sample $k of $samples: scale $scale, seed $s: prepared before, reused"
  else
    echo "== sample $k of $samples: scale $scale, seed $s"
    rm -f "$dir"/*.key
    /usr/bin/python3 "$root/scripts/generate_sample.py" --scale "$scale" --seed "$s" --out "$dir/sample.data"
    "${mpi[@]}" "$exe" -in in.prepare -var data "$dir/sample.data" -var out "$dir/prepared.restart" \
        -log "$dir/log.prepare" > "$dir/screen.prepare"
    grep -E "^PREPARED porosity" "$dir/screen.prepare" || { tail -20 "$dir/screen.prepare"; exit 1; }
    echo "$prep_key" > "$dir/prepare.key"
  fi
  if [ "$k" = 1 ]; then         # where bench/ looks for the prepared sample
    for f in prepared.restart prepared.restart.walls; do ln -sfn "$(basename "$dir")/$f" "$out/$f"; done
  fi

  for case in rigid membrane; do
    shear_key="$prep_key rate $rate strain $strain scripts $(script_hash in.shear_$case damping.inc)"
    if [ "$(cat "$dir/shear_$case.key" 2>/dev/null)" = "$shear_key" ] \
        && grep -qE "^SHEAR done" "$dir/screen.shear_$case" 2>/dev/null; then
      echo "== shear, $case, seed $s: done before, reused"
      continue
    fi
    echo "== shear, $case, seed $s: rate $rate 1/s to axial strain $strain on $np ranks"
    rm -f "$dir/shear_$case.key"
    "${mpi[@]}" "$exe" -in in.shear_$case -var restart "$dir/prepared.restart" -var rate "$rate" \
        -var eatarget "$strain" -var out "$dir/shear_$case.txt" -log "$dir/log.shear_$case" \
        > "$dir/screen.shear_$case" &
    pid=$!
    /usr/bin/python3 "$root/scripts/progress.py" "$dir/shear_$case.txt" "$strain" "$pid" "$case" &
    mon=$!
    wait "$pid" || { kill "$mon" 2>/dev/null; tail -20 "$dir/screen.shear_$case"; exit 1; }
    kill "$mon" 2>/dev/null || true
    grep -E "^SHEAR done" "$dir/screen.shear_$case"
    echo "$shear_key" > "$dir/shear_$case.key"
  done
done

echo "== report"
/usr/bin/python3 "$root/scripts/biaxial_report.py" --samples "${dirs[@]}" --outdir "$out"
echo "== done in $(( $(date +%s) - t0 )) s; summary.md and stress_strain.png in out/biaxial/," \
     "each sample's report and figures in out/biaxial/scale${scale}_seed*/"

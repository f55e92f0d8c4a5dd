#!/usr/bin/env bash
# The main job: install what is missing, build, prepare one biaxial sample (or N),
# shear it with rigid servo-controlled side walls and with fix membrane2d, and write
# the comparison (plots and table) to out/biaxial/.
#
#   ./run.sh                 published size (75 x 150 mm, 8 404 disks), 10 % axial strain
#   ./run.sh --quick         a quarter-size sample (526 disks), 2 % strain: about a minute
#   ./run.sh --scale S       linear scale of the published sample, S >= 0.1: about 8 404 S^2 disks
#                            (0.25: 526, 0.5: 2 100, 2: 33 614, 4: 134 455, 8: 537 817); box,
#                            meshes and box z extent follow S (examples/biaxial/README.md,
#                            "Any sample size"); results in out/biaxial/scale<S>_seed<seed>/
#   ./run.sh --paper         the published procedure as closely as LIGGGHTS allows (doc/paper_preset.md):
#                            2 %/min, PFC local damping alpha 0.7, side-wall servo without
#                            feed-forward; writes restart files and resumes an interrupted
#                            shear from the latest; results in out/paper/ (full size:
#                            about 50 min per case on 2 cores; --scale 0.25 --np 1:
#                            34 min for the preparation and both cases)
#   ./run.sh --restart-every N   with --paper: restart files every N steps (default 50 000)
#   ./run.sh --np N          MPI ranks (default: the number of cores)
#   ./run.sh --rate R        axial strain rate [1/s] (default 0.0025: the fastest within the
#                            sample scatter for the membrane, bench/accuracy_sweep.md)
#   ./run.sh --strain E      final axial strain (default 0.10)
#   ./run.sh --vtk E         ParaView files of each shear every E of axial strain (default 0.005;
#                            0: none) in <case folder>/shear_<case>.txt.paraview/, opened in one
#                            click from its run.pvd (doc/paraview.md)
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
. tools/run_options.sh

scale=1; strain=0.10; rate=0.0025; np=$(nproc); seed=12345; samples=1; paper=0; restart_every=50000; vtk=0.005
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) scale=0.25; strain=0.02 ;;
    --full) scale=1 ;;
    --scale) scale=$2; shift ;;
    --paper) paper=1 ;;
    --restart-every) restart_every=$2; shift ;;
    --np) np=${2-}; ranks_or_exit "$np"; shift ;;
    --rate) rate=$2; shift ;;
    --strain) strain=$2; shift ;;
    --seed) seed=$2; shift ;;
    --vtk) vtk=$2; shift ;;
    --samples) samples=$2; shift ;;
    *) echo "unknown option $1 (see the comments at the top of run.sh)"; exit 2 ;;
  esac
  shift
done
[[ "$samples" =~ ^[1-9][0-9]*$ ]] || { echo "--samples needs a positive integer, not '$samples'"; exit 2; }
/usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) >= 0.1 else 1)" "$scale" 2>/dev/null \
  || { echo "--scale needs a number >= 0.1 (the meshes' ghost images in z, examples/biaxial/README.md), not '$scale'"; exit 2; }

/usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) >= 0 else 1)" "$vtk" 2>/dev/null \
  || { echo "--vtk needs an axial strain >= 0 between ParaView frames (0: none), not '$vtk'"; exit 2; }

tools/install-deps.sh
tools/build.sh >/dev/null
exe=$root/build/app/liggghts-membrane
out=$root/out/biaxial
shear_vars=()
if [ "$paper" = 1 ]; then
  rate=$(/usr/bin/python3 -c "print(0.02 / 60)")      # 2 %/min
  out=$root/out/paper
  [[ "$restart_every" =~ ^[1-9][0-9]*$ ]] || { echo "--restart-every needs a positive integer, not '$restart_every'"; exit 2; }
  shear_vars=(-var damping 1 -var adamp 0.7 -var feedforward 0 -var restartevery $restart_every)
else
  restart_every=0                                     # restart files (and resuming) only with --paper
fi
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
  prep_key="scale $scale seed $s np $np scripts $(script_hash in.prepare material.inc "$root/scripts/generate_sample.py")"
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
    shear_key="$prep_key rate $rate strain $strain vtk $vtk ${shear_vars[*]} scripts $(script_hash in.shear_$case material.inc shear_setup.inc shear_measure.inc shear_loading.inc damping.inc paraview.inc)"
    if [ "$(cat "$dir/shear_$case.key" 2>/dev/null)" = "$shear_key" ] \
        && grep -qE "^SHEAR done" "$dir/screen.shear_$case" 2>/dev/null; then
      echo "== shear, $case, seed $s: done before, reused"
      continue
    fi
    echo "== shear, $case, seed $s: rate $rate 1/s to axial strain $strain on $np ranks"
    rm -f "$dir/shear_$case.key"
    o=$dir/shear_$case.txt
    run_vars=(-var restart "$dir/prepared.restart" -var out "$o")
    writing=$o
    if [ "$restart_every" -gt 0 ]; then        # resume an interrupted shear from its latest restart
      if [ "$(cat "$dir/shear_$case.running" 2>/dev/null)" != "$shear_key" ]; then
        # restart files of another definition of the shear are not resumed
        /usr/bin/python3 "$root/scripts/resume_shear.py" clean "$o"; rm -f "$o".part*
        echo "$shear_key" > "$dir/shear_$case.running"
      fi
      resume_from=$(/usr/bin/python3 "$root/scripts/resume_shear.py" start "$o" "$dir/prepared.restart.walls")
      if [ -n "$resume_from" ]; then
        echo "   resuming from $(basename "$resume_from")"
        run_vars=(-var restart "$resume_from" -var resume 1 -var start "$o.start" -var out "$o.part")
        writing=$o.part
      fi
    fi
    "${mpi[@]}" "$exe" -in in.shear_$case "${run_vars[@]}" -var rate "$rate" -var eatarget "$strain" \
        "${shear_vars[@]}" -var vtkstrain "$vtk" -log "$dir/log.shear_$case" > "$dir/screen.shear_$case" &
    pid=$!
    /usr/bin/python3 "$root/scripts/progress.py" "$writing" "$strain" "$pid" "$case" &
    mon=$!
    status=0; wait "$pid" || status=$?
    kill "$mon" 2>/dev/null || true
    if [ "$restart_every" -gt 0 ]; then /usr/bin/python3 "$root/scripts/resume_shear.py" finish "$o"; fi
    [ "$status" = 0 ] || { tail -20 "$dir/screen.shear_$case"; exit 1; }
    if [ "$restart_every" -gt 0 ]; then
      /usr/bin/python3 "$root/scripts/resume_shear.py" clean "$o"; rm -f "$dir/shear_$case.running"
    fi
    grep -E "^SHEAR done" "$dir/screen.shear_$case"
    if [ -d "$o.paraview" ]; then /usr/bin/python3 "$root/scripts/paraview_collection.py" "$o.paraview"; fi
    echo "$shear_key" > "$dir/shear_$case.key"
  done
done

echo "== report"
/usr/bin/python3 "$root/scripts/biaxial_report.py" --samples "${dirs[@]}" --outdir "$out"
rel=${out#"$root"/}
echo "== done in $(( $(date +%s) - t0 )) s; summary.md and stress_strain.png in $rel/," \
     "each sample's report and figures in $rel/scale${scale}_seed*/"

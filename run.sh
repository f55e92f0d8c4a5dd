#!/usr/bin/env bash
# The main job: install what is missing, build, prepare one biaxial sample (or N),
# shear it with rigid servo-controlled side walls and with fix membrane2d, and write
# the comparison (plots and table) to out/biaxial/. The options: ./run.sh --help
# (the text of usage() below).
#
# Each sample keeps its files in out/biaxial/scale<scale>_seed<seed>/ (and its own
# report); out/biaxial/prepared.restart and .walls link to the first sample's, for
# bench/. A re-run reuses a sample's preparation and each of its shears when they
# finished with the same scale, seed, rank count and scripts (and rate and strain, for
# a shear): stamps prepare.key and shear_<case>.key in the folder.
set -euo pipefail
cd "$(dirname "$0")"
root=$(pwd)
export PYTHONPATH="$root/python${PYTHONPATH:+:$PYTHONPATH}"   # the package python/liggghts_membrane
. tools/run_options.sh

usage() {
  cat <<'TEXT'
usage: ./run.sh [options]
Install what is missing, build, prepare a biaxial sample, shear it with rigid walls and
with the membrane, and write the comparison to out/biaxial/ (out/paper/ with --paper).

  --quick              a quarter-size sample (--scale 0.25, 526 disks) to 2 % strain
                       (--strain 0.02): about a minute
  --full               the published size (--scale 1, 8 404 disks; the default)
  --scale S            linear scale of the published 75 x 150 mm sample, 0.1 <= S <= 16:
                       about 8 404 S^2 disks (0.25: 526, 0.5: 2 100, 2: 33 614, 4: 134 455,
                       8: 537 817); box, meshes and box z extent follow S
                       (examples/biaxial/README.md, "Any sample size"); results in
                       out/biaxial/scale<S>_seed<seed>/
  --strain E           final axial strain, 0 < E <= 0.5 (default 0.10)
  --rate R             axial strain rate [1/s], 1e-6 <= R <= 1 (default 0.0025: the fastest
                       within the sample scatter for the membrane, bench/accuracy_sweep.md);
                       E / (R x 1e-4 s) steps must stay below 2 147 483 647
  --vtk E              ParaView files of each shear every E of axial strain, 0 (none) or
                       1e-4 <= E <= 1 (default 0.005), in <case folder>/shear_<case>.txt.paraview/,
                       opened in one click from its run.pvd (doc/paraview.md); a shear
                       shorter than E has none
  --seed S             seed of the (first) sample, an integer 0 <= S <= 2 147 483 647
                       (default 12345)
  --samples N          N independent samples, 1 <= N <= 100, seeds S, S + 1000, ...,
                       S + 1000 (N - 1), each sheared with both boundaries; the table gives
                       means with 95 % intervals and paired rigid - membrane differences
                       (default 1)
  --np N               MPI ranks, 1 <= N <= 4096 (default: the number of cores)
  --paper              the published procedure as closely as LIGGGHTS allows
                       (doc/paper_preset.md): 2 %/min (so no --rate), PFC local damping
                       alpha 0.7, side-wall servo without feed-forward; writes restart files
                       and resumes an interrupted shear from the latest; results in out/paper/
                       (full size: about 50 min per case on 2 cores; --scale 0.25 --np 1:
                       34 min for the preparation and both cases)
  --restart-every N    with --paper: restart files every N steps, 1 <= N <= 2 147 483 647
                       (default 50 000)
  -h, --help           this text

Every option is checked before anything is installed, built or run.
TEXT
}

scale=1; strain=0.10; rate=0.0025; np=$(nproc); seed=12345; samples=1; paper=0; restart_every=50000; vtk=0.005
rate_given=0; restart_given=0
while [ $# -gt 0 ]; do
  opt=$1
  case "$opt" in
    -h|--help) usage; exit 0 ;;
    --quick) scale=0.25; strain=0.02 ;;
    --full) scale=1 ;;
    --paper) paper=1 ;;
    --scale|--restart-every|--np|--rate|--strain|--seed|--vtk|--samples)
      if [ $# -lt 2 ] || [ -z "$2" ]; then
        option_error "$opt needs a value (./run.sh --help)"
        shift; continue
      fi
      v=$2; shift
      case "$opt" in
        --scale) scale=$v ;;
        --restart-every) restart_every=$v; restart_given=1 ;;
        --np) np=$v ;;
        --rate) rate=$v; rate_given=1 ;;
        --strain) strain=$v ;;
        --seed) seed=$v ;;
        --vtk) vtk=$v ;;
        --samples) samples=$v ;;
      esac ;;
    *) option_error "unknown option '$opt' (./run.sh --help lists them)" ;;
  esac
  shift
done
check_number --scale "$scale" 0.1 16 "a linear scale of the published sample" closed \
  "16: 2.2 million disks; below 0.1 the meshes' ghost images in z fail, examples/biaxial/README.md"
check_number --strain "$strain" 0 0.5 "the final axial strain" open
check_number --rate "$rate" 1e-6 1 "an axial strain rate [1/s]" closed \
  "above 1 /s the inertial number passes 0.07: no longer quasi-static"
if is_number "$vtk" && awk_true "v == 0" "$vtk"; then :; else
  check_number --vtk "$vtk" 1e-4 1 "0 (no ParaView files) or the axial strain between frames"
fi
check_integer --samples "$samples" 1 100 "the number of samples"
check_integer --seed "$seed" 0 2147483647 "the seed of the first sample"
if is_integer "$seed" && is_integer "$samples" && [ "${#option_errors[@]}" -eq 0 ] \
    && [ $((10#$seed + 1000 * (10#$samples - 1))) -gt 2147483647 ]; then
  option_error "--seed $seed with --samples $samples: the last seed passes 2147483647; a smaller --seed"
fi
check_integer --np "$np" 1 "$MAX_RANKS" "MPI ranks"
check_integer --restart-every "$restart_every" 1 2147483647 "steps between restart files"
if [ "$restart_given" = 1 ] && [ "$paper" = 0 ]; then
  option_error "--restart-every $restart_every: restart files are written only with --paper; add --paper or leave it out"
fi
if [ "$rate_given" = 1 ] && [ "$paper" = 1 ]; then
  option_error "--rate $rate: --paper shears at 2 %/min (3.33e-4 1/s); leave --rate out or --paper out"
fi
if [ "$paper" = 1 ]; then rate=0.0003333333333333333; fi   # 2 %/min (the text Python prints for 0.02 / 60)
if [ "${#option_errors[@]}" -eq 0 ] && ! awk_true "$strain / ($rate * 1e-4) < 2147483647"; then
  option_error "--strain $strain at --rate $rate: $(awk "BEGIN { printf \"%.3g\", $strain / ($rate * 1e-4) }") steps of 1e-4 s, more than LIGGGHTS runs at once (2147483647); a faster --rate or a smaller --strain"
fi
options_or_exit "./run.sh --help lists the options"

tools/install-deps.sh
tools/build.sh >/dev/null
exe=$root/build/app/liggghts-membrane
out=$root/out/biaxial
shear_vars=()
if [ "$paper" = 1 ]; then
  out=$root/out/paper
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
  prep_key="scale $scale seed $s np $np scripts $(script_hash in.prepare material.inc "$root/python/liggghts_membrane/sample.py")"
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

#!/bin/bash
#SBATCH --job-name=biaxial --ntasks=64 --time=24:00:00
# A biaxial test at linear scale SCALE of the published sample (4: ~134 000 disks)
# as a batch job: generate, prepare (once), shear CASE (membrane or rigid) writing a
# restart file every EVERY steps. Submit the same script again until OUT.log says
# "SHEAR done": each job goes on from the newest restart file of the one before and
# splices its outputs onto the earlier ones (scripts/resume_shear.py; the same
# mechanism as ./run.sh --paper). Then `resume_shear.py clean OUT` removes the
# restart files. Files go to WORK (default out/cluster/). Variables (environment):
# REPO WORK SCALE SEED CASE LAUNCH EVERY NDUMP EXTRA. From the repository root:
#   sbatch examples/biaxial/cluster_job.sh           (Slurm)
#   LAUNCH="mpirun -np 8" bash examples/biaxial/cluster_job.sh
# With the package installed (doc/install.md), from any folder (WORK default: ./cluster):
#   sbatch /usr/share/liggghts-membrane/examples/biaxial/cluster_job.sh
set -euo pipefail
REPO=${REPO:-${SLURM_SUBMIT_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}}   # built with tools/build.sh
if [ -x "$REPO/build/app/liggghts-membrane" ]; then
  LM=$REPO/build/app/liggghts-membrane; WORK=${WORK:-$REPO/out/cluster}
  export PYTHONPATH="$REPO/python${PYTHONPATH:+:$PYTHONPATH}"   # the package python/liggghts_membrane
else                                        # the installed package
  LM=$(command -v liggghts-membrane) || { echo "cluster_job.sh: no $REPO/build/app/liggghts-membrane and no liggghts-membrane on PATH"; exit 1; }
  prefix=$(dirname "$(readlink -f "$LM")")/..
  REPO=$prefix/share/liggghts-membrane; WORK=${WORK:-$PWD/cluster}
  export PYTHONPATH="$prefix/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"
fi
mkdir -p "$WORK"; WORK=$(cd "$WORK" && pwd)
SCALE=${SCALE:-4}; SEED=${SEED:-1}; CASE=${CASE:-membrane}
LAUNCH=${LAUNCH:-srun}                      # or: mpirun -np $SLURM_NTASKS
cd "$REPO/examples/biaxial"                 # the scripts find their includes and meshes here
S=$WORK/s${SCALE}_${SEED}; OUT=$S.$CASE.txt
[ -f $S.data ] || /usr/bin/python3 ../../scripts/generate_sample.py --scale $SCALE --seed $SEED --out $S.data
[ -f $S.restart ] || $LAUNCH $LM -in in.prepare -var data $S.data -var out $S.restart -log $S.prepare.log
from=$(/usr/bin/python3 ../../scripts/resume_shear.py start $OUT $S.restart.walls)
if [ -n "$from" ]; then
  args=(-var restart $from -var resume 1 -var start $OUT.start -var out $OUT.part)
else
  args=(-var restart $S.restart -var out $OUT)
fi
$LAUNCH $LM -in in.shear_$CASE "${args[@]}" -var restartevery ${EVERY:-50000} -var ndump ${NDUMP:-50000} ${EXTRA:-} -log $OUT.log
[ -z "$from" ] || /usr/bin/python3 ../../scripts/resume_shear.py finish $OUT

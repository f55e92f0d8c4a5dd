#!/bin/sh
# The whole chain on a quarter-size sample (526 disks, 18.75 x 37.5 mm, 1 % axial strain).
#   sh run_tiny.sh [NP]        (NP = MPI ranks, default 1); outputs in ./tiny/
set -e
cd "$(dirname "$0")"
NP=${1:-1}
LM=${LM:-../../build/app/liggghts-membrane}
case "$LM" in /*) ;; *) LM="$(pwd)/$LM" ;; esac
mkdir -p tiny
/usr/bin/python3 ../../scripts/generate_sample.py --scale 0.25 --seed 12345 --out tiny/sample.data
RUN="mpirun --allow-run-as-root --oversubscribe -np $NP $LM"
$RUN -in in.prepare -var data tiny/sample.data -var out tiny/prepared.restart -log tiny/log.prepare > tiny/out.prepare
grep -E "^(grown|PREPARED|equilibrium)" tiny/out.prepare
$RUN -in in.shear_rigid -var restart tiny/prepared.restart -var eatarget 0.01 -var out tiny/shear_rigid.txt \
     -log tiny/log.shear_rigid > tiny/out.shear_rigid
grep -E "^(walls|shear|SHEAR)" tiny/out.shear_rigid
head -2 tiny/shear_rigid.txt; tail -1 tiny/shear_rigid.txt

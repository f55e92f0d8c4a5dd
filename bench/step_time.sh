# Sourced by the shell benchmarks: ms_per_step NP SCRIPT [NAME VALUE ...] prints the
# milliseconds per step of one run of liggghts-membrane ($exe) on NP ranks, from
# LIGGGHTS' "Loop time" line, with each NAME VALUE given as -var NAME VALUE and
# -var meshdir the walls' folder ($meshdir, default the biaxial example's meshes).
ms_per_step() {
  local np=$1 script=$2
  shift 2
  local vars=()
  while [ $# -gt 1 ]; do vars+=(-var "$1" "$2"); shift 2; done
  mpirun --allow-run-as-root --oversubscribe -np "$np" "$exe" -in "$script" -log none "${vars[@]}" \
    -var meshdir "$(readlink -f "${meshdir:-../examples/biaxial/meshes}")" | grep "^Loop time" | tail -1 |
    awk '{printf "%.4f", 1000 * $4 / $9}'
}

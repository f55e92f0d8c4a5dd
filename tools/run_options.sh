# Sourced by the run scripts (run.sh, examples/triaxial/run_triaxial.sh,
# examples/triaxial/run_comparison.sh): the checks their options share.
# ranks_or_exit N: the MPI ranks of --np, an integer >= 1 (Open MPI runs on every slot
# for -np 0, and its own refusals of -1 or 1.5 are pages long).
ranks_or_exit() {
  [[ "${1-}" =~ ^[1-9][0-9]*$ ]] || { echo "--np needs an integer >= 1 (MPI ranks), not '${1-}'" >&2; exit 2; }
}

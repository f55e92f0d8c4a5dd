// Which rank's candidate a message names (fix stability/guard's checks, the atom
// faults of both membranes), the same on every rank whatever the decomposition
// (collective; MPI only, no LIGGGHTS).
#ifndef LIGGGHTS_MEMBRANE_RANK_CHOICE_H
#define LIGGGHTS_MEMBRANE_RANK_CHOICE_H

#include <mpi.h>

namespace rank_choice {

// a value and the atom ID it belongs to, for MPI_MAXLOC over the ranks
struct ValueTag {
  double value;
  int tag;
};

inline ValueTag max_over_ranks(ValueTag local, MPI_Comm world)
{
  ValueTag global;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  return global;
}

// The smallest of the ranks' keys (LLONG_MAX: this rank has none; the low 32 bits
// of a key are an atom ID, the high ones a priority): returns that atom ID and
// gives every rank the n `values_of_first` of the rank that proposed it. At least
// one rank must have a key.
inline int name_first(MPI_Comm world, long long key, double *values_of_first, int n)
{
  int me = 0, nprocs = 1;
  MPI_Comm_rank(world, &me);
  MPI_Comm_size(world, &nprocs);
  long long first = key;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_LONG_LONG, MPI_MIN, world);
  int owner = key == first ? me : nprocs;
  MPI_Allreduce(MPI_IN_PLACE, &owner, 1, MPI_INT, MPI_MIN, world);
  MPI_Bcast(values_of_first, n, MPI_DOUBLE, owner, world);
  return static_cast<int>(first & 0xffffffffLL);
}

} // namespace rank_choice

#endif

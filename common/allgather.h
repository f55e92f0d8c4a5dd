#ifndef LIGGGHTS_MEMBRANE_ALLGATHER_H
#define LIGGGHTS_MEMBRANE_ALLGATHER_H

#include <mpi.h>
#include <vector>

// Concatenate every rank's send buffer, in rank order, on every rank. Both
// styles work on small gathered sets (contacts, a side band) so that every
// rank computes identical results in an identical order. The buffers are
// kept by the caller so a step allocates nothing once they have grown. Returns the
// bytes this rank received: the values and every rank's count.
inline double allgather_doubles(MPI_Comm comm, const std::vector<double> &send,
                              std::vector<double> &recv, std::vector<int> &counts,
                              std::vector<int> &displs)
{
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  counts.resize(nprocs);
  displs.resize(nprocs);
  int nsend = static_cast<int>(send.size());
  MPI_Allgather(&nsend, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  recv.resize(total);
  MPI_Allgatherv(const_cast<double *>(send.data()), nsend, MPI_DOUBLE, recv.data(), counts.data(),
                 displs.data(), MPI_DOUBLE, comm);
  return sizeof(double) * static_cast<double>(total) + sizeof(int) * static_cast<double>(nprocs);
}

#endif

/* ----------------------------------------------------------------------
   The contacts compute fabric reads, on each rank its own: found in
   LIGGGHTS' compute pair/gran/local (particle-particle) and wall/gran/local
   (particle-mesh wall), kept when both ends are selected and counted on
   exactly one rank (see collect). No rank holds another rank's contacts:
   the sample statistics are partial sums (fabric_sums.h) merged with
   MPI_Allreduce (reduce), and the contact angles of the disks a rank owns
   come from its own contacts plus those of their ghost copies on other
   ranks (a reverse communication, exchange_ends). See
   doc/compute_fabric.md, "How contact forces are obtained" and "Parallel
   computation".
------------------------------------------------------------------------- */

#ifndef LIGGGHTS_MEMBRANE_FABRIC_LOCAL_H
#define LIGGGHTS_MEMBRANE_FABRIC_LOCAL_H

#include <mpi.h>

#include <string>
#include <vector>

#include "fabric_sums.h"
#include "fabric_tensors3d.h"
#include "gran_local_sources.h"
#include "pointers.h"

namespace LAMMPS_NS {

class Atom;
class Compute;
class ComputePairGranLocal;
class Region;

// Local atom i counts when it is in the group (groupbit) and, with a region,
// its centre is inside it.
bool atom_selected(const Atom *atom, int i, int groupbit, Region *region);

class FabricLocal : protected Pointers {
 public:
  // `fabric_compute`: the compute fabric it works for (its ID and group name the
  // messages and the computes it creates, ID_contacts and ID_walls); it must
  // have comm_reverse = END_SLOTS and pass its reverse communication to
  // pack_ends / unpack_ends; `prefix` starts its messages (style_prefix())
  FabricLocal(LAMMPS *lammps, Compute *fabric_compute, const std::string &prefix);
  ~FabricLocal();
  FabricLocal(const FabricLocal &) = delete;
  FabricLocal &operator=(const FabricLocal &) = delete;

  static constexpr int END_SLOTS = 8; // doubles per atom in one reverse communication

  // at every init: the computes to read (created when there are none); with
  // walls, an error without a mesh wall
  void init(bool with_walls);

  // this rank's contacts between selected particles (with walls: and a wall),
  // a = the smaller tag, and the contact count of their ends by local index
  // (ghosts included) -- with_angles: also their contact angles --, then one
  // round of sending the ghosts' counts (angles) to their owners; 1 if this rank
  // has angles left to send (then finish_ends), else 0. The same with_angles on
  // every rank.
  int collect(Region *region, bool with_angles);
  // the rounds until no rank has angles left (collective)
  void finish_ends();
  const std::vector<fabric::Contact> &contacts() const { return local; }    // in 2D
  const std::vector<fabric::Contact3> &contacts3() const { return local3; } // in 3D
  // atan2(ny, nx) of each contact (NaN without a normal), after a collect
  // with_angles (else empty)
  const std::vector<double> &angles() const { return theta; }

  // the number of counted contacts of owned atom i < nlocal, those seen on other
  // ranks included, and (after a collect with_angles) their angles (NaN: no normal)
  int count_of(int i) const { return counts[i]; }
  const std::vector<double> &ends_of(int i) const { return ends[i]; }

  // merge the ranks' partial sums (pairs of doubles, see fabric_sums.h) in place,
  // the same result on every rank
  void reduce(std::vector<double> &packed);
  // both sums at once, and whether any rank had angles `left` (collect)
  bool reduce(fabric::FabricSums &sums, fabric::ParticleSums &particles, int left);

  // the warning (by rank 0) that `count` contacts have no normal, naming the one
  // with the smallest (tag a, tag b) over all ranks and `count_output`, the
  // output that counts them (collective; call only when there is one)
  void warn_missing_normals(long count, const std::string &count_output);

  int pack_ends(int n, int first, double *buf);
  void unpack_ends(int n, const int *list, const double *buf);

  double memory_usage() const;

 private:
  // a contact without a normal: its tags and the length of its branch vector
  struct MissingNormal {
    long a, b;
    double length;
  };

  Compute *owner; // the compute fabric
  std::string prefix;
  bool three_d; // domain->dimension == 3: contacts3(), else contacts()
  GranLocalSources sources;
  std::vector<fabric::Contact> local;
  std::vector<fabric::Contact3> local3;
  std::vector<MissingNormal> missing;
  std::vector<double> theta;             // per contact, see angles()
  bool with_angles = false;              // of the last collect
  std::vector<int> counts;               // contact ends by local index, up to nall
  std::vector<std::vector<double>> ends; // their angles, with_angles
  std::vector<int> sent;                 // ends of a ghost already sent to its owner
  MPI_Datatype pair_type;                // (hi, lo) of an ExactSum
  MPI_Op merge_op;

  void add_rows(ComputePairGranLocal *source, bool wall, Region *region);
  void add_contact(const fabric::Contact &c, int index_a, int index_b);
  void add_contact3(const fabric::Contact3 &c, int index_a, int index_b);
  int send_ends_round();
};

} // namespace LAMMPS_NS

#endif

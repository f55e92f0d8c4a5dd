/* ----------------------------------------------------------------------
   The contacts compute fabric reads, on every rank: found in LIGGGHTS'
   compute pair/gran/local (particle-particle) and wall/gran/local
   (particle-mesh wall), kept when both ends are selected, gathered from
   all ranks and sorted by tags (contact_record.h) so that every rank holds
   the same list in the same order. See doc/compute_fabric.md, "How contact
   forces are obtained" and "Rank-independent gathering".
------------------------------------------------------------------------- */

#ifndef LIGGGHTS_MEMBRANE_FABRIC_GATHER_H
#define LIGGGHTS_MEMBRANE_FABRIC_GATHER_H

#include <vector>

#include "fabric_statistics.h"
#include "pointers.h"

namespace LAMMPS_NS {

class Atom;
class Compute;
class ComputePairGranLocal;
class Region;

// Local atom i counts when it is in the group (groupbit) and, with a region,
// its centre is inside it.
bool atom_selected(const Atom *atom, int i, int groupbit, Region *region);

class FabricGather : protected Pointers {
 public:
  // `fabric_compute`: the compute fabric it gathers for (its ID and group name the
  // messages and the computes it creates, ID_contacts and ID_walls)
  FabricGather(LAMMPS *lammps, Compute *fabric_compute);
  ~FabricGather();
  FabricGather(const FabricGather &) = delete;
  FabricGather &operator=(const FabricGather &) = delete;

  // at every init: the computes to read (created when there are none); with
  // walls, an error without a mesh wall
  void init(bool with_walls);

  // the contacts between selected particles (with walls: and a wall), sorted
  // by (tag a, tag b) with a < b, the same on every rank
  std::vector<fabric::Contact> gather(Region *region);

  // the selected particles on all ranks
  long count_particles(Region *region) const;

  double memory_usage() const;

 private:
  struct ContactSource {
    const char *style;
    char *id = nullptr; // the user's compute, or ours
    ComputePairGranLocal *compute = nullptr;
  };

  Compute *owner; // the compute fabric
  ContactSource pairs{"pair/gran/local"}, walls{"wall/gran/local"};
  std::vector<double> sendbuf, recvbuf;
  std::vector<int> recvcounts, displs;

  void find_source(ContactSource &src);
  void create_source(ContactSource &src, const char *suffix);
  void init_source(ContactSource &src, const char *suffix);
  void pack_contacts(const ContactSource &src, bool wall, Region *region);
};

} // namespace LAMMPS_NS

#endif

/* ----------------------------------------------------------------------
   The LIGGGHTS computes compute fabric reads its contacts from: compute
   pair/gran/local (particle-particle) and, with walls yes, wall/gran/local
   (particle-mesh wall), the user's or created by us (see init).
------------------------------------------------------------------------- */

#ifndef LIGGGHTS_MEMBRANE_GRAN_LOCAL_SOURCES_H
#define LIGGGHTS_MEMBRANE_GRAN_LOCAL_SOURCES_H

#include <string>

#include "pointers.h"

namespace LAMMPS_NS {

class Compute;
class ComputePairGranLocal;

class GranLocalSources : protected Pointers {
 public:
  // `fabric_compute`: the compute fabric they serve (its ID names the computes
  // created, ID_contacts and ID_walls, and its group the messages, which start
  // with `prefix`, style_prefix())
  GranLocalSources(LAMMPS *lammps, Compute *fabric_compute, const std::string &prefix);
  ~GranLocalSources();
  GranLocalSources(const GranLocalSources &) = delete;
  GranLocalSources &operator=(const GranLocalSources &) = delete;

  // at every init: find or create the computes; with walls, an error without
  // a mesh wall
  void init(bool with_walls);
  ComputePairGranLocal *pairs() const { return pairs_.compute; }
  ComputePairGranLocal *walls() const { return walls_.compute; } // nullptr: walls no

 private:
  struct ContactSource {
    const char *style;
    char *id = nullptr; // the user's compute, or ours
    ComputePairGranLocal *compute = nullptr;
  };

  Compute *owner;
  std::string prefix;
  ContactSource pairs_{"pair/gran/local"}, walls_{"wall/gran/local"};

  void find_source(ContactSource &src);
  void create_source(ContactSource &src, const char *suffix);
  void init_source(ContactSource &src, const char *suffix);
};

} // namespace LAMMPS_NS

#endif

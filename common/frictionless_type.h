#ifndef LIGGGHTS_MEMBRANE_FRICTIONLESS_TYPE_H
#define LIGGGHTS_MEMBRANE_FRICTIONLESS_TYPE_H

// The keyword 'frictionless T' of the membrane styles: the membrane's particles wear
// atom type T, which must have no friction with any type (checked at every run).
// `which`: what keeps its friction without the keyword ("chain disks", ...).

#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_property_global.h"
#include "lammps.h"
#include "modify.h"

inline void check_frictionless_type(LAMMPS_NS::LAMMPS *lmp, const char *prefix, int type,
                                    const char *style, const char *which)
{
  if (type <= 0) {
    if (lmp->comm->me == 0)
      lmp->error->warning(FLERR, (std::string(prefix) + "no 'frictionless' type given: " + which +
                                  " keep their friction")
                                     .c_str());
    return;
  }
  const int ntypes = lmp->atom->ntypes;
  LAMMPS_NS::FixPropertyGlobal *mu = static_cast<LAMMPS_NS::FixPropertyGlobal *>(
      lmp->modify->find_fix_property("coefficientFriction", "property/global", "peratomtypepair",
                                     ntypes, ntypes, const_cast<char *>(style)));
  for (int j = 1; j <= ntypes; j++) {
    const double value = mu->compute_array(type - 1, j - 1);
    if (value != 0.0)
      lmp->error->all(FLERR,
                      (std::string(prefix) + "coefficientFriction of the frictionless type " +
                       std::to_string(type) + " with type " + std::to_string(j) + " is " +
                       std::to_string(value) + ", it must be 0")
                          .c_str());
  }
}

#endif

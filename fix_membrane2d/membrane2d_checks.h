#ifndef LIGGGHTS_MEMBRANE_MEMBRANE2D_CHECKS_H
#define LIGGGHTS_MEMBRANE_MEMBRANE2D_CHECKS_H

// The checks of fix membrane2d's own input against the LIGGGHTS state (those it
// shares with fix membrane3d: membrane/membrane_checks.h). Each stops the run on
// every rank at once with a message that starts with `prefix`.

#include <string>

#include "lammps.h"

#include "membrane_gather.h"
#include "scalar_input.h"

// The band width is a length this D50 can use.
void check_band(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, double band, double d50);
// The platens enclose every disk centre of the group.
void check_platens_enclose(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                           MembraneGather &gather, const ScalarInput &ylo_in, double ylo,
                           const ScalarInput &yhi_in, double yhi);

#endif

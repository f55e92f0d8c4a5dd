// What both membranes need of LIGGGHTS' atoms and box, checked in each fix's
// constructor with one message per problem (doc/messages.md): the dimension, per-atom
// radii, atom IDs with a map (the membrane is kept by atom ID), and no periodic
// boundary across the sample. A periodic boundary that cuts the sample would give the
// membrane wrapped positions, two half-samples with the membrane's load on the seam
// inside the sample; periodic along the platens' axis, the platens bound nothing.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_SETUP_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_SETUP_H

#include <string>

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lammps.h"

inline void check_membrane_setup(LAMMPS_NS::LAMMPS *lmp, const char *prefix, int dimension)
{
  const auto stop = [&](const std::string &text) {
    lmp->error->all(FLERR, (std::string(prefix) + text).c_str());
  };
  const bool three = dimension == 3;
  if (lmp->domain->dimension != dimension)
    stop(three ? "requires dimension 3; for 2D samples use fix membrane2d"
               : "requires dimension 2; for 3D samples use fix membrane3d");
  if (!lmp->atom->radius_flag) stop("requires atom style sphere; use atom_style granular");
  if (lmp->atom->tag_enable == 0 || lmp->atom->map_style == 0)
    stop("requires atom IDs and an atom map; use atom_modify map array");
  // the lateral axes (x; x and y) and the platens' axis (y; z)
  const std::string boundary = three ? "boundary f f f (or m m f)" : "boundary f f p (or m f p)";
  const int periodic[3] = {lmp->domain->xperiodic, lmp->domain->yperiodic,
                           lmp->domain->zperiodic};
  const int platen_axis = three ? 2 : 1;
  for (int axis = 0; axis < platen_axis; axis++)
    if (periodic[axis])
      stop(std::string("the box is periodic in ") + "xyz"[axis] +
           "; the sample would wrap across the boundary, cut in two with the membrane's load "
           "on the seam: use " + boundary);
  if (periodic[platen_axis])
    stop(std::string("the box is periodic in ") + "xyz"[platen_axis] +
         "; the platens bound the sample in " + "xyz"[platen_axis] + ": use " + boundary);
}

#endif

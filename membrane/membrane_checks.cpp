#include "membrane_checks.h"

#include <mpi.h>

#include <cmath>
#include <cstring>

#include "atom.h"
#include "domain.h"
#include "fix_property_global.h"
#include "modify.h"
#include "update.h"

#include "frame_files.h"
#include "membrane_fix.h"
#include "style_args.h"
#include "style_error.h"
#include "vtk_series.h"

using namespace LAMMPS_NS;

void check_membrane_setup(LAMMPS *lmp, const std::string &prefix, int dimension)
{
  const auto stop = [&](const std::string &text) { style_error(lmp, prefix, text); };
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

void check_frictionless_type(LAMMPS *lmp, const std::string &prefix, int type, const char *style,
                             const std::string &which)
{
  if (type <= 0) {
    style_warning(lmp, prefix, "no 'frictionless' type given: " + which + " keep their friction");
    return;
  }
  const int ntypes = lmp->atom->ntypes;
  auto *mu = static_cast<FixPropertyGlobal *>(
      lmp->modify->find_fix_property("coefficientFriction", "property/global", "peratomtypepair",
                                     ntypes, ntypes, const_cast<char *>(style)));
  for (int j = 1; j <= ntypes; j++) {
    const double value = mu->compute_array(type - 1, j - 1);
    if (value != 0.0)
      style_error(lmp, prefix,
                  "coefficientFriction of the frictionless type " + std::to_string(type) +
                      " with type " + std::to_string(j) + " is " + std::to_string(value) +
                      ", it must be 0");
  }
}

// Two membranes on one particle would press it twice and fight over its type; two on
// one file would overwrite each other's frames.
void check_other_membranes(LAMMPS *lmp, const std::string &prefix, MembraneFix *self)
{
  Modify *modify = lmp->modify;
  Atom *atom = lmp->atom;
  for (int f = 0; f < modify->nfix; f++) {
    auto *other = dynamic_cast<MembraneFix *>(modify->fix[f]);
    if (!other || other == self || strcmp(other->style, self->style) != 0) continue;
    double shared = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & self->groupbit) && (atom->mask[i] & other->groupbit)) shared += 1.0;
    MPI_Allreduce(MPI_IN_PLACE, &shared, 1, MPI_DOUBLE, MPI_SUM, lmp->world);
    const bool first = f < modify->find_fix(self->id);
    const std::string pair = std::string("fixes '") + (first ? other->id : self->id) +
                             "' and '" + (first ? self->id : other->id) + "' ";
    const std::string particles = self->traits.particles;
    if (shared > 0.0)
      style_error(lmp, prefix,
                  pair + "are both " + self->style + " on " + number_text(shared) + " " +
                      particles + ": one membrane per sample (unfix one; two samples need " +
                      "groups with no " + particles.substr(0, particles.size() - 1) +
                      " in common)");
    for (const auto &mine : self->frame_files())
      for (const auto &theirs : other->frame_files())
        if (mine.first == theirs.first && vtk_series::same_file(mine.second, theirs.second))
          style_error(lmp, prefix,
                      pair + "both write " + mine.first + " frames to '" + mine.second +
                          "': give each fix its own file");
  }
}

void same_on_every_rank(LAMMPS *lmp, const std::string &prefix,
                        const ScalarInput *const (&inputs)[3], const char *const (&names)[3],
                        double (&v)[3], bool &warned)
{
  // the largest of v and of -v in one reduction (this runs at every step)
  double mine[6] = {v[0], v[1], v[2], -v[0], -v[1], -v[2]}, most[6];
  MPI_Allreduce(mine, most, 6, MPI_DOUBLE, MPI_MAX, lmp->world);
  MPI_Bcast(v, 3, MPI_DOUBLE, 0, lmp->world);
  for (int k = 0; k < 3; k++) {
    const double spread = most[k] + most[k + 3]; // largest minus smallest
    if (warned || !(spread > 1e-12 * std::fabs(v[k]))) continue;
    warned = true;
    style_warning(lmp, prefix,
                  keyword_text(names[k], inputs[k]->text(),
                                  "differs between the ranks by " + number_text(spread) +
                                      " at step " + std::to_string(lmp->update->ntimestep) +
                                      "; rank 0's value is used (a mesh's reference point "
                                      "f_ID[7..9] lags a step on some ranks)"));
  }
}

void check_platens_in_order(LAMMPS *lmp, const std::string &prefix, const char *lo_key,
                            const ScalarInput &lo_in, double lo, const char *hi_key,
                            const ScalarInput &hi_in, double hi)
{
  if (lo < hi) return;
  const std::string l = lo_key, h = hi_key;
  style_error(lmp, prefix,
              "keywords '" + l + "' = " + lo_in.text() + " and '" + h + "' = " + hi_in.text() +
                  ": " + l + " is " + number_text(lo) + ", not below " + h + " = " +
                  number_text(hi) + " at step " + std::to_string(lmp->update->ntimestep) + "; " +
                  l + " is the lower platen surface, " + h + " the upper one");
}

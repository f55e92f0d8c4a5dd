#include "membrane3d_checks.h"

#include <mpi.h>

#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include "fix_membrane3d.h"
#include "style_args.h"

using namespace LAMMPS_NS;

// Two membranes on one sphere would press it twice; two on one file would overwrite
// each other's frames.
void check_other_membranes(LAMMPS *lmp, const char *prefix, Fix *self)
{
  Modify *modify = lmp->modify;
  Atom *atom = lmp->atom;
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == self || strcmp(other->style, self->style) != 0) continue;
    double shared = 0.0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & self->groupbit) && (atom->mask[i] & other->groupbit)) shared += 1.0;
    MPI_Allreduce(MPI_IN_PLACE, &shared, 1, MPI_DOUBLE, MPI_SUM, lmp->world);
    const bool first = f < modify->find_fix(self->id);
    const std::string pair = std::string(prefix) + "fixes '" + (first ? other->id : self->id) +
                             "' and '" + (first ? self->id : other->id) + "' ";
    const std::string mine = static_cast<FixMembrane3d *>(self)->vtk_file();
    if (!mine.empty() && mine == static_cast<FixMembrane3d *>(other)->vtk_file())
      lmp->error->all(FLERR, (pair + "both write vtk frames to '" + mine +
                              "': give each fix its own file")
                                 .c_str());
    if (shared > 0.0)
      lmp->error->all(FLERR, (pair + "are both membrane3d on " + number_text(shared) +
                              " spheres: one membrane per sample (unfix one; two samples need "
                              "groups with no sphere in common)")
                                 .c_str());
  }
}

void check_ranks_agree(LAMMPS *lmp, const char *prefix, const std::vector<int> &member_tags,
                       std::size_t facets)
{
  double mine[3] = {static_cast<double>(member_tags.size()), static_cast<double>(facets), 0.0};
  for (int tag : member_tags) mine[2] += tag;
  double lo[3], hi[3];
  MPI_Allreduce(mine, lo, 3, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(mine, hi, 3, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (lo[0] != hi[0] || lo[1] != hi[1] || lo[2] != hi[2])
    lmp->error->all(FLERR, (std::string(prefix) + "the ranks found different membranes at step " +
                            std::to_string(lmp->update->ntimestep) + " (members " +
                            number_text(lo[0]) + " to " + number_text(hi[0]) + ", facets " +
                            number_text(lo[1]) + " to " + number_text(hi[1]) +
                            "); please report this with the input script")
                               .c_str());
}

void same_on_every_rank(LAMMPS *lmp, const char *prefix, const ScalarInput *const (&inputs)[3],
                        std::initializer_list<const char *> names, double (&v)[3], bool &warned)
{
  double lo[3], hi[3];
  MPI_Allreduce(v, lo, 3, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(v, hi, 3, MPI_DOUBLE, MPI_MAX, lmp->world);
  MPI_Bcast(v, 3, MPI_DOUBLE, 0, lmp->world);
  int k = 0;
  for (const char *name : names) {
    const double spread = hi[k] - lo[k];
    if (!warned && spread > 1e-12 * std::fabs(v[k])) {
      warned = true;
      if (lmp->comm->me == 0)
        lmp->error->warning(
            FLERR, keyword_message(prefix, name, inputs[k]->text(),
                                   "differs between the ranks by " + number_text(spread) +
                                       " at step " + std::to_string(lmp->update->ntimestep) +
                                       "; rank 0's value is used (a mesh's reference point "
                                       "f_ID[7..9] lags a step on some ranks)")
                .c_str());
    }
    k++;
  }
}

void check_between_platens(LAMMPS *lmp, const char *prefix, const GatheredSpheres &g,
                           const membrane3d::Platens &platens)
{
  for (std::size_t k = 0; k < g.spheres.size(); k++) {
    const double z = g.spheres[k].x.z();
    if (z > platens.lo && z < platens.hi) continue;
    lmp->error->all(FLERR, (std::string(prefix) + "atom " + std::to_string(g.tags[k]) +
                            " at z = " + number_text(z) + " is not between zlo = " +
                            number_text(platens.lo) + " and zhi = " + number_text(platens.hi) +
                            " at step " + std::to_string(lmp->update->ntimestep) +
                            "; the platens must enclose every sphere centre of the group")
                               .c_str());
  }
}

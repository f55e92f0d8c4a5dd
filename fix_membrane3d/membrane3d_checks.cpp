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

#include "atom_faults.h"

#include "fix_membrane3d.h"
#include "style_args.h"
#include "vtk_series.h"

using namespace LAMMPS_NS;

namespace {
// The lateral net load of a closed membrane, relative to the sum of the loads' sizes:
// zero but for the round-off of summing them.
const double CLOSURE_ROUND_OFF = 1e-9;
} // namespace

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
    if (vtk_series::same_file(mine, static_cast<FixMembrane3d *>(other)->vtk_file()))
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
    const membrane3d::Sphere &s = g.spheres[k];
    // a fault of the input (a run gone unstable, a radius set to 0) named as such
    if (atom_is_faulty(s.x.data(), 3, s.r))
      lmp->error->all(FLERR, (std::string(prefix) + atom_fault_text(g.tags[k], s.x.data(), 3, s.r,
                                                                    lmp->update->ntimestep))
                                 .c_str());
    const double z = s.x.z();
    if (z > platens.lo && z < platens.hi) continue;
    lmp->error->all(FLERR, (std::string(prefix) + "atom " + std::to_string(g.tags[k]) +
                            " at z = " + number_text(z) + " is not between zlo = " +
                            number_text(platens.lo) + " and zhi = " + number_text(platens.hi) +
                            " at step " + std::to_string(lmp->update->ntimestep) +
                            "; the platens must enclose every sphere centre of the group")
                               .c_str());
  }
}

void check_enough_spheres(LAMMPS *lmp, const char *prefix, const char *group, std::size_t spheres)
{
  if (spheres >= 4) return;
  lmp->error->all(FLERR, (std::string(prefix) + "the group '" + group + "' has " +
                          count_text(spheres, "atom", "atoms") + " at step " +
                          std::to_string(lmp->update->ntimestep) +
                          "; a membrane needs a sample of at least four spheres (were atoms lost "
                          "from the box?)")
                             .c_str());
}

void warn_if_open(LAMMPS *lmp, const char *prefix, const membrane3d::LateralSurface &membrane,
                  bool &warned)
{
  if (membrane.reaches_lo && membrane.reaches_hi) return;
  if (!warned && lmp->comm->me == 0)
    lmp->error->warning(FLERR, (std::string(prefix) + "the membrane does not reach the " +
                                (!membrane.reaches_lo ? "lower (zlo)" : "upper (zhi)") +
                                " platen at step " + std::to_string(lmp->update->ntimestep) +
                                ": no sphere is within the tolerance of it, so the membrane "
                                "closes over that end of the sample and presses on it")
                                   .c_str());
  warned = true;
}

void check_platens_in_order(LAMMPS *lmp, const char *prefix, const ScalarInput &lo,
                            const ScalarInput &hi, const membrane3d::Platens &platens)
{
  if (platens.lo < platens.hi) return;
  lmp->error->all(FLERR, (std::string(prefix) + "keywords 'zlo' = " + lo.text() + " and 'zhi' = " +
                          hi.text() + ": zlo is " + number_text(platens.lo) +
                          ", not below zhi = " + number_text(platens.hi) + " at step " +
                          std::to_string(lmp->update->ntimestep) +
                          "; zlo is the lower platen surface, zhi the upper one")
                             .c_str());
}

void check_tolerance(LAMMPS *lmp, const char *prefix, const std::string &text, double tolerance,
                     double d, double most, double usual)
{
  if (!(tolerance > most * d)) return;
  lmp->error->all(FLERR, keyword_message(prefix, "tolerance", text,
                                         "is " + number_text(tolerance / d) +
                                             " x the group's mean diameter d = " + number_text(d) +
                                             "; the largest gap at which two spheres are linked "
                                             "is a length of at most " + number_text(most) +
                                             " x d (wider ones bridge the hollows of the "
                                             "sample's surface), usually " + number_text(usual) +
                                             " x d = " + number_text(usual * d) + " (the default)")
                             .c_str());
}

Eigen::Vector3d check_closed(LAMMPS *lmp, const char *prefix, const std::vector<Eigen::Vector3d> &load,
                             double pressure)
{
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  double magnitude = 0.0;
  for (const Eigen::Vector3d &f : load) {
    net += f;
    magnitude += f.norm();
  }
  const auto step = [lmp] { return std::to_string(lmp->update->ntimestep); }; // errors only
  // loads that overflow (an absurd pressure) are the input's fault, not the membrane's
  if (!std::isfinite(magnitude) && std::isfinite(pressure))
    lmp->error->all(FLERR, (std::string(prefix) + "the membrane's loads at step " + step() +
                            " are not finite: the pressure " + number_text(pressure) +
                            " times the facets' areas overflows; give the confining pressure in "
                            "the units of the box (force/area)")
                               .c_str());
  // a load that is not finite fails the test too (NaN compares false with everything)
  if (!(net.head<2>().norm() <= CLOSURE_ROUND_OFF * magnitude) || !std::isfinite(magnitude))
    lmp->error->all(FLERR, (std::string(prefix) + "the membrane's loads have a lateral net force of " +
                            number_text(net.head<2>().norm()) + " N (of " + number_text(magnitude) +
                            " N in all) at step " + step() +
                            (net.allFinite() ? ": the membrane is not closed" : ": a load is not finite") +
                            "; this is a fault of fix membrane3d; please report it with the input script")
                               .c_str());
  return net;
}

void warn_if_moved(LAMMPS *lmp, const char *prefix, const GatheredSpheres &now,
                   std::vector<membrane3d::Sphere> &at, double tolerance, long long since,
                   bool &warned)
{
  if (warned) return;
  if (at.size() != now.spheres.size()) {
    at = now.spheres;
    return;
  }
  std::size_t farthest = 0;
  double most = 0.0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    const double moved = (now.spheres[k].x - at[k].x).norm();
    if (moved > most) {
      most = moved;
      farthest = k;
    }
  }
  if (!(most > tolerance)) return;
  warned = true;
  if (lmp->comm->me == 0)
    lmp->error->warning(FLERR, (std::string(prefix) + "membrane sphere " +
                                std::to_string(now.tags[farthest]) + " has moved " +
                                number_text(most) + " since the membrane was found at step " +
                                std::to_string(since) + ", more than the tolerance " +
                                number_text(tolerance) + " (at step " +
                                std::to_string(lmp->update->ntimestep) +
                                "): that membrane can be out of date; find it more often "
                                "(a smaller every, or every auto)")
                                   .c_str());
}

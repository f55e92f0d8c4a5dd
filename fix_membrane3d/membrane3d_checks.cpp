#include "membrane3d_checks.h"

#include <mpi.h>

#include <cmath>
#include <string>

#include "atom.h"
#include "comm.h"
#include "update.h"

#include "atom_faults.h"

#include "membrane3d_tuning.h"
#include "style_error.h"
#include "style_args.h"

using namespace LAMMPS_NS;

using membrane3d::CLOSURE_ROUND_OFF;

void check_ranks_agree(LAMMPS *lmp, const char *prefix, const std::vector<int> &member_tags,
                       std::size_t facets)
{
  double mine[3] = {static_cast<double>(member_tags.size()), static_cast<double>(facets), 0.0};
  for (int tag : member_tags) mine[2] += tag;
  double lo[3], hi[3];
  MPI_Allreduce(mine, lo, 3, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(mine, hi, 3, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (lo[0] != hi[0] || lo[1] != hi[1] || lo[2] != hi[2])
    style_error(lmp, prefix, "the ranks found different membranes at step " +
                            std::to_string(lmp->update->ntimestep) + " (members " +
                            number_text(lo[0]) + " to " + number_text(hi[0]) + ", facets " +
                            number_text(lo[1]) + " to " + number_text(hi[1]) +
                            "); please report this with the input script");
}

void check_between_platens(LAMMPS *lmp, const char *prefix, const GatheredSpheres &g,
                           const membrane3d::Platens &platens)
{
  for (std::size_t k = 0; k < g.spheres.size(); k++) {
    const membrane3d::Sphere &s = g.spheres[k];
    // a fault of the input (a run gone unstable, a radius set to 0) named as such
    if (atom_is_faulty(s.x.data(), 3, s.r))
      style_error(lmp, prefix, atom_fault_text(g.tags[k], s.x.data(), 3, s.r,
                                                                    lmp->update->ntimestep));
    const double z = s.x.z();
    if (z > platens.lo && z < platens.hi) continue;
    style_error(lmp, prefix, "atom " + std::to_string(g.tags[k]) +
                            " at z = " + number_text(z) + " is not between zlo = " +
                            number_text(platens.lo) + " and zhi = " + number_text(platens.hi) +
                            " at step " + std::to_string(lmp->update->ntimestep) +
                            "; the platens must enclose every sphere centre of the group");
  }
}

void check_enough_spheres(LAMMPS *lmp, const char *prefix, const char *group, std::size_t spheres)
{
  if (spheres >= 4) return;
  style_error(lmp, prefix, std::string("the group '") + group + "' has " +
                          count_text(spheres, "atom", "atoms") + " at step " +
                          std::to_string(lmp->update->ntimestep) +
                          "; a membrane needs a sample of at least four spheres (were atoms lost "
                          "from the box?)");
}

void warn_if_open(LAMMPS *lmp, const char *prefix, const membrane3d::LateralSurface &membrane,
                  bool &warned)
{
  if (membrane.reaches_lo && membrane.reaches_hi) return;
  if (!warned)
    style_warning(lmp, prefix, std::string("the membrane does not reach the ") +
                                (!membrane.reaches_lo ? "lower (zlo)" : "upper (zhi)") +
                                " platen at step " + std::to_string(lmp->update->ntimestep) +
                                ": no sphere is within the tolerance of it, so the membrane "
                                "closes over that end of the sample and presses on it");
  warned = true;
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
    style_error(lmp, prefix, "the membrane's loads at step " + step() +
                            " are not finite: the pressure " + number_text(pressure) +
                            " times the facets' areas overflows; give the confining pressure in "
                            "the units of the box (force/area)");
  // a load that is not finite fails the test too (NaN compares false with everything)
  if (!(net.head<2>().norm() <= CLOSURE_ROUND_OFF * magnitude) || !std::isfinite(magnitude))
    style_error(lmp, prefix, "the membrane's loads have a lateral net force of " +
                            number_text(net.head<2>().norm()) + " N (of " + number_text(magnitude) +
                            " N in all) at step " + step() +
                            (net.allFinite() ? ": the membrane is not closed" : ": a load is not finite") +
                            "; this is a fault of fix membrane3d; please report it with the input script");
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
  style_warning(lmp, prefix, "membrane sphere " +
                                std::to_string(now.tags[farthest]) + " has moved " +
                                number_text(most) + " since the membrane was found at step " +
                                std::to_string(since) + ", more than the tolerance " +
                                number_text(tolerance) + " (at step " +
                                std::to_string(lmp->update->ntimestep) +
                                "): that membrane can be out of date; find it more often "
                                "(a smaller every, or every auto)");
}

#include "membrane3d_messages.h"

#include <cmath>

#include "membrane3d_tuning.h"
#include "number_text.h"

namespace membrane3d {

std::string platens_problem(AtomId tag, double z, const Platens &platens, long long step)
{
  if (z > platens.lo && z < platens.hi) return "";
  return "atom " + std::to_string(tag) + " at z = " + number_text(z) +
         " is not between zlo = " + number_text(platens.lo) +
         " and zhi = " + number_text(platens.hi) + " at step " + std::to_string(step) +
         "; the platens must enclose every sphere centre of the group";
}

std::string too_few_spheres(const std::string &group, std::size_t spheres, long long step)
{
  if (spheres >= 4) return "";
  return "the group '" + group + "' has " + count_text(spheres, "atom", "atoms") + " at step " +
         std::to_string(step) +
         "; a membrane needs a sample of at least four spheres (were atoms lost from the box?)";
}

std::string open_warning(const LateralSurface &membrane, long long step)
{
  if (membrane.reaches_lo && membrane.reaches_hi) return "";
  return std::string("the membrane does not reach the ") +
         (!membrane.reaches_lo ? "lower (zlo)" : "upper (zhi)") + " platen at step " +
         std::to_string(step) +
         ": no sphere is within the tolerance of it, so the membrane closes over that end of "
         "the sample and presses on it";
}

std::string closure_problem(const std::vector<Eigen::Vector3d> &load, double pressure,
                            long long step, Eigen::Vector3d &net)
{
  net = Eigen::Vector3d::Zero();
  double magnitude = 0.0;
  for (const Eigen::Vector3d &f : load) {
    net += f;
    magnitude += f.norm();
  }
  return closure_problem(net, magnitude, pressure, step);
}

std::string closure_problem(const Eigen::Vector3d &net, double magnitude, double pressure,
                            long long step)
{
  // loads that overflow (an absurd pressure) are the input's fault, not the membrane's
  if (!std::isfinite(magnitude) && std::isfinite(pressure))
    return "the membrane's loads at step " + std::to_string(step) +
           " are not finite: the pressure " + number_text(pressure) +
           " times the facets' areas overflows; give the confining pressure in the units of "
           "the box (force/area)";
  // a load that is not finite fails the test too (NaN compares false with everything)
  if (net.head<2>().norm() <= CLOSURE_ROUND_OFF * magnitude && std::isfinite(magnitude)) return "";
  return "the membrane's loads have a lateral net force of " + number_text(net.head<2>().norm()) +
         " N (of " + number_text(magnitude) + " N in all) at step " + std::to_string(step) +
         (net.allFinite() ? ": the membrane is not closed" : ": a load is not finite") +
         "; this is a fault of fix membrane3d; please report it with the input script";
}

std::string moved_warning(const GatheredSpheres &now, std::vector<Sphere> &at, double tolerance,
                          long long since, long long step)
{
  if (at.size() != now.spheres.size()) {
    at = now.spheres;
    return "";
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
  if (!(most > tolerance)) return ""; // (none at all: no member to name)
  return moved_warning(now.tags[farthest], most, tolerance, since, step);
}

std::string moved_warning(AtomId tag, double moved, double tolerance, long long since,
                          long long step)
{
  if (!(moved > tolerance)) return "";
  return "membrane sphere " + std::to_string(tag) + " has moved " + number_text(moved) +
         " since the membrane was found at step " + std::to_string(since) +
         ", more than the tolerance " + number_text(tolerance) + " (at step " +
         std::to_string(step) +
         "): that membrane can be out of date; find it more often (a smaller every, or every "
         "auto)";
}

std::string ranks_disagree(const double (&lo)[3], const double (&hi)[3], long long step)
{
  if (lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) return "";
  return "the ranks found different membranes at step " + std::to_string(step) + " (members " +
         number_text(lo[0]) + " to " + number_text(hi[0]) + ", facets " + number_text(lo[1]) +
         " to " + number_text(hi[1]) + "); please report this with the input script";
}

} // namespace membrane3d

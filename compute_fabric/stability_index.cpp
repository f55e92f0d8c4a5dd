#include "stability_index.h"

#include "particle_contacts.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fabric {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// fmod is exact and slow; the fast paths below give its result bit for bit
double wrap_to_full_turn(double angle)
{
  double wrapped = std::fabs(angle) < kTwoPi ? angle : std::fmod(angle, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  if (wrapped >= kTwoPi) wrapped = 0.0; // -tiny + 2pi can round up to 2pi
  return wrapped;
}

double circular_distance(double alpha, double beta)
{
  // |fmod(x, 2 pi)| = fmod(|x|, 2 pi); for 2 pi <= |x| < 4 pi that is |x| - 2 pi,
  // exact by Sterbenz's lemma (here |x| < 4 pi: both angles in [0, 4 pi))
  double d = std::fabs(alpha - beta);
  if (d >= kTwoPi) d = d < 2.0 * kTwoPi ? d - kTwoPi : std::fmod(d, kTwoPi);
  return std::min(d, kTwoPi - d);
}

// Misfit of the sorted contacts against the even arrangement anchored at one of them.
double misfit_from_anchor(const std::vector<double> &sorted, std::size_t anchor)
{
  const std::size_t n = sorted.size();
  const double spacing = kTwoPi / static_cast<double>(n);
  double total = 0.0;
  for (std::size_t k = 1; k < n; ++k) { // k = 0 is the anchor itself: distance 0
    const double ideal = sorted[anchor] + static_cast<double>(k) * spacing;
    total += circular_distance(sorted[(anchor + k) % n], ideal);
  }
  return total;
}

} // namespace

double stability_index(std::vector<double> angles)
{
  // a contact without a normal (NaN angle) has no place on the circle
  angles.erase(std::remove_if(angles.begin(), angles.end(),
                              [](double angle) { return !std::isfinite(angle); }),
               angles.end());
  if (angles.size() < 2) return 1.0;
  for (double &angle : angles) angle = wrap_to_full_turn(angle);
  std::sort(angles.begin(), angles.end());

  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t anchor = 0; anchor < angles.size(); ++anchor)
    smallest = std::min(smallest, misfit_from_anchor(angles, anchor));
  return smallest / kTwoPi;
}

double mean_stability_index(const ParticleContacts &particles, long n_particles, bool with_rattlers)
{
  const std::vector<int> &first = particles.first_contact_of;
  double sum = 0.0;
  long n = 0;
  for (std::size_t t = 0; t + 1 < first.size(); ++t) {
    if (first[t + 1] - first[t] < 2) continue;
    sum += stability_index(std::vector<double>(particles.angles.begin() + first[t],
                                               particles.angles.begin() + first[t + 1]));
    ++n;
  }
  if (with_rattlers) {
    sum += static_cast<double>(n_particles - n);
    n = n_particles;
  }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

} // namespace fabric

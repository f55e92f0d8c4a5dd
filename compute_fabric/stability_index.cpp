#include "stability_index.h"

#include "fabric_statistics.h"
#include "particle_contacts.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "math_constants.h"

namespace fabric {
namespace {

using math_constants::TWO_PI;

double circular_distance(double alpha, double beta)
{
  // |fmod(x, 2 pi)| = fmod(|x|, 2 pi); for 2 pi <= |x| < 4 pi that is |x| - 2 pi,
  // exact by Sterbenz's lemma (here |x| < 4 pi: both angles in [0, 4 pi))
  double d = std::fabs(alpha - beta);
  if (d >= TWO_PI) d = d < 2.0 * TWO_PI ? d - TWO_PI : std::fmod(d, TWO_PI);
  return std::min(d, TWO_PI - d);
}

// Misfit of the contacts (sorted, then repeated once: ring[j + n] = ring[j])
// against the even arrangement anchored at ring[anchor]; stops early, with a
// value >= bound, once the sum reaches `bound` (the sum only grows, so such an
// anchor cannot give the minimum).
double misfit_from_anchor(const double *ring, std::size_t n, std::size_t anchor, double bound)
{
  const double spacing = TWO_PI / static_cast<double>(n);
  double total = 0.0;
  for (std::size_t k = 1; k < n && total < bound; ++k) { // k = 0 is the anchor itself
    const double ideal = ring[anchor] + static_cast<double>(k) * spacing;
    total += circular_distance(ring[anchor + k], ideal);
  }
  return total;
}

// Sorts in place; a particle has a handful of contacts: insertion sort.
void sort_small(double *a, std::size_t n)
{
  for (std::size_t i = 1; i < n; ++i) {
    const double x = a[i];
    std::size_t j = i;
    for (; j > 0 && a[j - 1] > x; --j) a[j] = a[j - 1];
    a[j] = x;
  }
}

} // namespace

double stability_index(const double *angles, std::size_t n)
{
  // called once per particle at every output: no allocation below SMALL contacts
  constexpr std::size_t SMALL = 32;
  double small[2 * SMALL];
  std::vector<double> large;
  double *wrapped = small;
  if (n > SMALL) {
    large.resize(2 * n);
    wrapped = large.data();
  }
  // a contact without a normal (NaN angle) has no place on the circle
  std::size_t m = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (std::isfinite(angles[k])) wrapped[m++] = wrap_to_full_turn(angles[k]);
  if (m < 2) return 1.0;
  if (m <= SMALL)
    sort_small(wrapped, m);
  else
    std::sort(wrapped, wrapped + m);

  std::copy(wrapped, wrapped + m, wrapped + m);

  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t anchor = 0; anchor < m; ++anchor)
    smallest = std::min(smallest, misfit_from_anchor(wrapped, m, anchor, smallest));
  return smallest / TWO_PI;
}

double stability_index(const std::vector<double> &angles)
{
  return stability_index(angles.data(), angles.size());
}

double mean_stability_index(const ParticleContacts &particles, long n_particles, bool with_rattlers)
{
  const std::vector<int> &first = particles.first_contact_of;
  double sum = 0.0;
  long n = 0;
  for (std::size_t t = 0; t + 1 < first.size(); ++t) {
    if (first[t + 1] - first[t] < 2) continue;
    sum += stability_index(particles.angles.data() + first[t],
                           static_cast<std::size_t>(first[t + 1] - first[t]));
    ++n;
  }
  if (with_rattlers) {
    sum += static_cast<double>(n_particles - n);
    n = n_particles;
  }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

} // namespace fabric

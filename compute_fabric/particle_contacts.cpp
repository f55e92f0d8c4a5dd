#include "particle_contacts.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "math_constants.h"

namespace fabric {

std::vector<double> ParticleContacts::angles_of(long tag) const
{
  const auto it = std::lower_bound(tags.begin(), tags.end(), tag);
  if (it == tags.end() || *it != tag) return {};
  const std::size_t t = static_cast<std::size_t>(it - tags.begin());
  return {angles.begin() + first_contact_of[t], angles.begin() + first_contact_of[t + 1]};
}

ParticleContacts particle_contacts(const std::vector<Contact> &contacts)
{
  struct End {
    long tag;
    double angle;
  };
  std::vector<End> ends;
  ends.reserve(2 * contacts.size());
  for (const Contact &k : contacts) {
    // a contact without a normal counts for both particles but has no angle
    const double theta = has_normal(k) ? std::atan2(k.ny, k.nx) : NAN;
    ends.push_back({k.a, theta});
    if (k.b >= 0) ends.push_back({k.b, theta + math_constants::PI});
  }
  std::stable_sort(ends.begin(), ends.end(),
                   [](const End &x, const End &y) { return x.tag < y.tag; });

  ParticleContacts particles;
  particles.angles.resize(ends.size());
  for (std::size_t e = 0; e < ends.size(); e++) {
    if (e == 0 || ends[e].tag != ends[e - 1].tag) {
      particles.tags.push_back(ends[e].tag);
      particles.first_contact_of.push_back(static_cast<int>(e));
    }
    particles.angles[e] = ends[e].angle;
  }
  particles.first_contact_of.push_back(static_cast<int>(ends.size()));
  return particles;
}

std::vector<int> contact_counts(const ParticleContacts &particles, long n_particles)
{
  const std::vector<int> &first = particles.first_contact_of;
  std::vector<int> counts;
  for (std::size_t t = 0; t + 1 < first.size(); t++) counts.push_back(first[t + 1] - first[t]);
  counts.resize(std::max(n_particles, static_cast<long>(counts.size())), 0);
  return counts;
}

} // namespace fabric

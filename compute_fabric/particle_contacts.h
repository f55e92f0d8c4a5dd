// The contacts of each particle: how many it has (coordination numbers) and
// their angles about its centre (stability index). Built from the contact list
// by a stable sort of the contact ends, so time and memory follow the number of
// contacts, not the largest atom ID (IDs may be sparse up to 2^31).
#ifndef LIGGGHTS_MEMBRANE_PARTICLE_CONTACTS_H
#define LIGGGHTS_MEMBRANE_PARTICLE_CONTACTS_H

#include <vector>

#include "fabric_statistics.h"

namespace fabric {

struct ParticleContacts {
  std::vector<long> tags; // the particles with at least one contact, ascending
  // The contacts of tags[t] are first_contact_of[t] ... first_contact_of[t+1] - 1
  // (one more entry than tags; in the order of the contact list).
  std::vector<int> first_contact_of;
  // Per contact, the angle of its normal seen from the particle: theta for a,
  // theta + pi for b (radians, not wrapped); NaN for a contact without a normal.
  std::vector<double> angles;

  // the angles of the contacts of particle `tag`; none when it has no contact
  std::vector<double> angles_of(long tag) const;
};

ParticleContacts particle_contacts(const std::vector<Contact> &contacts);

// The contact count of every particle with contacts, in tag order, then zeros
// up to n_particles entries for the particles without contacts.
std::vector<int> contact_counts(const ParticleContacts &particles, long n_particles);

} // namespace fabric

#endif

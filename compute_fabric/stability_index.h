// Geometrical stability index (Momeni et al., Geotechnics 2 (2022) 297-316;
// doc/compute_fabric.md). Separate from fabric_statistics.h because it is per particle
// (dumpable per atom) rather than a sample statistic.
#ifndef LIGGGHTS_MEMBRANE_STABILITY_INDEX_H
#define LIGGGHTS_MEMBRANE_STABILITY_INDEX_H

#include <cstddef>
#include <vector>

namespace fabric {

// lambda = D / 2pi, D the smallest total circular misfit between the contacts
// and n evenly spaced positions anchored at one of them, matched in circular
// order. 0 for an evenly spaced arrangement; larger means less stable.
// angles: radians about the particle's centre, any order and any range. NaN or
// infinite angles (contacts without a normal) are left out; 0 or 1 remaining
// contact -> 1.
double stability_index(const double *angles, std::size_t n);
double stability_index(const std::vector<double> &angles);

struct ParticleContacts;

// The sample's lambda from the list of all contacts (compute fabric sums it per
// rank instead, fabric_sums.h): the mean over the particles with >= 2 contacts
// (with or without a normal), summed in tag order. with_rattlers: the other particles up to
// n_particles (0 or 1 contact) enter with lambda = 1. 0 when no particle qualifies.
double mean_stability_index(const ParticleContacts &particles, long n_particles,
                            bool with_rattlers);

} // namespace fabric

#endif

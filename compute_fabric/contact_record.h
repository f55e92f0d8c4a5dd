// One contact as read from a row of LIGGGHTS' compute pair/gran/local or
// wall/gran/local, stored with a = the smaller tag. No LIGGGHTS:
// fabric_local.cpp fills the records from LIGGGHTS' computes and turns them
// into contacts.
#ifndef LIGGGHTS_MEMBRANE_CONTACT_RECORD_H
#define LIGGGHTS_MEMBRANE_CONTACT_RECORD_H

#include <array>

#include "fabric_statistics.h"
#include "fabric_tensors3d.h"

namespace fabric {

// Tags (b = -1 for a wall), centres (wall: b's position is the contact
// point), force on a, radius sum (wall: a's radius).
enum ContactField { TAG_A, TAG_B, XA, YA, XB, YB, FAX, FAY, RADIUS_SUM, CONTACT_FIELDS };
using ContactRecord = std::array<double, CONTACT_FIELDS>;

// A particle-particle contact as compute pair/gran/local reports it (the force
// on i), stored with a = the smaller tag: when i and j swap, so does the side
// the force acts on, and it changes sign.
ContactRecord pair_record(long tag_i, long tag_j, const double x_i[2], const double x_j[2],
                          const double force_on_i[2], double radius_sum);

// A particle-wall contact: the wall is b (tag -1), placed at the contact point.
ContactRecord wall_record(long tag, const double centre[2], const double contact_point[2],
                          const double force[2], double radius);

// The contact of a record, given its branch vector (lx, ly) = x_b - x_a: the
// caller undoes periodic wraps, which needs the simulation box. The force on b
// from a is minus the recorded force on a.
Contact record_contact(const double *record, double lx, double ly);

// In 3D, the contact of a row straight away: a pair/gran/local row of i and j
// with l_ij = x_j - x_i (periodic wraps undone) and the force on i, stored with
// a = the smaller tag as in 2D; a wall/gran/local row with l from the particle's
// centre to the contact point and the force on the particle.
Contact3 pair_contact3(long tag_i, long tag_j, const double l_ij[3], const double force_on_i[3],
                       double radius_sum);
Contact3 wall_contact3(long tag, const double l[3], const double force_on_particle[3],
                       double radius);

} // namespace fabric

#endif

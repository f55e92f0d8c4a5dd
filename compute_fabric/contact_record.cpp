#include "contact_record.h"

namespace fabric {

namespace {

ContactRecord record(double tag_a, double tag_b, const double x_a[2], const double x_b[2],
                     const double force_on_a[2], double radius_sum)
{
  return {tag_a, tag_b, x_a[0], x_a[1], x_b[0], x_b[1], force_on_a[0], force_on_a[1], radius_sum};
}

} // namespace

ContactRecord pair_record(long tag_i, long tag_j, const double x_i[2], const double x_j[2],
                          const double force_on_i[2], double radius_sum)
{
  if (tag_i <= tag_j)
    return record(static_cast<double>(tag_i), static_cast<double>(tag_j), x_i, x_j, force_on_i,
                  radius_sum);
  const double force_on_j[2] = {-force_on_i[0], -force_on_i[1]};
  return record(static_cast<double>(tag_j), static_cast<double>(tag_i), x_j, x_i, force_on_j,
                radius_sum);
}

ContactRecord wall_record(long tag, const double centre[2], const double contact_point[2],
                          const double force[2], double radius)
{
  return record(static_cast<double>(tag), -1.0, centre, contact_point, force, radius);
}

Contact record_contact(const double *record, double lx, double ly)
{
  return make_contact(static_cast<long>(record[TAG_A]), static_cast<long>(record[TAG_B]), lx, ly,
                      -record[FAX], -record[FAY], record[RADIUS_SUM]);
}

Contact3 pair_contact3(long tag_i, long tag_j, const double l_ij[3], const double force_on_i[3],
                       double radius_sum)
{
  const Eigen::Vector3d l(l_ij[0], l_ij[1], l_ij[2]),
      f(force_on_i[0], force_on_i[1], force_on_i[2]);
  // the force on b from a: on j it is minus the force on i, on i it is that force
  if (tag_i <= tag_j) return make_contact3(tag_i, tag_j, l, -f, radius_sum);
  return make_contact3(tag_j, tag_i, -l, f, radius_sum);
}

Contact3 wall_contact3(long tag, const double l[3], const double force_on_particle[3],
                       double radius)
{
  const Eigen::Vector3d f(force_on_particle[0], force_on_particle[1], force_on_particle[2]);
  return make_contact3(tag, -1, Eigen::Vector3d(l[0], l[1], l[2]), -f, radius);
}

} // namespace fabric

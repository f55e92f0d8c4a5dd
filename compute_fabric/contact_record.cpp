#include "contact_record.h"

#include <algorithm>
#include <cstdint>
#include <utility>

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

std::vector<int> order_by_tags(const std::vector<double> &records)
{
  const int n = static_cast<int>(records.size() / CONTACT_FIELDS);
  // one 64-bit key per contact sorts faster than comparing doubles; the index
  // breaks ties, so equal tags keep their order
  std::vector<std::pair<uint64_t, int>> keys(n);
  for (int c = 0; c < n; c++) {
    const double *rec = records.data() + c * CONTACT_FIELDS;
    // a wall (tag -1) becomes 2^32 - 1: after the particles a touches
    const uint64_t low = static_cast<uint32_t>(static_cast<int64_t>(rec[TAG_B]));
    keys[c] = {(static_cast<uint64_t>(rec[TAG_A]) << 32) | low, c};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<int> order(n);
  for (int c = 0; c < n; c++) order[c] = keys[c].second;
  return order;
}

Contact record_contact(const double *record, double lx, double ly)
{
  return make_contact(static_cast<long>(record[TAG_A]), static_cast<long>(record[TAG_B]), lx, ly,
                      -record[FAX], -record[FAY], record[RADIUS_SUM]);
}

} // namespace fabric

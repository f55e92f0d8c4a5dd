// The membrane placed by parts (membrane_part.h): the members split among k "ranks"
// (in blocks, by x slabs, round robin), each part placed from only the members within
// two rings of its own (member_halo_plan.h), give the loads of the whole membrane to
// the last bit and its sums to round-off.
#include "lateral_surface.h"
#include "member_halo_plan.h"
#include "membrane_part.h"
#include "packings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace packings;
using membrane3d::MembranePart;
using membrane3d::Side;

namespace {

struct Whole {
  std::vector<Sphere> members;
  membrane3d::MembraneTopology topology;
  membrane3d::LateralSurface placed;
  std::vector<Eigen::Vector3d> membrane_load, load; // without, with the escape pushes
};

Whole whole_of(const std::vector<Sphere> &s, const Platens &platens, double tolerance, double p,
               membrane3d::Vertices at)
{
  Whole w;
  std::vector<int> index;
  w.topology = membrane3d::members_only(membrane3d::detect_membrane(s, platens, tolerance), index);
  for (int i : index) w.members.push_back(s[i]);
  w.placed = membrane3d::place_membrane(w.topology, w.members, platens, at);
  w.membrane_load = membrane3d::membrane_loads(w.placed, w.members.size(), p);
  w.load = w.membrane_load;
  membrane3d::add_escape_loads(w.placed, w.members, p, w.load);
  return w;
}

// Places every part of the split `owner` (member -> rank) and checks it against the whole.
void expect_parts_give_whole(const Whole &w, const std::vector<int> &owner, int ranks,
                             const Platens &platens, double p, membrane3d::Vertices at)
{
  const membrane::MemberCells cells = membrane3d::facet_cells(w.topology);
  std::vector<MembranePart> parts;
  std::vector<membrane::HaloPlan> plans;
  std::array<double, membrane3d::PART_SUMS> total{};
  std::vector<int> loaded(w.members.size(), 0);
  for (int r = 0; r < ranks; ++r) {
    plans.push_back(membrane::plan_halo(cells, owner, r, at == membrane3d::Vertices::centres ? 1 : 2));
    const membrane::HaloPlan &plan = plans.back();
    std::vector<Sphere> given;
    for (int m : plan.needed) given.push_back(w.members[m]);
    parts.push_back(membrane3d::place_part(w.topology, cells, plan.owned, plan.needed, given,
                                           platens, p, at));
    for (int k = 0; k < membrane3d::PART_SUMS; ++k) total[k] += parts.back().sums[k];
    for (std::size_t k = 0; k < plan.owned.size(); ++k) {
      const int m = plan.owned[k];
      ++loaded[m];
      // the same bits as the whole's
      for (int d = 0; d < 3; ++d) EXPECT_EQ(parts.back().load[k][d], w.membrane_load[m][d]) << m;
      EXPECT_EQ(parts.back().side[k], w.placed.side[m]) << m;
    }
  }
  for (std::size_t m = 0; m < loaded.size(); ++m) EXPECT_EQ(loaded[m], 1) << m;
  int on = 0, out = 0;
  for (Side s : w.placed.side) {
    on += s == Side::surface;
    out += s == Side::outside;
  }
  using namespace membrane3d;
  EXPECT_EQ(total[ON_SURFACE], on);
  EXPECT_EQ(total[ESCAPED], out);
  EXPECT_EQ(total[CLIPPED], static_cast<double>(w.placed.surface.facets.size()));
  const double volume = lateral_volume(w.placed.surface);
  EXPECT_NEAR(total[VOLUME_SUM] / 2, volume, 1e-13 * std::abs(volume));
  EXPECT_EQ(total[REACHES_LO] > 0, w.placed.reaches_lo);
  EXPECT_EQ(total[REACHES_HI] > 0, w.placed.reaches_hi);
  Eigen::Vector3d net = Eigen::Vector3d::Zero();
  double magnitude = 0;
  for (const auto &f : w.membrane_load) {
    net += f;
    magnitude += f.norm();
  }
  EXPECT_NEAR(total[NET_Z], net.z(), 1e-13 * magnitude);
  EXPECT_NEAR(total[MAGNITUDE], magnitude, 1e-13 * magnitude);
  const Eigen::Vector2d axis = membrane_axis(w.placed);
  EXPECT_NEAR(total[AXIS_X] / total[AREA], axis.x(), 1e-13 * (1 + axis.norm()));
  EXPECT_NEAR(total[AXIS_Y] / total[AREA], axis.y(), 1e-13 * (1 + axis.norm()));
  for (int r = 0; r < ranks; ++r) {
    const membrane::HaloPlan &plan = plans[r];
    std::vector<Sphere> given;
    for (int m : plan.needed) given.push_back(w.members[m]);
    add_part_escapes(parts[r], membrane3d::part_layout(w.topology, cells, plan.owned, plan.needed, at),
                     given, total, p);
    for (std::size_t k = 0; k < plan.owned.size(); ++k)
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(parts[r].load[k][d], w.load[plan.owned[k]][d],
                    1e-12 * (1 + w.load[plan.owned[k]].norm()));
  }
}

// Splits of M members among `ranks`.
std::vector<std::function<int(int, const Sphere &)>> splits(int members, int ranks)
{
  return {[members, ranks](int m, const Sphere &) { return m * ranks / members; },
          [ranks](int m, const Sphere &) { return m % ranks; },
          [ranks](int, const Sphere &s) {
            return std::min(ranks - 1, std::max(0, static_cast<int>(std::floor(s.x.x() * ranks / 4.0))));
          }};
}

void check_all_splits(const Whole &w, const Platens &platens, double p, membrane3d::Vertices at)
{
  const int n = static_cast<int>(w.members.size());
  for (int ranks : {1, 2, 3, 7})
    for (const auto &split : splits(n, ranks)) {
      std::vector<int> owner(n);
      for (int m = 0; m < n; ++m) owner[m] = split(m, w.members[m]);
      SCOPED_TRACE(std::to_string(ranks) + " ranks");
      expect_parts_give_whole(w, owner, ranks, platens, p, at);
    }
}

} // namespace

// A sample sheared by a run (polydisperse, irregular: outer faces on fins and folds),
// closed over both ends between far platens, and cut by platens through it (clipped
// facets, images).
TEST(MembranePart, ShearedSampleSplitAnyWayGivesTheWhole)
{
  const auto s = sheared_sample();
  const double d = mean_diameter(s);
  const Platens far{-1.0, 1.0};
  const Whole w = whole_of(s, far, 0.7 * d, 2.5e4, membrane3d::Vertices::outer_faces);
  ASSERT_GT(w.members.size(), 50u);
  check_all_splits(w, far, 2.5e4, membrane3d::Vertices::outer_faces);
  const Whole centres = whole_of(s, far, 0.7 * d, 2.5e4, membrane3d::Vertices::centres);
  check_all_splits(centres, far, 2.5e4, membrane3d::Vertices::centres);
  double lo = 1, hi = -1;
  for (const Sphere &x : s) {
    lo = std::min(lo, x.x.z());
    hi = std::max(hi, x.x.z());
  }
  const Platens cut{lo - 0.1 * d, hi + 0.1 * d};
  const Whole clipped = whole_of(s, cut, 0.7 * d, 2.5e4, membrane3d::Vertices::outer_faces);
  ASSERT_TRUE(clipped.placed.reaches_lo && clipped.placed.reaches_hi);
  check_all_splits(clipped, cut, 2.5e4, membrane3d::Vertices::outer_faces);
}

// A block with an escaped sphere (pushed towards the summed axis) and offset platens.
TEST(MembranePart, BlockWithEscapeeSplitAnyWayGivesTheWhole)
{
  auto s = simple_cubic(4, 3, 5);
  s.push_back({Eigen::Vector3d(3 + std::sqrt(1.1 * 1.1 - 0.5), 0.5, 2.5), radius}); // a bump
  s.push_back({Eigen::Vector3d(1.5, -1.6, 2.5), radius}); // beyond the tolerance: escaped
  const Platens platens = touching_platens(s);
  const double tolerance = radius; // the bump (gap 0.1) linked, the other (0.68) not
  const Whole w = whole_of(s, platens, tolerance, 3.0, membrane3d::Vertices::outer_faces);
  ASSERT_EQ(w.placed.side.back(), Side::outside);
  check_all_splits(w, platens, 3.0, membrane3d::Vertices::outer_faces);
  const Platens cut{platens.lo + 0.3, platens.hi - 0.3}; // rims through facets
  const Whole clipped = whole_of(s, cut, tolerance, 3.0, membrane3d::Vertices::outer_faces);
  check_all_splits(clipped, cut, 3.0, membrane3d::Vertices::outer_faces);
}

// A part that gets too few spheres says so rather than placing a wrong membrane.
TEST(MembranePart, MissingSphereThrows)
{
  const auto s = simple_cubic(3, 3, 4);
  const Whole w = whole_of(s, touching_platens(s), radius, 1.0, membrane3d::Vertices::outer_faces);
  const membrane::MemberCells cells = membrane3d::facet_cells(w.topology);
  std::vector<int> owner(w.members.size(), 1);
  owner[0] = 0;
  const membrane::HaloPlan plan = membrane::plan_halo(cells, owner, 0, 1); // one ring short
  std::vector<Sphere> given;
  for (int m : plan.needed) given.push_back(w.members[m]);
  EXPECT_THROW(membrane3d::place_part(w.topology, cells, plan.owned, plan.needed, given,
                                      touching_platens(s), 1.0, membrane3d::Vertices::outer_faces),
               std::invalid_argument);
}

// fix membrane3d's restart record (fix_membrane3d/membrane3d_record.h): what is
// written is read back, and a cut or corrupt record is refused with the reason.
#include "membrane3d_record.h"

#include <gtest/gtest.h>

using membrane3d::Membrane3dState;
using membrane3d::Side;

namespace {

Membrane3dState sample_state() {
  Membrane3dState s;
  s.tolerance_given = 2.5e-4;
  s.every = 7;
  s.last_detection = 28;
  s.detections = 5;
  s.member_tags = {3, 9, 12, 40};
  s.topology.side = {Side::surface, Side::surface, Side::outside, Side::surface};
  s.topology.facets = {{{{0, 0}, {1, -1}, {3, 1}}}};
  return s;
}

} // namespace

TEST(Membrane3dRecord, RoundTrip) {
  const auto rec = membrane3d::write_record(sample_state());
  Membrane3dState back;
  ASSERT_EQ(membrane3d::read_record(rec.data(), rec.size(), back), "");
  EXPECT_EQ(back.tolerance_given, 2.5e-4);
  EXPECT_EQ(back.every, 7);
  EXPECT_EQ(back.last_detection, 28);
  EXPECT_EQ(back.detections, 5);
  EXPECT_EQ(back.member_tags, (std::vector<int>{3, 9, 12, 40}));
  EXPECT_EQ(back.topology.side, sample_state().topology.side);
  ASSERT_EQ(back.topology.facets.size(), 1u);
  EXPECT_EQ(back.topology.facets[0][1].sphere, 1);
  EXPECT_EQ(back.topology.facets[0][1].image, -1);
  EXPECT_EQ(back.topology.facets[0][2].sphere, 3);
  EXPECT_EQ(back.topology.facets[0][2].image, 1);
}

TEST(Membrane3dRecord, CutOrCorruptIsRefused) {
  auto rec = membrane3d::write_record(sample_state());
  Membrane3dState back;
  EXPECT_NE(membrane3d::read_record(rec.data(), rec.size() - 1, back), "");  // cut
  auto bad = rec;
  bad.back() = 9;  // the last vertex's image: 9 is none of -1, 0, 1
  EXPECT_NE(membrane3d::read_record(bad.data(), bad.size(), back), "");
  bad = rec;
  bad[0] = 1.0;  // another style's magic number
  EXPECT_NE(membrane3d::read_record(bad.data(), bad.size(), back), "");
  EXPECT_EQ(back.every, 1);  // nothing was read into it
}

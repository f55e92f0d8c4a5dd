// fix membrane3d's restart record (fix_membrane3d/membrane3d_record.h): what is
// written is read back, and a cut or corrupt record is refused with the reason.
#include "membrane3d_record.h"

#include <gtest/gtest.h>

#include <cmath>

using membrane3d::Membrane3dState;
using membrane3d::Side;

namespace {

Membrane3dState sample_state() {
  Membrane3dState s;
  s.tolerance_given = 2.5e-4;
  s.every = 7;
  s.last_detection = 28;
  s.decided_step = 30;
  s.detections = 5;
  s.member_tags = {3, 9, 12, 40};
  s.topology.side = {Side::surface, Side::surface, Side::outside, Side::surface};
  s.topology.facets = {{{{0, 0}, {1, -1}, {3, 1}}}};
  s.window_steps = 40;
  s.window_detections = 31;
  s.unwatched_until = -1;
  s.sample_platens = {0.0, 0.02};
  s.sample_tags = {3, 9};
  s.sample = {{Eigen::Vector3d(1e-3, 2e-3, 3e-3), 5e-4}, {Eigen::Vector3d(-1e-3, 0.0, 7e-3), 6e-4}};
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
  EXPECT_EQ(back.decided_step, 30);
  EXPECT_EQ(back.detections, 5);
  EXPECT_EQ(back.member_tags, (std::vector<int>{3, 9, 12, 40}));
  EXPECT_EQ(back.topology.side, sample_state().topology.side);
  ASSERT_EQ(back.topology.facets.size(), 1u);
  EXPECT_EQ(back.topology.facets[0][1].sphere, 1);
  EXPECT_EQ(back.topology.facets[0][1].image, -1);
  EXPECT_EQ(back.topology.facets[0][2].sphere, 3);
  EXPECT_EQ(back.topology.facets[0][2].image, 1);
  EXPECT_EQ(back.window_steps, 40);
  EXPECT_EQ(back.window_detections, 31);
  EXPECT_EQ(back.unwatched_until, -1);
  EXPECT_EQ(back.sample_platens.hi, 0.02);
  EXPECT_EQ(back.sample_tags, (std::vector<int>{3, 9}));
  ASSERT_EQ(back.sample.size(), 2u);
  EXPECT_EQ(back.sample[1].x.z(), 7e-3);
  EXPECT_EQ(back.sample[1].r, 6e-4);
}

// A record of version 1 (before every auto: no schedule, no spheres) is read.
TEST(Membrane3dRecord, VersionOneIsRead) {
  auto rec = membrane3d::write_record(sample_state());
  rec.resize(rec.size() - (3 + 2 + 1 + 2 * 5 + 1 + 5)); // the version-2, -3 and -4 tails
  rec[1] = 1;
  rec[2] = static_cast<double>(rec.size());
  Membrane3dState back;
  ASSERT_EQ(membrane3d::read_record(rec.data(), rec.size(), back), "");
  EXPECT_EQ(back.member_tags, (std::vector<int>{3, 9, 12, 40}));
  EXPECT_TRUE(back.sample.empty());
  EXPECT_EQ(back.unwatched_until, -1);
  EXPECT_EQ(back.decided_step, -1);
}

// A record of version 2 (before the decided step) is read: no step decided yet.
TEST(Membrane3dRecord, VersionTwoIsRead) {
  auto rec = membrane3d::write_record(sample_state());
  rec.resize(rec.size() - 1 - 5); // the version-3 and -4 tails
  rec[1] = 2;
  rec[2] = static_cast<double>(rec.size());
  Membrane3dState back;
  ASSERT_EQ(membrane3d::read_record(rec.data(), rec.size(), back), "");
  EXPECT_EQ(back.sample_tags, (std::vector<int>{3, 9}));
  EXPECT_EQ(back.decided_step, -1);
}

// A record of version 3 (before the group's checksum) is read: no checksum, so the
// membrane is kept as in that version.
TEST(Membrane3dRecord, VersionThreeIsRead) {
  auto rec = membrane3d::write_record(sample_state());
  rec.resize(rec.size() - 5); // the version-4 tail
  rec[1] = 3;
  rec[2] = static_cast<double>(rec.size());
  Membrane3dState back;
  ASSERT_EQ(membrane3d::read_record(rec.data(), rec.size(), back), "");
  EXPECT_EQ(back.decided_step, 30);
  EXPECT_FALSE(back.has_checksum);
  EXPECT_TRUE(std::isnan(back.detected_platens.hi)); // unknown: never taken as moved
}

// All 64 bits of the checksum come back (a double holds 53: two halves).
TEST(Membrane3dRecord, ChecksumRoundTrip) {
  Membrane3dState s = sample_state();
  s.has_checksum = true;
  s.checksum = 0xfedcba9876543211ull;
  s.detected_platens = {-5e-4, 4.5e-3};
  const auto rec = membrane3d::write_record(s);
  Membrane3dState back;
  ASSERT_EQ(membrane3d::read_record(rec.data(), rec.size(), back), "");
  EXPECT_TRUE(back.has_checksum);
  EXPECT_EQ(back.checksum, 0xfedcba9876543211ull);
  EXPECT_EQ(back.detected_platens.lo, -5e-4);
  EXPECT_EQ(back.detected_platens.hi, 4.5e-3);
}

TEST(Membrane3dRecord, CutOrCorruptIsRefused) {
  auto rec = membrane3d::write_record(sample_state());
  Membrane3dState back;
  EXPECT_NE(membrane3d::read_record(rec.data(), rec.size() - 1, back), "");  // cut
  auto bad = rec;
  bad[3 + 4 + 1 + 4 * 2 + 1 + 5] = 9;  // the last vertex's image: 9 is none of -1, 0, 1
  EXPECT_NE(membrane3d::read_record(bad.data(), bad.size(), back), "");
  bad = rec;
  bad[0] = 1.0;  // another style's magic number
  EXPECT_NE(membrane3d::read_record(bad.data(), bad.size(), back), "");
  EXPECT_EQ(back.every, Membrane3dState().every);  // nothing was read into it
}

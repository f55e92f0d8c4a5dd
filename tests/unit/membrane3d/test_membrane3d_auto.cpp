// fix membrane3d's spheres as the style gathers them (gathered_spheres.h), its detection
// from the skin of the last members (membrane3d_skin.h) and every auto
// (membrane3d_auto.h), with the style's gathers replaced by a sample held here.
#include "membrane3d_auto.h"
#include "membrane3d_skin.h"
#include "membrane3d_tuning.h"
#include "packings.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::GatheredSpheres;
using membrane3d::GroupSignature;
using membrane3d::Membrane3dAuto;
using membrane3d::MembraneTopology;
using membrane3d::Platens;
using membrane3d::Sphere;

const auto same = packings::same_topology;
// far from the sheared sample: no images (as in test_detection_watch.cpp)
const Platens kFarPlatens{-1.0, 1.0};

// The sheared sample as gathered: atom IDs 3, 5, 7, ... (not the indices), type 1.
GatheredSpheres gathered_sample()
{
  GatheredSpheres g;
  g.spheres = packings::sheared_sample();
  for (std::size_t k = 0; k < g.spheres.size(); ++k) {
    g.tags.push_back(3 + 2 * static_cast<int>(k));
    g.types.push_back(1);
  }
  return g;
}

GroupSignature signature_of(const GatheredSpheres &g)
{
  GroupSignature s;
  for (std::size_t k = 0; k < g.tags.size(); ++k) s.add(g.tags[k], g.spheres[k].r);
  return s;
}

// The style's gathers over `group`, counted.
struct FakeGroup {
  GatheredSpheres group;
  int signatures = 0, gathers = 0;
  Membrane3dAuto::Group gathers_of()
  {
    return {[this] {
              ++signatures;
              return signature_of(group);
            },
            [this](const std::vector<int> &tags, GatheredSpheres &out) {
              ++gathers;
              std::vector<int> index;
              for (int tag : tags) {
                const int k = membrane3d::index_of(group, tag);
                if (k >= 0) index.push_back(k);
              }
              out = membrane3d::subset(group, index);
            }};
  }
};

// A detection of every auto on the sample at step 0 with D50 = d50_in_d x the mean
// diameter d, its members set.
struct Detected {
  FakeGroup group{gathered_sample()};
  double d = packings::mean_diameter(group.group.spheres);
  double tolerance = 0.7 * d, d50;
  Membrane3dAuto automatic;
  MembraneTopology topology;
  std::vector<int> members; // indices into the sample
  explicit Detected(double d50_in_d) : d50(d50_in_d * d)
  {
    topology = membrane3d::members_only(
        automatic.detect(group.group, {}, kFarPlatens, tolerance, d50, 0), members);
    automatic.set_members(members);
  }
  bool changed(long long step, GatheredSpheres &now)
  {
    return automatic.can_have_changed(group.gathers_of(), kFarPlatens, tolerance, d50, step, now);
  }
};

TEST(GatheredSpheres, MeanDiameterIndexAndSubset)
{
  GatheredSpheres g;
  g.tags = {3, 7, 9};
  g.spheres = {{Vector3d(0, 0, 0), 0.5}, {Vector3d(1, 0, 0), 1.5}, {Vector3d(2, 0, 0), 1.0}};
  g.types = {1, 2, 3};
  EXPECT_DOUBLE_EQ(membrane3d::mean_diameter(g), 2.0); // (1 + 3 + 2) / 3
  EXPECT_EQ(membrane3d::mean_diameter(GatheredSpheres()), 0.0);
  EXPECT_EQ(membrane3d::index_of(g, 7), 1);
  EXPECT_EQ(membrane3d::index_of(g, 9), 2);
  EXPECT_EQ(membrane3d::index_of(g, 2), -1);
  EXPECT_EQ(membrane3d::index_of(g, 8), -1);
  EXPECT_EQ(membrane3d::index_of(g, 10), -1);
  const GatheredSpheres s = membrane3d::subset(g, {2, 0});
  EXPECT_EQ(s.tags, (std::vector<int>{9, 3}));
  EXPECT_EQ(s.types, (std::vector<int>{3, 1}));
  ASSERT_EQ(s.spheres.size(), 2u);
  EXPECT_EQ(s.spheres[0].x, Vector3d(2, 0, 0));
  EXPECT_EQ(s.spheres[1].r, 0.5);
}

TEST(GroupSignature, CountsSumsAndLargest)
{
  GroupSignature s;
  s.add(3, 0.5);
  s.add(7, 0.25);
  EXPECT_EQ(s.atoms, 2.0);
  EXPECT_EQ(s.id_sum, 10.0);
  EXPECT_EQ(s.largest, 0.5);
  GroupSignature t = s;
  EXPECT_TRUE(s == t);
  t.add(0, 0.1); // one atom more, same sum and radius
  EXPECT_FALSE(s == t);
}

// From the skin of the outermost spheres (no members yet) and from that of the members
// (one of them gone from the group): the membrane of all the spheres.
TEST(Membrane3dSkin, DetectsTheMembraneOfAllSpheres)
{
  const GatheredSpheres all = gathered_sample();
  const double tolerance = 0.7 * packings::mean_diameter(all.spheres);
  const MembraneTopology whole = membrane3d::detect_membrane(all.spheres, kFarPlatens, tolerance);
  EXPECT_TRUE(same(membrane3d::detect_near_members(all, {}, kFarPlatens, tolerance), whole));
  std::vector<int> members;
  membrane3d::members_only(whole, members);
  ASSERT_GT(members.size(), 10u);
  std::vector<int> tags{1}; // not an atom of the group
  for (int k : members) tags.push_back(all.tags[k]);
  EXPECT_TRUE(same(membrane3d::detect_near_members(all, tags, kFarPlatens, tolerance), whole));
}

// Nothing moved: the membrane found is detect_membrane's, unchanged, its members those
// gathered now.
TEST(Membrane3dAuto, UnmovedGroupKeepsItsMembrane)
{
  Detected at(1.0);
  std::vector<int> members;
  EXPECT_TRUE(same(at.topology,
                   membrane3d::members_only(membrane3d::detect_membrane(at.group.group.spheres,
                                                                        kFarPlatens, at.tolerance),
                                            members)));
  EXPECT_EQ(members, at.members);
  GatheredSpheres now;
  EXPECT_FALSE(at.changed(1, now));
  EXPECT_EQ(at.group.signatures, 1);
  EXPECT_EQ(at.group.gathers, 1);
  const GatheredSpheres expected = membrane3d::subset(at.group.group, at.members);
  EXPECT_EQ(now.tags, expected.tags);
  ASSERT_EQ(now.spheres.size(), expected.spheres.size());
  for (std::size_t k = 0; k < now.spheres.size(); ++k)
    EXPECT_EQ(now.spheres[k].x, expected.spheres[k].x);
}

// A translation of the whole sample by 0.015 d changes no certificate: within the budget
// of 0.02 D50 for D50 = d it is unchanged, beyond that of D50 = d / 2 (0.01 d) it can
// have changed.
TEST(Membrane3dAuto, BudgetIsAMultipleOfD50)
{
  for (double d50_in_d : {1.0, 0.5}) {
    Detected at(d50_in_d);
    for (Sphere &s : at.group.group.spheres) s.x.x() += 0.015 * at.d;
    GatheredSpheres now;
    EXPECT_EQ(at.changed(1, now), 0.015 >= membrane3d::WATCH_BUDGET * d50_in_d)
        << "D50 = " << d50_in_d << " d";
  }
}

// A group of other atoms: changed, without gathering the watched ones.
TEST(Membrane3dAuto, OtherGroupChangesWithoutGathering)
{
  Detected at(1.0);
  at.group.group.tags.back() += 2; // another atom, the same count
  GatheredSpheres now;
  EXPECT_TRUE(at.changed(1, now));
  EXPECT_EQ(at.group.signatures, 1);
  EXPECT_EQ(at.group.gathers, 0);
}

// 14 of 20 watched steps changed (a watched atom lost): the next 2 000 steps detect
// without the watch, deciding without a signature; a detection then builds none.
TEST(Membrane3dAuto, DenseWindowGoesUnwatched)
{
  Detected at(1.0);
  GatheredSpheres now;
  const GatheredSpheres whole = at.group.group;
  long long step = 1;
  for (; step <= membrane3d::DENSE_WINDOW_3D; ++step) {
    at.group.group = whole;
    if (step <= membrane3d::DENSE_DETECTIONS_3D) { // lost from the watched gather only
      at.group.group.tags.erase(at.group.group.tags.begin() + at.members.front());
      at.group.group.spheres.erase(at.group.group.spheres.begin() + at.members.front());
      at.group.group.types.erase(at.group.group.types.begin() + at.members.front());
      const FakeGroup full{whole};
      auto gathers = at.group.gathers_of();
      gathers.signature = [&full] { return signature_of(full.group); };
      EXPECT_TRUE(
          at.automatic.can_have_changed(gathers, kFarPlatens, at.tolerance, at.d, step, now));
    } else {
      EXPECT_FALSE(at.changed(step, now)) << step;
    }
  }
  at.group.group = whole;
  const int signatures = at.group.signatures;
  const long long last = step - 1; // the window closed here
  EXPECT_TRUE(at.changed(last + 1, now));
  EXPECT_TRUE(at.changed(last + membrane3d::UNWATCHED_STEPS_3D - 1, now));
  EXPECT_EQ(at.group.signatures, signatures);
  at.automatic.detect(whole, {}, kFarPlatens, at.tolerance, at.d, last + 1);
  membrane3d::Membrane3dState state;
  at.automatic.save(state);
  EXPECT_TRUE(state.sample_tags.empty());
  EXPECT_EQ(state.unwatched_until, static_cast<double>(last + membrane3d::UNWATCHED_STEPS_3D));
}

// After a restart the watch is built again from the detection's spheres: the same
// members, unchanged.
TEST(Membrane3dAuto, RestartBuildsTheWatchAgain)
{
  Detected at(1.0);
  membrane3d::Membrane3dState state;
  at.automatic.save(state);
  EXPECT_EQ(state.sample_tags, at.group.group.tags);
  Membrane3dAuto restarted;
  restarted.restore(state);
  GatheredSpheres now;
  EXPECT_FALSE(
      restarted.can_have_changed(at.group.gathers_of(), kFarPlatens, at.tolerance, at.d, 1, now));
  EXPECT_EQ(now.tags, membrane3d::subset(at.group.group, at.members).tags);
}

} // namespace

// The flood from a skin of the spheres (skin_flood.h): whenever it says it holds, it is
// the flood of all the spheres, facet for facet and side for side; it says so for a
// skin around the last membrane, and not when a left-out sphere would change it.
#include "packings.h"
#include "skin_flood.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::Boundary;
using membrane3d::MembraneTopology;
using membrane3d::Platens;
using membrane3d::Side;
using membrane3d::Sphere;

using packings::jittered_block;
using packings::not_inside;
using packings::same_topology;

std::vector<bool> unsealed(std::size_t n)
{
  return std::vector<bool>(n, false);
}

constexpr double kTolerance = 0.8; // links the jittered squares across their diagonals (gap < 0.6)

// The skin of `keep` holds, and it is the flood of all the spheres.
void expect_whole_flood(const std::vector<Sphere> &s, const std::vector<char> &keep,
                        const Boundary &all)
{
  Boundary skin;
  ASSERT_TRUE(membrane3d::skin_boundary(s, unsealed(s.size()), kTolerance, keep, skin));
  EXPECT_EQ(skin.facets, all.facets);
  EXPECT_EQ(skin.side, all.side);
}

// The last sphere, outside and no seed, left out of a skin of 0.6 around the other
// seeds: the skin does not hold; with it kept, it holds and the sphere is outside.
void expect_skin_needs_the_last(const std::vector<Sphere> &s)
{
  const Boundary all = membrane3d::exterior_boundary(s, unsealed(s.size()), kTolerance);
  ASSERT_EQ(all.side.back(), Side::outside);
  std::vector<int> seeds = not_inside(all.side);
  seeds.pop_back();
  std::vector<char> keep = membrane3d::spheres_near(s, seeds, 0.6);
  ASSERT_EQ(keep.back(), 0);
  Boundary skin;
  EXPECT_FALSE(membrane3d::skin_boundary(s, unsealed(s.size()), kTolerance, keep, skin));
  keep.back() = 1;
  expect_whole_flood(s, keep, all);
}

// The surface of a 7 x 7 x 7 block and one layer under it: 218 of 343 spheres; the
// 125 left out (the 5 x 5 x 5 core) change nothing the flood reads.
TEST(SkinFlood, SkinOfABlockGivesItsFlood)
{
  const auto s = jittered_block(7, 7, 7, 0.05, 1);
  const Boundary all = membrane3d::exterior_boundary(s, unsealed(s.size()), kTolerance);
  const std::vector<int> surface = not_inside(all.side);
  ASSERT_EQ(surface.size(), 7u * 7 * 7 - 5 * 5 * 5);
  const std::vector<char> keep = membrane3d::spheres_near(s, surface, 0.6);
  int kept = 0;
  for (char k : keep) kept += k;
  EXPECT_LT(kept, static_cast<int>(s.size()));
  expect_whole_flood(s, keep, all);
}

// Only the surface spheres kept: the dry cells behind the membrane lose their inner
// vertices, and a left-out sphere of the layer beneath enters their power spheres.
TEST(SkinFlood, SurfaceAloneIsNoSkin)
{
  const auto s = jittered_block(7, 7, 7, 0.05, 1);
  const Boundary all = membrane3d::exterior_boundary(s, unsealed(s.size()), kTolerance);
  std::vector<char> keep(s.size(), 0);
  for (int i : not_inside(all.side)) keep[i] = 1;
  Boundary skin;
  EXPECT_FALSE(membrane3d::skin_boundary(s, unsealed(s.size()), kTolerance, keep, skin));
  EXPECT_TRUE(skin.facets.empty()); // untouched
}

// A sphere left out far beyond the skin's hull (an escapee): the hull would change.
TEST(SkinFlood, LeftOutSphereBeyondTheHullIsNoSkin)
{
  auto s = jittered_block(7, 7, 7, 0.05, 2);
  s.push_back({Vector3d(3, 3, 20), 0.5});
  expect_skin_needs_the_last(s);
}

// A small sphere left out in a notch of the block, unlinked (gap 0.95 > T): it lies in
// a flooded cell, so it is outside, which the skin cannot tell.
TEST(SkinFlood, LeftOutSphereInTheFloodIsNoSkin)
{
  std::vector<Sphere> s;
  for (const Sphere &x : jittered_block(7, 7, 7, 0.05, 4))
    if (!(x.x.x() < 1.5 && x.x.y() > 1.5 && x.x.y() < 4.5)) s.push_back(x); // the notch
  s.push_back({Vector3d(0.5, 3, 3), 0.05});
  expect_skin_needs_the_last(s);
}

// Blocks of several jitters, skins of several thicknesses: whenever the skin holds,
// the flood is the whole one's; thick skins hold, thin ones do not always.
TEST(SkinFlood, WheneverTheSkinHoldsItIsTheWholeFlood)
{
  int held = 0, refused = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const auto s = jittered_block(8, 7, 6, 0.05, seed);
    const Boundary all = membrane3d::exterior_boundary(s, unsealed(s.size()), kTolerance);
    for (double thickness : {-0.3, 0.0, 0.3, 0.6}) {
      const std::vector<char> keep = membrane3d::spheres_near(s, not_inside(all.side), thickness);
      Boundary skin;
      if (!membrane3d::skin_boundary(s, unsealed(s.size()), kTolerance, keep, skin)) {
        ++refused;
        continue;
      }
      ++held;
      EXPECT_EQ(skin.facets, all.facets) << "seed " << seed << ", thickness " << thickness;
      EXPECT_EQ(skin.side, all.side) << "seed " << seed << ", thickness " << thickness;
    }
  }
  EXPECT_GE(held, 6);
  EXPECT_GE(refused, 1);
}

// Between platens (with the images' degenerate cells): the membrane found near the
// last one's members is the membrane, and from the skin; the skin left out some.
TEST(SkinFlood, MembraneNearItsMembersIsTheMembrane)
{
  const auto s = jittered_block(8, 8, 10, 0.05, 3);
  const Platens platens = packings::touching_platens(s);
  const MembraneTopology all = membrane3d::detect_membrane(s, platens, kTolerance);
  bool from_skin = false;
  const MembraneTopology near = membrane3d::detect_membrane_near(
      s, platens, kTolerance, not_inside(all.side), 1.0, &from_skin);
  EXPECT_TRUE(from_skin);
  EXPECT_TRUE(same_topology(near, all));
  // no seeds: the skin is empty, all are flooded, the same membrane
  const MembraneTopology none =
      membrane3d::detect_membrane_near(s, platens, kTolerance, {}, 1.0, &from_skin);
  EXPECT_FALSE(from_skin);
  EXPECT_TRUE(same_topology(none, all));
}

// A run's first detection starts from the outermost spheres (half a diameter deep): on a
// block they show the membrane of all spheres, from a skin that leaves its core out;
// one diameter deep they take the second layer too, whose links close the core off
// as a dry group of its own, and the skin is refused (all are triangulated: the same
// membrane). On the small sheared sample (198 spheres, most near its surface) the skin
// is refused either way, with the same membrane.
TEST(SkinFlood, OutermostSpheresSeedTheFirstDetection)
{
  const auto block = jittered_block(8, 8, 10, 0.05, 5);
  const Platens platens = packings::touching_platens(block);
  const MembraneTopology all = membrane3d::detect_membrane(block, platens, kTolerance);
  for (double depth : {0.5, 1.0}) {
    const std::vector<int> seeds = membrane3d::outermost_spheres(block, 1.0, depth);
    bool from_skin = false;
    const MembraneTopology near =
        membrane3d::detect_membrane_near(block, platens, kTolerance, seeds, 1.0, &from_skin);
    EXPECT_EQ(from_skin, depth < 1.0) << "depth " << depth;
    EXPECT_TRUE(same_topology(near, all)) << "depth " << depth;
    for (int k : not_inside(all.side)) // every member is a seed
      EXPECT_EQ(std::count(seeds.begin(), seeds.end(), k), 1) << "sphere " << k;
    EXPECT_EQ(seeds.size(), depth < 1.0 ? 333u : 422u); // of 640: the outer layer, then two
  }
  const auto sheared = packings::sheared_sample();
  const double d = packings::mean_diameter(sheared);
  bool from_skin = true;
  const MembraneTopology near = membrane3d::detect_membrane_near(
      sheared, packings::sheared_sample_platens, kTolerance * d,
      membrane3d::outermost_spheres(sheared, d, 0.5 * d), d, &from_skin);
  EXPECT_FALSE(from_skin);
  EXPECT_TRUE(same_topology(
      near, membrane3d::detect_membrane(sheared, packings::sheared_sample_platens, kTolerance * d)));
  // a 5 x 5 x 5 lattice: its core sphere (2, 2, 2) is no seed; no spheres, no seeds
  const std::vector<int> lattice = membrane3d::outermost_spheres(packings::simple_cubic(5, 5, 5), 1.0, 0.5);
  EXPECT_EQ(std::count(lattice.begin(), lattice.end(), 2 * 25 + 2 * 5 + 2), 0);
  EXPECT_TRUE(membrane3d::outermost_spheres({}, 1.0, 1.0).empty());
}

// What detect_membrane refuses, the skin refuses too, before it builds a grid on it.
TEST(SkinFlood, ACentreNotFiniteIsAnError)
{
  auto s = jittered_block(4, 4, 6, 0.05, 1);
  const Platens platens = packings::touching_platens(s);
  s[5].x.x() = std::nan("");
  EXPECT_THROW(membrane3d::detect_membrane(s, platens, kTolerance), std::invalid_argument);
  EXPECT_THROW(membrane3d::detect_membrane_near(s, platens, kTolerance, {0, 1, 2}, 1.0),
               std::invalid_argument);
  EXPECT_THROW(membrane3d::spheres_near(s, {0}, 1.0), std::invalid_argument);
  s[5].x.x() = 0.0;
  EXPECT_THROW(membrane3d::spheres_near(s, {0}, std::nan("")), std::invalid_argument);
  EXPECT_THROW(membrane3d::spheres_near(s, {static_cast<int>(s.size())}, 1.0), std::out_of_range);
}

TEST(SkinFlood, FlagsNotOnePerSphereAreAnError)
{
  const auto s = jittered_block(4, 4, 4, 0.05, 1);
  Boundary out;
  EXPECT_THROW(membrane3d::skin_boundary(s, unsealed(s.size()), kTolerance,
                                         std::vector<char>(s.size() - 1, 1), out),
               std::invalid_argument);
}

} // namespace

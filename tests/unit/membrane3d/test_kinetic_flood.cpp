// The kinetic flood (kinetic_flood.h): after every advance its boundary is that of
// exterior_boundary() on the same spheres from scratch, facet for facet, side for side,
// on moving polydisperse packings (flips, walls opening and closing, pockets flooded,
// spheres hidden and shown) and on lattices whose spheres are cospherical (ties decided
// by CGAL's perturbation), and the comparison notices a flood that is not repaired.
#include "kinetic_flood.h"
#include "packings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::Boundary;
using membrane3d::KineticFlood;
using membrane3d::Side;
using membrane3d::Sphere;

constexpr double kTolerance = 0.8; // links unit neighbours and, mostly, square diagonals

// nx x ny x nz spheres on a unit lattice, radii in [r_lo, 0.5], moved by up to `jitter`.
std::vector<Sphere> polydisperse_block(int nx, int ny, int nz, double r_lo, double jitter,
                                       unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> move(-jitter, jitter), radius(r_lo, 0.5);
  std::vector<Sphere> s = packings::simple_cubic(nx, ny, nz);
  for (Sphere &x : s) {
    for (int d = 0; d < 3; ++d) x.x[d] += move(random);
    x.r = radius(random);
  }
  return s;
}

void jiggle(std::vector<Sphere> &s, double step, std::mt19937 &random)
{
  std::uniform_real_distribution<double> move(-step, step);
  for (Sphere &x : s)
    for (int d = 0; d < 3; ++d) x.x[d] += move(random);
}

bool same(const Boundary &a, const Boundary &b)
{
  return a.facets == b.facets && a.side == b.side;
}

// Advances `flood` through `frames`, comparing each with a fresh flood; returns how
// many frames had a boundary other than the frame before (the comparison's reach).
int expect_fresh_boundaries(KineticFlood &flood, const std::vector<std::vector<Sphere>> &frames,
                            const std::vector<bool> &sealed, double tolerance)
{
  int changed = 0;
  Boundary last = flood.boundary();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    flood.advance(frames[f]);
    const Boundary fresh = membrane3d::exterior_boundary(frames[f], sealed, tolerance);
    EXPECT_TRUE(same(flood.boundary(), fresh)) << "frame " << f;
    if (!same(fresh, last)) ++changed;
    last = fresh;
  }
  return changed;
}

TEST(KineticFlood, StartsAsTheFreshFlood)
{
  const auto s = polydisperse_block(6, 6, 6, 0.35, 0.15, 1);
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  EXPECT_TRUE(same(flood.boundary(), membrane3d::exterior_boundary(s, sealed, kTolerance)));
  EXPECT_FALSE(flood.boundary().facets.empty());
}

// A jiggled polydisperse packing: facets flip, walls open and close, at every step the
// fresh flood; most certificates keep their margins, few are evaluated.
TEST(KineticFlood, FollowsAJiggledPolydispersePacking)
{
  auto s = polydisperse_block(7, 7, 7, 0.3, 0.15, 2);
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  std::mt19937 random(3);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 0; step < 40; ++step) {
    jiggle(s, step % 10 == 9 ? 0.01 : 0.0005, random);
    frames.push_back(s);
  }
  const int changed = expect_fresh_boundaries(flood, frames, sealed, kTolerance);
  EXPECT_GE(changed, 10); // the boundary moves: a flood not repaired would be caught
  EXPECT_GT(flood.stats().failed, 0);
  EXPECT_GT(flood.stats().removed, 0);
  EXPECT_LE(flood.stats().rebuilds, 5); // the first, and where most spheres moved far
}

// The comparison notices a flood that is not repaired: the kinetic flood of the first
// frame differs from the fresh flood of a later one.
TEST(KineticFlood, TheComparisonNoticesAStaleFlood)
{
  auto s = polydisperse_block(6, 6, 6, 0.3, 0.15, 4);
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood stale(s, sealed, kTolerance, 0.01);
  std::mt19937 random(5);
  jiggle(s, 0.1, random);
  EXPECT_FALSE(same(stale.boundary(), membrane3d::exterior_boundary(s, sealed, kTolerance)));
  stale.advance(s);
  EXPECT_TRUE(same(stale.boundary(), membrane3d::exterior_boundary(s, sealed, kTolerance)));
}

// Lattices: every power test of the cubic cells is zero. Frames go between the exact
// lattice (cospherical everywhere, ties decided by the perturbation), a few spheres
// moved by dyadic steps (new exact ties, repaired), a few jiggled away from it
// (repaired), and the whole lattice shifted by a dyadic step (the same ties, but every
// point moved: triangulated anew).
void expect_lattice_followed(std::vector<Sphere> lattice, unsigned seed)
{
  const std::vector<bool> sealed(lattice.size(), false);
  KineticFlood flood(lattice, sealed, kTolerance, 0.01);
  EXPECT_TRUE(same(flood.boundary(), membrane3d::exterior_boundary(lattice, sealed, kTolerance)));
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(lattice.size()) - 1);
  std::uniform_real_distribution<double> move(-0.03, 0.03);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 0; step < 24; ++step) {
    std::vector<Sphere> s = lattice;
    if (step % 4 == 1)
      for (int k = 0; k < 5; ++k) s[pick(random)].x += Vector3d(0.125, 0.0625, -0.125);
    if (step % 4 == 2)
      for (int k = 0; k < 5; ++k) s[pick(random)].x += Vector3d(move(random), move(random), 0);
    if (step == 11)
      for (Sphere &x : s) x.x += Vector3d(0.125, -0.25, 0.0625);
    frames.push_back(s);
  }
  expect_fresh_boundaries(flood, frames, sealed, kTolerance);
  EXPECT_LE(flood.stats().rebuilds, 3);
  EXPECT_GT(flood.stats().removed, 0);
}

TEST(KineticFlood, FollowsASimpleCubicLattice)
{
  expect_lattice_followed(packings::simple_cubic(5, 4, 6), 6);
}

TEST(KineticFlood, FollowsAFaceCentredCubicLattice)
{
  expect_lattice_followed(packings::face_centred_cubic(2, 2), 7);
}

// A wall of the surface opened and closed: a surface sphere pulled out and back (its
// gaps beyond the tolerance and within it again) floods the pocket behind it and dries
// it again.
TEST(KineticFlood, OpensAndClosesAWall)
{
  auto s = packings::simple_cubic(5, 5, 5);
  std::mt19937 random(8);
  jiggle(s, 0.05, random);
  const std::vector<bool> sealed(s.size(), false);
  const double tolerance = 0.5;
  // the centre of a face, and the sphere behind it: pulled out, the face opens
  const int face = 2 + 5 * 2, behind = face + 25;
  KineticFlood flood(s, sealed, tolerance, 0.01);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 0; step < 16; ++step) {
    const double out = step < 8 ? 0.15 * step : 0.15 * (16 - step);
    std::vector<Sphere> f = s;
    f[face].x.z() -= out;
    f[behind].r = step < 8 ? 0.5 - 0.04 * step : 0.5 - 0.04 * (16 - step);
    frames.push_back(f);
  }
  const int changed = expect_fresh_boundaries(flood, frames, sealed, tolerance);
  EXPECT_GE(changed, 4);
}

// Spheres hidden by the power triangulation (a small one inside a large one of the
// bottom face) come out below the face and go back in; their sides are those of the
// fresh flood (outside, on the surface, then inside again).
TEST(KineticFlood, ShowsAndHidesSmallSpheres)
{
  auto s = polydisperse_block(5, 5, 5, 0.45, 0.05, 9);
  const std::size_t big = s.size();
  for (int k : {6, 12, 18}) s.push_back({s[k].x + Vector3d(0, 0, 0.1), 0.2});
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  EXPECT_EQ(flood.stats().hidden, 3);
  std::vector<std::vector<Sphere>> frames;
  int shown = 0;
  for (int step = 0; step <= 16; ++step) {
    std::vector<Sphere> f = s;
    const double out = 0.1 * (step < 8 ? step : 16 - step);
    for (std::size_t k = big; k < f.size(); ++k) f[k].x.z() -= out;
    frames.push_back(f);
    const Boundary fresh = membrane3d::exterior_boundary(f, sealed, kTolerance);
    for (std::size_t k = big; k < f.size(); ++k) shown += fresh.side[k] != Side::inside;
  }
  EXPECT_GE(shown, 6) << shown; // the small spheres come out of the big ones
  expect_fresh_boundaries(flood, frames, sealed, kTolerance);
  EXPECT_EQ(flood.stats().hidden, 3);
}

// Sealed spheres (the platens' images of lateral_surface.h): the top layer mirrored in
// a platen above it, never a way in, the images moving with their spheres. Heights on
// a grid of 2^-30, so that the images are exact (platen_images.h: height_grid) and
// their symmetric tests exactly zero, decided by the perturbation.
TEST(KineticFlood, FollowsSealedSpheres)
{
  auto s = polydisperse_block(6, 6, 4, 0.35, 0.1, 10);
  const std::size_t n = s.size();
  std::vector<bool> sealed(n, false);
  std::vector<std::size_t> imaged;
  const double platen = 3.5;
  auto mirror = [&](std::vector<Sphere> &x) {
    for (std::size_t k = 0; k < imaged.size(); ++k) {
      double &z = x[imaged[k]].x.z();
      z = std::ldexp(std::round(std::ldexp(z, 30)), -30);
      x[n + k] = x[imaged[k]];
      x[n + k].x.z() = 2 * platen - x[imaged[k]].x.z();
    }
  };
  for (std::size_t k = 0; k < n; ++k)
    if (s[k].x.z() > 2.5) imaged.push_back(k);
  s.resize(n + imaged.size());
  sealed.resize(s.size(), true);
  mirror(s);
  KineticFlood flood(s, sealed, 0.4, 0.01);
  std::mt19937 random(11);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 0; step < 15; ++step) {
    jiggle(s, 0.001, random);
    mirror(s);
    frames.push_back(s);
  }
  expect_fresh_boundaries(flood, frames, sealed, 0.4);
  EXPECT_LE(flood.stats().rebuilds, 3);
  EXPECT_GT(flood.stats().removed, 0);
}

// A sample from a sheared run near its platen (packings.h), with its platen images
// (lateral_surface.h, exact on the height grid) and their mirror families, moved slowly:
// links change more often than the triangulation, so the flood is kept on most steps
// (kinetic_exterior.h), and each link it reads must be followed (a link left out of
// those it follows leaves a stale membrane).
TEST(KineticFlood, FollowsLinksWhileTheFloodIsKept)
{
  auto spheres = packings::sheared_sample();
  const membrane3d::Platens platens = packings::sheared_sample_platens;
  double d = 0;
  for (const Sphere &x : spheres) d += 2 * x.r / static_cast<double>(spheres.size());
  const double tolerance = 0.7 * d;
  const membrane3d::Mirrored m = membrane3d::mirror_in_platens(spheres, platens, tolerance);
  const membrane3d::MirrorFamilies families{m.original, m.image};
  auto points = [&](const std::vector<Sphere> &now) {
    std::vector<Sphere> p(m.original.size());
    for (std::size_t k = 0; k < p.size(); ++k)
      p[k] = {membrane3d::mirrored_position(now[m.original[k]].x, m.image[k], platens, m.grid),
              now[m.original[k]].r};
    return p;
  };
  KineticFlood flood(points(spheres), m.sealed, tolerance, 0.003 * d, &families);
  std::mt19937 random(15);
  std::vector<std::vector<Sphere>> frames;
  for (int step = 0; step < 150; ++step) {
    jiggle(spheres, 2e-4 * d, random);
    frames.push_back(points(spheres));
  }
  const int changed = expect_fresh_boundaries(flood, frames, m.sealed, tolerance);
  EXPECT_GE(changed, 5);
  EXPECT_GE(flood.stats().floods_kept, 50);
}

TEST(KineticFlood, TriangulatesAnewWhenForgotten)
{
  auto s = polydisperse_block(5, 5, 5, 0.35, 0.1, 12);
  const std::vector<bool> sealed(s.size(), false);
  KineticFlood flood(s, sealed, kTolerance, 0.01);
  std::mt19937 random(13);
  jiggle(s, 0.02, random);
  flood.forget();
  flood.advance(s);
  EXPECT_EQ(flood.stats().rebuilds, 2);
  EXPECT_TRUE(same(flood.boundary(), membrane3d::exterior_boundary(s, sealed, kTolerance)));
}

TEST(KineticFlood, RejectsWhatTheFloodRejects)
{
  auto s = packings::simple_cubic(3, 3, 3);
  const std::vector<bool> sealed(s.size(), false);
  EXPECT_THROW(KineticFlood(s, sealed, -1.0, 0.01), std::invalid_argument);
  EXPECT_THROW(KineticFlood(s, sealed, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(
      KineticFlood(packings::simple_cubic(4, 4, 1), std::vector<bool>(16, false), 0.5, 0.01),
      membrane3d::FlatSample);
  KineticFlood flood(s, sealed, 0.5, 0.01);
  s.pop_back();
  EXPECT_THROW(flood.advance(s), std::invalid_argument);
}

} // namespace

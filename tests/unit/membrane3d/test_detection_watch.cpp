// The watch of fix membrane3d's detection (every auto): while it says "unchanged", a
// detection on the moved spheres finds the same membrane, facet for facet.
#include "detection_watch.h"
#include "packings.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace {

using Eigen::Vector3d;
using membrane3d::DetectionWatch;
using membrane3d::MembraneTopology;
using membrane3d::Platens;
using membrane3d::Sphere;

using packings::mean_diameter;
using packings::sheared_sample;
const auto same = packings::same_topology;
const Platens kSamplePlatensAt = packings::sheared_sample_platens;
// platens far from the sample: no images (the images' mirror symmetry makes the
// triangulation degenerate, decided by CGAL's symbolic perturbation: see
// DegenerateAtThePlatens), the membrane closed over both ends
const Platens kFarPlatens{-1.0, 1.0};

std::vector<Sphere> watched(const DetectionWatch &w, const std::vector<Sphere> &all)
{
  std::vector<Sphere> now;
  for (int i : w.spheres) now.push_back(all[i]);
  return now;
}

// The sheared sample detected with its watch (tolerance 0.7 d, budget 0.02 d).
struct WatchedSample {
  std::vector<Sphere> s = sheared_sample();
  double d = mean_diameter(s);
  DetectionWatch w;
  MembraneTopology t;
  explicit WatchedSample(const Platens &platens)
    : t(membrane3d::detect_watched_membrane(s, platens, 0.7 * d, 0.02 * d, w))
  {
  }
};

TEST(DetectionWatch, UnmovedSpheresKeepTheirMembrane)
{
  const WatchedSample sample(kFarPlatens);
  const auto &[s, d, w, t] = sample;
  ASSERT_FALSE(w.flood.always);
  EXPECT_TRUE(same(t, membrane3d::detect_membrane(s, kFarPlatens, 0.7 * d)));
  EXPECT_FALSE(membrane3d::membrane_can_have_changed(w, watched(w, s), kFarPlatens));
  // the watch leaves out most certificates, and holds the membrane's spheres
  EXPECT_LT(w.flood.side.size() + w.flood.orientation.size() + w.flood.link.size(),
            w.flood.certificates / 2);
  for (const auto &f : t.facets)
    for (const auto &v : f)
      EXPECT_TRUE(std::binary_search(w.spheres.begin(), w.spheres.end(), v.sphere));
}

// A sphere moved by the budget, a radius changed, a sphere's images changed, one sphere
// fewer: changed.
TEST(DetectionWatch, LargeMotionsAndOtherSpheresCount)
{
  const auto s = sheared_sample();
  const double d = mean_diameter(s), budget = 0.02 * d;
  DetectionWatch w;
  membrane3d::detect_watched_membrane(s, kFarPlatens, 0.7 * d, budget, w);
  auto now = watched(w, s);
  now[w.points[0].sphere].x.x() += 1.01 * budget;
  EXPECT_TRUE(membrane3d::membrane_can_have_changed(w, now, kFarPlatens));
  now = watched(w, s);
  now[3].r *= 1.0 + 1e-15;
  EXPECT_TRUE(membrane3d::membrane_can_have_changed(w, now, kFarPlatens));
  now = watched(w, s);
  double top = 0; // a platen brought near: the spheres by it get images
  for (const Sphere &x : s) top = std::max(top, x.x.z() + x.r);
  EXPECT_TRUE(membrane3d::membrane_can_have_changed(w, now, {kFarPlatens.lo, top}));
  now.pop_back();
  EXPECT_TRUE(membrane3d::membrane_can_have_changed(w, now, kFarPlatens));
}

// A lattice is degenerate (cospherical spheres), its triangulation decided by CGAL's
// symbolic perturbation: the watch decides its zero tests in the same way, so the
// lattice moved as a whole by exact steps (the same zeros, the same lexicographic
// order) keeps its membrane; jittered at random, it keeps it whenever the watch says so.
TEST(DetectionWatch, LatticeDecidedAsCgalPerturbs)
{
  const auto s = packings::simple_cubic(4, 3, 5);
  const Platens platens = packings::touching_platens(s);
  DetectionWatch w;
  const auto t = membrane3d::detect_watched_membrane(s, platens, packings::radius, 0.01, w);
  ASSERT_FALSE(w.flood.always);
  EXPECT_FALSE(membrane3d::membrane_can_have_changed(w, watched(w, s), platens));
  auto moved = s;
  for (auto &x : moved) x.x += Vector3d(0.00390625, 0.0078125, 0.0);
  EXPECT_FALSE(membrane3d::membrane_can_have_changed(w, watched(w, moved), platens));
  EXPECT_TRUE(same(t, membrane3d::detect_membrane(moved, platens, packings::radius)));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int kept = 0;
  for (int trial = 0; trial < 100; ++trial) {
    moved = s;
    for (auto &x : moved) x.x += 1e-3 * Vector3d(u(rng), u(rng), u(rng)) * (trial % 2);
    if (membrane3d::membrane_can_have_changed(w, watched(w, moved), platens)) continue;
    ++kept;
    EXPECT_TRUE(same(t, membrane3d::detect_membrane(moved, platens, packings::radius)))
        << "trial " << trial;
  }
  EXPECT_GT(kept, 0);
}

// Near a platen the images make the triangulation degenerate: a cell with a sphere and
// its image has its power sphere centred in the platen plane, so the image of each
// of its other spheres is on that sphere too. The heights on their grid make the
// symmetry exact (and each image exactly a mirror), and the watch decides these
// tests as CGAL's symbolic perturbation does: the unmoved sample is unchanged.
TEST(DetectionWatch, DegenerateAtThePlatens)
{
  const WatchedSample sample(kSamplePlatensAt);
  const auto &[s, d, w, t] = sample;
  ASSERT_FALSE(w.flood.always);
  int by_images = 0;
  for (std::size_t k = 0; k < w.flood.side.size(); ++k) {
    int images = 0;
    for (int p : w.flood.side_cell[k]) images += p >= 0 && w.points[p].image != 0;
    by_images += images > 0;
  }
  EXPECT_GT(by_images, 0);
  EXPECT_FALSE(membrane3d::membrane_can_have_changed(w, watched(w, s), kSamplePlatensAt));
  // a grid-sized change of a height that keeps the symmetry: the same decisions
  auto moved = s;
  for (auto &x : moved) x.x.x() += 1e-9 * d;
  EXPECT_FALSE(membrane3d::membrane_can_have_changed(w, watched(w, moved), kSamplePlatensAt));
  EXPECT_TRUE(same(t, membrane3d::detect_membrane(moved, kSamplePlatensAt, 0.7 * d)));
}

// Random motions of every sphere below the budget, and of the upper platen: whenever
// the watch says unchanged, a detection finds the same membrane; some motions flagged
// do change it (the watch is not blind).
void random_motions(const Platens &platens, bool move_platen)
{
  const auto s = sheared_sample();
  const double d = mean_diameter(s), budget = 0.02 * d, tolerance = 0.7 * d;
  DetectionWatch w;
  const auto t = membrane3d::detect_watched_membrane(s, platens, tolerance, budget, w);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int kept = 0, flagged = 0, changed = 0;
  for (int trial = 0; trial < 400; ++trial) {
    // a few spheres far, the others a little
    const double amplitude = budget * std::pow(0.25, trial % 4);
    auto moved = s;
    for (auto &x : moved) {
      const double a = (rng() % 8 == 0) ? amplitude : amplitude / 10;
      Vector3d step(u(rng), u(rng), u(rng));
      x.x += a * step / std::sqrt(3.0);
    }
    Platens p = platens;
    if (move_platen && trial % 3 == 0) p.hi -= amplitude / 4 * std::abs(u(rng));
    bool inside = true;
    for (const auto &x : moved) inside = inside && x.x.z() > p.lo && x.x.z() < p.hi;
    if (!inside) continue;
    const bool may = membrane3d::membrane_can_have_changed(w, watched(w, moved), p);
    const bool differs = !same(t, membrane3d::detect_membrane(moved, p, tolerance));
    if (!may) {
      ++kept;
      EXPECT_FALSE(differs) << "trial " << trial;
    } else {
      ++flagged;
      changed += differs;
    }
  }
  EXPECT_GT(kept, 50);
  EXPECT_GT(changed, 0);
  std::printf("kept %d, flagged %d (of which changed %d)\n", kept, flagged, changed);
}

TEST(DetectionWatch, RandomMotionsBelowTheBudget)
{
  random_motions(kFarPlatens, false);
}

TEST(DetectionWatch, RandomMotionsAtThePlatens)
{
  random_motions(kSamplePlatensAt, true);
}

} // namespace

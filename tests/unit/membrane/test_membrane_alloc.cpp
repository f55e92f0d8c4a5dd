// Counts heap allocations so the "no allocation per call after warm-up" promise
// of ChainFinder is checked, not assumed. Replacing the global operator new is
// harmless for the other tests of this binary: it only counts.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <vector>

#include "membrane_chain.h"

namespace {
std::atomic<long> g_allocations{0};
}

void *operator new(std::size_t n)
{
  ++g_allocations;
  if (void *p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void *p) noexcept
{
  std::free(p);
}
void operator delete(void *p, std::size_t) noexcept
{
  std::free(p);
}

TEST(MembraneAlloc, RepeatedFindDoesNotAllocate)
{
  using namespace membrane;
  const double h = std::sqrt(3.0) / 2.0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  std::vector<Disk> d;
  for (int row = 0; row < 40; ++row)
    for (int col = 0; col < 12; ++col)
      d.push_back({row * 12 + col + 1, col + (row % 2 ? 0.5 : 0.0) + u(rng),
                   0.5 + row * h + u(rng), 0.5 * (1.0 + u(rng))});
  d.push_back({10000, 14.0, 10.0, 0.5}); // an escapee, so that list is exercised too
  const Platens pl{0.0, 1.0 + 39 * h};
  ChainFinder cf;
  ChainResult r;
  Polyline poly;
  std::vector<Eigen::Vector2d> f;
  BandSlices band;
  DetectionWatch watch;
  for (Side side : {Side::Left, Side::Right}) { // warm-up, both sides
    cf.find(d, side, pl, 0.1, r);
    ASSERT_TRUE(r.ok) << r.failure;
    watch_detection(d, r, pl, 0.1, 0.05, watch);
    polyline_from_chain(d, r.chain, pl, poly);
    chain_forces(poly, side, 1e5, 1.0, f);
    band.reset(side, pl, 5.0);
  }
  const long before = g_allocations.load();
  for (int rep = 0; rep < 5; ++rep) {
    for (Side side : {Side::Left, Side::Right}) {
      for (Disk &k : d) k.x += 1e-4 * u(rng); // positions move between steps
      cf.find(d, side, pl, 0.1, r);
      watch_detection(d, r, pl, 0.1, 0.05, watch);       // every auto, at a detection
      watched_relation_changed(watch, d, side, pl, 0.1); // every auto, every step
      polyline_from_chain(d, r.chain, pl, poly);
      chain_forces(poly, side, 1e5, 1.0, f);
      band.reset(side, pl, 5.0);
      for (const Disk &k : d) band.add(k.x, k.y, k.r);
    }
  }
  const long used = g_allocations.load() - before;
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.escaped.size(), 1u);
  EXPECT_EQ(used, 0);
}

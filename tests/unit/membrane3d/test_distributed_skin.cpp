// The certificate split among ranks (skin_flood.h SkinShell, distributed_skin.h): the
// spheres failing in a left-out set are those failing in its parts together, so the
// ranks' verdicts on their own spheres reduce to the verdict of the whole; a skin
// mirrored with the group's band and certified part by part gives the membrane of all
// the spheres; the failing spheres, joined, make the skin hold.
#include "distributed_skin.h"
#include "lateral_surface.h"
#include "packings.h"
#include "skin_flood.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using Eigen::Vector3d;
using membrane3d::Boundary;
using membrane3d::MembraneTopology;
using membrane3d::Platens;
using membrane3d::Side;
using membrane3d::SkinShell;
using membrane3d::Sphere;

constexpr double kTolerance = 0.8;

using packings::jittered_block;
using packings::not_inside;

// The spheres of `from` with `pick` set (and their entries in `from`).
struct Part {
  std::vector<Sphere> spheres;
  std::vector<bool> sealed;
  std::vector<int> entry;
};

Part part(const std::vector<Sphere> &from, const std::vector<bool> &sealed,
          const std::vector<char> &pick)
{
  Part p;
  for (std::size_t i = 0; i < from.size(); ++i)
    if (pick[i]) {
      p.spheres.push_back(from[i]);
      p.sealed.push_back(sealed[i]);
      p.entry.push_back(static_cast<int>(i));
    }
  return p;
}

// failing() of `p`, in the numbering of the set it was taken from
std::vector<int> failing_of(const SkinShell &shell, const Part &p)
{
  std::vector<int> out;
  for (int k : shell.failing(p.spheres, p.sealed)) out.push_back(p.entry[k]);
  return out;
}

// Blocks, skins of several thicknesses, the left-out spheres split in two by a plane
// (as two ranks' domains) and alternately: the failures of the halves together are
// the failures of the whole, and none exactly when skin_boundary holds.
TEST(DistributedSkin, FailuresOfTheHalvesAreTheWhole)
{
  int held = 0, refused = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    auto s = jittered_block(8, 7, 6, 0.05, seed);
    if (seed == 4) s.push_back({Vector3d(3, 3, 20), 0.5}); // an escapee, left out
    const std::vector<bool> open(s.size(), false);
    const Boundary all = membrane3d::exterior_boundary(s, open, kTolerance);
    std::vector<int> seeds = not_inside(all.side);
    if (seed == 4) seeds.pop_back();
    for (double thickness : {0.0, 0.3, 0.6}) {
      const std::vector<char> keep = membrane3d::spheres_near(s, seeds, thickness);
      std::vector<char> left_pick(s.size());
      for (std::size_t i = 0; i < s.size(); ++i) left_pick[i] = !keep[i];
      const Part skin = part(s, open, keep), left = part(s, open, left_pick);
      const SkinShell shell(skin.spheres, skin.sealed, kTolerance);
      const std::vector<int> whole = failing_of(shell, left);
      Boundary b;
      const bool holds = membrane3d::skin_boundary(s, open, kTolerance, keep, b);
      EXPECT_EQ(holds, whole.empty()) << "seed " << seed << ", thickness " << thickness;
      (holds ? held : refused) += 1;
      for (int split = 0; split < 2; ++split) {
        std::vector<char> a(s.size(), 0), c(s.size(), 0);
        for (std::size_t i = 0; i < s.size(); ++i) {
          if (!left_pick[i]) continue;
          const bool first = split == 0 ? s[i].x.x() < 3.5 : i % 2 == 0;
          (first ? a : c)[i] = 1;
        }
        std::vector<int> parts = failing_of(shell, part(s, open, a));
        const std::vector<int> second = failing_of(shell, part(s, open, c));
        parts.insert(parts.end(), second.begin(), second.end());
        std::sort(parts.begin(), parts.end());
        EXPECT_EQ(parts, whole) << "seed " << seed << ", thickness " << thickness;
        // the verdict of a part alone (first_only): one failing sphere of its own
        const Part pa = part(s, open, a);
        const std::vector<int> one = shell.failing(pa.spheres, pa.sealed, true);
        EXPECT_LE(one.size(), 1u);
        EXPECT_EQ(one.empty(), shell.failing(pa.spheres, pa.sealed).empty());
      }
      if (seed == 4) { // the escapee fails, wherever its skin is (beyond the hull)
        EXPECT_EQ(std::count(whole.begin(), whole.end(), static_cast<int>(s.size()) - 1), 1);
      }
    }
  }
  EXPECT_GE(held, 3);
  EXPECT_GE(refused, 3);
}

// Between platens: the skin around the members mirrored with the band of all the
// spheres, the left-out ones (and their images) tested in two parts, each mirrored
// with the same band: no failure, and the membrane is detect_membrane's on all. A
// sphere moved far away (no member, left out) fails; joined, the skin holds.
TEST(DistributedSkin, SkinMirroredWithTheGroupsBandIsTheMembrane)
{
  auto s = jittered_block(8, 8, 10, 0.05, 3);
  const Platens platens = packings::touching_platens(s);
  const MembraneTopology all = membrane3d::detect_membrane(s, platens, kTolerance);
  std::vector<int> members_all;
  const MembraneTopology all_members = membrane3d::members_only(all, members_all);
  const std::vector<int> seeds = not_inside(all.side);
  s.push_back({Vector3d(20, 3.5, 4.5), 0.5}); // after the detection: far away
  double r_max = 0;
  for (const Sphere &x : s) r_max = std::max(r_max, x.r);
  const double band = membrane3d::image_band(r_max, kTolerance);
  std::vector<Sphere> seed_spheres;
  for (int k : seeds) seed_spheres.push_back(s[k]);
  std::vector<char> keep = membrane3d::near_seeds(s, seed_spheres, 1.0);
  ASSERT_EQ(keep.back(), 0);
  for (int round = 0; round < 2; ++round) {
    std::vector<Sphere> skin, left[2];
    std::vector<int> skin_index, left_index[2];
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (keep[i]) {
        skin.push_back(s[i]);
        skin_index.push_back(static_cast<int>(i));
        continue;
      }
      const int rank = s[i].x.y() < 4 ? 0 : 1;
      left[rank].push_back(s[i]);
      left_index[rank].push_back(static_cast<int>(i));
    }
    const membrane3d::Mirrored m = membrane3d::mirror_in_band(skin, platens, band);
    const SkinShell shell(m.spheres, m.sealed, kTolerance);
    ASSERT_TRUE(shell.usable());
    std::vector<int> failed;
    for (int rank = 0; rank < 2; ++rank) {
      const membrane3d::Mirrored l = membrane3d::mirror_in_band(left[rank], platens, band);
      for (int k : shell.failing(l.spheres, l.sealed))
        failed.push_back(left_index[rank][l.original[k]]);
    }
    if (round == 0) { // the far sphere only: it joins the skin
      ASSERT_FALSE(failed.empty());
      for (int k : failed) EXPECT_EQ(k, static_cast<int>(s.size()) - 1);
      for (int k : failed) keep[k] = 1;
      continue;
    }
    EXPECT_TRUE(failed.empty());
    std::vector<int> index;
    const MembraneTopology t = membrane3d::members_only(
        membrane3d::skin_topology(shell.boundary(), m, skin.size(), s.size(), kTolerance), index);
    // the same as detect_membrane on all the spheres now (the far one outside)
    std::vector<int> now_index;
    const MembraneTopology now =
        membrane3d::members_only(membrane3d::detect_membrane(s, platens, kTolerance), now_index);
    std::vector<int> mapped;
    for (int k : index) mapped.push_back(skin_index[k]);
    EXPECT_EQ(mapped, now_index);
    EXPECT_TRUE(packings::same_topology(t, now));
    EXPECT_EQ(t.side.back(), Side::outside);
    // the block's members are those of the detection before the sphere moved away
    mapped.pop_back();
    EXPECT_EQ(mapped, members_all);
  }
}

// near_seeds is spheres_near's test: on a jittered block with spheres of two sizes.
TEST(DistributedSkin, NearSeedsIsSpheresNear)
{
  auto s = jittered_block(9, 8, 7, 0.1, 7);
  for (std::size_t i = 0; i < s.size(); i += 3) s[i].r = 0.3;
  const std::vector<int> seeds = {0, 17, 100, 250, 400, 503};
  std::vector<Sphere> seed_spheres;
  for (int k : seeds) seed_spheres.push_back(s[k]);
  for (double thickness : {0.05, 0.7, 2.5}) {
    const std::vector<char> expected = membrane3d::spheres_near(s, seeds, thickness);
    EXPECT_EQ(membrane3d::near_seeds(s, seed_spheres, thickness), expected)
        << "thickness " << thickness;
  }
  EXPECT_THROW(membrane3d::near_seeds(s, seed_spheres, std::nan("")), std::invalid_argument);
  // a sphere far beyond the seeds, a seed far from the others: near only to itself
  std::vector<Sphere> far = s;
  far.push_back({Vector3d(100, 3, 3), 0.5});
  seed_spheres.push_back(far.back());
  const std::vector<char> near = membrane3d::near_seeds(far, seed_spheres, 0.7);
  EXPECT_EQ(near.back(), 1);
  EXPECT_EQ(std::vector<char>(near.begin(), near.end() - 1),
            membrane3d::spheres_near(s, seeds, 0.7));
  EXPECT_EQ(membrane3d::near_seeds(s, {}, 0.7), std::vector<char>(s.size(), 0));
}

// The bins of the collective outermost spheres are outermost_spheres' bins: with every
// sphere on one rank, the same seeds; split between two ranks (each bin's farthest the
// larger of theirs), the same too.
TEST(DistributedSkin, OutermostBinsPickTheOutermostSpheres)
{
  const auto block = jittered_block(8, 8, 10, 0.05, 5);
  const double d = 1.0, depth = 0.5;
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();
  double z_lo = block[0].x.z(), z_hi = z_lo;
  for (const Sphere &x : block) {
    axis += x.x.head<2>() / static_cast<double>(block.size());
    z_lo = std::min(z_lo, x.x.z());
    z_hi = std::max(z_hi, x.x.z());
  }
  double outer = 0;
  for (const Sphere &x : block) outer = std::max(outer, (x.x.head<2>() - axis).norm() + x.r);
  const membrane3d::OutermostBins bins(axis, z_lo, z_hi, outer, d);
  EXPECT_EQ(bins.slabs, static_cast<long>((z_hi - z_lo) / d) + 1);
  EXPECT_EQ(bins.sectors, static_cast<long>(2 * M_PI * outer));
  std::vector<double> farthest[2];
  for (auto &f : farthest) f.assign(bins.count(), -1e300);
  for (std::size_t i = 0; i < block.size(); ++i) {
    double &f = farthest[block[i].x.x() < 4 ? 0 : 1][bins.bin(block[i].x)];
    f = std::max(f, bins.reach(block[i]));
  }
  std::vector<int> picked;
  for (std::size_t i = 0; i < block.size(); ++i) {
    const std::size_t b = bins.bin(block[i].x);
    if (bins.reach(block[i]) >= std::max(farthest[0][b], farthest[1][b]) - depth)
      picked.push_back(static_cast<int>(i));
  }
  EXPECT_EQ(picked, membrane3d::outermost_spheres(block, d, depth));
  EXPECT_EQ(picked.size(), 333u);
  // a sphere far away: the sectors are fewer, the bins at most MOST_BINS
  const membrane3d::OutermostBins far(axis, z_lo, z_hi, 1e9, d);
  EXPECT_LE(far.count(), static_cast<std::size_t>(membrane3d::OutermostBins::MOST_BINS));
  EXPECT_GE(far.sectors, 8);
}

// A skin that shows nothing fails every left-out sphere; a flat skin is not usable.
TEST(DistributedSkin, SkinThatShowsNothingFailsEverySphere)
{
  const std::vector<Sphere> flat = {{Vector3d(0, 0, 0), 0.5},
                                    {Vector3d(1, 0, 0), 0.5},
                                    {Vector3d(0, 1, 0), 0.5},
                                    {Vector3d(1, 1, 0), 0.5},
                                    {Vector3d(2, 1, 0), 0.5}};
  const SkinShell shell(flat, std::vector<bool>(flat.size(), false), kTolerance);
  EXPECT_FALSE(shell.usable());
  const std::vector<Sphere> left = {{Vector3d(5, 5, 5), 0.5}, {Vector3d(6, 5, 5), 0.5}};
  EXPECT_EQ(shell.failing(left, {false, false}), (std::vector<int>{0, 1}));
  EXPECT_EQ(shell.failing(left, {false, false}, true), (std::vector<int>{0}));
  EXPECT_THROW(shell.failing(left, {false}), std::invalid_argument);
  const SkinShell few(std::vector<Sphere>(flat.begin(), flat.begin() + 3),
                      std::vector<bool>(3, false), kTolerance);
  EXPECT_FALSE(few.usable());
}

} // namespace

namespace {

// The note at a run's end: nothing when every certificate held at once; the counts of
// the run (the counters less those at its start) otherwise.
TEST(DistributedSkin, RunNoteSaysWhatFailed)
{
  membrane3d::SkinCounters start, end;
  start.detections = 3;
  start.rounds = 1;
  start.joined = 2;
  start.bytes = 100;
  end = start;
  end.detections = 10;
  EXPECT_EQ(membrane3d::skin_run_note(end - start), "");
  end.rounds = 2;
  end.joined = 6;
  EXPECT_EQ(membrane3d::skin_run_note(end - start),
            "of the run's 7 detections from the skin, 1 certificate failed and was made again "
            "with the 4 left-out spheres that failed joining the skin");
  end.rounds = 9;
  end.doublings = 1;
  end.last_resorts = 1;
  EXPECT_EQ(membrane3d::skin_run_note(end - start),
            "of the run's 7 detections from the skin, 8 certificates failed and were made "
            "again with the 4 left-out spheres that failed joining the skin (its thickness "
            "doubled 1 time); 1 detection gathered all the group's spheres (the last resort)");
  end = start;
  end.detections = 4;
  end.last_resorts = 1;
  EXPECT_EQ(membrane3d::skin_run_note(end - start),
            "of the run's 1 detection from the skin, 1 detection gathered all the group's "
            "spheres (the last resort)");
}

} // namespace

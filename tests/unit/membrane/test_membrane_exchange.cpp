// What the ranks of fix membrane2d exchange (membrane_exchange.h), the band
// cache's key (membrane_band_cache.h) and the polyline file
// (membrane_polyline.h) against hand-worked cases.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "membrane_band_cache.h"
#include "membrane_exchange.h"
#include "membrane_output.h"
#include "membrane_polyline.h"
#include "membrane_vtk.h"

using namespace membrane;

namespace {

std::vector<AtomId> tags(const std::vector<Disk> &disks)
{
  std::vector<AtomId> t;
  for (const Disk &d : disks) t.push_back(d.tag);
  return t;
}

} // namespace

// Platens 0 and 4, band width 1: four slices. Four unit disks in a row in
// slice 0 (x - r = 0, 1, 2, 3; x + r = 1, 2, 3, 4) and tag 5 alone in slice 2
// (x - r = 0.5, x + r = 1.5). Edges near slice 0: left 0, right 4; near slice
// 2: left 0.5, right 1.5. Left band x - r <= edge + 1: tags 1, 2 and 5; right
// band x + r >= edge - 1: tags 3, 4 and 5.
TEST(MembraneExchange, BandRecordsGiveEachSideItsBand)
{
  const bool active[2] = {true, true};
  SideData sides[2];
  reset_slices(sides, active, Platens{0.0, 4.0}, 1.0);
  ASSERT_EQ(sides[LEFT].slices.count(), 4);
  const std::vector<Disk> disks = {{1, 0.5, 0.5, 0.5},
                                   {2, 1.5, 0.5, 0.5},
                                   {3, 2.5, 0.5, 0.5},
                                   {4, 3.5, 0.5, 0.5},
                                   {5, 1.0, 2.5, 0.5}};
  std::vector<int> slice;
  for (const Disk &d : disks) slice.push_back(add_to_slices(sides, active, d.x, d.y, d.r));
  EXPECT_EQ(slice, (std::vector<int>{0, 0, 0, 0, 2}));
  EXPECT_EQ(sides[LEFT].slices.extents()[0], 0.0);
  EXPECT_EQ(sides[RIGHT].slices.extents()[0], 4.0);
  EXPECT_EQ(sides[LEFT].slices.extents()[2], 0.5);
  EXPECT_EQ(sides[RIGHT].slices.extents()[2], 1.5);
  for (SideData &s : sides) s.slices.finish();
  std::vector<double> records;
  for (std::size_t k = 0; k < disks.size(); k++)
    put_band_records(records, sides, active, slice[k], disks[k], 1.0);
  EXPECT_EQ(records.size(), 6u * 5u); // tag 5 twice
  take_bands(records, sides);
  EXPECT_EQ(tags(sides[LEFT].band), (std::vector<AtomId>{1, 2, 5}));
  EXPECT_EQ(tags(sides[RIGHT].band), (std::vector<AtomId>{3, 4, 5}));
  EXPECT_EQ(sides[RIGHT].band[0].x, 2.5);
  EXPECT_EQ(sides[RIGHT].band[2].y, 2.5);

  // one side only: the other band stays empty
  const bool right_only[2] = {false, true};
  records.clear();
  for (std::size_t k = 0; k < disks.size(); k++)
    put_band_records(records, sides, right_only, slice[k], disks[k], 1.0);
  take_bands(records, sides);
  EXPECT_TRUE(sides[LEFT].band.empty());
  EXPECT_EQ(tags(sides[RIGHT].band), (std::vector<AtomId>{3, 4, 5}));
}

// Three watched disks: tag 7 (left chain 0), 9 (right chain 0, right band
// index 1), 12 (left chain 1). Rank 0 sends tag 9, rank 1 tags 12 and 7, both
// with the largest step fraction 0.03: the lower ID, 7, is the one named.
TEST(MembraneExchange, WatchedRecordsFillTheChainsAndTheLargestValues)
{
  std::vector<WatchEntry> list(3);
  list[0].tag = 7;
  list[0].chain_position[LEFT] = 0;
  list[1].tag = 9;
  list[1].chain_position[RIGHT] = 0;
  list[1].band_index[RIGHT] = 1;
  list[2].tag = 12;
  list[2].chain_position[LEFT] = 1;
  SideChain chains[2];
  chains[LEFT].active = chains[RIGHT].active = true;
  chains[LEFT].chain_tags = {7, 12};
  chains[RIGHT].chain_tags = {9};
  chains[RIGHT].now.resize(2);
  std::vector<double> records;
  put_watched(records, 1, Disk{9, 3.0, 1.0, 0.5}, 0.02, 3);
  put_band_displacement(records, 0.1);
  put_watched(records, 2, Disk{12, -1.0, 2.0, 0.4}, 0.03, 2);
  put_watched(records, 0, Disk{7, -1.5, 1.0, 0.5}, 0.03, 5);
  put_band_displacement(records, 0.25);
  EXPECT_TRUE(watched_complete(records.size(), 3, 2));
  EXPECT_FALSE(watched_complete(records.size(), 3, 3));
  EXPECT_FALSE(watched_complete(records.size() - 6, 3, 2)); // a disk lost
  SideData sides[2];
  const Watched w = take_watched(records, list, chains, sides);
  EXPECT_EQ(w.band_displacement, 0.25);
  EXPECT_EQ(w.chain_step, 0.03);
  EXPECT_EQ(w.chain_step_tag, 7);
  ASSERT_EQ(sides[LEFT].chain_disks.size(), 2u);
  EXPECT_EQ(tags(sides[LEFT].chain_disks), (std::vector<AtomId>{7, 12}));
  EXPECT_EQ(sides[LEFT].chain_disks[1].x, -1.0);
  EXPECT_EQ(sides[LEFT].chain_types, (std::vector<int>{5, 2}));
  EXPECT_EQ(tags(sides[RIGHT].chain_disks), (std::vector<AtomId>{9}));
  EXPECT_EQ(sides[RIGHT].chain_types, (std::vector<int>{3}));
  EXPECT_EQ(chains[RIGHT].now[1].tag, 9);
  EXPECT_EQ(chains[RIGHT].now[1].x, 3.0);
  // a side not active holds no chain disks
  chains[LEFT].active = false;
  take_watched(records, list, chains, sides);
  EXPECT_TRUE(sides[LEFT].chain_disks.empty());
}

TEST(MembraneExchange, OwnedIndicesAreLookedUpAgainOnlyWhenTheKeyChanges)
{
  OwnedIndices cache;
  std::vector<AtomId> ids = {4, 8, 15};
  auto id = [&](std::size_t k) { return ids[k]; };
  EXPECT_TRUE(cache.stale(3, 100, ids.size(), id)); // first use
  EXPECT_EQ(cache.index.size(), 3u);
  EXPECT_FALSE(cache.stale(3, 100, ids.size(), id));
  EXPECT_TRUE(cache.stale(4, 100, ids.size(), id)); // a neighbour list build
  EXPECT_TRUE(cache.stale(4, 99, ids.size(), id));  // an atom fewer
  ids[1] = 16;                                      // another disk in the list
  EXPECT_TRUE(cache.stale(4, 99, ids.size(), id));
  EXPECT_FALSE(cache.stale(4, 99, ids.size(), id));
  EXPECT_TRUE(cache.stale(4, 99, 2, id)); // a shorter list
  EXPECT_EQ(cache.index.size(), 2u);
}

TEST(MembraneExchange, GatheredBytesCountTheValuesAndTheCounts)
{
  EXPECT_EQ(gathered_bytes(30, 2), 30 * 8.0 + 2 * 4.0);
  EXPECT_EQ(gathered_bytes(0, 1), 4.0);
}

TEST(BandCandidates, UsableOnlyWithTheKeyOfTheBuild)
{
  EXPECT_TRUE(BandCandidates::motion_bounded(1, 0, true, false));
  EXPECT_FALSE(BandCandidates::motion_bounded(2, 0, true, false));
  EXPECT_FALSE(BandCandidates::motion_bounded(1, 5, true, false));
  EXPECT_FALSE(BandCandidates::motion_bounded(1, 0, false, false));
  EXPECT_FALSE(BandCandidates::motion_bounded(1, 0, true, true));

  BandCandidates c;
  const bool both[2] = {true, true}, left[2] = {true, false};
  EXPECT_FALSE(c.usable(1.0, both, 0, 0)); // never built
  BandSlices s[2];
  s[0].reset(Side::Left, Platens{0.0, 4.0}, 1.0);
  s[1].reset(Side::Right, Platens{0.0, 4.0}, 1.0);
  s[0].add(0.5, 0.5, 0.5);
  s[1].add(0.5, 0.5, 0.5);
  s[0].finish();
  s[1].finish();
  c.build({{0, 0.5, 0.5, 0.5}}, &s[0], &s[1], 1.0, 1.0, 0.1, 0.0, 4.0);
  c.stamp(5, 40, both);
  EXPECT_TRUE(c.usable(1.0, both, 5, 40));
  EXPECT_FALSE(c.usable(2.0, both, 5, 40)); // a widened band
  EXPECT_FALSE(c.usable(1.0, both, 6, 40)); // a neighbour list build
  EXPECT_FALSE(c.usable(1.0, both, 5, 41)); // another atom count
  EXPECT_FALSE(c.usable(1.0, left, 5, 40)); // other sides
  c.clear();
  EXPECT_FALSE(c.usable(1.0, both, 5, 40));
}

TEST(MembraneOutput, PlatensEncloseTheCentres)
{
  EXPECT_EQ(enclose_problem(false, 0.5, 0.5), "");
  EXPECT_EQ(enclose_problem(true, 2.0, 2.0), "");
  EXPECT_EQ(enclose_problem(false, 0.5, 0.4),
            "is 0.5, above the lowest disk centre of the group (y = 0.4); the platens must "
            "enclose the sample");
  EXPECT_EQ(enclose_problem(true, 2.0, 2.25),
            "is 2, below the highest disk centre of the group (y = 2.25); the platens must "
            "enclose the sample");
}

TEST(MembraneState, ChainTypesByIdEachOnce)
{
  SideData sides[2];
  sides[LEFT].chain_disks = {{5, 0, 0, 1}, {3, 0, 0, 1}};
  sides[LEFT].chain_types = {1, 2};
  sides[RIGHT].chain_disks = {{3, 0, 0, 1}, {8, 0, 0, 1}};
  sides[RIGHT].chain_types = {2, 4};
  std::vector<AtomId> ids = {99};
  std::vector<int> types;
  chain_types(sides, ids, types);
  EXPECT_EQ(ids, (std::vector<AtomId>{3, 5, 8}));
  EXPECT_EQ(types, (std::vector<int>{2, 1, 4}));
}

namespace {

std::string contents(const std::string &path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

// The right side only: its polyline (0.5, 0) (0.5, 1) and its one disk with
// its force; the same step written again replaces its frame.
TEST(MembranePolyline, OneFrameAStepInTheFile)
{
  SideChain chains[2];
  chains[RIGHT].active = true;
  SideData sides[2];
  sides[RIGHT].chain_disks = {{42, 0.25, 0.5, 0.25}};
  SideLoad loads[2];
  loads[RIGHT].polyline = {Eigen::Vector2d(0.5, 0.0), Eigen::Vector2d(0.5, 1.0)};
  loads[RIGHT].forces = {Eigen::Vector2d(-2.0, 0.0)};
  const std::string path = "test_membrane_polyline.txt";
  PolylineFile file;
  EXPECT_FALSE(file.due(0)); // not opened
  ASSERT_EQ(file.open(path, 10, true), "");
  EXPECT_EQ(file.path(), path);
  EXPECT_TRUE(file.due(0));
  EXPECT_FALSE(file.due(5));
  EXPECT_TRUE(file.due(20));
  const std::string frame = "ITEM: POLYLINE right 2\n0.5 0\n0.5 1\n"
                            "ITEM: CHAIN right 1 (tag x y r fx fy)\n42 0.25 0.5 0.25 -2 0\n";
  EXPECT_EQ(file.write(0, chains, sides, loads), "");
  EXPECT_EQ(file.write(10, chains, sides, loads), "");
  EXPECT_EQ(contents(path), "ITEM: TIMESTEP\n0\n" + frame + "ITEM: TIMESTEP\n10\n" + frame);
  sides[RIGHT].chain_disks[0].tag = 43;
  EXPECT_EQ(file.write(10, chains, sides, loads), "");
  std::string later = frame;
  later.replace(later.find("42 "), 3, "43 ");
  EXPECT_EQ(contents(path), "ITEM: TIMESTEP\n0\n" + frame + "ITEM: TIMESTEP\n10\n" + later);
  std::remove(path.c_str());

  PolylineFile nowhere;
  EXPECT_NE(nowhere.open("no_such_directory/polyline.txt", 1, true), "");
  EXPECT_FALSE(nowhere.due(0));
  // another rank knows the file but writes nothing
  PolylineFile other;
  EXPECT_EQ(other.open("no_such_directory/polyline.txt", 1, false), "");
  EXPECT_EQ(other.path(), "no_such_directory/polyline.txt");
  EXPECT_FALSE(other.due(0));
}

TEST(MembraneVtk, ChainsFrameShowsTheActiveSidesOnly)
{
  SideChain chains[2];
  chains[RIGHT].active = true;
  SideData sides[2];
  sides[LEFT].chain_disks = {{1, -1.0, 0.5, 0.5}};
  sides[RIGHT].chain_disks = {{2, 1.0, 0.5, 0.5}};
  SideLoad loads[2];
  loads[RIGHT].polyline = {Eigen::Vector2d(1.5, 0.0), Eigen::Vector2d(1.5, 1.0)};
  loads[RIGHT].forces = {Eigen::Vector2d(-1.0, 0.0)};
  const std::string vtp = chains_vtk_frame(chains, sides, loads);
  // two polyline points, one disk: the right side's (2) on each
  EXPECT_NE(vtp.find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(vtp.find("Name=\"side\" NumberOfComponents=\"1\" format=\"ascii\">\n          2 2 2\n"),
            std::string::npos);
  EXPECT_NE(
      vtp.find("Name=\"tag\" NumberOfComponents=\"1\" format=\"ascii\">\n          -1 -1 2\n"),
      std::string::npos);
}

namespace {

// Four local atoms, the group's bit 1: index 1 (tag 22) is not in the group.
struct FourAtoms {
  int mask[4] = {1, 2, 3, 1};
  AtomId tag[4] = {21, 22, 23, 24};
  double xs[4][3] = {{0.5, 0.5, 0}, {1.5, -3.0, 0}, {3.5, 0.5, 0}, {2.0, 2.5, 0}};
  double vs[4][3] = {{0, 0, 0}, {0, 0, 0}, {0.06, 0.08, 0}, {0, 0, 0}};
  double *x[4] = {xs[0], xs[1], xs[2], xs[3]};
  double *v[4] = {vs[0], vs[1], vs[2], vs[3]};
  double radius[4] = {0.5, 0.5, 0.5, 0.5};
  int type[4] = {1, 1, 2, 1};
  LocalAtoms local() const { return {4, mask, 1, tag, x, v, radius, type}; }
  LocalIndex index() const
  {
    return [](AtomId t) { return t == 21 ? 0 : t == 22 ? 1 : t == 23 ? 2 : t == 24 ? 3 : -1; };
  }
};

} // namespace

// Platens 0 and 4, band width 1. The group: tag 21 (x - r = 0, slice 0), 23
// (x + r = 4, slice 0), 24 (x - r = 1.5, x + r = 2.5, slice 2). Left band:
// 21 (0 <= 0 + 1) and 24 (1.5 <= 1.5 + 1); right band: 23 and 24.
TEST(MembraneExchange, TheGroupsAtomsGiveTheBands)
{
  const FourAtoms a;
  double lo, hi;
  y_range(a.local(), lo, hi);
  EXPECT_EQ(lo, 0.5);
  EXPECT_EQ(hi, 2.5);
  const std::vector<BandDisk> disks = band_disks(a.local());
  ASSERT_EQ(disks.size(), 3u);
  EXPECT_EQ(disks[1].index, 2);
  EXPECT_EQ(disks[2].y, 2.5);

  const bool active[2] = {true, true};
  SideData sides[2];
  reset_slices(sides, active, Platens{0.0, 4.0}, 1.0);
  std::vector<int> slice_of;
  add_to_slices(sides, active, a.local(), nullptr, slice_of);
  ASSERT_EQ(slice_of.size(), 4u);
  EXPECT_EQ(slice_of[0], 0);
  EXPECT_EQ(slice_of[2], 0);
  EXPECT_EQ(slice_of[3], 2);
  EXPECT_EQ(sides[LEFT].slices.extents()[2], 1.5);
  EXPECT_EQ(sides[RIGHT].slices.extents()[0], 4.0);
  for (SideData &s : sides) s.slices.finish();
  std::vector<double> records;
  put_band_records(records, sides, active, a.local(), nullptr, slice_of, 1.0);
  take_bands(records, sides);
  EXPECT_EQ(tags(sides[LEFT].band), (std::vector<AtomId>{21, 24}));
  EXPECT_EQ(tags(sides[RIGHT].band), (std::vector<AtomId>{23, 24}));
  // the candidates only: atom 2
  const std::vector<int> candidates = {2};
  records.clear();
  put_band_records(records, sides, active, a.local(), &candidates, slice_of, 1.0);
  take_bands(records, sides);
  EXPECT_TRUE(sides[LEFT].band.empty());
  EXPECT_EQ(tags(sides[RIGHT].band), (std::vector<AtomId>{23}));
}

// Watched: 21 (left chain), 23 (right chain), 99 (another rank's). Tag 23
// moves |v| dt / r = 0.1 x 0.5 / 0.5 = 0.1 of its radius in a step (|v| =
// |(0.06, 0.08)| = 0.1).
TEST(MembraneExchange, TheOwnedWatchedDisksAreSent)
{
  const FourAtoms a;
  std::vector<WatchEntry> list(3);
  list[0].tag = 21;
  list[0].chain_position[LEFT] = 0;
  list[1].tag = 23;
  list[1].chain_position[RIGHT] = 0;
  list[2].tag = 99;
  const std::vector<int> index = {0, 2, -1};
  std::vector<double> records;
  put_watched(records, list, index, a.local(), 0.5);
  // band disks taken at (0.5, 0.5) and (0.5, 4.5): moved 0 and 5 (3, -4)
  const std::vector<Disk> band = {{21, 0.5, 0.5, 0.5}, {23, 0.5, 4.5, 0.5}, {99, 0, 0, 1}};
  const double moved = largest_displacement(band, index, a.local());
  EXPECT_EQ(moved, 5.0);
  put_band_displacement(records, moved);
  EXPECT_TRUE(watched_complete(records.size(), 2, 1)); // two owned, one rank
  SideChain chains[2];
  chains[LEFT].active = chains[RIGHT].active = true;
  chains[LEFT].chain_tags = {21};
  chains[RIGHT].chain_tags = {23};
  SideData sides[2];
  const Watched w = take_watched(records, list, chains, sides);
  EXPECT_DOUBLE_EQ(w.chain_step, 0.1);
  EXPECT_EQ(w.chain_step_tag, 23);
  EXPECT_EQ(w.band_displacement, 5.0);
  EXPECT_EQ(sides[LEFT].chain_types, (std::vector<int>{1}));
  EXPECT_EQ(sides[RIGHT].chain_types, (std::vector<int>{2}));
  EXPECT_EQ(sides[RIGHT].chain_disks[0].x, 3.5);
}

// Right chain 23 with the load (-2, 1), escapee 21 pushed by p t 2r = 3 x 2
// x 1 = 6 to -x; the left chain's disk 99 is another rank's. Flags: 21
// escapee, 22 none, 23 right chain, 24 left chain.
TEST(MembraneExchange, ForcesAndFlagsOfTheOwnedAtoms)
{
  const FourAtoms a;
  SideChain chains[2];
  chains[LEFT].active = chains[RIGHT].active = true;
  chains[LEFT].side = Side::Left;
  chains[RIGHT].side = Side::Right;
  chains[LEFT].chain_tags = {99};
  chains[RIGHT].chain_tags = {23};
  chains[RIGHT].escaped_tags = {21};
  SideData sides[2];
  sides[LEFT].chain_disks = {{99, -1.0, 1.0, 0.5}};
  sides[RIGHT].chain_disks = {{23, 3.5, 0.5, 0.5}};
  SideLoad loads[2];
  loads[LEFT].forces = {Eigen::Vector2d(5.0, 5.0)};
  loads[RIGHT].forces = {Eigen::Vector2d(-2.0, 1.0)};
  double fs[4][3] = {};
  double *f[4] = {fs[0], fs[1], fs[2], fs[3]};
  add_forces(chains, sides, loads, 3.0, 2.0, a.local(), a.index(), f);
  EXPECT_EQ(fs[0][0], -6.0);
  EXPECT_EQ(fs[0][1], 0.0);
  EXPECT_EQ(fs[1][0], 0.0);
  EXPECT_EQ(fs[2][0], -2.0);
  EXPECT_EQ(fs[2][1], 1.0);
  EXPECT_EQ(fs[3][0], 0.0);

  chains[LEFT].chain_tags = {24};
  double flag[4] = {9, 9, 9, 9};
  set_flags(chains, 4, a.index(), flag);
  EXPECT_EQ(flag[0], ESCAPEE);
  EXPECT_EQ(flag[1], NONE);
  EXPECT_EQ(flag[2], RIGHT_CHAIN);
  EXPECT_EQ(flag[3], LEFT_CHAIN);
}

TEST(MembraneOutput, LostAndNotFiniteNameTheStep)
{
  EXPECT_EQ(lost_disk_error(12).rfind("a chain, escaped or band disk was lost at step 12 (", 0),
            0u);
  EXPECT_EQ(not_finite_error(7),
            "a chain particle position is not finite at step 7: the run has gone unstable; "
            "reduce the time step or the loading rate");
}

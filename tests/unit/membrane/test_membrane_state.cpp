// The state decisions of fix membrane2d (membrane_state.h) against
// hand-worked cases: accepting a chain, the watch list, type switching, the
// broadcast of a search result, the inertial-number window, when a detection
// is needed, the default lengths and the side load.
#include <gtest/gtest.h>

#include <cmath>

#include "membrane_state.h"

using namespace membrane;

namespace {

// five disks of radius 0.5 in a column from y = 0.5, touching; tags 10..14
std::vector<Disk> column()
{
  std::vector<Disk> d;
  for (int k = 0; k < 5; k++) d.push_back({10 + k, 0.0, 0.5 + k, 0.5});
  return d;
}

} // namespace

TEST(MembraneState, AcceptChainTakesTagsAndCountsChanges)
{
  SideChain s;
  const std::vector<Disk> band = column();
  ChainResult r;
  r.ok = true;
  r.chain = {0, 1, 2};
  r.escaped = {4};
  EXPECT_TRUE(accept_chain(s, band, r, nullptr)); // from nothing: a change
  EXPECT_EQ(s.chain_tags, (std::vector<AtomId>{10, 11, 12}));
  EXPECT_EQ(s.escaped_tags, (std::vector<AtomId>{14}));
  EXPECT_EQ(s.escaped_radius, (std::vector<double>{0.5}));
  EXPECT_TRUE(s.watch_band.empty());               // no watch asked
  EXPECT_FALSE(accept_chain(s, band, r, nullptr)); // the same chain again
  r.escaped.clear();
  EXPECT_TRUE(accept_chain(s, band, r, nullptr)); // an escapee less
}

// The band comes in the order the ranks gathered it (rank 0's disks first,
// each rank's in its own order): the same disks in another order, as after a
// disk moved to another rank, are the same chain and the same escapees.
TEST(MembraneState, EscapeesInAnotherBandOrderAreNoChange)
{
  SideChain s;
  std::vector<Disk> band = column();
  band[3].r = 0.25; // tag 13: a radius to follow
  ChainResult r;
  r.ok = true;
  r.chain = {0, 1, 2};
  r.escaped = {3, 4}; // tags 13, 14
  EXPECT_TRUE(accept_chain(s, band, r, nullptr));
  EXPECT_EQ(s.escaped_tags, (std::vector<AtomId>{13, 14}));
  // rank 1's disks first: tags 14, 13, 10, 11, 12
  const std::vector<Disk> moved = {band[4], band[3], band[0], band[1], band[2]};
  ChainResult q;
  q.ok = true;
  q.chain = {2, 3, 4};  // tags 10, 11, 12
  q.escaped = {0, 1};   // ascending indices: tags 14, 13
  EXPECT_FALSE(accept_chain(s, moved, q, nullptr));
  EXPECT_EQ(s.chain_tags, (std::vector<AtomId>{10, 11, 12}));
  EXPECT_EQ(s.escaped_tags, (std::vector<AtomId>{13, 14}));     // by tag
  EXPECT_EQ(s.escaped_radius, (std::vector<double>{0.25, 0.5})); // each with its disk's
  // and back: still no change
  EXPECT_FALSE(accept_chain(s, band, r, nullptr));
  // a different set is a change whatever the order
  q.escaped = {0};
  EXPECT_TRUE(accept_chain(s, moved, q, nullptr));
  EXPECT_EQ(s.escaped_tags, (std::vector<AtomId>{14}));
}

// A restart file written before the escapees were kept by tag holds them in
// band order: the same set found again is no change either.
TEST(MembraneState, UnsortedEscapeesFromARestartAreComparedAsASet)
{
  SideChain s;
  const std::vector<Disk> band = column();
  s.chain_tags = {10, 11, 12};
  s.escaped_tags = {14, 13};
  s.escaped_radius = {0.5, 0.5};
  ChainResult r;
  r.ok = true;
  r.chain = {0, 1, 2};
  r.escaped = {3, 4};
  EXPECT_FALSE(accept_chain(s, band, r, nullptr));
  EXPECT_EQ(s.escaped_tags, (std::vector<AtomId>{13, 14}));
}

TEST(MembraneState, ForgottenChainIsComparedWithTheNextOne)
{
  SideChain s;
  const std::vector<Disk> band = column();
  ChainResult r;
  r.ok = true;
  r.chain = {0, 1};
  accept_chain(s, band, r, nullptr);
  forget_chain(s);
  EXPECT_TRUE(s.chain_tags.empty());
  EXPECT_TRUE(s.watch.always);
  EXPECT_EQ(s.forgotten_tags, (std::vector<AtomId>{10, 11}));
  // the same chain found again after a forget is no change
  EXPECT_FALSE(accept_chain(s, band, r, nullptr));
  EXPECT_TRUE(s.forgotten_tags.empty());
}

TEST(MembraneState, AcceptChainWithWatchKeepsTheBand)
{
  SideChain s;
  s.side = Side::Right;
  const std::vector<Disk> band = column();
  ChainResult r;
  r.ok = true;
  r.chain = {0, 1, 2, 3, 4};
  r.visited = {0, 1, 2, 3, 4};
  const WatchSettings w{Platens{0.0, 5.0}, 0.01, 0.01};
  accept_chain(s, band, r, &w);
  ASSERT_EQ(s.watch_band.size(), 5u);
  ASSERT_EQ(s.now.size(), 5u);
  EXPECT_EQ(s.now[4].tag, 14);
  EXPECT_DOUBLE_EQ(s.watch.budget, 0.01);
}

TEST(MembraneState, WatchListHasOneEntryPerDiskWithAllItsRoles)
{
  SideChain sides[2];
  sides[LEFT].active = sides[RIGHT].active = true;
  sides[LEFT].chain_tags = {4, 2};
  sides[LEFT].escaped_tags = {6};
  sides[RIGHT].chain_tags = {2, 8};
  sides[RIGHT].watch.always = false;
  sides[RIGHT].watch_band = {{8, 0, 0, 1}, {10, 0, 0, 1}};
  sides[RIGHT].watch.disks = {0, 1};
  std::vector<WatchEntry> list;
  build_watch_list(sides, true, list);
  ASSERT_EQ(list.size(), 5u);
  EXPECT_EQ(list[0].tag, 2);
  EXPECT_EQ(list[0].chain_position[LEFT], 1);
  EXPECT_EQ(list[0].chain_position[RIGHT], 0);
  EXPECT_EQ(list[1].tag, 4);
  EXPECT_EQ(list[1].chain_position[LEFT], 0);
  EXPECT_EQ(list[1].chain_position[RIGHT], -1);
  EXPECT_EQ(list[2].tag, 6); // an escapee: no role
  EXPECT_EQ(list[2].chain_position[LEFT], -1);
  EXPECT_EQ(list[3].tag, 8);
  EXPECT_EQ(list[3].chain_position[RIGHT], 1);
  EXPECT_EQ(list[3].band_index[RIGHT], 0);
  EXPECT_EQ(list[4].tag, 10);
  EXPECT_EQ(list[4].band_index[RIGHT], 1);
  // every N: the watched relations are not gathered
  build_watch_list(sides, false, list);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[3].tag, 8);
}

TEST(MembraneState, SearchResultSurvivesPackingAndCorruptOnesAreRefused)
{
  ChainResult r;
  r.ok = false;
  r.failure = "no disk touches the top";
  r.chain = {3, 1};
  r.escaped = {0, 7, 9};
  r.visited = {1, 3, 5};
  r.pruned = 2;
  r.failed_starts = 4;
  std::vector<int> buf;
  pack_result(r, buf);
  ChainResult back;
  ASSERT_TRUE(unpack_result(buf.data(), buf.size(), back));
  EXPECT_EQ(back.ok, r.ok);
  EXPECT_EQ(back.failure, r.failure);
  EXPECT_EQ(back.chain, r.chain);
  EXPECT_EQ(back.escaped, r.escaped);
  EXPECT_EQ(back.visited, r.visited);
  EXPECT_EQ(back.pruned, 2);
  EXPECT_EQ(back.failed_starts, 4);
  EXPECT_FALSE(unpack_result(buf.data(), buf.size() - 1, back)); // cut
  EXPECT_FALSE(unpack_result(buf.data(), 3, back));
  buf[1] = -1;
  EXPECT_FALSE(unpack_result(buf.data(), buf.size(), back));
}

TEST(MembraneState, InertialWindowWarnsOnlyForTwoWindowsInARow)
{
  // height 1 -> 0.99 over 10 steps of 1 ms: rate 1 /s; I = 1 x 1e-3 x sqrt(2650 / 1e5)
  const double want = 1e-3 * std::sqrt(2650.0 / 1e5);
  InertialWindow w;
  EXPECT_FALSE(w.update(0, 1.0, 1e-3, 10, 1e-3, 2650.0, 1e5, 1e-4)); // opens
  EXPECT_FALSE(w.update(5, 0.995, 1e-3, 10, 1e-3, 2650.0, 1e5, 1e-4));
  EXPECT_FALSE(w.update(10, 0.99, 1e-3, 10, 1e-3, 2650.0, 1e5, 1e-4)); // first above
  EXPECT_NEAR(w.rate, 1.0, 1e-12);
  EXPECT_NEAR(w.value, want, 1e-15);
  EXPECT_TRUE(w.was_above);
  const double h = 0.99 * (1.0 - 0.01); // the same rate again
  EXPECT_TRUE(w.update(20, h, 1e-3, 10, 1e-3, 2650.0, 1e5, 1e-4));
  // at zero pressure there is no inertial number
  EXPECT_FALSE(w.update(30, h * 0.99, 1e-3, 10, 1e-3, 2650.0, 0.0, 1e-4));
  EXPECT_EQ(w.value, 0.0);
  // a step before the window (a new run from an earlier state) restarts it
  EXPECT_FALSE(w.update(3, 1.0, 1e-3, 10, 1e-3, 2650.0, 1e5, 1e-4));
  EXPECT_EQ(w.first_step, 3);
}

TEST(MembraneState, DetectionIsNeededWhenDisksOrPlatensMoveTheBudget)
{
  SideChain sides[2];
  sides[LEFT].active = sides[RIGHT].active = true;
  for (SideChain &s : sides) s.watch.always = false; // nothing watched exactly
  const Platens p{0.0, 1.0};
  EXPECT_FALSE(detection_needed(sides, p, p, 0.01, 0.004, 0.01));
  EXPECT_TRUE(detection_needed(sides, p, p, 0.01, 0.005, 0.01)); // 2 x 0.005 >= budget
  EXPECT_TRUE(detection_needed(sides, Platens{0.0, 0.993}, p, 0.01, 0.004, 0.01));
  EXPECT_FALSE(detection_needed(sides, Platens{0.0, 0.995}, p, 0.01, 0.004, 0.01));
  sides[RIGHT].watch.always = true; // a result that could not be watched
  EXPECT_TRUE(detection_needed(sides, p, p, 0.01, 0.0, 0.01));
  sides[RIGHT].active = false;
  EXPECT_FALSE(detection_needed(sides, p, p, 0.01, 0.0, 0.01));
}

TEST(MembraneState, BandIsTheGivenOneOrTheDefault)
{
  Definition def;
  RunState run;
  set_lengths(def, 0.002, 4e-5, run);
  EXPECT_DOUBLE_EQ(run.band_width, DEFAULT_BAND * 0.002);
  EXPECT_DOUBLE_EQ(run.search_width, run.band_width);
  EXPECT_DOUBLE_EQ(run.tolerance, 4e-5);
  def.band_given = 0.05;
  run.search_width = 0.3; // widened in an earlier run: kept
  set_lengths(def, 0.002, 0.0, run);
  EXPECT_EQ(run.band_width, 0.05);
  EXPECT_EQ(run.search_width, 0.3);
  EXPECT_EQ(run.tolerance, 0.0);
}

TEST(MembraneState, SideLoadSumsToThePressureOnTheChord)
{
  // right side, two disks touching at (0, 1): polyline (0,0) (0,1) (0,2)
  const std::vector<Disk> chain{{1, 0.0, 0.5, 0.5}, {2, 0.0, 1.5, 0.5}};
  SideLoad load;
  load_side(chain, Side::Right, Platens{0.0, 2.0}, 100.0, 0.1, load);
  ASSERT_EQ(load.polyline.size(), 3u);
  ASSERT_EQ(load.forces.size(), 2u);
  // the sum is p t (-Dy, Dx) with D = (0, 2): (-20, 0)
  EXPECT_NEAR(load.total.x(), -20.0, 1e-12);
  EXPECT_NEAR(load.total.y(), 0.0, 1e-12);
}

TEST(MembraneState, ADenseWindowSwitchesTheWatchOffForAWhile)
{
  RunState run;
  EXPECT_FALSE(unwatched_step(run, 0));
  long long step = 100;
  // one detection short of dense: the window closes and a new one opens
  for (long long k = 0; k < DENSE_WINDOW; k++)
    EXPECT_FALSE(count_watched_step(run, step++, k >= DENSE_WINDOW - DENSE_DETECTIONS + 1));
  EXPECT_EQ(run.dense.window_steps, 0);
  EXPECT_EQ(run.dense.window_detections, 0);
  EXPECT_FALSE(unwatched_step(run, step));
  // exactly DENSE_DETECTIONS of DENSE_WINDOW, spread over the window
  const long long n = DENSE_DETECTIONS - 1, m = DENSE_WINDOW - 1;
  for (long long k = 0; k < m; k++)
    EXPECT_FALSE(count_watched_step(run, step++, (k + 1) * n / m != k * n / m));
  EXPECT_EQ(run.dense.window_detections + 1, DENSE_DETECTIONS);
  const long long last = step;
  EXPECT_TRUE(count_watched_step(run, step, true));
  EXPECT_EQ(run.dense.window_steps, 0);
  EXPECT_EQ(run.dense.unwatched_until, last + UNWATCHED_STEPS);
  EXPECT_TRUE(unwatched_step(run, last + 1));
  EXPECT_TRUE(unwatched_step(run, last + UNWATCHED_STEPS - 1));
  EXPECT_FALSE(unwatched_step(run, last + UNWATCHED_STEPS)); // the watch is tried again
}

// A style's own schedule (fix membrane3d: 14 of 20, then 2 000 steps unwatched).
TEST(MembraneState, ADenseScheduleOfItsOwn)
{
  DenseDetections dense;
  dense.window = 20;
  dense.dense = 14;
  dense.unwatched_steps = 2000;
  long long step = 10;
  for (int k = 0; k < 20; k++) EXPECT_FALSE(dense.count_watched(step++, k < 13)); // 13 of 20
  EXPECT_FALSE(dense.unwatched(step));
  for (int k = 0; k < 19; k++) EXPECT_FALSE(dense.count_watched(step++, k < 13));
  EXPECT_TRUE(dense.count_watched(step, true)); // the 14th of 20
  EXPECT_TRUE(dense.unwatched(step + 1999));
  EXPECT_FALSE(dense.unwatched(step + 2000));
}

// reset_timestep 0 (or a restart of an earlier step) after a dense window closed at
// step 1 000 000: the steps of the new count are watched again, not the next 10^6
TEST(MembraneState, AStepCounterSetBackEndsTheUnwatchedRun)
{
  DenseDetections dense;
  for (long long step = 1000000 - 99; step <= 1000000; step++) dense.count_watched(step, true);
  EXPECT_EQ(dense.unwatched_until, 1000000 + UNWATCHED_STEPS);
  EXPECT_TRUE(dense.unwatched(1000001));
  EXPECT_FALSE(dense.unwatched(0));
  EXPECT_FALSE(dense.unwatched(1));
  EXPECT_FALSE(dense.unwatched(1000000 - 1)); // one step back: UNWATCHED_STEPS + 1 ahead
}

TEST(MembraneState, ADroppedWatchMakesTheNextWatchedStepDetect)
{
  SideChain chains[2];
  chains[LEFT].active = true;
  chains[LEFT].side = Side::Left;
  chains[LEFT].watch.always = false; // nothing watched: nothing can flip
  const Platens platens{0.0, 1.0};
  EXPECT_FALSE(detection_needed(chains, platens, platens, 0.01, 0.0, 0.1));
  chains[LEFT].watch.pairs.push_back({0, 1, true, true});
  chains[LEFT].watch_band = {{1, 0.0, 0.5, 0.1}, {2, 0.2, 0.5, 0.1}};
  chains[LEFT].now = chains[LEFT].watch_band;
  drop_watch(chains[LEFT]);
  EXPECT_TRUE(chains[LEFT].watch.always);
  EXPECT_TRUE(chains[LEFT].watch.pairs.empty());
  EXPECT_TRUE(chains[LEFT].watch_band.empty());
  EXPECT_TRUE(detection_needed(chains, platens, platens, 0.01, 0.0, 0.1));
  std::vector<WatchEntry> list;
  build_watch_list(chains, true, list); // no relation disks left to gather
  EXPECT_TRUE(list.empty());
}

TEST(MembraneState, PlatensMovedBeyondTheLimitSinceTheDetection)
{
  RunState run;
  run.ylo_detected = -0.001;
  run.yhi_detected = 0.006196;
  run.tolerance = 4e-5; // 0.02 D50 of 2 mm
  EXPECT_DOUBLE_EQ(platen_move_limit(run, 0.002), 4e-5);
  EXPECT_FALSE(platens_moved(run, Platens{-0.001, 0.006196}, 4e-5));
  EXPECT_FALSE(platens_moved(run, Platens{-0.00103, 0.006196}, 4e-5)); // 0.03 mm: within
  EXPECT_TRUE(platens_moved(run, Platens{-0.001, 0.007096}, 4e-5));   // 0.9 mm up
  EXPECT_TRUE(platens_moved(run, Platens{-0.001, 0.005896}, 4e-5));   // 0.3 mm down
  EXPECT_TRUE(platens_moved(run, Platens{-0.00095, 0.006196}, 4e-5)); // ylo 0.05 mm up
  run.tolerance = 0.0; // tolerance 0: at least 0.01 D50
  EXPECT_DOUBLE_EQ(platen_move_limit(run, 0.002), 2e-5);
}

// A failed search widens the band 2.5 x; while a chain stays lost it is widened again
// at every step (6.25 x a step): it stops at MOST_SEARCH_WIDTH D50, where it was inf
// after ~390 steps.
TEST(MembraneState, AWidenedBandStaysFinite)
{
  const double d50 = 2e-3;
  EXPECT_DOUBLE_EQ(widened_band(8e-3, d50), 2e-2);
  double width = 8e-3;
  for (int step = 0; step < 1000; step++) width = widened_band(widened_band(width, d50), d50);
  EXPECT_DOUBLE_EQ(width, MOST_SEARCH_WIDTH * d50);
}

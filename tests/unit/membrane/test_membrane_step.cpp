// The decisions of a step of fix membrane2d (membrane_step.h) against
// hand-worked cases: the schedule, a detection with its widenings and lost
// chains, the stability warnings.
#include <gtest/gtest.h>

#include "membrane_output.h"
#include "membrane_step.h"

using namespace membrane;

namespace {

// the band the fake search returns: tags 10..14, only their tags matter
std::vector<Disk> column()
{
  return {{10, 0.0, 0.5, 0.5},
          {11, 0.0, 1.5, 0.5},
          {12, 0.0, 2.5, 0.5},
          {13, 0.0, 3.5, 0.5},
          {14, 1.0, 3.5, 0.5}};
}

// A run after a detection at step 10 with the platens at 0 and 10, the
// tolerance 0.1 (the platens' move limit: it is above 0.01 x D50 = 0.01).
RunState detected_at_10()
{
  RunState run;
  run.force_detection = false;
  run.last_detection = 10;
  run.ylo_detected = 0.0;
  run.yhi_detected = 10.0;
  run.tolerance = 0.1;
  return run;
}

} // namespace

TEST(MembraneStep, EveryNDetectsAfterNStepsOrWhenAPlatenMoved)
{
  const RunState run = detected_at_10();
  SharedKeywords every5;
  every5.every = 5;
  EXPECT_FALSE(detection_due(run, every5, 14, Platens{0.0, 10.0}, 1.0));
  EXPECT_TRUE(detection_due(run, every5, 15, Platens{0.0, 10.0}, 1.0));
  EXPECT_FALSE(detection_due(run, every5, 14, Platens{0.0, 10.05}, 1.0)); // within the tolerance
  EXPECT_TRUE(detection_due(run, every5, 14, Platens{0.0, 10.2}, 1.0));
  EXPECT_TRUE(detection_due(run, every5, 9, Platens{0.0, 10.0}, 1.0)); // step set back
  RunState forced = run;
  forced.force_detection = true;
  EXPECT_TRUE(detection_due(forced, every5, 11, Platens{0.0, 10.0}, 1.0));
  // every auto: the platens are watched with the chains, not scheduled
  const SharedKeywords automatic;
  EXPECT_FALSE(detection_due(run, automatic, 14, Platens{0.0, 10.2}, 1.0));
  EXPECT_FALSE(detection_due(run, automatic, 1000, Platens{0.0, 10.0}, 1.0));
}

// The right side only, a band of 1 at first; the search finds the chain 10,
// 11, 12 (escapee 14) of the disk column in a band at least `found_from`
// wide, else fails with "cut"; detections at platens 0 and 5.
struct RightSide {
  SideChain chains[2];
  SideData sides[2];
  RunState run;
  std::vector<WatchEntry> list;
  double found_from;
  std::vector<double> widths;

  explicit RightSide(double found) : found_from(found)
  {
    chains[RIGHT].active = true;
    run.search_width = 1.0;
    run.force_detection = false;
  }
  std::vector<Notice> detect_at(long long step)
  {
    auto search = [this](double width, const bool(&pending)[2], ChainResult(&results)[2]) {
      widths.push_back(width);
      EXPECT_FALSE(pending[LEFT]);
      EXPECT_TRUE(pending[RIGHT]);
      sides[RIGHT].band = column();
      ChainResult &r = results[RIGHT];
      r = ChainResult();
      r.ok = width >= found_from;
      if (r.ok) {
        r.chain = {0, 1, 2};
        r.escaped = {4};
      } else {
        r.failure = "cut";
      }
    };
    return detect(chains, sides, run, list, 1.0, true, nullptr, Platens{0.0, 5.0}, step, search);
  }
};

TEST(MembraneStep, ADetectionFindsTheChainInTheBandItHas)
{
  RightSide s(1.0);
  EXPECT_TRUE(s.detect_at(7).empty());
  EXPECT_EQ(s.widths, (std::vector<double>{1.0}));
  EXPECT_EQ(s.chains[RIGHT].chain_tags, (std::vector<AtomId>{10, 11, 12}));
  EXPECT_EQ(s.chains[RIGHT].escaped_tags, (std::vector<AtomId>{14}));
  EXPECT_EQ(s.run.counters.detections, 1);
  EXPECT_EQ(s.run.counters.changes, 1);
  EXPECT_EQ(s.run.counters.widenings, 0);
  EXPECT_EQ(s.run.search_width, 1.0);
  EXPECT_FALSE(s.run.force_detection);
  EXPECT_EQ(s.run.last_detection, 7);
  EXPECT_EQ(s.run.ylo_detected, 0.0);
  EXPECT_EQ(s.run.yhi_detected, 5.0);
  // gathered from now on: the chain disks and the escapee
  std::vector<AtomId> listed;
  for (const WatchEntry &e : s.list) listed.push_back(e.tag);
  EXPECT_EQ(listed, (std::vector<AtomId>{10, 11, 12, 14}));
}

// Found in the band widened once (1 x 2.5): the width is kept and both sides
// are searched again with it at the next step.
TEST(MembraneStep, AWidenedBandIsKept)
{
  RightSide s(2.0);
  EXPECT_TRUE(s.detect_at(7).empty());
  EXPECT_EQ(s.widths, (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(s.run.counters.widenings, 1);
  EXPECT_EQ(s.run.search_width, 2.5);
  EXPECT_TRUE(s.run.force_detection);
  EXPECT_EQ(s.chains[RIGHT].chain_tags, (std::vector<AtomId>{10, 11, 12}));
}

// Never found: widened twice (1, 2.5, 6.25); without a chain to keep, the
// run stops; with one, it is warned about once and searched again.
TEST(MembraneStep, ALostChainStopsTheRunOrIsKeptAndWarnedOnce)
{
  RightSide s(1e6); // beyond MOST_SEARCH_WIDTH D50: never
  auto notices = s.detect_at(7);
  EXPECT_EQ(s.widths, (std::vector<double>{1.0, 2.5, 6.25}));
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_TRUE(notices[0].fatal);
  EXPECT_EQ(notices[0].text, no_chain_error("right side at step 7", "cut"));
  EXPECT_EQ(s.run.counters.failures, 1);
  EXPECT_EQ(s.run.counters.widenings, 2);
  EXPECT_EQ(s.run.search_width, 6.25);

  s.chains[RIGHT].chain_tags = {10, 11, 12};
  s.chains[RIGHT].watch.always = false;
  notices = s.detect_at(8);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_FALSE(notices[0].fatal);
  EXPECT_EQ(notices[0].text, chain_lost_warning("right side at step 8", "cut"));
  EXPECT_TRUE(s.chains[RIGHT].watch.always); // searched again at the next step
  EXPECT_EQ(s.chains[RIGHT].chain_tags, (std::vector<AtomId>{10, 11, 12}));
  EXPECT_TRUE(s.detect_at(9).empty());
  EXPECT_EQ(s.run.counters.failures, 3);
  EXPECT_EQ(s.run.counters.detections, 3);
}

TEST(MembraneStep, TheChainStepIsWarnedOnce)
{
  RunState run;
  EXPECT_TRUE(stability_warnings(run, 0.02, 7, 100, 10.0, 1e-6, 1.0, 2500.0, 1e5).empty());
  const auto first = stability_warnings(run, 0.03, 7, 101, 10.0, 1e-6, 1.0, 2500.0, 1e5);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0], chain_step_warning(7, 0.03, 101));
  EXPECT_TRUE(stability_warnings(run, 0.04, 8, 102, 10.0, 1e-6, 1.0, 2500.0, 1e5).empty());
}

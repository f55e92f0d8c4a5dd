#include <gtest/gtest.h>

#include <string>

#include "shared_keywords.h"

using membrane::detection_scheduled;
using membrane::SharedKeywords;

TEST(DetectionSchedule, EveryNCountsFromTheLastDetection)
{
  SharedKeywords k;
  k.every = 10;
  EXPECT_TRUE(detection_scheduled(k, 0, -1)); // none yet
  EXPECT_FALSE(detection_scheduled(k, 9, 0));
  EXPECT_TRUE(detection_scheduled(k, 10, 0));
  // a detection forced at step 13 (a platen jump) restarts the count: not 20, but 23
  EXPECT_FALSE(detection_scheduled(k, 20, 13));
  EXPECT_FALSE(detection_scheduled(k, 22, 13));
  EXPECT_TRUE(detection_scheduled(k, 23, 13));
  // a run that starts at step 1005 after one detected at 1000
  EXPECT_FALSE(detection_scheduled(k, 1005, 1000));
  EXPECT_TRUE(detection_scheduled(k, 1010, 1000));
}

TEST(DetectionSchedule, AStepCounterSetBackDetects)
{
  SharedKeywords k;
  k.every = 100;
  EXPECT_TRUE(detection_scheduled(k, 0, 500)); // reset_timestep 0 after a detection at 500
  EXPECT_FALSE(detection_scheduled(k, 500, 500));
}

TEST(DetectionSchedule, EveryAutoLeavesTheRestToTheWatch)
{
  SharedKeywords k; // the default
  EXPECT_TRUE(k.automatic());
  EXPECT_TRUE(detection_scheduled(k, 0, -1));
  EXPECT_TRUE(detection_scheduled(k, 3, 7));
  EXPECT_FALSE(detection_scheduled(k, 1000000, 0));
  EXPECT_FALSE(detection_scheduled(k, 8, 7));
}

TEST(SharedKeywords, DefaultsAreOneForBothStyles)
{
  const SharedKeywords k;
  EXPECT_EQ(k.every, membrane::EVERY_AUTO);
  EXPECT_EQ(k.frictionless, 0);
  EXPECT_EQ(k.tolerance_given, -1.0);
}

TEST(SharedKeywords, ToleranceIsLimitedInD50)
{
  // D50 = 2 mm, at most 0.25 D50 = 0.5 mm, default 0.02 D50 = 0.04 mm
  EXPECT_EQ(membrane::tolerance_problem(5e-4, 2e-3, 0.25, 0.02), "");
  EXPECT_EQ(membrane::tolerance_problem(0.0, 2e-3, 0.25, 0.02), "");
  const std::string t = membrane::tolerance_problem(1e-3, 2e-3, 0.25, 0.02);
  EXPECT_NE(t.find("is 0.5 x D50 (D50 = 0.002)"), std::string::npos) << t;
  EXPECT_NE(t.find("at most 0.25 x D50; typically 0.02 x D50 = 4e-05 (the default)"),
            std::string::npos)
      << t;
  // absurd: refused
  EXPECT_EQ(membrane::tolerance_problem(1e300, 2e-3, 2.0, 0.7).substr(0, 3), "is ");
}

TEST(SharedKeywords, RestartMessagesSayWhatIsFoundAnew)
{
  EXPECT_EQ(membrane::restart_unreadable("it is cut", false),
            "this fix's state in the restart file cannot be read: it is cut");
  EXPECT_NE(membrane::restart_unreadable("x", true).find("read it with the version that wrote it"),
            std::string::npos);
  EXPECT_EQ(membrane::restart_other_definition("tolerance or every"),
            "this fix is defined otherwise than in the restart file (tolerance or every): the "
            "membrane is found anew at the first step and its counters start from 0");
}

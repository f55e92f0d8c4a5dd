// What fix membrane2d writes (membrane_output.h): its vector from the state,
// the limits of its lengths and the wording of its warnings.
#include <gtest/gtest.h>

#include <filesystem>

#include <cmath>

#include "membrane_output.h"

using namespace membrane;

TEST(MembraneOutput, VectorOfARectangularSample)
{
  // straight chains at x = -1 and x = 2 between platens y = 0 and 3: area 9
  SideChain chains[2];
  chains[LEFT].active = chains[RIGHT].active = true;
  chains[LEFT].chain_tags = {1, 2};
  chains[RIGHT].chain_tags = {3, 4, 5};
  chains[RIGHT].escaped_tags = {6};
  SideLoad loads[2];
  loads[LEFT].polyline = {{-1.0, 0.0}, {-1.0, 1.5}, {-1.0, 3.0}};
  loads[RIGHT].polyline = {{2.0, 0.0}, {2.0, 1.0}, {2.0, 2.0}, {2.0, 3.0}};
  loads[LEFT].total = {30.0, 0.0};
  loads[RIGHT].total = {-30.0, 0.5};
  RunState run;
  run.counters = {7, 1, 2, 3};
  run.inertial.value = 2e-4;
  double v[OUTPUT_SIZE];
  output_vector(chains, loads, run, Platens{0.0, 3.0}, 1e5, 0.004, v);
  EXPECT_DOUBLE_EQ(v[AREA], 9.0);
  EXPECT_DOUBLE_EQ(v[MEAN_WIDTH], 3.0);
  EXPECT_DOUBLE_EQ(v[MID_WIDTH], 3.0);
  EXPECT_EQ(v[CHAIN_LEFT], 2.0);
  EXPECT_EQ(v[CHAIN_RIGHT], 3.0);
  EXPECT_EQ(v[ESCAPED], 1.0);
  EXPECT_EQ(v[FX_LEFT], 30.0);
  EXPECT_EQ(v[FY_RIGHT], 0.5);
  EXPECT_EQ(v[DETECTIONS], 7.0);
  EXPECT_EQ(v[FAILURES], 1.0);
  EXPECT_EQ(v[WIDENINGS], 2.0);
  EXPECT_EQ(v[CHANGES], 3.0);
  EXPECT_EQ(v[PRESSURE], 1e5);
  EXPECT_EQ(v[CHAIN_STEP], 0.004);
  EXPECT_EQ(v[INERTIAL], 2e-4);
  // one side only: no area or widths, the other side's entries 0
  chains[LEFT].active = false;
  loads[LEFT] = SideLoad();
  output_vector(chains, loads, run, Platens{0.0, 3.0}, 1e5, 0.004, v);
  EXPECT_EQ(v[AREA], 0.0);
  EXPECT_EQ(v[MID_WIDTH], 0.0);
  EXPECT_EQ(v[CHAIN_LEFT], 0.0);
  EXPECT_EQ(v[FX_LEFT], 0.0);
}

TEST(MembraneOutput, LengthLimitsAreRelativeToD50)
{
  EXPECT_EQ(band_problem(BAND_MIN * 0.002, 0.002), "");
  EXPECT_NE(band_problem(0.5 * BAND_MIN * 0.002, 0.002), "");
  EXPECT_NE(band_problem(1e-12, 0.002).find("is 5e-10 x D50 (D50 = 0.002)"), std::string::npos);
  EXPECT_EQ(tolerance_problem(MOST_TOLERANCE * 0.002, 0.002, MOST_TOLERANCE, DEFAULT_TOLERANCE), "");
  const std::string t = tolerance_problem(0.02, 0.002, MOST_TOLERANCE, DEFAULT_TOLERANCE);
  EXPECT_NE(t.find("is 10 x D50"), std::string::npos) << t;
  EXPECT_NE(t.find("typically 0.02 x D50 = 4e-05 (the default)"), std::string::npos) << t;
}

TEST(MembraneOutput, WarningsNameTheNumbers)
{
  const std::string c = chain_step_warning(42, 0.031, 1200);
  EXPECT_NE(c.find("chain disk 42 moved 0.031 of its radius in one step at step 1200 (limit "
                   "0.025; quasi-static chains move < 0.001)"),
            std::string::npos)
      << c;
  InertialWindow w;
  w.value = 2e-3;
  w.rate = 0.5;
  const std::string i = inertial_warning(w, 1e-3, 5000, 0.002, 2650, 1e5);
  EXPECT_NE(i.find("I = 0.002 > 0.001 at step 5000 (axial strain rate 0.5 1/s"), std::string::npos)
      << i;
  EXPECT_NE(i.find("lower the loading rate below 0.25 1/s"), std::string::npos) << i;
}

TEST(MembraneOutput, TrafficPerStepAndPerDetection)
{
  EXPECT_EQ(traffic_summary(199172.0, 87200.0, 100, 10, 3, 0.25, 0.0125),
            "each rank received 1.99 kB per step (chain, escaped and watched disks) and "
            "8.72 kB per detection (bands, search results) over 100 steps with 10 detections (3 "
            "of them a pass over all disks); the fix took 0.25 s (slowest rank), 0.0125 s of it "
            "in chain searches (one rank per side)");
  // a run of 0 steps: its setup's gather, no detection
  EXPECT_EQ(traffic_summary(1972.0, 0.0, 0, 0, 0, 0.0, 0.0),
            "each rank received 1.97 kB per step (chain, escaped and watched disks) and 0 kB "
            "per detection (bands, search results) over 0 steps with 0 detections (0 of them a "
            "pass over all disks); the fix took 0 s (slowest rank), 0 s of it in chain searches "
            "(one rank per side)");
}

// ---- the VTK frame (membrane_vtk.h) and collection (vtk_series.h) ----------------------

#include "membrane_vtk.h"
#include "vtk_series.h"

TEST(MembraneVtk, AFrameHoldsThePolylineThenTheDisksOfEachSide)
{
  const membrane::Polyline line = {{0.0, 0.0}, {0.5, 1.0}, {0.0, 2.0}};
  const std::vector<membrane::Disk> disks = {{7, 0.1, 0.5, 0.25}, {3, -0.1, 1.5, 0.5}};
  const std::vector<Eigen::Vector2d> forces = {{-1.0, 0.5}, {-2.0, -0.5}};
  const std::string vtp = membrane::vtk_frame({{2, &line, &disks, &forces}});
  EXPECT_NE(vtp.find("NumberOfPoints=\"5\" NumberOfVerts=\"2\" NumberOfLines=\"1\""), std::string::npos);
  // points 0-2 the polyline (one Line cell), 3-4 the disks (a Vertex cell each)
  EXPECT_NE(vtp.find("<Lines>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          0 1 2\n"),
            std::string::npos);
  EXPECT_NE(vtp.find("<Verts>\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          3 4\n"),
            std::string::npos);
  EXPECT_NE(vtp.find("Name=\"tag\" NumberOfComponents=\"1\" format=\"ascii\">\n          -1 -1 -1 7 3\n"),
            std::string::npos);
  EXPECT_NE(vtp.find("Name=\"force\" NumberOfComponents=\"3\" format=\"ascii\">\n          0 0 0 0 0 0 0 0 0 -1 0.5 0 -2 -0.5 0\n"),
            std::string::npos);
  EXPECT_NE(vtp.find("Name=\"side\" NumberOfComponents=\"1\" format=\"ascii\">\n          2 2 2 2 2\n"),
            std::string::npos);
}

TEST(MembraneVtk, TheCollectionListsTheFramesInOrder)
{
  const std::string pvd = vtk_series::pvd_collection({{0, "m_0.vtp"}, {50, "m_50.vtp"}});
  const std::size_t first = pvd.find("<DataSet timestep=\"0\" part=\"0\" file=\"m_0.vtp\"/>");
  const std::size_t second = pvd.find("<DataSet timestep=\"50\" part=\"0\" file=\"m_50.vtp\"/>");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(first, second);
  EXPECT_NE(vtk_series::pvd_collection({}).find("<Collection>\n  </Collection>"), std::string::npos);
  // read back
  const std::vector<std::pair<long long, std::string>> frames = {{0, "m_0.vtp"}, {1234567890123, "m_1234567890123.vtp"}};
  EXPECT_EQ(vtk_series::pvd_frames(vtk_series::pvd_collection(frames)), frames);
  EXPECT_TRUE(vtk_series::pvd_frames("").empty());
  EXPECT_TRUE(vtk_series::pvd_frames("<DataSet timestep=\"3\" file=\"cut").empty());
}

// Two fixes must not write one file however its name is spelled.
// After a reset_timestep the later run writes frames 0, 5, 10 again over the files of
// the earlier one: the collection lists each once (it listed 0, 5, 10, 0, 5, 10).
TEST(MembraneVtk, AStepGoingBackDropsTheLaterFrames)
{
  vtk_series::Series series;
  series.name("series_back_test");
  ASSERT_EQ(series.start(0), "");
  for (long long step : {0, 5, 10, 0, 5}) ASSERT_EQ(series.add(step, "frame"), "");
  EXPECT_EQ(vtk_series::pvd_frames(vtk_series::read_file(series.pvd())),
            (vtk_series::Frames{{0, "series_back_test_0.vtp"}, {5, "series_back_test_5.vtp"}}));
  for (const char *f : {"series_back_test.pvd", "series_back_test_0.vtp", "series_back_test_5.vtp",
                        "series_back_test_10.vtp"})
    std::remove(f);
}

TEST(MembraneVtk, OneFileHoweverItIsNamed)
{
  const std::string here = std::filesystem::current_path().string();
  EXPECT_TRUE(vtk_series::same_file("a.pvd", "./a.pvd"));
  EXPECT_TRUE(vtk_series::same_file("a.pvd", here + "/a.pvd"));
  EXPECT_TRUE(vtk_series::same_file("nosuchdir/../a.pvd", "a.pvd")); // neither need exist
  EXPECT_FALSE(vtk_series::same_file("a.pvd", "b.pvd"));
  EXPECT_FALSE(vtk_series::same_file("", ""));  // no file: no clash
}

TEST(MembraneOutput, PolylineFramesEachStepOnce)
{
  std::vector<PolylineFrame> frames;
  EXPECT_EQ(polyline_frame_start(frames, 0, 0), 0);
  EXPECT_EQ(polyline_frame_start(frames, 5, 100), 100);
  EXPECT_EQ(polyline_frame_start(frames, 10, 200), 200);
  // a continued run starts at step 10 again: its frame replaces the last one
  EXPECT_EQ(polyline_frame_start(frames, 10, 300), 200);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(polyline_frame_start(frames, 15, 300), 300);
  // reset_timestep 0: every frame goes, the file starts again
  EXPECT_EQ(polyline_frame_start(frames, 0, 400), 0);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].step, 0);
  EXPECT_EQ(frames[0].offset, 0);
  // a restart of step 7 read into frames 0, 5, 10: 10 goes, 5 stays
  EXPECT_EQ(polyline_frame_start(frames, 5, 100), 100);
  EXPECT_EQ(polyline_frame_start(frames, 10, 200), 200);
  EXPECT_EQ(polyline_frame_start(frames, 7, 300), 200);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_EQ(frames[2].step, 7);
}

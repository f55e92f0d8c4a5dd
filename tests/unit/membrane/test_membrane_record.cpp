// The restart record: a round trip gives back every field; a record of an
// earlier format, another version, a cut one or one with extra fields is refused.
#include <gtest/gtest.h>

#include "membrane_record.h"

using namespace membrane;

namespace {

DetectionWatch sample_watch()
{
  DetectionWatch w;
  w.budget = 3.5e-5;
  w.always = false;
  w.pairs = {{0, 3, true, false}, {2, 5, false, true}};
  w.platen_contacts = {{1, true, true}, {4, false, false}};
  w.ahead = {{0, 6}};
  w.disks = {0, 1, 2, 3, 4, 5, 6};
  return w;
}

std::vector<double> sample_record()
{
  RestartRecordWriter out = record_writer();
  out.put(42.0);
  put_tags(out, {7, 3, 11});
  put_disks(out, {{5, 0.1, 0.2, 0.003}, {9, -1e-3, 0.5, 0.001}});
  put_watch(out, sample_watch());
  return out.finish();
}

} // namespace

TEST(MembraneRecord, RoundTripGivesEveryField)
{
  const std::vector<double> rec = sample_record();
  RestartRecordReader in = record_reader(rec.data(), rec.size());
  ASSERT_TRUE(in.ok()) << in.error();
  EXPECT_EQ(in.version(), RECORD_VERSION);
  EXPECT_EQ(in.get(), 42.0);
  std::vector<AtomId> tags;
  get_tags(in, tags);
  EXPECT_EQ(tags, (std::vector<AtomId>{7, 3, 11}));
  std::vector<Disk> disks;
  get_disks(in, disks);
  ASSERT_EQ(disks.size(), 2u);
  EXPECT_EQ(disks[1].tag, 9);
  EXPECT_EQ(disks[1].x, -1e-3);
  EXPECT_EQ(disks[0].r, 0.003);
  DetectionWatch w;
  get_watch(in, w);
  const DetectionWatch want = sample_watch();
  EXPECT_EQ(w.budget, want.budget);
  EXPECT_FALSE(w.always);
  ASSERT_EQ(w.pairs.size(), 2u);
  EXPECT_EQ(w.pairs[1].j, 5);
  EXPECT_FALSE(w.pairs[1].ij);
  EXPECT_TRUE(w.pairs[1].ji);
  ASSERT_EQ(w.platen_contacts.size(), 2u);
  EXPECT_FALSE(w.platen_contacts[1].bottom);
  EXPECT_EQ(w.ahead[0].other, 6);
  EXPECT_EQ(w.disks, want.disks);
  EXPECT_TRUE(in.finished()) << in.error();
}

TEST(MembraneRecord, EarlierFormatIsRefused)
{
  // a version-1 record starts with the left chain length
  const std::vector<double> old = {20.0, 1.0, 2.0, 3.0};
  RestartRecordReader in = record_reader(old.data(), old.size());
  EXPECT_FALSE(in.ok());
  EXPECT_NE(in.error().find("earlier version"), std::string::npos);
}

TEST(MembraneRecord, OtherVersionIsRefused)
{
  std::vector<double> rec = sample_record();
  rec[1] = RECORD_VERSION + 1;
  RestartRecordReader in = record_reader(rec.data(), rec.size());
  EXPECT_FALSE(in.ok());
  EXPECT_NE(in.error().find("format " + std::to_string(RECORD_VERSION + 1)), std::string::npos);
}

TEST(MembraneRecord, CutRecordIsRefused)
{
  std::vector<double> rec = sample_record();
  rec[2] = 8; // the header says the record ends inside the tag list
  RestartRecordReader in = record_reader(rec.data(), rec.size());
  ASSERT_TRUE(in.ok());
  in.get();
  std::vector<AtomId> tags;
  get_tags(in, tags); // 3 tags announced, 3 fit
  std::vector<Disk> disks;
  get_disks(in, disks);
  EXPECT_FALSE(in.ok());
  EXPECT_TRUE(disks.empty());
}

TEST(MembraneRecord, ExtraFieldsAreRefused)
{
  const std::vector<double> rec = sample_record();
  RestartRecordReader in = record_reader(rec.data(), rec.size());
  in.get();
  EXPECT_FALSE(in.finished());
  EXPECT_NE(in.error().find("more fields"), std::string::npos);
}

TEST(MembraneRecord, LengthBeyondTheBufferIsRefused)
{
  std::vector<double> rec = sample_record();
  rec[2] = static_cast<double>(rec.size() + 1);
  RestartRecordReader in = record_reader(rec.data(), rec.size());
  EXPECT_FALSE(in.ok());
}

namespace {

void sample_state(RunState &run, SideChain (&sides)[2])
{
  run.checksum = 0x0123456789abcdefull;
  run.band_width = 0.008;
  run.search_width = 0.02;
  run.tolerance = 4e-5;
  run.force_detection = false;
  run.ylo_detected = -0.1;
  run.yhi_detected = 0.1;
  run.counters = {12, 1, 2, 5};
  run.inertial.value = 3e-4;
  run.inertial.first_step = 4000;
  run.inertial.first_height = 0.2;
  run.inertial.was_above = true;
  run.warned_inertial = true;
  run.dense.window_steps = 7;
  run.dense.window_detections = 6;
  run.dense.unwatched_until = 12345;
  sides[LEFT].chain_tags = {3, 1, 4};
  sides[LEFT].escaped_tags = {15};
  sides[LEFT].escaped_radius = {0.001};
  sides[RIGHT].chain_tags = {9, 2};
  sides[RIGHT].watch = sample_watch();
  sides[RIGHT].watch_band = {{9, 0.1, 0.0, 0.001}, {2, 0.1, 0.002, 0.001}};
  sides[RIGHT].warned_lost = true;
}

// the record of sample_state as `def` writes it
std::vector<double> sample_whole_record(const Definition &def)
{
  RunState run;
  SideChain sides[2];
  sample_state(run, sides);
  return write_record(def, run, sides);
}

} // namespace

TEST(MembraneRecord, WholeStateRoundTrips)
{
  Definition def;
  def.frictionless_type = 2;
  RunState run;
  SideChain sides[2];
  sample_state(run, sides);
  const std::vector<double> rec = write_record(def, run, sides);
  RunState back;
  SideChain back_sides[2];
  bool same = false;
  EXPECT_EQ(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_TRUE(same);
  EXPECT_EQ(back.checksum, run.checksum);
  EXPECT_EQ(back.search_width, 0.02);
  EXPECT_FALSE(back.force_detection);
  EXPECT_EQ(back.yhi_detected, 0.1);
  EXPECT_EQ(back.counters.detections, 12);
  EXPECT_EQ(back.counters.changes, 5);
  EXPECT_EQ(back.inertial.first_step, 4000);
  EXPECT_TRUE(back.inertial.was_above);
  EXPECT_TRUE(back.warned_inertial);
  EXPECT_FALSE(back.warned_chain_step);
  EXPECT_EQ(back.dense.window_steps, 7);
  EXPECT_EQ(back.dense.window_detections, 6);
  EXPECT_EQ(back.dense.unwatched_until, 12345);
  EXPECT_EQ(back_sides[LEFT].chain_tags, sides[LEFT].chain_tags);
  EXPECT_EQ(back_sides[LEFT].escaped_radius, sides[LEFT].escaped_radius);
  EXPECT_EQ(back_sides[RIGHT].watch_band.size(), 2u);
  EXPECT_EQ(back_sides[RIGHT].now.size(), 2u); // the watched disks start where they were
  EXPECT_TRUE(back_sides[RIGHT].warned_lost);
  EXPECT_FALSE(back_sides[LEFT].warned_lost);
}

TEST(MembraneRecord, AnotherDefinitionLeavesTheStateAlone)
{
  Definition def;
  const std::vector<double> rec = sample_whole_record(def);
  Definition other = def;
  other.detect_every = 10;
  RunState back;
  SideChain back_sides[2];
  bool same = true;
  EXPECT_EQ(read_record(rec.data(), rec.size(), other, same, back, back_sides), "");
  EXPECT_FALSE(same);
  EXPECT_EQ(back.counters.detections, 0);
  EXPECT_TRUE(back_sides[LEFT].chain_tags.empty());
}

TEST(MembraneRecord, CutWholeRecordIsRefused)
{
  Definition def;
  std::vector<double> rec = sample_whole_record(def);
  rec[2] -= 1.0; // one field less than written
  RunState back;
  SideChain back_sides[2];
  bool same = false;
  EXPECT_NE(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_TRUE(same); // the definition was read: the error says the rest is corrupt
}

TEST(MembraneRecord, FormatTwoIsReadWithoutAWindow)
{
  // a format-2 record (before the every-auto window) is the format-4 one
  // without its last four fields (the window, the last detection's step)
  Definition def;
  std::vector<double> rec = sample_whole_record(def);
  rec.resize(rec.size() - 4);
  rec[1] = 2;
  rec[2] = static_cast<double>(rec.size());
  RunState back;
  SideChain back_sides[2];
  bool same = false;
  EXPECT_EQ(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_TRUE(same);
  EXPECT_EQ(back.counters.detections, 12);
  EXPECT_TRUE(back.warned_inertial);
  EXPECT_EQ(back.dense.window_steps, 0);
  EXPECT_EQ(back.dense.window_detections, 0);
  EXPECT_EQ(back.dense.unwatched_until, -1);
  EXPECT_EQ(back.last_detection, -1); // not known: the next run detects
  // format 1 is refused (EarlierFormatIsRefused), and so is format 2 cut short
  rec.pop_back();
  rec[2] = static_cast<double>(rec.size());
  EXPECT_NE(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
}

TEST(MembraneRecord, LastDetectionRoundTripsAndOldEveryNIsAnotherDefinition)
{
  Definition def;
  def.detect_every = 25;
  RunState run;
  SideChain sides[2];
  sample_state(run, sides);
  run.last_detection = 1234;
  std::vector<double> rec = write_record(def, run, sides);
  RunState back;
  SideChain back_sides[2];
  bool same = false;
  EXPECT_EQ(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_TRUE(same);
  EXPECT_EQ(back.last_detection, 1234);
  // format 3: every 25 then detected on multiples of 25, not 25 steps after the last
  rec.pop_back();
  rec[1] = 3;
  rec[2] = static_cast<double>(rec.size());
  EXPECT_EQ(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_FALSE(same);
  // every auto meant what it means now
  def.detect_every = EVERY_AUTO;
  rec = write_record(def, run, sides);
  rec.pop_back();
  rec[1] = 3;
  rec[2] = static_cast<double>(rec.size());
  EXPECT_EQ(read_record(rec.data(), rec.size(), def, same, back, back_sides), "");
  EXPECT_TRUE(same);
  EXPECT_EQ(back.last_detection, -1);
}

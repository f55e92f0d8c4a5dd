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
  std::vector<long> tags;
  get_tags(in, tags);
  EXPECT_EQ(tags, (std::vector<long>{7, 3, 11}));
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
  std::vector<long> tags;
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

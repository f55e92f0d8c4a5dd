// The one restart record format (common/restart_record.h) in LIGGGHTS' envelope:
// written as a fix's write_restart writes it, read back as Modify::read_restart
// hands it to Fix::restart (the int size, then that many bytes in a new[] buffer).
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "restart_record.h"

namespace {

constexpr double MAGIC = 7.0e9 + 4871.0; // fix stability/guard's
constexpr int VERSION = 1;

// the record through a file: what LIGGGHTS gives Fix::restart, and the size it read
std::unique_ptr<char[]> through_file(const std::vector<double> &record, int &size)
{
  std::FILE *fp = std::tmpfile();
  EXPECT_NE(fp, nullptr);
  EXPECT_TRUE(write_record_bytes(fp, record));
  std::rewind(fp);
  size = -1;
  EXPECT_EQ(std::fread(&size, sizeof(int), 1, fp), 1u);
  std::unique_ptr<char[]> raw(new char[size > 0 ? size : 1]);
  EXPECT_EQ(std::fread(raw.get(), 1, size, fp), static_cast<size_t>(size));
  char extra;
  EXPECT_EQ(std::fread(&extra, 1, 1, fp), 0u); // nothing after the record
  std::fclose(fp);
  return raw;
}

std::vector<double> guard_record(double warnings, double dt)
{
  RestartRecordWriter out(MAGIC, VERSION);
  for (double v : {warnings, 1.0, 0.0, dt}) out.put(v);
  return out.finish();
}

} // namespace

TEST(RestartRecord, RoundTripThroughTheEnvelope)
{
  const std::vector<double> rec = guard_record(3.0, 2.5e-5);
  ASSERT_EQ(rec.size(), 7u); // magic, version, length, 4 fields
  EXPECT_EQ(rec[2], 7.0);
  int size = 0;
  const std::unique_ptr<char[]> raw = through_file(rec, size);
  EXPECT_EQ(size, 7 * 8); // the int LIGGGHTS reads: bytes, not doubles
  RestartRecordReader in = read_restart_record(raw.get(), MAGIC, VERSION);
  EXPECT_EQ(in.version(), 1);
  EXPECT_EQ(in.get(), 3.0);
  EXPECT_EQ(in.get(), 1.0);
  EXPECT_EQ(in.get(), 0.0);
  EXPECT_EQ(in.get(), 2.5e-5);
  EXPECT_TRUE(in.finished()) << in.error();
}

// a file fix stability/guard wrote by hand before the envelope existed: int
// 56, then magic, version 1, length 7 and its four fields
TEST(RestartRecord, OldHandWrittenRecordReads)
{
  const double old[7] = {MAGIC, 1.0, 7.0, 2.0, 0.0, 1.0, 1e-4};
  RestartRecordReader in =
      read_restart_record(reinterpret_cast<const char *>(old), MAGIC, VERSION, VERSION, 7);
  EXPECT_EQ(in.get(), 2.0);
  EXPECT_EQ(in.get(), 0.0);
  EXPECT_EQ(in.get(), 1.0);
  EXPECT_EQ(in.get(), 1e-4);
  EXPECT_TRUE(in.finished()) << in.error();
}

TEST(RestartRecord, AnotherStylesRecordIsRefused)
{
  const std::vector<double> rec = guard_record(0.0, 0.0);
  RestartRecordReader in =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), 3.0e7 + 3, 4);
  EXPECT_FALSE(in.ok());
  EXPECT_EQ(in.error(), "it was written by an earlier version of this style (before format 4)");
  EXPECT_EQ(in.get(), 0.0); // nothing is read past a refusal
  EXPECT_FALSE(in.finished());
}

TEST(RestartRecord, VersionsOutsideTheRangeAreRefused)
{
  std::vector<double> rec = guard_record(0.0, 0.0);
  rec[1] = 2.0; // written by a newer build
  RestartRecordReader newer =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, 1);
  EXPECT_EQ(newer.error(), "it is in format 2; this build reads format 1");
  rec[1] = 1.0;
  RestartRecordReader older =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, 4, 2);
  EXPECT_EQ(older.error(), "it is in format 1; this build reads formats 2 to 4");
  RestartRecordReader in_range =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, 4, 1);
  EXPECT_TRUE(in_range.ok());
  EXPECT_EQ(in_range.version(), 1);
}

TEST(RestartRecord, LengthBeyondTheBoundIsCorrupt)
{
  std::vector<double> rec = guard_record(0.0, 0.0);
  rec[2] = 8.0; // one more than the 7 the caller knows it holds
  RestartRecordReader in =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, VERSION, VERSION, 7);
  EXPECT_EQ(in.error(), "its length field is corrupt");
  rec[2] = 6.5;
  RestartRecordReader fraction =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, VERSION);
  EXPECT_EQ(fraction.error(), "its length field is corrupt");
}

TEST(RestartRecord, ShortAndLongRecordsAreCorrupt)
{
  std::vector<double> rec = guard_record(0.0, 0.0);
  rec[2] = 6.0; // says 3 fields, the reader takes 4
  RestartRecordReader short_one =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, VERSION);
  for (int k = 0; k < 4; k++) short_one.get();
  EXPECT_FALSE(short_one.finished());
  EXPECT_EQ(short_one.error(), "it is shorter than its fields (cut or corrupt)");

  RestartRecordWriter out(MAGIC, VERSION);
  for (int k = 0; k < 5; k++) out.put(k);
  const std::vector<double> &longer = out.finish();
  RestartRecordReader long_one =
      read_restart_record(reinterpret_cast<const char *>(longer.data()), MAGIC, VERSION);
  for (int k = 0; k < 4; k++) long_one.get();
  EXPECT_FALSE(long_one.finished());
  EXPECT_EQ(long_one.error(), "it holds more fields than this format (corrupt)");
}

TEST(RestartRecord, CountsAreCheckedAgainstWhatIsLeft)
{
  RestartRecordWriter out(MAGIC, VERSION);
  out.put(3.0); // three items of two fields ...
  for (int k = 0; k < 5; k++) out.put(k); // ... but five fields follow
  const std::vector<double> &rec = out.finish();
  RestartRecordReader in =
      read_restart_record(reinterpret_cast<const char *>(rec.data()), MAGIC, VERSION);
  EXPECT_EQ(in.count(2), 0u);
  EXPECT_EQ(in.error(), "a count in it exceeds its length (cut or corrupt)");
}

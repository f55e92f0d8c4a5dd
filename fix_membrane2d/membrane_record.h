#pragma once
// The restart record of fix membrane2d as a flat array of doubles, headed by a
// magic number, the format version and the record length, so that a record of
// another format, or a cut one, is refused instead of misread. No LIGGGHTS.

#include <cstddef>
#include <string>
#include <vector>

#include "membrane_chain.h"

namespace membrane {

constexpr double RECORD_MAGIC = 7.0e9 + 2213.0;   // not a count a version-1 record starts with
constexpr int RECORD_VERSION = 2;

class RecordWriter {
 public:
  RecordWriter();
  void put(double v) { data_.push_back(v); }
  void put_tags(const std::vector<long>& tags);
  void put_disks(const std::vector<Disk>& disks);
  void put_watch(const DetectionWatch& w);
  // the record, its length filled in
  const std::vector<double>& finish();

 private:
  std::vector<double> data_;
};

class RecordReader {
 public:
  // `n` doubles are available at `data` (the caller's bound; LIGGGHTS does
  // not pass the record length, the header does)
  RecordReader(const double* data, std::size_t n);
  // empty when the header is right; else why the record cannot be read
  const std::string& error() const { return error_; }
  bool ok() const { return error_.empty(); }
  int version() const { return version_; }

  double get();
  long get_long() { return static_cast<long>(get()); }
  void get_tags(std::vector<long>& out);
  void get_disks(std::vector<Disk>& out);
  void get_watch(DetectionWatch& out);
  // after the last field: every field of the header's length was read, no more
  bool finished();

 private:
  std::size_t count(std::size_t per_item);
  const double* data_;
  std::size_t n_ = 0, pos_ = 0;
  int version_ = 0;
  std::string error_;
};

}  // namespace membrane

#include <cstdint>
#include <cstring>

namespace membrane {

// A hash of one disk's identity, type, radius and position: their sum over a
// group (any order, any rank split) tells whether the group changed.
inline std::uint64_t disk_checksum(long tag, int type, double x, double y, double r)
{
  auto mix = [](std::uint64_t h) {   // splitmix64 finaliser
    h += 0x9e3779b97f4a7c15ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
  };
  auto bits = [](double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  };
  std::uint64_t h = mix(static_cast<std::uint64_t>(tag));
  h = mix(h ^ static_cast<std::uint64_t>(type));
  h = mix(h ^ bits(x));
  h = mix(h ^ bits(y));
  return mix(h ^ bits(r));
}

}  // namespace membrane

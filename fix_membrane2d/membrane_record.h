#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_RECORD_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_RECORD_H

// The restart record of fix membrane2d (common/restart_record.h): its
// definition, then the state of membrane_state.h. No LIGGGHTS.

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "membrane_chain.h"
#include "membrane_state.h"
#include "restart_record.h"

namespace membrane {

constexpr double RECORD_MAGIC = 7.0e9 + 2213.0; // not a count a version-1 record starts with
constexpr int RECORD_VERSION = 3;        // 3: the every-auto detection window (RunState)
constexpr int RECORD_OLDEST_VERSION = 2; // read too: no window yet

inline RestartRecordWriter record_writer()
{
  return RestartRecordWriter(RECORD_MAGIC, RECORD_VERSION);
}
inline RestartRecordReader record_reader(const double *data, std::size_t n)
{
  return RestartRecordReader(data, n, RECORD_MAGIC, RECORD_VERSION, RECORD_OLDEST_VERSION);
}

// The whole record.
std::vector<double> write_record(const Definition &def, const RunState &run,
                                 const SideChain (&sides)[2]);
// Reads a record of at most `n` doubles: "" when read, else why it cannot be.
// `same_definition` is false, and nothing beyond the definition is read,
// when the record was written by another definition than `def`.
std::string read_record(const double *data, std::size_t n, const Definition &def,
                        bool &same_definition, RunState &run, SideChain (&sides)[2]);

// Its fields.
void put_tags(RestartRecordWriter &out, const std::vector<long> &tags);
void put_disks(RestartRecordWriter &out, const std::vector<Disk> &disks);
void put_watch(RestartRecordWriter &out, const DetectionWatch &w);
void get_tags(RestartRecordReader &in, std::vector<long> &out);
void get_disks(RestartRecordReader &in, std::vector<Disk> &out);
void get_watch(RestartRecordReader &in, DetectionWatch &out);

// A hash of one disk's identity, type, radius and position: their sum over a
// group (any order, any rank split) tells whether the group changed.
inline std::uint64_t disk_checksum(long tag, int type, double x, double y, double r)
{
  auto mix = [](std::uint64_t h) { // splitmix64 finaliser
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

} // namespace membrane

#endif

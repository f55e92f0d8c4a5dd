#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_RECORD_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_RECORD_H

// The restart record of fix membrane2d (common/restart_record.h): its
// definition, then the state of membrane_state.h. No LIGGGHTS.

#include <cstdint>
#include <string>
#include <vector>

#include "membrane_chain.h"
#include "membrane_state.h"
#include "restart_record.h"

namespace membrane {

constexpr double RECORD_MAGIC = 7.0e9 + 2213.0; // not a count a version-1 record starts with
// 3: the every-auto detection window (RunState); 4: the step of the last detection
// (every N counts from it)
constexpr int RECORD_VERSION = 4;
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
void put_tags(RestartRecordWriter &out, const std::vector<AtomId> &tags);
void put_disks(RestartRecordWriter &out, const std::vector<Disk> &disks);
void put_watch(RestartRecordWriter &out, const DetectionWatch &w);
void get_tags(RestartRecordReader &in, std::vector<AtomId> &out);
void get_disks(RestartRecordReader &in, std::vector<Disk> &out);
void get_watch(RestartRecordReader &in, DetectionWatch &out);

} // namespace membrane

#endif

#ifndef LIGGGHTS_MEMBRANE_RESTART_RECORD_H
#define LIGGGHTS_MEMBRANE_RESTART_RECORD_H

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

// The restart record of a style as a flat array of doubles, headed by a magic
// number (one per style), the format version and the record length, so that
// a record of another format, or a cut one, is refused instead of misread.
// LIGGGHTS passes a fix its record without the length: the header carries it.
// No LIGGGHTS here (unit-tested in tests/unit/common and with the membranes'
// records); common/restart_envelope.h writes and reads it in a restart file.
//
//   write: RestartRecordWriter out(MAGIC, VERSION); out.put(x) ...;
//          write_restart_record(lmp, fp, out.finish());          (restart_envelope.h)
//   read:  RestartRecordReader in = read_restart_record(raw, MAGIC, VERSION);
//          x = in.get() ...; if (!in.finished()) -> in.error() says why

class RestartRecordWriter {
 public:
  RestartRecordWriter(double magic, int version) : data_{magic, static_cast<double>(version), 0.0}
  {
  }
  void put(double v) { data_.push_back(v); }
  // the record, its length filled in
  const std::vector<double> &finish()
  {
    data_[2] = static_cast<double>(data_.size());
    return data_;
  }

 private:
  std::vector<double> data_;
};

class RestartRecordReader {
 public:
  // what LIGGGHTS tells a fix of its record's size: nothing (Fix::restart gets
  // the bytes alone), so the header's length field is the only bound
  static constexpr std::size_t UNKNOWN_LENGTH = static_cast<std::size_t>(-1) / sizeof(double);

  // `n` bounds what may be read at `data` (UNKNOWN_LENGTH when unknown); formats
  // `oldest` to `version` are read (the caller asks version() what is there)
  RestartRecordReader(const double *data, std::size_t n, double magic, int version, int oldest = -1)
    : data_(data)
  {
    if (oldest < 0) oldest = version;
    if (n < HEADER || data[0] != magic) {
      error_ = "it was written by an earlier version of this style (before format " +
               std::to_string(version) + ")";
      return;
    }
    version_ = static_cast<int>(data[1]);
    if (version_ < oldest || version_ > version) {
      error_ = "it is in format " + std::to_string(version_) + "; this build reads format" +
               (oldest < version ? "s " + std::to_string(oldest) + " to " : " ") +
               std::to_string(version);
      return;
    }
    const double length = data[2];
    if (!(length >= HEADER) || length > static_cast<double>(n) || length != std::floor(length)) {
      error_ = "its length field is corrupt";
      return;
    }
    n_ = static_cast<std::size_t>(length);
    pos_ = HEADER;
  }

  // empty when all is well; else why the record cannot be read
  const std::string &error() const { return error_; }
  bool ok() const { return error_.empty(); }
  int version() const { return version_; }

  double get()
  {
    if (!ok()) return 0.0;
    if (pos_ >= n_) {
      error_ = "it is shorter than its fields (cut or corrupt)";
      return 0.0;
    }
    return data_[pos_++];
  }

  // a count of items of `per_item` fields each, checked against what is left
  std::size_t count(std::size_t per_item)
  {
    const double c = get();
    if (!ok()) return 0;
    if (!(c >= 0.0) || c * static_cast<double>(per_item) > static_cast<double>(n_ - pos_)) {
      error_ = "a count in it exceeds its length (cut or corrupt)";
      return 0;
    }
    return static_cast<std::size_t>(c);
  }

  // after the last field: every field of the header's length was read, no more
  bool finished()
  {
    if (ok() && pos_ != n_) error_ = "it holds more fields than this format (corrupt)";
    return ok();
  }

 private:
  static constexpr std::size_t HEADER = 3; // magic, version, length
  const double *data_;
  std::size_t n_ = 0, pos_ = 0;
  int version_ = 0;
  std::string error_;
};

// LIGGGHTS' envelope of a fix's global state in a restart file (what
// Modify::write_restart expects of Fix::write_restart): the size in bytes as an
// int, then the record's doubles. Returns false when the file took less.
inline bool write_record_bytes(std::FILE *fp, const std::vector<double> &record)
{
  const int size = static_cast<int>(record.size() * sizeof(double));
  return std::fwrite(&size, sizeof(int), 1, fp) == 1 &&
         std::fwrite(record.data(), sizeof(double), record.size(), fp) == record.size();
}

// The record in the bytes LIGGGHTS passes to Fix::restart (the envelope's
// content without the size, aligned by new[]; every rank gets them): a reader that has checked the
// magic, the version (`oldest` to `version`) and the length (at most
// `max_length` doubles when the caller knows a bound), or says in error() why
// the record cannot be read.
inline RestartRecordReader
read_restart_record(const char *raw, double magic, int version, int oldest = -1,
                    std::size_t max_length = RestartRecordReader::UNKNOWN_LENGTH)
{
  return RestartRecordReader(reinterpret_cast<const double *>(raw), max_length, magic, version,
                             oldest);
}

#endif

#include "membrane_record.h"

#include <cmath>

namespace membrane {

namespace {
constexpr std::size_t HEADER = 3;   // magic, version, length
}

RecordWriter::RecordWriter() : data_{RECORD_MAGIC, static_cast<double>(RECORD_VERSION), 0.0} {}

void RecordWriter::put_tags(const std::vector<long>& tags)
{
  put(static_cast<double>(tags.size()));
  for (long t : tags) put(static_cast<double>(t));
}

void RecordWriter::put_disks(const std::vector<Disk>& disks)
{
  put(static_cast<double>(disks.size()));
  for (const Disk& d : disks) {
    put(static_cast<double>(d.tag));
    put(d.x);
    put(d.y);
    put(d.r);
  }
}

void RecordWriter::put_watch(const DetectionWatch& w)
{
  put(w.budget);
  put(w.always ? 1.0 : 0.0);
  put(static_cast<double>(w.pairs.size()));
  for (const DetectionWatch::Pair& p : w.pairs) {
    put(p.i);
    put(p.j);
    put(p.ij ? 1.0 : 0.0);
    put(p.ji ? 1.0 : 0.0);
  }
  put(static_cast<double>(w.platen_contacts.size()));
  for (const DetectionWatch::PlatenContact& c : w.platen_contacts) {
    put(c.i);
    put(c.bottom ? 1.0 : 0.0);
    put(c.touching ? 1.0 : 0.0);
  }
  put(static_cast<double>(w.ahead.size()));
  for (const DetectionWatch::Ahead& a : w.ahead) {
    put(a.start);
    put(a.other);
  }
  put(static_cast<double>(w.disks.size()));
  for (int i : w.disks) put(i);
}

const std::vector<double>& RecordWriter::finish()
{
  data_[2] = static_cast<double>(data_.size());
  return data_;
}

RecordReader::RecordReader(const double* data, std::size_t n) : data_(data), n_(n)
{
  if (n < HEADER || data[0] != RECORD_MAGIC) {
    error_ = "it was written by an earlier version of fix membrane2d (before format " +
             std::to_string(RECORD_VERSION) + ")";
    return;
  }
  version_ = static_cast<int>(data[1]);
  if (version_ != RECORD_VERSION) {
    error_ = "it is in format " + std::to_string(version_) + "; this build reads format " +
             std::to_string(RECORD_VERSION);
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

double RecordReader::get()
{
  if (!ok()) return 0.0;
  if (pos_ >= n_) {
    error_ = "it is shorter than its fields (cut or corrupt)";
    return 0.0;
  }
  return data_[pos_++];
}

std::size_t RecordReader::count(std::size_t per_item)
{
  const double c = get();
  if (!ok()) return 0;
  if (!(c >= 0.0) || c * static_cast<double>(per_item) > static_cast<double>(n_ - pos_)) {
    error_ = "a count in it exceeds its length (cut or corrupt)";
    return 0;
  }
  return static_cast<std::size_t>(c);
}

void RecordReader::get_tags(std::vector<long>& out)
{
  out.resize(count(1));
  for (long& t : out) t = get_long();
}

void RecordReader::get_disks(std::vector<Disk>& out)
{
  out.resize(count(4));
  for (Disk& d : out) {
    d.tag = get_long();
    d.x = get();
    d.y = get();
    d.r = get();
  }
}

void RecordReader::get_watch(DetectionWatch& w)
{
  w.budget = get();
  w.always = get() != 0.0;
  w.pairs.resize(count(4));
  for (DetectionWatch::Pair& p : w.pairs) {
    p.i = static_cast<int>(get());
    p.j = static_cast<int>(get());
    p.ij = get() != 0.0;
    p.ji = get() != 0.0;
  }
  w.platen_contacts.resize(count(3));
  for (DetectionWatch::PlatenContact& c : w.platen_contacts) {
    c.i = static_cast<int>(get());
    c.bottom = get() != 0.0;
    c.touching = get() != 0.0;
  }
  w.ahead.resize(count(2));
  for (DetectionWatch::Ahead& a : w.ahead) {
    a.start = static_cast<int>(get());
    a.other = static_cast<int>(get());
  }
  w.disks.resize(count(1));
  for (int& i : w.disks) i = static_cast<int>(get());
}

bool RecordReader::finished()
{
  if (ok() && pos_ != n_) error_ = "it holds more fields than this format (corrupt)";
  return ok();
}

}  // namespace membrane

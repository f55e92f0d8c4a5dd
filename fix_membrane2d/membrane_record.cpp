#include "membrane_record.h"

namespace membrane {

void put_tags(RestartRecordWriter &out, const std::vector<long> &tags)
{
  out.put(static_cast<double>(tags.size()));
  for (long t : tags) out.put(static_cast<double>(t));
}

void put_disks(RestartRecordWriter &out, const std::vector<Disk> &disks)
{
  out.put(static_cast<double>(disks.size()));
  for (const Disk &d : disks) {
    out.put(static_cast<double>(d.tag));
    out.put(d.x);
    out.put(d.y);
    out.put(d.r);
  }
}

void put_watch(RestartRecordWriter &out, const DetectionWatch &w)
{
  out.put(w.budget);
  out.put(w.always ? 1.0 : 0.0);
  out.put(static_cast<double>(w.pairs.size()));
  for (const DetectionWatch::Pair &p : w.pairs) {
    out.put(p.i);
    out.put(p.j);
    out.put(p.ij ? 1.0 : 0.0);
    out.put(p.ji ? 1.0 : 0.0);
  }
  out.put(static_cast<double>(w.platen_contacts.size()));
  for (const DetectionWatch::PlatenContact &c : w.platen_contacts) {
    out.put(c.i);
    out.put(c.bottom ? 1.0 : 0.0);
    out.put(c.touching ? 1.0 : 0.0);
  }
  out.put(static_cast<double>(w.ahead.size()));
  for (const DetectionWatch::Ahead &a : w.ahead) {
    out.put(a.start);
    out.put(a.other);
  }
  out.put(static_cast<double>(w.disks.size()));
  for (int i : w.disks) out.put(i);
}

void get_tags(RestartRecordReader &in, std::vector<long> &out)
{
  out.resize(in.count(1));
  for (long &t : out) t = static_cast<long>(in.get());
}

void get_disks(RestartRecordReader &in, std::vector<Disk> &out)
{
  out.resize(in.count(4));
  for (Disk &d : out) {
    d.tag = static_cast<long>(in.get());
    d.x = in.get();
    d.y = in.get();
    d.r = in.get();
  }
}

void get_watch(RestartRecordReader &in, DetectionWatch &w)
{
  w.budget = in.get();
  w.always = in.get() != 0.0;
  w.pairs.resize(in.count(4));
  for (DetectionWatch::Pair &p : w.pairs) {
    p.i = static_cast<int>(in.get());
    p.j = static_cast<int>(in.get());
    p.ij = in.get() != 0.0;
    p.ji = in.get() != 0.0;
  }
  w.platen_contacts.resize(in.count(3));
  for (DetectionWatch::PlatenContact &c : w.platen_contacts) {
    c.i = static_cast<int>(in.get());
    c.bottom = in.get() != 0.0;
    c.touching = in.get() != 0.0;
  }
  w.ahead.resize(in.count(2));
  for (DetectionWatch::Ahead &a : w.ahead) {
    a.start = static_cast<int>(in.get());
    a.other = static_cast<int>(in.get());
  }
  w.disks.resize(in.count(1));
  for (int &i : w.disks) i = static_cast<int>(in.get());
}

} // namespace membrane

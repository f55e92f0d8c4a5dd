#include "membrane_record.h"

namespace membrane {

namespace {

void put_definition(RestartRecordWriter &out, const Definition &d)
{
  out.put(d.sides_mask);
  out.put(d.frictionless_type);
  out.put(d.detect_every);
  out.put(d.band_given);
  out.put(d.tolerance_given);
  out.put(d.thickness);
}

Definition get_definition(RestartRecordReader &in)
{
  Definition d;
  d.sides_mask = static_cast<int>(in.get());
  d.frictionless_type = static_cast<int>(in.get());
  d.detect_every = static_cast<int>(in.get());
  d.band_given = in.get();
  d.tolerance_given = in.get();
  d.thickness = in.get();
  return d;
}

double flag(bool b)
{
  return b ? 1.0 : 0.0;
}

} // namespace

std::vector<double> write_record(const Definition &def, const RunState &run,
                                 const SideChain (&sides)[2])
{
  RestartRecordWriter out = record_writer();
  put_definition(out, def);
  out.put(static_cast<double>(run.checksum >> 32));
  out.put(static_cast<double>(run.checksum & 0xffffffffu));
  out.put(run.band_width);
  out.put(run.search_width);
  out.put(run.tolerance);
  out.put(flag(run.force_detection));
  out.put(run.ylo_detected);
  out.put(run.yhi_detected);
  for (const SideChain &s : sides) {
    put_tags(out, s.chain_tags);
    put_tags(out, s.escaped_tags);
    for (double r : s.escaped_radius) out.put(r);
    put_watch(out, s.watch);
    put_disks(out, s.watch_band);
    out.put(flag(s.warned_lost));
  }
  const Counters &c = run.counters;
  for (long long n : {c.detections, c.failures, c.widenings, c.changes})
    out.put(static_cast<double>(n));
  out.put(run.inertial.value);
  out.put(static_cast<double>(run.inertial.first_step));
  out.put(run.inertial.first_height);
  out.put(flag(run.inertial.was_above));
  out.put(flag(run.warned_inertial));
  out.put(flag(run.warned_chain_step));
  out.put(static_cast<double>(run.dense.window_steps));
  out.put(static_cast<double>(run.dense.window_detections));
  out.put(static_cast<double>(run.dense.unwatched_until));
  out.put(static_cast<double>(run.last_detection));
  return out.finish();
}

std::string read_record(const double *data, std::size_t n, const Definition &def,
                        bool &same_definition, RunState &run, SideChain (&sides)[2])
{
  RestartRecordReader in = record_reader(data, n);
  Definition written = get_definition(in);
  // every N of format 3 and before detected on multiples of N: another definition
  if (in.version() < 4 && written.detect_every != EVERY_AUTO) written.detect_every *= -1;
  same_definition = in.ok() && written == def;
  if (!in.ok() || !same_definition) return in.error();
  const std::uint64_t hi = static_cast<std::uint64_t>(in.get()),
                      lo = static_cast<std::uint64_t>(in.get());
  run.checksum = (hi << 32) | lo;
  run.band_width = in.get();
  run.search_width = in.get();
  run.tolerance = in.get();
  run.force_detection = in.get() != 0.0;
  run.ylo_detected = in.get();
  run.yhi_detected = in.get();
  for (SideChain &s : sides) {
    get_tags(in, s.chain_tags);
    get_tags(in, s.escaped_tags);
    s.escaped_radius.resize(s.escaped_tags.size());
    for (double &r : s.escaped_radius) r = in.get();
    get_watch(in, s.watch);
    get_disks(in, s.watch_band);
    s.now = s.watch_band;
    s.warned_lost = in.get() != 0.0;
  }
  Counters &c = run.counters;
  for (long long *k : {&c.detections, &c.failures, &c.widenings, &c.changes})
    *k = static_cast<long long>(in.get());
  run.inertial.value = in.get();
  run.inertial.first_step = static_cast<long long>(in.get());
  run.inertial.first_height = in.get();
  run.inertial.was_above = in.get() != 0.0;
  run.warned_inertial = in.get() != 0.0;
  run.warned_chain_step = in.get() != 0.0;
  if (in.version() >= 3) {
    run.dense.window_steps = static_cast<long long>(in.get());
    run.dense.window_detections = static_cast<long long>(in.get());
    run.dense.unwatched_until = static_cast<long long>(in.get());
  }
  // before format 4 the step of the last detection is unknown: found again
  run.last_detection = in.version() >= 4 ? static_cast<long long>(in.get()) : -1;
  in.finished();
  return in.error();
}

void put_tags(RestartRecordWriter &out, const std::vector<AtomId> &tags)
{
  out.put(static_cast<double>(tags.size()));
  for (AtomId t : tags) out.put(static_cast<double>(t));
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

void get_tags(RestartRecordReader &in, std::vector<AtomId> &out)
{
  out.resize(in.count(1));
  for (AtomId &t : out) t = static_cast<AtomId>(in.get());
}

void get_disks(RestartRecordReader &in, std::vector<Disk> &out)
{
  out.resize(in.count(4));
  for (Disk &d : out) {
    d.tag = static_cast<AtomId>(in.get());
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

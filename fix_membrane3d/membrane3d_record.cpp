#include "membrane3d_record.h"

#include "restart_record.h"

#include <cmath>

namespace membrane3d {

namespace {
const double MAGIC = 3.0e7 + 3;  // fix membrane3d's records, not membrane2d's
// 2: the detection's spheres; 3: the decided step; 4: the platens, the checksum;
// 5: the default tolerance is a multiple of D50 (before: of the mean diameter)
const int VERSION = 5;
} // namespace

std::vector<double> write_record(const Membrane3dState &s) {
  RestartRecordWriter w(MAGIC, VERSION);
  w.put(s.tolerance_given);
  w.put(s.every);
  w.put(s.last_detection);
  w.put(s.detections);
  w.put(static_cast<double>(s.member_tags.size()));
  for (std::size_t k = 0; k < s.member_tags.size(); ++k) {
    w.put(s.member_tags[k]);
    w.put(static_cast<int>(s.topology.side.at(k)));
  }
  w.put(static_cast<double>(s.topology.facets.size()));
  for (const auto &f : s.topology.facets)
    for (const MembraneVertex &v : f) {
      w.put(v.sphere);
      w.put(v.image);
    }
  w.put(s.window_steps);
  w.put(s.window_detections);
  w.put(s.unwatched_until);
  w.put(s.sample_platens.lo);
  w.put(s.sample_platens.hi);
  w.put(static_cast<double>(s.sample_tags.size()));
  for (std::size_t k = 0; k < s.sample_tags.size(); ++k) {
    w.put(s.sample_tags[k]);
    for (int d = 0; d < 3; ++d) w.put(s.sample.at(k).x[d]);
    w.put(s.sample[k].r);
  }
  w.put(s.decided_step);
  // two exact halves: a double holds 53 bits
  w.put(s.detected_platens.lo);
  w.put(s.detected_platens.hi);
  w.put(s.has_checksum ? 1.0 : 0.0);
  w.put(static_cast<double>(s.checksum >> 32));
  w.put(static_cast<double>(s.checksum & 0xffffffffu));
  return w.finish();
}

std::string read_record(const double *data, std::size_t n, Membrane3dState &s) {
  RestartRecordReader r(data, n, MAGIC, VERSION, 1);
  Membrane3dState in;
  in.tolerance_given = r.get();
  in.every = static_cast<int>(r.get());
  in.last_detection = r.get();
  in.detections = r.get();
  const std::size_t members = r.count(2);
  for (std::size_t k = 0; k < members && r.ok(); ++k) {
    in.member_tags.push_back(static_cast<AtomId>(r.get()));
    const int side = static_cast<int>(r.get());
    if (side < 0 || side > static_cast<int>(Side::outside)) return "a sphere's side is corrupt";
    in.topology.side.push_back(static_cast<Side>(side));
  }
  const std::size_t facets = r.count(6);
  for (std::size_t f = 0; f < facets && r.ok(); ++f) {
    std::array<MembraneVertex, 3> facet;
    for (MembraneVertex &v : facet) {
      v.sphere = static_cast<int>(r.get());
      v.image = static_cast<int>(r.get());
      if (v.sphere < 0 || v.sphere >= static_cast<int>(members) || v.image < -1 || v.image > 1)
        return "a facet's vertex is corrupt";
    }
    in.topology.facets.push_back(facet);
  }
  if (r.version() >= 2) {
    in.window_steps = r.get();
    in.window_detections = r.get();
    in.unwatched_until = r.get();
    in.sample_platens.lo = r.get();
    in.sample_platens.hi = r.get();
    const std::size_t spheres = r.count(5);
    for (std::size_t k = 0; k < spheres && r.ok(); ++k) {
      in.sample_tags.push_back(static_cast<AtomId>(r.get()));
      Sphere sphere;
      for (int d = 0; d < 3; ++d) sphere.x[d] = r.get();
      sphere.r = r.get();
      in.sample.push_back(sphere);
    }
  }
  if (r.version() >= 3) in.decided_step = r.get();
  // before version 4 the platens of the detection are unknown: never taken as moved
  in.detected_platens = {std::nan(""), std::nan("")};
  if (r.version() >= 4) {
    in.detected_platens.lo = r.get();
    in.detected_platens.hi = r.get();
    in.has_checksum = r.get() != 0.0;
    const auto hi = static_cast<std::uint64_t>(r.get()), lo = static_cast<std::uint64_t>(r.get());
    in.checksum = (hi << 32) | lo;
  }
  // a default tolerance of another definition: not this fix's default
  if (r.version() < 5 && in.tolerance_given < 0) in.tolerance_given = MEAN_DIAMETER_DEFAULT;
  if (!r.finished()) return r.error();
  s = in;
  return "";
}

} // namespace membrane3d

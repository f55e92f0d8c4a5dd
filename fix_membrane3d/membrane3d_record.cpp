#include "membrane3d_record.h"

#include "restart_record.h"

namespace membrane3d {

namespace {
const double MAGIC = 3.0e7 + 3;  // fix membrane3d's records, not membrane2d's
const int VERSION = 1;
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
  return w.finish();
}

std::string read_record(const double *data, std::size_t n, Membrane3dState &s) {
  RestartRecordReader r(data, n, MAGIC, VERSION);
  Membrane3dState in;
  in.tolerance_given = r.get();
  in.every = static_cast<int>(r.get());
  in.last_detection = r.get();
  in.detections = r.get();
  const std::size_t members = r.count(2);
  for (std::size_t k = 0; k < members && r.ok(); ++k) {
    in.member_tags.push_back(static_cast<int>(r.get()));
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
  if (!r.finished()) return r.error();
  s = in;
  return "";
}

} // namespace membrane3d

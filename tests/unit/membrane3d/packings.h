// Hand-made packings of equal spheres (radius 1/2, touching at spacing 1) for the
// membrane3d surface tests: a simple-cubic block, a face-centred cubic block, and
// the platens that touch their bottom and top layers; and a sample from a run. Also a
// jittered simple-cubic block and the spheres of a flood that are not inside.
#ifndef LIGGGHTS_MEMBRANE_TEST_PACKINGS_H
#define LIGGGHTS_MEMBRANE_TEST_PACKINGS_H

#include "lateral_surface.h"

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace packings {

using membrane3d::Platens;
using membrane3d::Sphere;
using Eigen::Vector3d;

constexpr double radius = 0.5;

// Centres (i, j, k) for i < nx, j < ny, k < nz.
inline std::vector<Sphere> simple_cubic(int nx, int ny, int nz) {
  std::vector<Sphere> s;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) s.push_back({Vector3d(i, j, k), radius});
  return s;
}

// Face-centred cubic, cube edge a = sqrt 2 (nearest neighbours at 1): centres
// (i, j, k) a / 2 with i + j + k even, 0 <= i, j <= 2 m, 0 <= k <= 2 l. The faces
// x, y = 0 and m a are (100) planes, square lattices of touching spheres.
inline std::vector<Sphere> face_centred_cubic(int m, int l) {
  const double h = std::sqrt(2.0) / 2;
  std::vector<Sphere> s;
  for (int k = 0; k <= 2 * l; ++k)
    for (int j = 0; j <= 2 * m; ++j)
      for (int i = 0; i <= 2 * m; ++i)
        if ((i + j + k) % 2 == 0) s.push_back({Vector3d(i * h, j * h, k * h), radius});
  return s;
}

// Platens touching the lowest and highest spheres.
inline Platens touching_platens(const std::vector<Sphere> &s) {
  double lo = s.front().x.z(), hi = lo;
  for (const Sphere &p : s) {
    lo = std::min(lo, p.x.z());
    hi = std::max(hi, p.x.z());
  }
  return {lo - radius, hi + radius};
}

// data/cuboid_near_platen.txt: 198 spheres of a small cuboid sample sheared with fix
// membrane3d (examples/triaxial), near its upper platen, and its platens.
inline std::vector<Sphere> sheared_sample() {
  std::ifstream in(MEMBRANE3D_TEST_DATA "/cuboid_near_platen.txt");
  std::vector<Sphere> s;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    Sphere sphere;
    row >> sphere.x.x() >> sphere.x.y() >> sphere.x.z() >> sphere.r;
    s.push_back(sphere);
  }
  return s;
}
const Platens sheared_sample_platens{0.0, 0.019190253904679787};

// Whether two detections found the same membrane: the same facets in the same order,
// the same sides.
inline bool same_topology(const membrane3d::MembraneTopology &a,
                          const membrane3d::MembraneTopology &b) {
  if (a.side != b.side || a.facets.size() != b.facets.size()) return false;
  for (std::size_t f = 0; f < a.facets.size(); ++f)
    for (int j = 0; j < 3; ++j)
      if (a.facets[f][j].sphere != b.facets[f][j].sphere ||
          a.facets[f][j].image != b.facets[f][j].image)
        return false;
  return true;
}

inline double mean_diameter(const std::vector<Sphere> &s) {
  double d = 0;
  for (const Sphere &x : s) d += 2 * x.r / s.size();
  return d;
}

// A simple_cubic block, each sphere moved by up to `jitter` along each axis (a lattice
// is cospherical throughout: ties, which the skin does not decide, it floods all).
inline std::vector<Sphere> jittered_block(int nx, int ny, int nz, double jitter, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> move(-jitter, jitter);
  std::vector<Sphere> s = simple_cubic(nx, ny, nz);
  for (Sphere &x : s)
    for (int d = 0; d < 3; ++d) x.x[d] += move(random);
  return s;
}

// The spheres whose side is not inside (on the membrane or outside), ascending.
inline std::vector<int> not_inside(const std::vector<membrane3d::Side> &side) {
  std::vector<int> out;
  for (std::size_t i = 0; i < side.size(); ++i)
    if (side[i] != membrane3d::Side::inside) out.push_back(static_cast<int>(i));
  return out;
}

} // namespace packings

#endif

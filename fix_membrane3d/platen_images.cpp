#include "platen_images.h"

#include <algorithm>
#include <cmath>

namespace membrane3d {

double height_grid(const Platens &p, double band)
{
  // every height and image is below 4 (|lo| + |hi| + band) in size: 50 bits of it
  // leave a margin of 2 below the 53 of a double, so that sums of two are exact
  const double reach = 4 * (std::abs(p.lo) + std::abs(p.hi) + band);
  int exponent = 0;
  std::frexp(reach, &exponent);
  return std::ldexp(1.0, exponent - 50);
}

Eigen::Vector3d mirrored_position(const Eigen::Vector3d &x, int image, const Platens &p,
                                  double grid)
{
  auto on_grid = [grid](double z) { return std::nearbyint(z / grid) * grid; };
  const Eigen::Vector3d y(x.x(), x.y(), on_grid(x.z()));
  return image_position(y, image, {on_grid(p.lo), on_grid(p.hi)});
}

double image_band(const std::vector<Sphere> &spheres, double tolerance)
{
  double r_max = 0;
  for (const Sphere &s : spheres) r_max = std::max(r_max, s.r);
  return image_band(r_max, tolerance);
}

Mirrored mirror_in_platens(const std::vector<Sphere> &spheres, const Platens &platens,
                           double tolerance)
{
  return mirror_in_band(spheres, platens, image_band(spheres, tolerance));
}

Mirrored mirror_in_band(const std::vector<Sphere> &spheres, const Platens &platens, double band)
{
  Mirrored m;
  m.band = band;
  m.grid = height_grid(platens, m.band);
  auto add = [&m, &platens](const Sphere &s, int i, int image) {
    m.spheres.push_back({mirrored_position(s.x, image, platens, m.grid), s.r});
    m.sealed.push_back(image != 0);
    m.original.push_back(i);
    m.image.push_back(image);
  };
  for (std::size_t i = 0; i < spheres.size(); ++i) add(spheres[i], static_cast<int>(i), 0);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Sphere &s = spheres[i];
    if (imaged_below(s.x.z(), platens, m.band)) add(s, static_cast<int>(i), -1);
    if (imaged_above(s.x.z(), platens, m.band)) add(s, static_cast<int>(i), +1);
  }
  return m;
}

} // namespace membrane3d

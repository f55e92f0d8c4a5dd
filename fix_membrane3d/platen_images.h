// The platens of a triaxial sample and the spheres' images in them (fix membrane3d):
// near a platen the packing is continued beyond it by its mirror image, so that the
// exterior flood reaches the sample from the sides only (lateral_surface.h). No
// LIGGGHTS here.
#ifndef LIGGGHTS_MEMBRANE_PLATEN_IMAGES_H
#define LIGGGHTS_MEMBRANE_PLATEN_IMAGES_H

#include "exterior_flood.h"
#include "platens.h"

#include <Eigen/Core>

#include <vector>

namespace membrane3d {

using membrane::Platens; // lo, hi: z of the lower and upper platen

// Whether a platen of `now` is more than `tolerance` from where it was `then` (NaN:
// unknown, not moved): the links of the spheres with their images can have changed.
inline bool moved_apart(const Platens &now, const Platens &then, double tolerance)
{
  return platens_moved_beyond(now, then, tolerance);
}

// x, or its mirror image in the lower (image -1) or upper (+1) platen (inline: at
// every facet's corners every step).
inline Eigen::Vector3d image_position(const Eigen::Vector3d &x, int image, const Platens &p)
{
  Eigen::Vector3d y = x;
  if (image != 0) y.z() = 2 * (image < 0 ? p.lo : p.hi) - x.z();
  return y;
}

// The triangulation's heights lie on a grid of this spacing (a power of two, some
// 1e-15 of the heights): on it a mirror image 2 z_platen - z is exact, so that the
// images' symmetry is exact and its degenerate tests are decided by CGAL's symbolic
// perturbation, not by the round-off of the images (flood_watch.h).
double height_grid(const Platens &p, double band);

// image_position on the grid: the point the triangulation holds.
Eigen::Vector3d mirrored_position(const Eigen::Vector3d &x, int image, const Platens &p,
                                  double grid);

// The distance from a platen within which a sphere has an image: 3 (2 r_max + T).
double image_band(const std::vector<Sphere> &spheres, double tolerance);
// The band of spheres whose largest radius is r_max.
inline double image_band(double r_max, double tolerance)
{
  return 3 * (2 * r_max + tolerance);
}

// Whether a sphere centred at height z has an image in the lower / upper platen.
inline bool imaged_below(double z, const Platens &p, double band)
{
  return z - p.lo < band;
}
inline bool imaged_above(double z, const Platens &p, double band)
{
  return p.hi - z < band;
}

// The spheres and their images; entry k is sphere original[k] or its image in the
// lower (-1) or upper (+1) platen, sealed (exterior_flood.h) when an image.
struct Mirrored {
  double band = 0;             // image_band
  double grid = 0;             // height_grid
  std::vector<Sphere> spheres; // at mirrored_position
  std::vector<bool> sealed;
  std::vector<int> original, image;
};

Mirrored mirror_in_platens(const std::vector<Sphere> &spheres, const Platens &platens,
                           double tolerance);

// mirror_in_platens with the band given: a part of the spheres mirrored with the band of
// them all (a skin's, membrane3d_distributed.h) is the part of their Mirrored, in order.
Mirrored mirror_in_band(const std::vector<Sphere> &spheres, const Platens &platens, double band);

} // namespace membrane3d

#endif

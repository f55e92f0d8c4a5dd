// The membrane of a triaxial sample (fix membrane3d): the lateral surface of the packing
// between two platens normal to z, its loads on the spheres and which spheres have
// escaped. No LIGGGHTS here: unit-tested in tests/unit/membrane3d.
//
// The platens. Each sphere within the image band of a platen (3 (2 r_max + T) from
// it) is mirrored in the platen plane, so that near a platen the packing continues
// beyond it as it is before it; the images are sealed (exterior_flood.h), so the
// flood reaches the packing from the sides only. The boundary of the flood is then
// clipped at the two platen planes: the membrane ends exactly on the platens, its rims
// lie in their planes, and lateral_volume (surface_loads.h) is the sample's volume
// between them. A sphere within T of a platen is linked to it (to its image, at a gap
// of at most 2 T), so the membrane does not run between the platen and such spheres:
// it is sealed to the platen as a latex sleeve is, and where the end layer stands off
// the platen by up to T it hangs from the outermost spheres down to the platen.
//
// Vertex convention (Vertices): through the sphere centres, or on the spheres' outer
// faces, where the latex lies: each centre moved out by o_i, the least-squares
// solution of o . n_f = r_i over the facets f on sphere i (area-weighted), so that
// every facet plane of a flat face moves out by r, an edge between two faces by r
// along both normals and a cube's corner to its corner (|o_i| at most 2 r_i, and never
// past a platen plane, beyond which the facets of images only are left out). On the
// outer faces the loads sum to p times the sample's cross-section to its outer
// faces, as a rigid wall's would: through the centres a box of side W gets only
// (W - 2 r) / W of it, a cylinder of radius R (R - r) / R (a clipped facet has
// corners on its edges, in the platen planes, either way).
//
// Loads: the pressure on the part of a facet between the platens is shared among the
// facet's spheres as the consistent loads of a uniform pressure on a linear triangle,
// sum of -p x area x (mean shape function at the part's corners): equal thirds for an
// unclipped facet; a load at an image goes to its sphere unchanged. The loads sum to
// -p times the vector area of the lateral surface, whose x and y components are zero to
// round-off because its rims lie in planes normal to z.
#ifndef LIGGGHTS_MEMBRANE_LATERAL_SURFACE_H
#define LIGGGHTS_MEMBRANE_LATERAL_SURFACE_H

#include "exterior_flood.h"
#include "platen_images.h"
#include "surface_loads.h"

#include <array>
#include <vector>

namespace membrane3d {

// A corner of the lateral surface as weights over up to three spheres (-1: unused).
struct Corner {
  std::array<int, 3> sphere;
  std::array<double, 3> weight;
};

struct LateralSurface {
  Surface surface;             // the corners as points, facets counter-clockwise from outside
  std::vector<Corner> corners; // one per surface point
  std::vector<Side> side;      // per sphere: surface when it carries a load
  bool reaches_lo = false, reaches_hi = false; // a rim on each platen
};

// A vertex of the membrane: a sphere, or its image in the lower (-1) or upper (+1) platen.
struct MembraneVertex {
  int sphere;
  int image;
};

// What a detection finds: the membrane's facets, counter-clockwise from outside, and
// each sphere's side. It holds while the spheres move a little: the membrane is placed
// on the spheres' positions of each step (place_membrane) and found again now and then.
struct MembraneTopology {
  std::vector<std::array<MembraneVertex, 3>> facets;
  std::vector<Side> side; // per sphere
};

// The topology of the spheres' membrane. Throws std::invalid_argument for platens not
// in order, a centre not strictly between them (naming the sphere) and what
// exterior_boundary throws; std::runtime_error when no surface separates the spheres
// from the outside (no packing: no closed shell of links).
// With `mirrored` and `cells`, also the spheres with their images and the flooded
// triangulation (for detection_watch.h).
MembraneTopology detect_membrane(const std::vector<Sphere> &spheres, const Platens &platens,
                                 double tolerance, Mirrored *mirrored = nullptr,
                                 FloodCells *cells = nullptr);

// detect_membrane(spheres, platens, tolerance), from the spheres with a gap of at most
// `thickness` to a seed (e.g. the last detection's members) when they show the same
// result (skin_flood.h), else from all; `from_skin` tells which.
MembraneTopology detect_membrane_near(const std::vector<Sphere> &spheres, const Platens &platens,
                                      double tolerance, const std::vector<int> &seeds,
                                      double thickness, bool *from_skin = nullptr);

// The topology of the boundary of a skin's flood shown to be the group's (skin_flood.h),
// the skin of n_skin spheres mirrored in `m` (mirror_in_band, the band of the group's
// n_group spheres): that of detect_membrane on the group, over the skin's spheres
// (the others are inside), with its errors and their counts.
MembraneTopology skin_topology(const Boundary &boundary, const Mirrored &m, std::size_t n_skin,
                               std::size_t n_group, double tolerance);

// The topology over its members only: the spheres on a facet or outside, renumbered in
// their order; `members` gets their indices in the detection's spheres.
MembraneTopology members_only(const MembraneTopology &topology, std::vector<int> &members);

enum class Vertices { centres, outer_faces };

// The offsets o_i of the outer-face convention (zero for a sphere on no facet).
std::vector<Eigen::Vector3d> outer_face_offsets(const MembraneTopology &topology,
                                                const std::vector<Sphere> &spheres,
                                                const Platens &platens);

// outer_face_offsets without its checks: the caller has made them, or places a part of
// the membrane (membrane_part.h), whose spheres' offsets are exact when the topology
// holds every facet on them.
std::vector<Eigen::Vector3d> outer_face_offsets_unchecked(const MembraneTopology &topology,
                                                          const std::vector<Sphere> &spheres,
                                                          const Platens &platens);

// The membrane on `spheres` (indexed as the topology): facets clipped at the platens,
// corners, loads' weights, its vertices `at` the centres or the outer faces. Throws
// std::invalid_argument for platens not in order, a centre not strictly between them,
// or a facet whose sphere is not in `spheres`.
LateralSurface place_membrane(const MembraneTopology &topology, const std::vector<Sphere> &spheres,
                              const Platens &platens, Vertices at = Vertices::centres);

// place_membrane's facets clipped at the platens, their vertices at `vertex` (indexed as
// the topology's spheres), without checks. Each facet is clipped alone (a cut on an edge
// from the edge's lower-numbered vertex), so that any subset of the facets, numbered in
// the same order, gives the same bits; `origin` gets the topology's facet of each
// surface facet.
LateralSurface clip_membrane(const MembraneTopology &topology,
                             const std::vector<Eigen::Vector3d> &vertex, const Platens &platens,
                             std::vector<int> *origin = nullptr);

// detect_membrane, then place_membrane on the same spheres.
LateralSurface lateral_surface(const std::vector<Sphere> &spheres, const Platens &platens,
                               double tolerance, Vertices at = Vertices::centres);

// The membrane's load on each sphere (zero off the surface) at pressure p.
std::vector<Eigen::Vector3d> membrane_loads(const LateralSurface &membrane, std::size_t n_spheres,
                                            double p);

// The sample's axis: the area-weighted centroid (x, y) of the membrane's facets.
Eigen::Vector2d membrane_axis(const LateralSurface &membrane);

// Adds to `load` the push on each escaped sphere: p pi r^2 horizontally towards the
// axis (nothing for a sphere on the axis).
void add_escape_loads(const LateralSurface &membrane, const std::vector<Sphere> &spheres, double p,
                      std::vector<Eigen::Vector3d> &load);

// One escaped sphere's push towards the axis (zero on the axis).
Eigen::Vector3d escape_push(const Sphere &sphere, const Eigen::Vector2d &axis, double p);

} // namespace membrane3d

#endif

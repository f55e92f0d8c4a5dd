// The loads and measures of a triangulated membrane surface in 3D (fix membrane3d):
// the pressure as forces on the surface spheres, the surface's vector area and the
// volume it encloses with the platens. No LIGGGHTS here: unit-tested in
// tests/unit/membrane3d.
//
// A surface is the sphere centres and the facets between them, each facet's three
// vertices counter-clockwise seen from outside the sample, so that its vector area
// N_f = (b - a) x (c - a) / 2 points outwards.
//
// Sharing rule: the pressure p on facet f is the force -p N_f (inwards), shared in
// three equal parts among its vertices. The forces therefore sum to -p times the
// vector area of the surface, to round-off; on a closed surface (the lateral surface
// with its two platen caps) that is zero. Equal thirds are the consistent nodal loads
// of a uniform pressure on a linear triangle.
#ifndef LIGGGHTS_MEMBRANE_SURFACE_LOADS_H
#define LIGGGHTS_MEMBRANE_SURFACE_LOADS_H

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include <array>
#include <vector>

namespace membrane3d {

struct Surface {
  std::vector<Eigen::Vector3d> points;        // sphere centres
  std::vector<std::array<int, 3>> facets;     // indices into points, outward order
};

// N_f = (b - a) x (c - a) / 2 (inline: several times per facet and step).
inline Eigen::Vector3d facet_vector_area(const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                         const Eigen::Vector3d &c)
{
  return 0.5 * (b - a).cross(c - a);
}

// Throws std::out_of_range naming the first facet with an index outside the points.
void check_facets(const Surface &surface);

// Sum of N_f over the facets.
Eigen::Vector3d vector_area(const Surface &surface);

// One force per point: the sum over its facets of -p N_f / 3 (zero for a point on
// no facet).
std::vector<Eigen::Vector3d> pressure_forces(const Surface &surface, double p);

// Volume enclosed by a closed surface: the divergence theorem with F = x / 3,
// sum over facets of a . (b x c) / 6.
double enclosed_volume(const Surface &surface);

// Volume between the lateral surface and two platens normal to z (the axis), whose
// caps need not be triangulated: the divergence theorem with F = (x, y, 0) / 2, which
// has no flux through a cap normal to z, sum over facets of (c_x N_x + c_y N_y) / 2
// with c the facet's centroid (exact: the integrand is linear on a facet). Valid when
// the lateral surface's rims lie in the platen planes.
double lateral_volume(const Surface &surface);

// Radius of the circular cylinder of that volume and height: the lateral strain
// measure of a triaxial sample.
double equivalent_radius(double volume, double height);

} // namespace membrane3d

#endif

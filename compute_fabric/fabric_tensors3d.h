// Contact fabric of a 3D granular sample (definitions: doc/compute_fabric.md,
// "In 3D"): the deviatoric fabric tensor, the normal- and tangential-force
// anisotropy tensors of Ouadfel & Rothenburg (2001) and the Love-Weber stress,
// from partial sums that each MPI rank adds its own contacts to and that are
// merged over the ranks (as fabric_sums.h in 2D). No LIGGGHTS.
//
// Models, over unit directions n (dOmega: solid angle):
//   E(n)     = (1 + a_ij n_i n_j) / (4 pi)          contact normals,
//   fn(n)    = f0 (1 + an_ij n_i n_j)               mean normal force,
//   ft_i(n)  = f0 (at_ij n_j - (at_kl n_k n_l) n_i) mean tangential force,
// with a, an, at symmetric and traceless. With phi = (1/N) sum n (x) n,
//   a  = 15/2 dev(phi),
//   chi_n = (1/N) sum fn n (x) n / w,  chi_t = (1/N) sum ft (x) n / w,
//   w = 1 + a_kl n_k n_l (each contact weighted by 1 / its fabric density),
//   f0 = tr chi_n,  an = 15/2 dev(chi_n) / f0,  at = 5 sym(chi_t) / f0,
// each exact for contacts that sample the models on a spherical 4-design (the
// integrals of n_i n_j n_k n_l over the sphere): tests/unit/fabric.
#ifndef LIGGGHTS_MEMBRANE_FABRIC_TENSORS3D_H
#define LIGGGHTS_MEMBRANE_FABRIC_TENSORS3D_H

#include <Eigen/Core>

#include <array>
#include <vector>

#include "fabric_sums.h"

namespace fabric {

// One contact between spheres a and b (b = -1: a wall), counted once.
struct Contact3 {
  long a, b;
  Eigen::Vector3d n;  // unit normal from a to b; zero without a normal
  double fn;          // f . n, > 0 in compression (f: the force on b from a)
  Eigen::Vector3d ft; // f - fn n
  Eigen::Vector3d l;  // branch vector a -> b (wall: a's centre -> contact point, as in 2D)
};

// The contact from the branch vector l, the force f on b from a and the radius
// sum (wall: r_a); without a normal (|l| <= kCoincidentFraction * radius_sum or
// not finite) n, fn and ft are zero whatever the force, as make_contact in 2D.
Contact3 make_contact3(long a, long b, const Eigen::Vector3d &l, const Eigen::Vector3d &f,
                       double radius_sum);
bool has_normal(const Contact3 &c);

// A symmetric tensor's components in the order of the outputs: xx yy zz xy xz yz.
using Components = std::array<double, 6>;
Components components(const Eigen::Matrix3d &t);

// A deviatoric anisotropy tensor and its magnitude sqrt(3/2 a_ij a_ij) (for
// the axisymmetric a = diag(-x/2, -x/2, x) it is 3/2 |x|).
struct Anisotropy3 {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  double invariant = 0.0;
};
Anisotropy3 anisotropy_of(const Eigen::Matrix3d &deviator);

// Sums of ExactSums indexed by a Field enum, packed as (hi, lo) pairs like
// the 2D sums.
template <int N> struct FieldSums {
  std::array<ExactSum, N> sum;
  void merge(const FieldSums &other);
  std::vector<double> pack() const;
  void unpack(const double *packed);
  static constexpr int pairs() { return N; }
};

// The first pass over the contacts: counts, fabric and f (x) l.
struct ContactSums3 : FieldSums<17> {
  enum Field { CONTACTS, NO_NORMAL, PHI, FL = PHI + 6, FIELDS = FL + 9 };
  void add(const Contact3 &c);
  Eigen::Matrix3d phi() const; // (1/N) sum n (x) n over the contacts with a normal
  Eigen::Matrix3d f_l() const; // sum f (x) l
};

// The second pass, once the fabric is known: the weighted force sums.
struct ForceSums3 : FieldSums<17> {
  enum Field { WITH_NORMAL, SKIPPED, CHI_N, CHI_T = CHI_N + 6, FIELDS = CHI_T + 9 };
  // contacts whose weight w <= 0 (a strong fabric, outside the model's range;
  // kMinModelDensity: 0 up to round-off)
  // count in N but add no force; their number is SKIPPED
  void add(const Contact3 &c, const Eigen::Matrix3d &fabric);
};

struct ForceAnisotropy3 {
  Anisotropy3 normal, tangential;
  double f0 = 0.0;
  long skipped = 0;
};

Anisotropy3 fabric_anisotropy(const ContactSums3 &sums);
ForceAnisotropy3 force_anisotropy(const ForceSums3 &sums);
// sigma_ij = (1/V) sum f_i l_j, compression positive; volume <= 0 throws
// std::invalid_argument (the compute checks it first)
Eigen::Matrix3d love_weber_stress(const ContactSums3 &sums, double volume);

} // namespace fabric

#endif

// Contact-fabric statistics of a 2D granular sample (definitions: doc/compute_fabric.md).
//
// Kept free of LIGGGHTS so every formula can be checked against exact cases. These
// take the list of all contacts; the compute style fits from partial sums merged
// over the MPI ranks instead (fabric_sums.h, which reuses the histogram fits and
// equals the others to round-off).
#ifndef LIGGGHTS_MEMBRANE_FABRIC_STATISTICS_H
#define LIGGGHTS_MEMBRANE_FABRIC_STATISTICS_H

#include <Eigen/Core>

#include <vector>

namespace fabric {

// One contact, counted once. Angular statistics add the -n copy themselves, so a
// caller must not list a contact twice (newton off: both ranks see it).
struct Contact {
  long a, b;     // particle tags; b = -1 for a wall contact
  double nx, ny; // unit normal from a to b (wall: from a's centre towards the wall)
  double fn;     // normal force, > 0 in compression
  // Signed force on b along t = (-ny, nx) (n turned by +90 deg). Seen from b the
  // normal and t both flip and so does the force, so ft is the same from either
  // side: the -n copy in a histogram carries the same ft.
  double ft;
  // Branch vector from a's centre to b's centre. Wall: from a's centre to the
  // contact point (not twice that), because the wall lies outside the sample and
  // only a's half of the moment f (x) l counts; then sum f (x) l / A over walls is
  // exactly the wall traction (tests: LoveWeber.WallContactsGiveTheWallTraction).
  double lx, ly;
};

// Two disks whose centres coincide (e.g. created at one point) have no contact
// normal: a branch vector shorter than this fraction of the radius sum leaves the
// contact without one. Such a contact still counts in the coordination numbers but
// is left out of every direction statistic below (fabric, force roses, stress)
// and of the stability index.
constexpr double kCoincidentFraction = 1e-12;

// A contact's fabric density relative to the mean, w = 1 + a:nn (2D: 1 + a cos
// 2(theta - theta_a)), weights it by 1/w in the force tensors; at or below
// kMinModelDensity the model cannot describe it and the contact adds no force.
// Not 0: w = 0 in exact arithmetic (e.g. 4 contacts along z and 1 along x in 3D:
// a_xx = -1) comes out as +2e-16 in floating point, and a weight of 4.5e15 made
// f0 9e13 N. The fabric's round-off is ~1e-15 (components up to 7.5 of sums of
// unit dyads), so 1e-12 is zero to round-off and no physical density is as low.
constexpr double kMinModelDensity = 1e-12;
inline bool model_density_usable(double w)
{
  return w > kMinModelDensity;
}

// The contact of a and b from the branch vector l (see Contact), the force (fx, fy)
// on b and the radius sum r_a + r_b (wall: r_a): n = l / |l|, fn = f.n, ft = f.t.
// Without a normal (|l| <= kCoincidentFraction * radius_sum, l not finite, or
// radius_sum NaN) nx = ny = fn = ft = 0, whatever the force (LIGGGHTS' contact
// models return NaN forces for coincident centres).
Contact make_contact(long a, long b, double lx, double ly, double fx, double fy, double radius_sum);

// False when the contact has no normal: nx or ny not finite, or both 0. Such
// contacts are skipped by polar_histogram, the tensors and love_weber_stress.
bool has_normal(const Contact &c);

// Contacts without a normal: how many, and the index of the first (-1: none),
// for the warning that names it.
struct MissingNormals {
  long count;
  long first;
};
MissingNormals missing_normals(const std::vector<Contact> &contacts);

// The centre (bin + 1/2) 2 pi / nbins of a bin, in radians (see angle_bin).
double bin_centre(int bin, int nbins);

// A finite angle in radians wrapped to [0, 2 pi): fmod's result bit for bit (the
// angle itself when it is in [0, 2 pi) already, as atan2's are or their + pi).
double wrap_to_full_turn(double angle);

// The bin among nbins (width 2 pi / nbins, bin 0 from +x) of an angle in radians of
// any range, wrapped to [0, 2 pi); -1 (no bin) for a NaN or infinite angle or
// nbins < 1, so a histogram never indexes out of range.
int angle_bin(double angle, int nbins);

// angle_bin(atan2(ny, nx), nbins) for a unit normal (nx, ny), for an even nbins
// without the atan2 (which costs most of a contact's binning): the sign of
// the cross product with the bin edges of its half plane, found by bisection,
// decides; an edge closer than 1e-12 (the two computations could then differ)
// falls back to angle_bin(atan2), so the bin is the same bit for bit.
class NormalBins {
 public:
  explicit NormalBins(int nbins); // nbins even and >= 2
  int bin(double nx, double ny) const;

 private:
  int nbins_;
  std::vector<double> edge_x_, edge_y_; // edges k 2 pi / nbins, k < nbins / 2
};

// The paper's prefactor 2 sin(dth)/(N dth) inverts the bin-averaging correction;
// Unbiased (2 dth/(N sin dth)) recovers a model anisotropy exactly. The published
// one is low by the factor (sin dth/dth)^2: 0.9600 for 18 bins.
enum class BinCorrection { Unbiased, Published };

// a >= 0; theta in (-pi/2, pi/2] because the fabric is pi-periodic.
struct Anisotropy {
  double a;
  double theta;
};

// Built by polar_histogram, or by hand to feed synthetic binned data to the
// estimators. count is a double so model-exact fractional counts are possible.
// Bin g covers [g dth, (g+1) dth) from +x, dth = 2 pi / nbins, centre (g+1/2) dth.
// mean_fn, mean_ft are 0 in empty bins; empty_bins counts bins with count == 0.
struct Histogram {
  int nbins;
  std::vector<double> count;
  std::vector<double> mean_fn;
  std::vector<double> mean_ft;
  int empty_bins;
};

// Each contact enters twice (n and -n), so the rose is point-symmetric and
// sum(count) = 2 x contacts with a normal (has_normal). nbins must be >= 3 and != 4: with 1 or 2
// bins sin(dth) = 0, and with 4 bins every centre has cos 2theta = 0, so the cos 2theta_a part of
// the fabric is invisible. Throws std::invalid_argument.
Histogram polar_histogram(const std::vector<Contact> &contacts, int nbins);

// Rothenburg & Bathurst (1989) from binned counts, N = sum of counts.
// Empty histogram -> {0, 0}. Throws std::invalid_argument on a malformed histogram.
Anisotropy normal_anisotropy_histogram(const Histogram &h,
                                       BinCorrection correction = BinCorrection::Unbiased);

// phi = (1/N) sum n (x) n over the N contacts with a normal; a = 2 (phi1 - phi2),
// theta along the major axis. Binning-free and the exact limit of the histogram
// estimate. No contacts with a normal -> {0, 0}.
Anisotropy normal_anisotropy_tensor(const std::vector<Contact> &contacts);

// Mean-force rose f_n(th) = f0 [1 + an cos 2(th - theta_n)] and tangential rose
// f_t(th) = -f0 at sin 2(th - theta_t) (Rothenburg & Bathurst). an, at >= 0.
// All zero when there are no contacts or f0 <= 0; empty_bins is 0 for the tensor.
struct ForceAnisotropy {
  double an;
  double theta_n;
  double f0;
  double at;
  double theta_t;
  int empty_bins;
};

// The tensor estimator's force anisotropy from the major axes of the mean
// normal-force and tangential tensors, f0 the normal one's trace (> 0).
ForceAnisotropy force_anisotropy_of(double f0, const Anisotropy &normal,
                                    const Anisotropy &tangential);

// Bin means are independent of how many contacts a bin holds, so no fabric
// correction is needed here. Empty bins are left out of the sums and f0 is the
// mean over the angle the non-empty bins cover (doc/compute_fabric.md, force anisotropy):
//   f0 = sum' f(g) dth / (n' dth)
//   an cos 2theta_n =  c/(pi f0) sum' fn(g) cos 2theta_g dth   (sin: likewise)
//   at sin 2theta_t =  c/(pi f0) sum' ft(g) cos 2theta_g dth
//   at cos 2theta_t = -c/(pi f0) sum' ft(g) sin 2theta_g dth
// with c = dth/sin dth (Unbiased) or sin dth/dth (Published).
ForceAnisotropy force_anisotropy_histogram(const Histogram &h,
                                           BinCorrection correction = BinCorrection::Unbiased);

// Dividing each contact by the fitted fabric density w = 1 + a cos 2(th - theta_a)
// removes the fabric's own anisotropy from the force tensors:
//   chi_n = (1/N) sum fn n (x) n / w;       f0 = tr chi_n;  an = 2 (chi_n1 - chi_n2) / f0
//   chi_t = sym((1/N) sum ft n (x) t / w);  at = 2 (chi_t1 - chi_t2) / f0
// over the N contacts with a normal; theta_n, theta_t along the major eigenvectors. For the model
// roses above this returns (an, theta_n, f0, at, theta_t) exactly. The model density is only valid
// for a < 1; contacts where w <= 0 (kMinModelDensity) are skipped (the model cannot describe them).
ForceAnisotropy force_anisotropy_tensor(const std::vector<Contact> &contacts,
                                        const Anisotropy &fabric);

// How compute fabric's 'estimator' fits both roses: from the polar histogram
// of nbins bins with either bin correction, or from the tensors (nbins unused).
enum class Estimator { Unbiased, Published, Tensor };

struct Anisotropies {
  Anisotropy fabric;
  ForceAnisotropy force;
};

// The fabric and force anisotropies by one estimator; the tensor force fit
// divides by the tensor fabric.
Anisotropies anisotropies(const std::vector<Contact> &contacts, int nbins, Estimator estimator);

// n_contacts is sum(contacts_per_particle), i.e. 2 N_c when only particle-particle
// contacts are counted; whether a wall contact adds 1 is the caller's choice.
// n0, n1: particles with 0 and 1 contacts (rattlers), left out of Zm.
struct Coordination {
  double Cn;
  double Zm;
  long n_contacts;
  long n_particles;
  long n0;
  long n1;
};

// Cn = sum/Np; Zm = (sum - N1)/(Np - N0 - N1), 0 when no particle has >= 2
// contacts. Empty input -> all zero. A negative count throws std::invalid_argument.
Coordination coordination(const std::vector<int> &contacts_per_particle);

// sigma_ij = (1/A) sum f_i l_j with f = fn n + ft t the force on b: compression
// positive, as in soil mechanics. Not symmetric when tangential forces carry a
// moment. Contacts without a normal are skipped (their branch vector is ~0, so
// they carry no moment, and their force may be NaN). area is the sample area per unit thickness;
// area <= 0 throws std::invalid_argument (check it before, e.g. as an error->all in the compute).
Eigen::Matrix2d love_weber_stress(const std::vector<Contact> &contacts, double area);

} // namespace fabric

#endif

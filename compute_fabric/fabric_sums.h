// The partial sums from which every sample statistic of compute fabric is fitted
// (doc/compute_fabric.md). Each MPI rank adds its own contacts to one
// FabricSums (add), the ranks' sums are merged (merge; compute fabric does it
// with one MPI_Allreduce of pack()), and the fits below are done from the merged
// sums, identically on every rank. No LIGGGHTS.
//
// Every floating-point sum is an ExactSum (a double-double): its value is the
// exact sum rounded once, up to an error of about n * 1e-32 of the sum of the
// magnitudes, so the fits do not depend on the order in which contacts are
// added or on how they are split over ranks (to round-off of that order).
#ifndef LIGGGHTS_MEMBRANE_FABRIC_SUMS_H
#define LIGGGHTS_MEMBRANE_FABRIC_SUMS_H

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "fabric_statistics.h"

namespace fabric {

// hi + lo, with lo the rounding errors of the additions to hi (Knuth's TwoSum).
struct ExactSum {
  double hi = 0.0, lo = 0.0;
  void add(double x);
  void merge(const ExactSum &other);
  double value() const { return hi + lo; }
};

// merge, pack and unpack of a struct of ExactSums (fabric_sums.cpp lists the
// fields of each): pack() gives all sums as (hi, lo) pairs, 2 * pairs()
// doubles, and unpack of a packed array gives them back exactly.
template <class S> struct PackedSums {
  void merge(const S &other);
  std::vector<double> pack() const;
  void unpack(const double *packed);
};

// The sums over the contacts (with walls: and wall contacts) of one rank or of
// the sample. Counts are kept as ExactSum too (exact up to 2^53) so that the
// whole struct packs into pairs of doubles.
struct FabricSums : PackedSums<FabricSums> {
  explicit FabricSums(int nbins = 18);

  int nbins;
  ExactSum contacts;                               // N_c
  ExactSum no_normal;                              // N_c^0 (coincident centres)
  std::vector<ExactSum> bin_count, bin_fn, bin_ft; // per bin: entries, sum fn, sum ft
  ExactSum phi_xx, phi_xy, phi_yy;                 // sum n (x) n
  ExactSum f_l_xx, f_l_xy, f_l_yx, f_l_yy;         // sum f_i l_j (Love-Weber)

  // one contact: N_c, and with a normal the two bins of n and -n, the fabric
  // tensor and f (x) l (as polar_histogram, normal_anisotropy_tensor and
  // love_weber_stress do with a list). With an even nbins the bin of -n is the
  // bin of n plus nbins/2, so the histogram is point-symmetric exactly (the
  // list's polar_histogram bins -n by its own angle: the same but for angles on
  // a bin edge). theta = atan2(ny, nx) when the caller has it already; without
  // it an even nbins bins n by NormalBins (the same bin, no atan2).
  void add(const Contact &c);
  void add(const Contact &c, double theta);
  void merge(const FabricSums &other); // of the same nbins
  int pairs() const;

 private:
  void add_to_bins(const Contact &c, int bin, int opposite);
  std::optional<NormalBins> normal_bins; // with an even nbins
};

// The tensor estimator's force sums, a second pass over the contacts once the
// fabric fit is known (each contact is divided by its fabric density w).
struct ForceTensorSums : PackedSums<ForceTensorSums> {
  ExactSum with_normal; // N_n, including the contacts skipped for w <= 0
  ExactSum chi_n_xx, chi_n_xy, chi_n_yy, chi_t_xx, chi_t_xy, chi_t_yy; // sums, not / N_n

  void add(const Contact &c, const Anisotropy &fabric);
  void add(const Contact &c, const Anisotropy &fabric, double theta); // theta as above
  int pairs() const { return 7; }
};

// The per-particle sums: contact counts and the stability index, over the
// particles of the group (and region).
struct ParticleSums : PackedSums<ParticleSums> {
  ExactSum particles;            // N_p
  ExactSum contact_ends;         // sum of the contact counts (2 N_c without walls)
  ExactSum rattlers0, rattlers1; // N_0, N_1
  ExactSum lambda;               // sum of lambda over the particles with >= 2 contacts

  // a particle with `contacts` contacts and stability index `lambda` (used only
  // for >= 2 contacts)
  void add(long contacts, double lambda_value);
  int pairs() const { return 5; }
};

// The fits from reduced sums; each equals the function of fabric_statistics.h
// applied to the list of all contacts (to round-off).
Histogram histogram_of(const FabricSums &sums);
Anisotropy normal_anisotropy_tensor(const FabricSums &sums);
ForceAnisotropy force_anisotropy_tensor(const ForceTensorSums &sums);
Eigen::Matrix2d love_weber_stress(const FabricSums &sums, double area);
Coordination coordination(const ParticleSums &sums);
// The fabric and force anisotropies by one estimator, as anisotropies() of
// fabric_statistics.h; `tensor` (the second pass) is used by Estimator::Tensor only.
Anisotropies anisotropies(const FabricSums &sums, const ForceTensorSums &tensor,
                          Estimator estimator);
// as mean_stability_index of stability_index.h
double mean_stability_index(const ParticleSums &sums, bool with_rattlers);

} // namespace fabric

#endif

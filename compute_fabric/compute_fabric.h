/* ----------------------------------------------------------------------
   compute fabric: contact-normal and contact-force fabric of a 2D
   granular assembly (Rothenburg & Bathurst 1989), coordination numbers,
   geometrical stability index (Momeni et al. 2022) and Love-Weber stress;
   in 3D the fabric and force anisotropy tensors (Ouadfel & Rothenburg
   2001, fabric_output3d.h), coordination numbers and stress.
   See doc/compute_fabric.md. Each rank reads its own contacts
   (fabric_local.h), adds them to partial sums that are merged over the
   ranks (fabric_sums.h) and fits from those; the mathematics is in
   fabric_sums.h, fabric_statistics.h and stability_index.h (no LIGGGHTS).
   This class parses its arguments, calls them and fills its outputs.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

// clang-format off
ComputeStyle(fabric,ComputeFabric)
// clang-format on

#else

#ifndef LIGGGHTS_MEMBRANE_COMPUTE_FABRIC_H
#define LIGGGHTS_MEMBRANE_COMPUTE_FABRIC_H

#include <string>
#include <vector>

#include "compute.h"
#include "fabric_local.h"
#include "fabric_sums.h"
#include "scalar_input.h"

namespace LAMMPS_NS {

class ComputeFabric : public Compute {
 public:
  ComputeFabric(class LAMMPS *, int &iarg, int, char **);
  ~ComputeFabric();
  void init();
  void compute_vector();
  void compute_array();
  void compute_peratom();
  double memory_usage();
  // the contact angles seen at ghosts go to their owners (FabricLocal)
  int pack_reverse_comm(int n, int first, double *buf)
  {
    return contact_source.pack_ends(n, first, buf);
  }
  void unpack_reverse_comm(int n, int *list, double *buf) { contact_source.unpack_ends(n, list, buf); }

  // global vector layout in 2D (1-based in input scripts: c_ID[k]; 3D: fabric3d)
  enum VectorIndex {
    A = 0,
    THETA_A,
    A_N,
    THETA_N,
    F0,
    A_T,
    THETA_T,
    CN,
    ZM,
    NCONTACT,
    NPARTICLE,
    EMPTY_BINS,
    MEAN_STABILITY_INDEX, // lambda
    SXX,
    SYY,
    SXY,
    NO_NORMAL,
    VECTOR_SIZE
  };

 private:
  const std::string prefix; // of every message: "Compute fabric (id fab): "
  int nbins;
  fabric::Estimator estimator;
  bool stability_flag; // mean stability index in the vector
  bool rattlers_flag;  // include particles with < 2 contacts in the mean stability index
  bool histogram_flag; // polar histogram as global array
  bool stress_flag;
  bool walls_flag;      // count particle-wall contacts
  ScalarInput area_in;  // Love-Weber area: a number or v_name
  int area_ivar;        // ... the variable, found at init
  std::string idregion; // empty: no region
  int iregion;
  bool three_d; // dimension 3: the tensors of fabric_output3d.h

  FabricLocal contact_source;

  // The reduced sums of one timestep, shared by the vector, the array and the
  // per-atom array (they may all be invoked in one step).
  struct StepSums {
    bigint step = -1;
    fabric::FabricSums sums;
    fabric::ForceTensorSums tensor; // estimator tensor only
    fabric::ParticleSums particles; // lambda only with stability yes
    std::vector<double> lambda;     // per local atom, when computed
    bool have_lambda = false;
    bool with_angles = false; // contact angles per particle collected
  } current;
  bool warned_no_normal;
  bool evaluating_area = false; // sample_area is running (a variable reading this compute)

  int nmax_atom;

  void parse_args(int iarg, int narg, char **arg);
  Region *region() const;
  // the sums of this step; with_angles: the per-particle contact angles too
  // (for lambda), else counts only (cheaper, less communication)
  const StepSums &sums_now(bool with_angles);
  fabric::ParticleSums particle_sums(bool with_lambda);
  void warn_no_normal(long count);
  double sample_area();
};

} // namespace LAMMPS_NS

#endif
#endif

/* ----------------------------------------------------------------------
   compute fabric: contact-normal and contact-force fabric of a 2D
   granular assembly (Rothenburg & Bathurst 1989), coordination numbers,
   geometrical stability index (Momeni et al. 2022) and Love-Weber stress.
   See doc/compute_fabric.md. The contacts come from fabric_gather.h, the
   mathematics from fabric_statistics.h, particle_contacts.h and
   stability_index.h (no LIGGGHTS); this class parses its arguments, calls
   them and fills its outputs.
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
#include "fabric_gather.h"
#include "fabric_statistics.h"
#include "particle_contacts.h"
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

  // global vector layout (1-based in input scripts: c_ID[k])
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

  FabricGather contact_gather;

  // The contacts of one timestep, shared by the vector, the array and the
  // per-atom array (they may all be invoked in one step).
  struct StepContacts {
    bigint step = -1;
    std::vector<fabric::Contact> contacts; // sorted by tags, the same on every rank
    fabric::ParticleContacts particles;
    long nparticles = 0; // in group (and region)
    fabric::MissingNormals no_normal{0, -1};
  } current;
  bool warned_no_normal;

  int nmax_atom;

  void parse_args(int iarg, int narg, char **arg);
  Region *region() const;
  const StepContacts &contacts_now();
  void warn_no_normal(const StepContacts &step);
  double sample_area();
};

} // namespace LAMMPS_NS

#endif
#endif

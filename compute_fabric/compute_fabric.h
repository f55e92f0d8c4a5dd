/* ----------------------------------------------------------------------
   compute fabric: contact-normal and contact-force fabric of a 2D
   granular assembly (Rothenburg & Bathurst 1989), coordination numbers,
   geometrical stability index (Momeni et al. 2022) and Love-Weber stress.
   See doc/compute_fabric.md. Mathematics in fabric_statistics.h and
   stability_index.h (no LIGGGHTS); this class gathers contacts only.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS

// clang-format off
ComputeStyle(fabric,ComputeFabric)
// clang-format on

#else

#ifndef LMP_COMPUTE_FABRIC_H
#define LMP_COMPUTE_FABRIC_H

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "compute.h"
#include "fabric_statistics.h"
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
    MEAN_GSI,
    SXX,
    SYY,
    SXY,
    NO_NORMAL,
    VECTOR_SIZE
  };

 private:
  enum class Estimator { Unbiased, Published, Tensor };

  int nbins;
  Estimator estimator;
  bool stability_flag; // mean GSI in the vector
  bool rattlers_flag;  // include particles with < 2 contacts in the mean GSI
  bool histogram_flag; // polar histograms as global array
  bool stress_flag;
  ScalarInput area_in;  // Love-Weber area: a number or v_name
  int area_ivar;        // ... the variable, found at init
  std::string idregion; // empty: no region
  int iregion;

  // LIGGGHTS' computes that report contact forces: pair/gran/local for
  // particle-particle, wall/gran/local for particle-(mesh) wall contacts
  struct ContactSource {
    const char *style;
    char *id = nullptr; // the user's compute, or ours (ID_contacts, ID_walls)
    class ComputePairGranLocal *compute = nullptr;
  };
  ContactSource pairs{"pair/gran/local"}, walls{"wall/gran/local"};
  bool walls_flag; // count particle-wall contacts

  bigint gathered_step;                      // timestep of the contact list below
  std::vector<fabric::Contact> contact_list; // all contacts, identical on every rank
  std::vector<double> sendbuf, recvbuf;
  std::vector<std::pair<uint64_t, int>> sort_keys;
  struct End {
    long tag;
    double angle;
  };
  std::vector<End> ends;      // both ends of every contact
  std::vector<long> end_tag;  // the tags with contacts, ascending
  std::vector<int> end_start; // contact angles about end_tag[t] (CSR)
  std::vector<double> end_angle, angles;
  std::vector<int> recvcounts, displs;
  long nparticles;     // particles in group (and region)
  long no_normal;      // contacts with coincident centres (no normal)
  int first_no_normal; // ... the first of them in contact_list
  bool warned_no_normal;

  int nmax_atom;

  void parse_args(int iarg, int narg, char **arg);
  void find_source(ContactSource &src);
  void create_source(ContactSource &src, const char *suffix);
  void init_source(ContactSource &src, const char *suffix);
  void pack_contacts(const ContactSource &src, bool wall);
  void gather_contacts();
  bool atom_selected(int i) const;
  double sample_area();
  std::vector<int> contacts_per_particle() const;
  void warn_no_normal();
  void index_contact_ends();
  double mean_stability_index();
};

} // namespace LAMMPS_NS

#endif
#endif

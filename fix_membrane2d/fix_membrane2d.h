/* ----------------------------------------------------------------------
   fix membrane2d: a deformable latex membrane on the left and right of a
   2D biaxial sample (Cheung & O'Sullivan 2008; Momeni et al. 2024).
   The chain of outermost disks on each side carries the confining
   pressure as one force per disk. See doc/fix_membrane2d.md. Geometry in
   membrane_chain.h (no LIGGGHTS); this class gathers the side bands,
   calls it and applies the forces to owned atoms.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(membrane2d,FixMembrane2d)
// clang-format on

#else

#ifndef LMP_FIX_MEMBRANE2D_H
#define LMP_FIX_MEMBRANE2D_H

#include <cstdint>
#include <cstdio>
#include <map>
#include <vector>

#include "fix.h"
#include "membrane_chain.h"
#include "scalar_input.h"

namespace LAMMPS_NS {

class FixMembrane2d : public Fix {
 public:
  FixMembrane2d(class LAMMPS *, int, char **);
  ~FixMembrane2d();
  int setmask();
  void init();
  void setup_pre_force(int);
  void setup(int);
  void pre_force(int);
  void post_force(int);
  void post_run();
  double compute_vector(int);
  void write_restart(FILE *);
  void restart(char *);
  int pack_restart(int, double *);
  void unpack_restart(int, int) {}
  int size_restart(int) { return 1; }
  int maxsize_restart() { return 1; }
  double memory_usage();
  // LIGGGHTS sizes its per-type-pair contact tables by the types atoms and fixes
  // report: the frictionless type may not be on any atom before the first run.
  int min_type() { return membrane_type; }
  int max_type() { return membrane_type; }

  // global vector layout (1-based in input scripts: f_ID[k])
  enum VectorIndex {
    AREA = 0,
    MEAN_WIDTH,
    MID_WIDTH,
    CHAIN_LEFT,
    CHAIN_RIGHT,
    ESCAPED,
    FX_LEFT,
    FY_LEFT,
    FX_RIGHT,
    FY_RIGHT,
    REDETECTIONS,
    FAILURES,
    PRESSURE,
    WIDENINGS,
    CHAIN_STEP,
    INERTIAL,
    CHANGES,
    VECTOR_SIZE
  };
  enum Flag { NONE = 0, LEFT_CHAIN = 1, RIGHT_CHAIN = 2, ESCAPEE = 3 };

 private:
  struct SideState {
    membrane::Side side;
    bool active = false;
    std::vector<long> chain_tags; // bottom -> top, kept between detections
    std::vector<long> escaped_tags;
    std::vector<long> forgotten_tags, forgotten_escaped; // of the last run, when not kept
    std::vector<double> escaped_radius;
    membrane::BandSlices slices;
    std::vector<membrane::Disk> band;        // gathered at the last detection
    std::vector<int> band_type;              // type of each band disk
    std::vector<membrane::Disk> chain_disks; // current positions, chain order
    std::vector<int> chain_types;            // current types, chain order
    membrane::DetectionWatch watch;          // every auto: what the last search depended on
    std::vector<membrane::Disk> watch_band;  // the band it searched, as it was then
    std::vector<membrane::Disk> now;         // the same, watched disks at their current positions
    membrane::Polyline polyline;
    std::vector<Eigen::Vector2d> forces;
    Eigen::Vector2d total{0.0, 0.0};
    bool warned = false;
  };

  ScalarInput pressure_in, ylo_in, yhi_in; // numbers or v_name
  double thickness;
  double band_width;   // <= 0: 4 x D50 of the group, set in init()
  double search_width; // band width of the next search: band_width, or wider once widened
  double tolerance;    // < 0: 0.02 x D50
  double band_given, tolerance_given; // as given (-1: default), compared on restart
  double d50;
  double density;    // group mass / group disk area [kg/m^2 per unit thickness]
  int detect_every;  // 0: auto (when the chain can have changed)
  int membrane_type; // 0: chain disks keep their friction
  bigint polyline_every;
  char *polyline_file;
  FILE *polyline_fp;

  SideState sides[2]; // LEFT, RIGHT
  membrane::ChainFinder finder;
  membrane::ChainResult result;
  std::vector<int> result_buf;       // a side's chain search, broadcast by the rank that ran it
  std::map<long, int> observed_type; // chain tag -> its own (not frictionless) type
  // Between runs (and in restart files) every disk carries its own type: the
  // chain disks take the frictionless type while the fix runs.
  bool types_applied = false;
  std::vector<char> restored_for_restart; // local atoms write_restart gave their own type back
  // The chain state is kept from one run to the next (and through restart
  // files) when the group's disks are as they were: same tags, types, radii
  // and positions, checked by a checksum at the start of the run.
  bool state_kept = false;
  std::uint64_t state_checksum = 0;
  std::vector<int> slice_of_atom; // band slice of each local disk
  std::vector<int> chain_index;   // 0..n-1: chain_disks are already in chain order

  // disks whose positions are gathered every step: chain disks and watched disks
  struct WatchEntry {
    long tag = 0;
    int chain_index[2] = {-1, -1}; // position in sides[k].chain_disks
    int band_index[2] = {-1, -1};  // index in sides[k].now
  };
  std::vector<WatchEntry> watch_list; // sorted by tag
  double band_displacement = 0.0;     // largest band-disk displacement since the detection
  double ylo_detected = 0.0, yhi_detected = 0.0;

  double pressure, ylo, yhi;
  bool force_detection;
  double vector_values[VECTOR_SIZE];
  bigint redetections, failures, widenings;
  bigint changes; // detections that changed a chain or its escapees (per side)

  // stability guards
  struct ChainStep {
    double fraction; // largest |v| dt / r of a chain disk this step
    long tag;
  } chain_step;
  double inertial;       // last inertial number (0 before the first window)
  bigint inertial_step0; // start of the current strain-rate window (-1: none)
  double inertial_height0;
  bool warned_chain_step, warned_inertial;
  double warned_dt = 0.0;     // the time step last warned about
  bool inertial_above_before; // the previous window was above the limit

  int nmax_flag;
  std::vector<double> sendbuf, recvbuf;
  std::vector<int> recvcounts, displs;

  void evaluate_platens();
  void check_other_membranes();
  void check_lengths();
  std::uint64_t group_checksum();
  void forget_state();
  void apply_types();
  void restore_types();
  void check_platens();
  void check_chain_step();
  void check_inertial_number();
  void gather_bands(double width);
  void accept_chain(int side);
  void chain_lost(int side);
  void detect_chains();
  void find_chain(int side);
  void switch_types(const std::vector<long> &old_tags, const std::vector<long> &new_tags);
  void build_watch_list();
  void gather_watched();
  bool chains_may_have_changed();
  void apply_forces();
  void update_flags();
  void update_outputs();
  void write_polylines();
};

} // namespace LAMMPS_NS

#endif
#endif

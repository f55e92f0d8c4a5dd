/* ----------------------------------------------------------------------
   fix membrane3d: a flexible latex membrane around a 3D triaxial sample
   between two platens normal to z. The outer surface of the packing is
   found by flooding the spheres' regular triangulation from outside
   (exterior_flood.h), clipped at the platens (lateral_surface.h), and the
   confining pressure acts on it as the consistent loads of its facets;
   escaped spheres are pushed back. See doc/fix_membrane3d.md. This class
   gathers the spheres (membrane3d_gather.h), calls the core and applies
   the loads to owned atoms.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(membrane3d,FixMembrane3d)
// clang-format on

#else

#ifndef LIGGGHTS_MEMBRANE_FIX_MEMBRANE3D_H
#define LIGGGHTS_MEMBRANE_FIX_MEMBRANE3D_H

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fix.h"
#include "lateral_surface.h"
#include "membrane3d_auto.h"
#include "membrane3d_frames.h"
#include "membrane3d_gather.h"
#include "membrane3d_types.h"
#include "platen_inputs.h"

namespace LAMMPS_NS {

class FixMembrane3d : public Fix {
 public:
  // the global vector (doc/fix_membrane3d.md, Output)
  enum Output {
    VOLUME,
    EQUIVALENT_RADIUS,
    MEMBRANE_SPHERES,
    ESCAPED_SPHERES,
    FACETS,
    DETECTIONS,
    AXIAL_FORCE,
    LATERAL_FORCE,
    OUTER_VOLUME,
    OUTER_RADIUS,
    OUTPUT_SIZE
  };

  FixMembrane3d(class LAMMPS *, int, char **);
  ~FixMembrane3d();
  int setmask();
  void init();
  void setup_pre_force(int);
  void setup(int);
  // the detection before the pair forces (a sphere that joins the membrane is
  // frictionless in that very step), the loads after them
  void pre_force(int);
  void post_force(int);
  void post_run();
  // the frictionless type, so that the pair style sizes its tables for it
  int min_type() { return types.type(); }
  int max_type() { return types.type(); }
  double compute_vector(int n);
  // restart: the last detection (its topology over atom IDs, its step) and the
  // counter, so that a run continued from the file gives the output of one
  // straight through
  void write_restart(FILE *);
  void restart(char *);
  // with frictionless: the atoms are written with their own types (membrane3d_types.h)
  int pack_restart(int, double *);
  void unpack_restart(int, int) {}
  int size_restart(int) { return 1; }
  int maxsize_restart() { return 1; }
  double memory_usage();
  // FILE.pvd of keyword vtk, "" without it (two fixes may not share it)
  std::string vtk_file() const { return frames.pvd(); }

 private:
  PlatenInputs inputs; // pressure, zlo, zhi
  double tolerance_given = -1.0;           // -1: the default, from the mean diameter
  enum { AUTO = 0 };
  int every = 1; // or AUTO
  Membrane3dAuto automatic; // every auto
  double tolerance = 0.0;
  Membrane3dFrames frames; // keyword vtk
  Membrane3dTypes types;   // keyword frictionless

  // the last detection: its topology over the member atoms, their IDs, its step
  membrane3d::MembraneTopology topology;
  std::vector<int> member_tags;
  bigint last_detection = -1;
  membrane3d::Platens detected_platens{0.0, 0.0}; // at the last detection
  bigint decided_step = -1; // the last step pre_force decided on
  // the group at the end of the last run (or when the restart file was written): a
  // run that starts on another group (delete_atoms renumbers the IDs) finds the
  // membrane anew
  bool has_checksum = false;
  std::uint64_t checksum = 0;
  std::vector<membrane3d::Sphere> detected_at; // the members then (after a restart: at its start)
  double detections = 0.0;

  // this step
  GatheredSpheres members; // the member atoms now, in member_tags' order
  double pressure = 0.0;
  membrane3d::Platens platens{0.0, 0.0};
  bool warned_rim = false;
  bool warned_spread = false; // an input differing between the ranks, once per fix
  bool warned_moved = false;  // a member far from where the membrane was found, once per run
  double output[OUTPUT_SIZE];
  bool centres_placed = false; // output[VOLUME] is this step's

  void evaluate_inputs();
  void detect();
  void wear_types(const GatheredSpheres &g);
  void place_and_apply();
  [[noreturn]] void fail(const char *what, const char *advice);
};

} // namespace LAMMPS_NS

#endif
#endif

/* ----------------------------------------------------------------------
   fix membrane3d: a flexible latex membrane around a 3D triaxial sample
   between two platens normal to z. The outer surface of the packing is
   found by flooding the spheres' regular triangulation from outside
   (exterior_flood.h), clipped at the platens (lateral_surface.h), and the
   confining pressure acts on it as the consistent loads of its facets;
   escaped spheres are pushed back. See doc/fix_membrane3d.md. What it
   shares with fix membrane2d (keywords, inputs, checks, frictionless
   types, frames, restart envelope) is membrane/membrane_fix.h; this class
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
#include <functional>
#include <vector>

#include "distributed_skin.h"
#include "gathered_spheres.h"
#include "lateral_surface.h"
#include "membrane3d_auto.h"
#include "membrane3d_gather.h"
#include "membrane3d_traffic.h"
#include "membrane_fix.h"
#include "member_halo.h"
#include "membrane_part.h"

namespace LAMMPS_NS {

class FixMembrane3d : public MembraneFix {
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
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  // the detection before the pair forces (a sphere that joins the membrane is
  // frictionless in that very step), the loads after them
  void pre_force(int) override;
  void post_force(int) override;
  void post_run() override;
  double compute_vector(int n) override;
  // restart: the last detection (its topology over atom IDs, its step) and the
  // counter, so that a run continued from the file gives the output of one
  // straight through
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

  // the detections from a skin: rounds, last resorts, bytes gathered (for the benchmarks)
  membrane3d::SkinCounters skin_counters;

 private:
  membrane3d::SkinCounters skin_at_setup; // skin_counters at this run's setup
  membrane3d::Membrane3dAuto automatic; // every auto

  // the last detection: its topology over the member atoms, their IDs, its step
  membrane3d::MembraneTopology topology;
  std::vector<AtomId> member_tags;
  bigint last_detection = -1;
  membrane3d::Platens detected_platens{0.0, 0.0}; // at the last detection
  bigint decided_step = -1;                       // the last step pre_force decided on
  std::vector<membrane3d::Sphere> detected_at; // the members then (after a restart: at its start)
  double detections = 0.0;

  // this step
  membrane3d::GatheredSpheres members; // the member atoms now (at a detection, every auto)
  // placement: the members within two rings of this rank's own (member_halo.h), now
  MemberHalo halo{lmp, 4, 2};
  std::vector<membrane3d::Sphere> near; // halo.plan().needed's
  membrane3d::PartLayout layout;         // what this rank places, for halo.plans_made:
  double layout_plan = -1.0;
  std::function<void(int, double *)> pack; // a member's record: position, radius
  bigint halo_step = -1;                // refreshed for this step
  double halo_detections = -1.0;        // ... and this topology
  bigint halo_detected = -1;
  bool warned_rim = false;
  bool warned_moved = false; // a member far from where the membrane was found, once per run
  double output[OUTPUT_SIZE];
  mutable Membrane3dTraffic traffic; // this run's figures, printed at its end
  bool centres_placed = false; // output[VOLUME] is this step's

  Membrane3dGather gather() const; // this step's (membrane3d_gather.h)
  bool detection_due();
  void detect();
  void wear_types(const membrane3d::GatheredSpheres &g);
  bool members_present();
  void place_and_apply();
  void write_frame();
};

} // namespace LAMMPS_NS

#endif
#endif

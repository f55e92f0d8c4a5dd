/* ----------------------------------------------------------------------
   fix membrane2d: a deformable latex membrane on the left and right of a
   2D biaxial sample (Cheung & O'Sullivan 2008; Momeni et al. 2024).
   The chain of outermost disks on each side carries the confining
   pressure as one force per disk. See doc/fix_membrane2d.md. What it
   shares with fix membrane3d (keywords, inputs, checks, frictionless
   types, frames, restart envelope) is membrane/membrane_fix.h; the chain
   geometry is in membrane_chain.h, its state in membrane_state.h, the
   decisions of a step in membrane_step.h, what the ranks exchange in
   membrane_exchange.h (no LIGGGHTS), the gathers in membrane_gather.h. This
   class calls them and applies the forces to owned atoms.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS

// clang-format off
FixStyle(membrane2d,FixMembrane2d)
// clang-format on

#else

#ifndef LIGGGHTS_MEMBRANE_FIX_MEMBRANE2D_H
#define LIGGGHTS_MEMBRANE_FIX_MEMBRANE2D_H

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "membrane_chain.h"
#include "membrane_fix.h"
#include "membrane_gather.h"
#include "membrane_polyline.h"
#include "membrane_state.h"

namespace LAMMPS_NS {

class FixMembrane2d : public MembraneFix {
 public:
  FixMembrane2d(class LAMMPS *, int, char **);
  ~FixMembrane2d() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  void post_run() override;
  double compute_vector(int n) override { return vector_values[n]; }
  // restart (membrane_record.h): everything a run continued from the file
  // needs to give the output of one straight through, with the definition it
  // was written with
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  std::vector<std::pair<std::string, std::string>> frame_files() const override;

  // the global vector: membrane::Output (membrane_output.h); per-atom flags:
  // membrane::Flag (membrane_exchange.h)

 private:
  membrane::Definition definition; // as given (band -1: default)
  membrane::PolylineFile polyline;
  MembraneGather gather;
  membrane::ChainFinder finder;

  // what a detection found, what it depended on, the counters: all a restart carries
  membrane::SideChain chains[2]; // LEFT, RIGHT
  membrane::RunState run;

  // what each step works with
  membrane::SideData sides[2];
  membrane::SideLoad loads[2];
  std::vector<membrane::WatchEntry> watch_list; // the disks gathered at every step
  membrane::Watched watched;                    // and what they did this step
  double vector_values[membrane::OUTPUT_SIZE];
  double warned_dt = 0.0; // the time step last warned about

  int flag_capacity = 0; // rows of vector_atom

  bool automatic() const { return shared.automatic(); }
  void forget_state();
  void detect_chains(bool watch_it); // watch_it: every auto builds the watch of each side
  void gather_watched();
  void wear_chain_types();
};

} // namespace LAMMPS_NS

#endif
#endif

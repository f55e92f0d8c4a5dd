/* ----------------------------------------------------------------------
   fix membrane2d: a deformable latex membrane on the left and right of a
   2D biaxial sample (Cheung & O'Sullivan 2008; Momeni et al. 2024).
   The chain of outermost disks on each side carries the confining
   pressure as one force per disk. See doc/fix_membrane2d.md. Geometry in
   membrane_chain.h, its state and decisions in membrane_state.h (no
   LIGGGHTS); the gathers in membrane_gather.h. This class calls them and
   applies the forces to owned atoms.
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
#include <vector>

#include "fix.h"
#include "membrane_chain.h"
#include "membrane_gather.h"
#include "membrane_state.h"
#include "membrane_atoms.h"
#include "membrane_output.h"
#include "membrane_frames.h"
#include "platen_inputs.h"
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
  double compute_vector(int n) { return vector_values[n]; }
  // restart (membrane_record.h): everything a run continued from the file
  // needs to give the output of one straight through, with the definition it
  // was written with. The disks in the file carry their own types:
  // write_restart() gives them back before LIGGGHTS packs the atoms and
  // pack_restart() switches each packed one again, so a restart read by
  // another definition, another fix ID or no membrane at all holds the true
  // sample.
  void write_restart(FILE *);
  void restart(char *);
  int pack_restart(int, double *);
  void unpack_restart(int, int) {}
  int size_restart(int) { return 1; }
  int maxsize_restart() { return 1; }
  double memory_usage();
  // LIGGGHTS sizes its per-type-pair contact tables by the types atoms and fixes
  // report: the frictionless type may not be on any atom before the first run.
  int min_type() { return definition.frictionless_type; }
  int max_type() { return definition.frictionless_type; }
  const MembraneFrames &frame_files() const { return frames; }

  // the global vector: membrane::Output (membrane_output.h); per-atom flags:
  // MembraneAtoms::Flag (membrane_atoms.h)

 private:
  PlatenInputs inputs; // pressure, ylo, yhi
  membrane::Definition definition;         // as given (band/tolerance -1: default)
  bool detect_auto() const { return definition.detect_every == membrane::DETECT_AUTO; }
  MembraneFrames frames; // keywords polyline and vtk
  MembraneGather gather;
  MembraneAtoms atoms; // forces, flags and types of the chain disks
  membrane::ChainFinder finder;

  // what a detection found, what it depended on, the counters: all a restart carries
  membrane::SideChain chains[2]; // LEFT, RIGHT
  membrane::RunState run;
  double d50;
  double density; // group mass / group disk area [kg/m^2 per unit thickness]

  // what each step works with
  MembraneSideData sides[2];
  membrane::SideLoad loads[2];
  std::vector<membrane::WatchEntry> watch_list; // the disks gathered at every step
  MembraneGather::Watched watched;              // and what they did this step
  double pressure, ylo, yhi;
  double vector_values[membrane::OUTPUT_SIZE];
  double warned_dt = 0.0; // the time step last warned about

  // The chain state is kept from one run to the next (and through restart
  // files) when the group's disks are as they were (a checksum of tags,
  // types, radii and positions at the start of the run).
  bool state_kept = false;

  int flag_capacity; // rows of vector_atom
  int sides_mask() const { return (chains[0].active ? 1 : 0) + (chains[1].active ? 2 : 0); }

  void evaluate_platens();
  void forget_state();
  void detect_chains(bool watch_it); // watch_it: every auto builds the watch of each side
  void chain_lost(int side, const std::string &why);
  void gather_watched();
  void check_stability();
};

} // namespace LAMMPS_NS

#endif
#endif

/* ----------------------------------------------------------------------
   The shared layer of fix membrane2d and fix membrane3d as LIGGGHTS styles:
   a flexible boundary found again from the outermost grains between two
   platens, the confining pressure on it (doc/membrane_keywords.md). This
   class holds what the two have in common: the shared keywords with one
   meaning each, the inputs evaluated each step with rank 0's values on every
   rank, the set-up and cross-fix checks, the frictionless types and their
   restart handling, the vtk frames, the group checksum and the restart
   envelope. Each style keeps only what is its own: detect, place, loads and
   its output vector.
------------------------------------------------------------------------- */

#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_FIX_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_FIX_H

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "fix.h"

#include "frame_files.h"
#include "frictionless_atoms.h"
#include "platen_inputs.h"
#include "platens.h"
#include "shared_keywords.h"

class StyleArgs;

namespace LAMMPS_NS {

// What a membrane style tells the shared layer about itself.
struct MembraneTraits {
  int dimension;               // 2 or 3
  const char *lo_key, *hi_key; // the platens: ylo, yhi or zlo, zhi
  const char *lo_usage, *hi_usage;
  const char *particles;       // "disks" or "spheres"
  double default_tolerance;    // x D50
  double most_tolerance;       // x D50
};

class MembraneFix : public Fix {
 public:
  MembraneFix(class LAMMPS *, int narg, char **arg, const MembraneTraits &traits);
  ~MembraneFix() override;
  int setmask() override;
  // the frictionless type, so that the pair style sizes its tables for it
  int min_type() override { return types.type(); }
  int max_type() override { return types.type(); }
  // with frictionless: the atoms are written with their own types (frictionless_atoms.h)
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override {}
  int size_restart(int) override { return 1; }
  int maxsize_restart() override { return 1; }

  // the frame files ({keyword, file}) no other membrane may write to
  virtual std::vector<std::pair<std::string, std::string>> frame_files() const;
  const MembraneTraits traits;

 protected:
  const std::string prefix; // "Fix membrane2d (id mem): ", every message starts so
  membrane::SharedKeywords shared;
  PlatenInputs inputs;
  VtkFrames vtk;
  FrictionlessAtoms types;
  // this step's inputs, the same on every rank (rank 0's)
  double pressure = 0.0;
  membrane::Platens platens{0.0, 0.0};
  // set by init_shared: the group's D50 by mass and density (contact_scales.h), the
  // tolerance in use
  double d50 = 0.0, density = 0.0, tolerance = 0.0;

  // The keywords after the group: the shared ones here, the style's own through
  // `own` (false for a keyword it does not know either), `own_keywords` listed in
  // the message for an unknown one.
  using OwnKeyword = std::function<bool(StyleArgs &, const std::string &)>;
  void parse(int narg, char **arg, const std::vector<std::string> &own_keywords,
             const OwnKeyword &own);
  // init(): the variables, the group, the other membranes, the frictionless type,
  // D50 and the tolerance
  void init_shared();
  // pressure and platens of this step, checked
  void evaluate_inputs();
  // one decision for all ranks: a rank that decided alone would wait forever in a
  // collective call the others never make
  bool on_any_rank(bool mine) const;
  // order-free hash of the group's atoms (IDs, types, positions, radii): collective
  std::uint64_t group_checksum() const;
  // The group as the last run ended (post_run) or as a restart record holds it: the
  // membrane of that run is kept only by a run that starts on the same group
  // (delete_atoms renumbers the IDs; create_atoms, set, displace_atoms change it).
  void remember_group(std::uint64_t checksum);
  // collective; false when no group is remembered, and forgets it (asked once a run)
  bool group_as_remembered();
  [[noreturn]] void fail(const std::string &text) const;
  void warn(const std::string &text) const;

 private:
  std::vector<std::string> keywords_; // all, in the order of the message
  bool warned_spread_ = false;        // an input differing between the ranks
  bool group_remembered_ = false;
  std::uint64_t remembered_group_ = 0;
};

} // namespace LAMMPS_NS

#endif

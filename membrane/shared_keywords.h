// The keywords fix membrane2d and fix membrane3d share, with one meaning each
// (doc/membrane_keywords.md), and the detection schedule they set. No LIGGGHTS
// (unit-tested in tests/unit/membrane_layer).
#ifndef LIGGGHTS_MEMBRANE_SHARED_KEYWORDS_H
#define LIGGGHTS_MEMBRANE_SHARED_KEYWORDS_H

#include <string>

namespace membrane {

// every auto: detect when the membrane can have changed, with the result of a
// detection at every step
constexpr int EVERY_AUTO = 0;

struct SharedKeywords {
  double tolerance_given = -1.0; // a length; -1: the style's default, a multiple of D50
  int every = EVERY_AUTO;        // steps between detections, or EVERY_AUTO
  int frictionless = 0;          // the atom type membrane particles wear; 0: none
  bool automatic() const { return every == EVERY_AUTO; }
};

// Whether the schedule alone makes `step` detect, given the step of the last
// detection (`last`, -1 for none): the first detection, a step counter set back
// before the last one (reset_timestep, an older restart), and with every N, N
// steps since the last detection (as neigh_modify every counts; a detection
// forced in between restarts the count).
inline bool detection_scheduled(const SharedKeywords &k, long long step, long long last)
{
  if (last < 0 || step < last) return true;
  return !k.automatic() && step - last >= k.every;
}

// The tolerance (a length) against D50: "" when it is at most `most` x D50, else
// what is wrong with it, with the style's default (`usual` x D50).
std::string tolerance_problem(double tolerance, double d50, double most, double usual);

// Why a membrane cannot use its state in a restart file: the record cannot be read
// (`reason`; `other_format`: another version wrote it), or the fix is defined
// otherwise than in the file (`keywords`: those compared).
std::string restart_unreadable(const std::string &reason, bool other_format);
std::string restart_other_definition(const std::string &keywords);

} // namespace membrane

#endif

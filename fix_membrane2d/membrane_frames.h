#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H

// Keyword polyline of fix membrane2d: the chains every N steps to one text file
// (membrane_polyline.h), written by rank 0, which holds every chain.

#include <string>
#include <utility>
#include <vector>

#include "pointers.h"

#include "membrane_polyline.h"

class StyleArgs;

class PolylineFrames : protected LAMMPS_NS::Pointers {
 public:
  PolylineFrames(LAMMPS_NS::LAMMPS *lammps, std::string prefix)
    : Pointers(lammps), prefix_(std::move(prefix))
  {
  }
  // N and FILE after the keyword; FILE may not be one of the style's `keywords`
  void read(StyleArgs &args, const std::vector<std::string> &keywords);
  // the frame due at `step`, if any
  void write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
             const membrane::SideData (&sides)[2], const membrane::SideLoad (&loads)[2]);
  const std::string &file() const { return file_; } // "" when not given

 private:
  std::string prefix_;
  LAMMPS_NS::bigint every_ = 0;
  std::string file_;
  membrane::PolylineFile out_;
};

#endif

#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H

// The frames fix membrane2d writes of its chains, by rank 0, which holds every
// chain (doc/fix_membrane2d.md): keyword polyline (one text file), and the
// frame of keyword vtk, whose series is the shared layer's (membrane/frame_files.h).

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pointers.h"

#include "membrane_gather.h"
#include "membrane_output.h"
#include "membrane_state.h"

class StyleArgs;

class PolylineFrames : protected LAMMPS_NS::Pointers {
 public:
  static const char *const USAGE;

  PolylineFrames(LAMMPS_NS::LAMMPS *lammps, std::string prefix)
    : Pointers(lammps), prefix_(std::move(prefix))
  {
  }
  ~PolylineFrames();
  PolylineFrames(const PolylineFrames &) = delete;
  PolylineFrames &operator=(const PolylineFrames &) = delete;

  // N and FILE after the keyword; FILE may not be one of the style's `keywords`
  void read(StyleArgs &args, const std::vector<std::string> &keywords);
  // the frame due at `step`, if any
  void write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
             const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2]);
  const std::string &file() const { return file_; } // "" when not given

 private:
  std::string prefix_;
  LAMMPS_NS::bigint every_ = 0;
  std::FILE *out_ = nullptr;
  std::string file_;
  std::vector<membrane::PolylineFrame> frames_; // steps written, where each starts
};

// The chains as a VTK frame (membrane_vtk.h).
std::string chains_vtk_frame(const membrane::SideChain (&chains)[2],
                             const MembraneSideData (&sides)[2],
                             const membrane::SideLoad (&loads)[2]);

#endif

// The frame files of the membranes: keyword 'vtk N FILE' (both styles: the membrane
// every N steps to FILE_<step>.vtp, collected in FILE.pvd, vtk_series.h), and the
// checks of any frame file keyword (fix membrane2d's polyline too). Rank 0 writes:
// it holds the whole membrane. Every rank stops with rank 0's reason when a file
// cannot be created.
#ifndef LIGGGHTS_MEMBRANE_FRAME_FILES_H
#define LIGGGHTS_MEMBRANE_FRAME_FILES_H

#include <string>
#include <vector>

#include "pointers.h"

#include "vtk_series.h"

class StyleArgs;

// The value FILE of a frame keyword: not empty, not one of the style's `keywords`
// (a forgotten FILE).
std::string frame_file_name(StyleArgs &args, const std::string &usage,
                            const std::vector<std::string> &keywords);

// Stops the run on every rank when rank 0's `reason` (only rank 0's counts) is not
// empty: the file of keyword `key` cannot be opened for writing.
void check_file_opened(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix, const std::string &key,
                       const std::string &file, const std::string &reason);

class VtkFrames : protected LAMMPS_NS::Pointers {
 public:
  static const char *const USAGE;

  VtkFrames(LAMMPS_NS::LAMMPS *lammps, std::string prefix);
  // N and FILE after the keyword
  void read(StyleArgs &args, const std::vector<std::string> &keywords);
  // whether this rank writes a frame at `step`
  bool due(LAMMPS_NS::bigint step) const;
  void write(LAMMPS_NS::bigint step, const std::string &frame);
  std::string pvd() const { return series_.pvd(); } // "" without the keyword

 private:
  std::string prefix_;
  LAMMPS_NS::bigint every_ = 0; // 0: no frames
  vtk_series::Series series_;
};

#endif

#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_FRAMES_H

// The files fix membrane2d writes frames of the chains to, written by rank 0,
// which holds every chain (doc/fix_membrane2d.md): keyword polyline (one text
// file) and keyword vtk (a .vtp file per frame and a .pvd collection).

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "pointers.h"

#include "membrane_gather.h"
#include "membrane_output.h"
#include "membrane_state.h"
#include "vtk_series.h"

class StyleArgs;

class MembraneFrames : protected LAMMPS_NS::Pointers {
 public:
  MembraneFrames(LAMMPS_NS::LAMMPS *lammps, std::string prefix)
    : Pointers(lammps), prefix_(std::move(prefix))
  {
  }
  ~MembraneFrames();
  MembraneFrames(const MembraneFrames &) = delete;
  MembraneFrames &operator=(const MembraneFrames &) = delete;

  // `key` (polyline or vtk) and its values N FILE; a file name that is one of
  // the style's `keywords` is refused (a forgotten FILE). Every rank stops with
  // rank 0's reason when it cannot create the file.
  void read(const std::string &key, StyleArgs &args, const char *const *keywords, int nkeywords);
  // The frames due at `step`.
  void write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
             const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2]);
  // The file of keyword `key` (polyline: FILE, vtk: FILE.pvd); "" when not given.
  std::string file(const std::string &key) const;

 private:
  std::string prefix_;
  LAMMPS_NS::bigint polyline_every_ = 0, vtk_every_ = 0;
  std::FILE *polyline_ = nullptr;
  std::string polyline_file_;
  std::vector<membrane::PolylineFrame> polyline_frames_; // steps written, where each starts
  vtk_series::Series vtk_;
};

#endif

#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_POLYLINE_FILE_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_POLYLINE_FILE_H

// The polyline file of fix membrane2d (keyword polyline): written by rank 0,
// which holds every chain (doc/fix_membrane2d.md).

#include <cstdio>
#include <string>

#include "pointers.h"

#include "membrane_gather.h"
#include "membrane_state.h"

class MembranePolylineFile : protected LAMMPS_NS::Pointers {
 public:
  MembranePolylineFile(LAMMPS_NS::LAMMPS *lammps, std::string prefix)
    : Pointers(lammps), prefix_(std::move(prefix))
  {
  }
  ~MembranePolylineFile();
  // Every rank stops with rank 0's reason when it cannot open the file.
  void open(const std::string &file);
  bool is_open() const { return open_; }
  // One frame: the step, then per active side its polyline and chain forces.
  void write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
             const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2]);

 private:
  std::string prefix_;
  std::FILE *fp_ = nullptr;
  bool open_ = false;
};

#endif

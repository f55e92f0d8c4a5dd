// The polyline file of fix membrane2d (keyword polyline, doc/fix_membrane2d.md):
// the chains of both sides, one frame per step written, each step once
// (membrane::polyline_frame_start). No LIGGGHTS.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_POLYLINE_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_POLYLINE_H

#include <cstdio>
#include <string>
#include <vector>

#include "membrane_output.h"
#include "membrane_state.h"

namespace membrane {

class PolylineFile {
 public:
  PolylineFile() = default;
  ~PolylineFile();
  PolylineFile(const PolylineFile &) = delete;
  PolylineFile &operator=(const PolylineFile &) = delete;

  // Keyword polyline N FILE: every N steps to `path`, written by the rank that
  // is the `writer` (on the others nothing is due). Creates (empties) the
  // file: "" when done, else why not.
  std::string open(const std::string &path, long long every, bool writer);
  const std::string &path() const { return path_; } // "" when not given
  bool due(long long step) const { return out_ && step % every_ == 0; }
  // The frame of `step` (replacing the frames at or after it): "" when
  // written, else why the file could not be cut.
  std::string write(long long step, const SideChain (&chains)[2], const SideData (&sides)[2],
                    const SideLoad (&loads)[2]);

 private:
  std::string path_;
  long long every_ = 1;
  std::FILE *out_ = nullptr;
  std::vector<PolylineFrame> frames_; // steps written, where each starts
};

} // namespace membrane

#endif

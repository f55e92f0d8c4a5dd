#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_OUTPUT_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_OUTPUT_H

// What fix membrane2d writes besides its vector: the text of its checks and
// warnings (numbers in, words out) and the polyline file. No LIGGGHTS.

#include <cstdio>
#include <string>
#include <vector>

#include "membrane_chain.h"
#include "membrane_state.h"

namespace membrane {

// The global vector of fix membrane2d (1-based in input scripts: f_ID[k]).
enum Output {
  AREA = 0,
  MEAN_WIDTH,
  MID_WIDTH,
  CHAIN_LEFT,
  CHAIN_RIGHT,
  ESCAPED,
  FX_LEFT,
  FY_LEFT,
  FX_RIGHT,
  FY_RIGHT,
  DETECTIONS,
  FAILURES,
  PRESSURE,
  WIDENINGS,
  CHAIN_STEP,
  INERTIAL,
  CHANGES,
  OUTPUT_SIZE
};
// Fills `v` (OUTPUT_SIZE values); area and widths need both sides.
void output_vector(const SideChain (&chains)[2], const SideLoad (&loads)[2], const RunState &run,
                   Platens platens, double pressure, double chain_step, double *v);

inline const char *side_name(int k)
{
  return k == LEFT ? "left" : "right";
}

// Why the band width or the gap tolerance (lengths) cannot be used with this
// D50; "" when they can.
std::string band_problem(double band, double d50);
// Why the bottom (`top` false) or top platen at `platen` does not enclose the
// group, whose lowest or highest disk centre is at `centre`; "" when it does.
std::string enclose_problem(bool top, double platen, double centre);

// The warnings of the stability guards (warned once per run).
std::string chain_step_warning(AtomId tag, double fraction, long long step);
std::string inertial_warning(const InertialWindow &w, double limit, long long step, double d50,
                             double density, double pressure);

// The errors and warnings of a chain search that failed on one side
// (`where`: "left side at step N", `why`: the search's reason).
std::string no_chain_error(const std::string &where, const std::string &why);
std::string chain_lost_warning(const std::string &where, const std::string &why);
// A watched disk was lost, or one is not finite, at `step`.
std::string lost_disk_error(long long step);
std::string not_finite_error(long long step);

// What one rank received in the fix's collectives during a run of `steps`
// steps with `detections` detections (`full_passes` of them looked at every
// disk of the rank, the others at the band candidates only), and the seconds
// the fix and its chain searches took on the slowest rank (the info line at the
// end of a run; a run of 0 steps counts its setup as one).
std::string traffic_summary(double step_bytes, double detection_bytes,
                            long long steps, long long detections, long long full_passes,
                            double fix_seconds, double search_seconds);

// The polyline file lists each step once, as the vtk collection does: before the
// frame of `step` is written, the frames at or after that step are dropped (the
// first step of a continued run, which the last one wrote; a step counter set
// back by reset_timestep or an earlier restart). `frames` holds the steps written
// and where each starts; `end` is the file's length. Returns where the new frame
// starts (cut the file there when it is before `end`) and records it.
struct PolylineFrame {
  long long step;
  long offset;
};
long polyline_frame_start(std::vector<PolylineFrame> &frames, long long step, long end);

// One side's part of a polyline-file frame (doc/fix_membrane2d.md, "polyline").
void write_polyline_side(std::FILE *fp, const char *side, const Polyline &polyline,
                         const std::vector<Disk> &chain,
                         const std::vector<Eigen::Vector2d> &forces);

} // namespace membrane

#endif

// What fix membrane2d decides at a step on the state of membrane_state.h:
// whether a detection is due, a detection with its widened bands, the
// stability warnings. The style gathers (membrane_gather.h) and speaks. No
// LIGGGHTS.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_STEP_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_STEP_H

#include <functional>
#include <string>
#include <vector>

#include "shared_keywords.h"

#include "membrane_chain.h"
#include "membrane_state.h"

namespace membrane {

// This rank's view of the schedule at `step` (the style makes it every
// rank's): a forced detection, the schedule of the keyword every, a dense
// every-auto window, with every N the platens (`now`) moved beyond the
// tolerance.
bool detection_due(const RunState &run, const SharedKeywords &shared, long long step, Platens now,
                   double d50);

// What a step says: an error (the run stops) or a warning.
struct Notice {
  bool fatal;
  std::string text;
};

// Gathers the bands of `width` into sides[k].band and searches the `pending`
// sides into results[k].
using BandSearch =
    std::function<void(double width, const bool (&pending)[2], ChainResult (&results)[2])>;

// A detection at `step`: the active sides are searched in bands of
// run.search_width; a side whose search fails is searched again in a band
// widened (widened_band) up to MAX_WIDENINGS times: a band narrower than the
// sample's surface roughness can cut every contact path to the top. The
// width reached is kept for the rest of the run (a rough outline stays
// rough), and both sides are searched again with it at the next step
// (force_detection), so every auto and every 1 search the same bands. With
// `watch` (every auto) what each search depended on is recorded; without,
// every auto forgets it. A side still without a chain keeps its previous one,
// counted, and is searched again at the next step: the returned notices (side
// order) are the error when it has none, else the warning, once per side.
// The detection's step and platens are kept in `run`, and `watch_list` lists
// the disks to gather from now on (build_watch_list).
std::vector<Notice> detect(SideChain (&chains)[2], const SideData (&sides)[2], RunState &run,
                           std::vector<WatchEntry> &watch_list, double d50, bool automatic,
                           const WatchSettings *watch, Platens platens, long long step,
                           const BandSearch &search);

// The stability guards at `step` (warned once per run each): the chain
// disks' step (`chain_step` of disk `tag`, bench/stability_sweep.md) and the
// inertial number of the loading (the sample `height` fed to run.inertial;
// p = the membrane pressure, the smaller principal stress: I is an upper
// bound).
std::vector<std::string> stability_warnings(RunState &run, double chain_step, AtomId tag,
                                            long long step, double height, double dt, double d50,
                                            double density, double pressure);

} // namespace membrane

#endif

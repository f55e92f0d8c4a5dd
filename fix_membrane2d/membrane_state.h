#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_STATE_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_STATE_H

// What fix membrane2d keeps from one chain detection to the next (and through
// restart files), and the decisions taken on it: accepting a search result,
// the disks gathered at every step, the types the chain disks wear, the
// inertial-number window. No LIGGGHTS (unit-tested in tests/unit/membrane).

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "dense_detections.h"
#include "shared_keywords.h"

#include "membrane_chain.h"

namespace membrane {

enum { LEFT = 0, RIGHT = 1 }; // index of a side in the arrays below

// The tuned numbers of fix membrane2d (doc/fix_membrane2d.md), defined here only.
constexpr double DEFAULT_BAND = 4.0;       // band width, x D50
constexpr double BAND_MIN = 0.01;          // x D50: narrower bands are cut into too many slices
constexpr double DEFAULT_TOLERANCE = 0.02; // gap tolerance, x D50
constexpr double MOST_TOLERANCE = 0.25;    // x D50: wider ones bridge real gaps between disks
// a failed search is repeated with the band widened by this factor, at most this often
constexpr double BAND_WIDENING = 2.5;
constexpr int MAX_WIDENINGS = 2;
// ... up to this many D50 (wider than any sample: every disk is in the band). While a
// chain stays lost each step widened it again: after ~390 failed steps it was inf.
constexpr double MOST_SEARCH_WIDTH = 1e5;
// every auto: relations within this many D50 of their threshold are watched
// every step; the others may flip only after a band disk moved half as far
constexpr double WATCH_BUDGET = 0.01;
// every auto: DENSE_WINDOW, DENSE_DETECTIONS, UNWATCHED_STEPS (dense_detections.h)
// |v| dt / r of a chain disk shot by the membrane (quasi-static chains: < 1e-3)
constexpr double CHAIN_STEP_LIMIT = 0.025;
constexpr long long INERTIAL_WINDOW = 1000; // steps over which the strain rate is averaged

// One side's chain as the last detection found it.
struct SideChain {
  Side side = Side::Right;
  bool active = false;
  std::vector<AtomId> chain_tags; // bottom -> top
  std::vector<AtomId> escaped_tags; // ascending (a set: the band's order is the ranks')
  std::vector<double> escaped_radius;
  // the chain of the last run when it could not be kept: only to count
  // whether the next detection changes it
  std::vector<AtomId> forgotten_tags, forgotten_escaped;
  DetectionWatch watch;         // every auto: what the last search depended on
  std::vector<Disk> watch_band; // the band it searched, as it was then
  std::vector<Disk> now;        // the same, its watched disks at their current positions
  bool warned_lost = false;     // "chain lost" was warned
};

// What one side works with between its detections, gathered on every rank
// (membrane_exchange.h).
struct SideData {
  BandSlices slices;
  std::vector<Disk> band;        // at the last detection, in no particular order
  std::vector<Disk> chain_disks; // now, chain order
  std::vector<int> chain_types;  // their atom types now
};

// The chain disks of both sides, each once, by ascending ID (`tags`), with
// their types now (`types`): the particles that wear the frictionless type.
void chain_types(const SideData (&sides)[2], std::vector<AtomId> &tags, std::vector<int> &types);

// What a search depended on is recorded (every auto) with these.
struct WatchSettings {
  Platens platens;
  double tolerance, budget;
};

// Forgets the chain; it is kept aside to count whether the next one differs.
void forget_chain(SideChain &s);

// Takes the successful search `r` on `band` as the side's chain; with
// `watch` (every auto) records what the search depended on. Returns true
// when the chain or the set of its escapees differ from the previous (or
// forgotten) ones. The escapees are kept by ascending tag: the band's order
// (and so r.escaped's) is the order the ranks gathered it in, which changes
// with the decomposition and whenever a disk moves to another rank.
bool accept_chain(SideChain &s, const std::vector<Disk> &band, const ChainResult &r,
                  const WatchSettings *watch);

// Every auto: whether the chains can have changed since the last detection,
// i.e. a relation a search depended on can have flipped: a watched one did
// (at `platens`), or a band disk (by `band_displacement`, the largest since
// the detection) or a platen moved far enough (`budget`) to flip another.
bool detection_needed(const SideChain (&chains)[2], Platens platens, Platens detected,
                      double tolerance, double band_displacement, double budget);

// The band width and search width of a run (as given, else the default for this
// D50; a search width already widened is kept) and its gap `tolerance`.
void set_lengths(const struct Definition &def, double d50, double tolerance, struct RunState &run);

// A disk whose position every rank gathers at every step, with its roles.
struct WatchEntry {
  AtomId tag = 0;
  int chain_position[2] = {-1, -1}; // index in sides[k].chain_tags
  int band_index[2] = {-1, -1};     // index in sides[k].watch_band
};

// The chain disks and escapees of both sides and (watch_relations: every
// auto) the disks of their watched relations: sorted by tag, one entry per
// disk whatever its roles. `out` is reused (no allocation once grown).
void build_watch_list(const SideChain (&sides)[2], bool watch_relations,
                      std::vector<WatchEntry> &out);

// A chain search result as ints, so that the rank that ran it can broadcast
// it; unpack_result returns false when `data` does not hold one.
void pack_result(const ChainResult &r, std::vector<int> &out);
bool unpack_result(const int *data, std::size_t n, ChainResult &r);

// The inertial number of the platens' axial strain rate, averaged over
// windows of a fixed number of steps.
struct InertialWindow {
  long long first_step = -1; // of the open window; -1: none
  double first_height = 0.0;
  double value = 0.0;     // I of the last closed window (0 before the first)
  double rate = 0.0;      // its mean axial strain rate [1/s]
  bool was_above = false; // the last closed window was above the limit

  // Feeds the sample height at `step`. A window closes when `window` steps
  // have passed (a step before the window restarts it). Returns true when it
  // closes above `limit` right after another that did: a servo's transient
  // exceeds it for one window, a loading too fast for two.
  bool update(long long step, double height, double dt, long long window, double d50,
              double density, double pressure, double limit);
};

// The membrane's load on one side: the polyline through the chain disks
// (`chain`, in chain order, at their current positions), one force per disk
// and their sum.
struct SideLoad {
  Polyline polyline;
  std::vector<Eigen::Vector2d> forces;
  Eigen::Vector2d total{0.0, 0.0};
  std::vector<int> order; // 0..n-1, kept so that a step allocates nothing
};
void load_side(const std::vector<Disk> &chain, Side side, Platens platens, double pressure,
               double thickness, SideLoad &out);

// How the fix was defined: a restart is used only by the same definition.
struct Definition {
  int sides_mask = 3; // 1 left, 2 right
  int frictionless_type = 0;
  int detect_every = EVERY_AUTO; // steps between detections, or EVERY_AUTO
  double band_given = -1.0, tolerance_given = -1.0, thickness = 1.0;
  bool operator==(const Definition &o) const
  {
    return sides_mask == o.sides_mask && frictionless_type == o.frictionless_type &&
           detect_every == o.detect_every && band_given == o.band_given &&
           tolerance_given == o.tolerance_given && thickness == o.thickness;
  }
};

struct Counters {
  long long detections = 0, failures = 0, widenings = 0;
  long long changes = 0; // detections that changed a chain or its escapees (per side)
};

// Everything beyond the chains that a run continued from a restart needs.
struct RunState {
  std::uint64_t checksum = 0; // of the group when the state was saved
  double band_width = 0.0;    // as set in init (4 x D50 by default)
  double search_width = 0.0;  // of the next search: band_width, or wider once widened
  double tolerance = 0.0;
  bool force_detection = true;
  long long last_detection = -1; // its step (every N counts from it)
  double ylo_detected = 0.0, yhi_detected = 0.0; // the platens at the last detection
  Counters counters;
  InertialWindow inertial;
  bool warned_inertial = false, warned_chain_step = false;
  DenseDetections dense; // every auto: when the watch is not worth building
};

// A failed search's band: `width` widened by BAND_WIDENING, at most MOST_SEARCH_WIDTH D50.
double widened_band(double width, double d50);

// every N, and the setup of a run that keeps the chains: whether a platen moved
// more than `limit` since the last detection (then the chains are searched anew,
// the kept ones the fallback; a platen moved beyond the gap tolerance can have
// made or broken the contacts with it)
bool platens_moved(const RunState &run, Platens now, double limit);
// the `limit` of platens_moved: the tolerance, at least WATCH_BUDGET x D50 (a
// tolerance of 0 would make every N detect at every step of a moving platen)
double platen_move_limit(const RunState &run, double d50);
// every auto: whether `step` detects without a watch (RunState::unwatched_until)
bool unwatched_step(const RunState &run, long long step);
// every auto, after a watched step decided whether to detect: counts it in
// the window; true when the window closes dense (this detection and the next
// UNWATCHED_STEPS - 1 steps then go without a watch)
bool count_watched_step(RunState &run, long long step, bool detected);
// Forget what the last detection depended on (a side detected without a
// watch): the next watched step detects.
void drop_watch(SideChain &s);

} // namespace membrane

#endif

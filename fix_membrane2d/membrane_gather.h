#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_GATHER_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_GATHER_H

// The MPI side of fix membrane2d: what every rank must hold identically (the
// side bands, the watched disks, the search results) so that the chain never
// depends on the number of ranks, and the group-wide reductions it checks.

#include <cstdint>
#include <string>
#include <vector>

#include "lmptype.h"
#include "pointers.h"

#include "membrane_band_cache.h"
#include "membrane_chain.h"
#include "membrane_state.h"

// What one side works with between its detections, gathered on every rank.
struct MembraneSideData {
  membrane::BandSlices slices;
  std::vector<membrane::Disk> band; // at the last detection, in no particular order
  std::vector<int> band_type;
  std::vector<membrane::Disk> chain_disks; // now, chain order
  std::vector<int> chain_types;
};

// Adds the wall-clock time of its scope to `total`.
class ScopedSeconds {
 public:
  explicit ScopedSeconds(double &total);
  ~ScopedSeconds();
  ScopedSeconds(const ScopedSeconds &) = delete;
  ScopedSeconds &operator=(const ScopedSeconds &) = delete;

 private:
  double &total_;
  double start_;
};

class MembraneGather : protected LAMMPS_NS::Pointers {
 public:
  MembraneGather(LAMMPS_NS::LAMMPS *lammps, std::string prefix, int groupbit)
    : Pointers(lammps), prefix_(std::move(prefix)), groupbit_(groupbit)
  {
  }

  // The disks of the group within `width` of the outer edge of each active side:
  // from the candidates of the last full pass over the rank's disks while they
  // provably hold, else by a full pass (membrane_band_cache.h).
  void bands(const membrane::Platens &platens, double width, const bool active[2],
             MembraneSideData (&sides)[2]);

  // The searches of the `pending` sides, each run by its own rank (left on
  // rank 0, right on rank 1) at the same time; every rank gets both results.
  void search(membrane::ChainFinder &finder, const MembraneSideData (&sides)[2],
              const bool pending[2], const membrane::Platens &platens, double tolerance,
              membrane::ChainResult (&results)[2]);

  struct Watched {
    double band_displacement = 0.0; // largest of a band disk since the detection (every auto)
    double chain_step = 0.0;        // largest |v| dt / r of a chain disk this step
    long chain_step_tag = -1;       // its ID (of tied disks the lowest)
  };
  // Positions, types and step fractions of the disks of `list` now; stops the
  // run when one of them is lost or not finite.
  Watched watched(const std::vector<membrane::WatchEntry> &list, membrane::SideChain (&chains)[2],
                  bool watch_relations, MembraneSideData (&sides)[2]);

  // What this rank receives in the collectives above during a run (the
  // per-step gathers of watched disks, the gathers of a detection): counted
  // from the start of a run (`step`, the detections so far) and written to
  // the screen and log at its end (membrane::traffic_summary).
  // With them, the wall-clock time the fix spends on each rank (fix_seconds:
  // its pre_force and post_force, through a ScopedSeconds) and in the chain
  // searches, which run on one rank per side while the others wait: the
  // report gives the largest over the ranks (collective).
  void start_traffic(LAMMPS_NS::bigint step, long long detections);
  void report_traffic(const char *id, LAMMPS_NS::bigint step, long long detections);
  double &fix_seconds() { return traffic_.fix_seconds; }

  // Lowest and highest disk centre of the group.
  void group_y_range(double &lo, double &hi);

 private:
  std::string prefix_;
  int groupbit_;
  std::vector<double> send_, recv_;
  std::vector<int> counts_, displs_, slice_of_atom_, result_buf_;
  struct Traffic {
    double step_bytes = 0.0, detection_bytes = 0.0;
    double fix_seconds = 0.0, search_seconds = 0.0;
    long long full_passes = 0; // band detections that looked at every local disk
    LAMMPS_NS::bigint first_step = 0;
    long long first_detections = 0;
  } traffic_;
  double gathered_bytes() const; // of the last allgather_doubles, counts included

  // Local indices of the watched disks (list entries, then each side's watch
  // band): -1 where another rank owns the disk. Atoms change index or rank only
  // when LIGGGHTS rebuilds its neighbour lists, so they are looked up again
  // (atom->map) only then or when the list changed (and at the start of a run).
  struct OwnedIndices {
    std::vector<int> index;
    LAMMPS_NS::bigint neighbour_builds = -1;
    int nlocal = -1;
    std::uint64_t tags_hash = 0;
  };
  OwnedIndices watched_owned_, band_owned_[2];
  template <class TagOf> const std::vector<int> &owned(OwnedIndices &cache, std::size_t n, TagOf tag_of);

  membrane::BandCandidates candidates_;
  LAMMPS_NS::bigint candidates_neighbour_builds_ = -1;
  int candidates_nlocal_ = -1;
  bool candidates_active_[2] = {false, false};
  template <class Index>
  void extents(const membrane::Platens &platens, double width, const bool active[2],
               MembraneSideData (&sides)[2], int n, Index local_index);
  bool candidates_usable(double width, const bool active[2]) const;
  void remember_candidates(double width, const bool active[2],
                           const membrane::BandSlices *const slices[2]);
};

#endif

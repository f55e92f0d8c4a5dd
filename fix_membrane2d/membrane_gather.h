#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_GATHER_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_GATHER_H

// The MPI side of fix membrane2d: what every rank must hold identically (the
// side bands, the watched disks, the search results) so that the chain never
// depends on the number of ranks, and the group-wide reductions it checks.
// The records and caches: membrane_exchange.h.

#include <string>
#include <vector>

#include "lmptype.h"
#include "pointers.h"

#include "membrane_band_cache.h"
#include "membrane_exchange.h"
#include "scalar_input.h"

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
             membrane::SideData (&sides)[2]);

  // The searches of the `pending` sides, each run by its own rank (left on
  // rank 0, right on rank 1) at the same time; every rank gets both results.
  void search(membrane::ChainFinder &finder, const membrane::SideData (&sides)[2],
              const bool pending[2], const membrane::Platens &platens, double tolerance,
              membrane::ChainResult (&results)[2]);

  // Positions, types and step fractions of the disks of `list` now; stops the
  // run when one of them is lost or not finite.
  membrane::Watched watched(const std::vector<membrane::WatchEntry> &list,
                            membrane::SideChain (&chains)[2], bool watch_relations,
                            membrane::SideData (&sides)[2]);

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

  // This rank's atoms, and the local index of an owned one (-1: not owned).
  membrane::LocalAtoms local() const;
  int owned_index(AtomId tag) const;

  // The platens enclose every disk centre of the group, else the run stops.
  void check_enclosed(const ScalarInput &ylo_in, double ylo, const ScalarInput &yhi_in,
                      double yhi);

 private:
  std::string prefix_;
  int groupbit_;
  std::vector<double> send_, recv_;
  std::vector<int> counts_, displs_, slice_of_atom_, result_buf_;
  membrane::Traffic traffic_;
  void allgather(double &bytes); // send_ to recv_ on every rank, counted in `bytes`

  // Local indices of the watched disks (list entries, then each side's watch band).
  membrane::OwnedIndices watched_owned_, band_owned_[2];
  template <class TagOf>
  const std::vector<int> &owned(membrane::OwnedIndices &cache, std::size_t n, TagOf tag_of);

  membrane::BandCandidates candidates_;
  void extents(const membrane::Platens &platens, double width, const bool active[2],
               membrane::SideData (&sides)[2], const std::vector<int> *indices);
  void remember_candidates(double width, const bool active[2],
                           const membrane::BandSlices *const slices[2]);
};

#endif

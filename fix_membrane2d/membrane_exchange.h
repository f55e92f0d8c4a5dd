// What the ranks of fix membrane2d exchange so that every rank holds the same
// side bands and watched disks (membrane_gather.h makes the MPI calls): the
// records, as doubles, and what is read from them; the cache of the watched
// disks' local indices; the traffic counted; and what the style does to the
// owned atoms (forces, flags). No LIGGGHTS: the atoms' arrays are passed in.
#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_EXCHANGE_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_EXCHANGE_H

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "membrane_band_cache.h"
#include "membrane_chain.h"
#include "membrane_state.h"
#include "scoped_seconds.h"

namespace membrane {

// This rank's atoms as LIGGGHTS holds them (atom->nlocal, mask, tag, x, v,
// radius, type) and the group's bit.
struct LocalAtoms {
  int n;
  const int *mask;
  int groupbit;
  const AtomId *tag;
  const double *const *x, *const *v;
  const double *radius;
  const int *type;
  bool in_group(int i) const { return (mask[i] & groupbit) != 0; }
  Disk disk(int i) const { return Disk{tag[i], x[i][0], x[i][1], radius[i]}; }
};

// The local index of the owned atom with an ID, -1 when this rank does not own it.
using LocalIndex = std::function<int(AtomId)>;

// The membrane's forces added to the owned atoms' `f`: the loads on the chain
// disks, the escapees pushed back (escapee_force).
void add_forces(const SideChain (&chains)[2], const SideData (&sides)[2],
                const SideLoad (&loads)[2], double pressure, double thickness,
                const LocalAtoms &atoms, const LocalIndex &local_index, double *const *f);
// The per-atom flag of the owned atoms (`flag`, atoms.n of them).
enum Flag { NONE = 0, LEFT_CHAIN = 1, RIGHT_CHAIN = 2, ESCAPEE = 3 };
void set_flags(const SideChain (&chains)[2], int nlocal, const LocalIndex &local_index,
               double *flag);

// The slices of the active sides (sides[k].slices) for bands of `width`.
void reset_slices(SideData (&sides)[2], const bool active[2], Platens platens, double width);
// A disk of this rank in the extents of the active sides; returns its slice
// (the same for both sides).
int add_to_slices(SideData (&sides)[2], const bool active[2], double x, double y, double r);
// The same for the group's atoms among `atoms` (indices: the local indices to
// look at, nullptr: all); slice_of[i] is the slice of atom i.
void add_to_slices(SideData (&sides)[2], const bool active[2], const LocalAtoms &atoms,
                   const std::vector<int> *indices, std::vector<int> &slice_of);

// After the extents were merged over the ranks: the record of disk `d` (of
// slice `slice`) for each active side whose band holds it.
void put_band_records(std::vector<double> &out, const SideData (&sides)[2], const bool active[2],
                      int slice, const Disk &d, double width);
// The same for the group's atoms among `atoms` (indices as above).
void put_band_records(std::vector<double> &out, const SideData (&sides)[2], const bool active[2],
                      const LocalAtoms &atoms, const std::vector<int> *indices,
                      const std::vector<int> &slice_of, double width);
// The group's atoms as the band cache takes them.
std::vector<BandDisk> band_disks(const LocalAtoms &atoms);
// The lowest and highest centre of the group's atoms (1e300, -1e300: none).
void y_range(const LocalAtoms &atoms, double &lo, double &hi);
// The bands (sides[k].band) from every rank's records, in the ranks' order.
void take_bands(const std::vector<double> &records, SideData (&sides)[2]);

// The record of the watched disk at `entry` of the watch list: where it is,
// |v| dt / r and its type.
void put_watched(std::vector<double> &out, std::size_t entry, const Disk &now, double step_fraction,
                 int type);
// The records of the listed disks this rank owns (index[k]: the local index
// of list[k], -1: another rank's), with the time step `dt`.
void put_watched(std::vector<double> &out, const std::vector<WatchEntry> &list,
                 const std::vector<int> &index, const LocalAtoms &atoms, double dt);
// The largest displacement of the owned disks of `band` (index as above)
// since it was taken.
double largest_displacement(const std::vector<Disk> &band, const std::vector<int> &index,
                            const LocalAtoms &atoms);
// The last record of each rank: the largest displacement of its band disks.
void put_band_displacement(std::vector<double> &out, double displacement);
// Whether `n` doubles are the records of all `listed` watched disks and the
// last records of `ranks` ranks (a disk lost: fewer).
bool watched_complete(std::size_t n, std::size_t listed, int ranks);

struct Watched {
  double band_displacement = 0.0; // largest of a band disk since the detection (every auto)
  double chain_step = 0.0;        // largest |v| dt / r of a chain disk this step
  AtomId chain_step_tag = -1;     // its ID (of tied disks the lowest)
};
// Reads every rank's records (complete): the chain disks now and their types
// (sides[k].chain_disks, chain_types), the watched band disks now
// (chains[k].now) and the largest values.
Watched take_watched(const std::vector<double> &records, const std::vector<WatchEntry> &list,
                     SideChain (&chains)[2], SideData (&sides)[2]);

// The local indices of listed atoms (-1: another rank's), looked up again
// only when LIGGGHTS may have moved atoms between ranks or reordered them
// (a neighbour list build, another atom count) or the list changed (its IDs'
// hash).
struct OwnedIndices {
  std::vector<int> index;
  long long neighbour_builds = -1;
  int nlocal = -1;
  std::uint64_t tags_hash = 0;

  // True when `index` must be looked up again for the `n` IDs tag_of(0..n-1):
  // then it has n entries and the new key is kept.
  template <class TagOf> bool stale(long long builds, int local, std::size_t n, TagOf tag_of)
  {
    std::uint64_t hash = n;
    for (std::size_t k = 0; k < n; k++)
      hash = hash * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(tag_of(k));
    if (neighbour_builds == builds && nlocal == local && tags_hash == hash && index.size() == n)
      return false;
    index.resize(n);
    neighbour_builds = builds;
    nlocal = local;
    tags_hash = hash;
    return true;
  }
};

// What one rank received in the collectives of a run, and the seconds the fix
// took (membrane::traffic_summary writes them).
struct Traffic {
  double step_bytes = 0.0, detection_bytes = 0.0;
  double fix_seconds = 0.0, search_seconds = 0.0;
  long long full_passes = 0; // band detections that looked at every local disk
  long long first_step = 0;
  long long first_detections = 0;
};
// The wall-clock time of a scope (Traffic's seconds).
using ::ScopedSeconds;

// The bytes a rank receives in an allgather of `doubles` values from `ranks`
// ranks, the counts included.
double gathered_bytes(std::size_t doubles, std::size_t ranks);

} // namespace membrane

#endif

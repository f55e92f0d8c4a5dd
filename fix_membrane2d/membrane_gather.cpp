#include "membrane_gather.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "neighbor.h"
#include "update.h"

#include "allgather.h"
#include "atom_faults.h"
#include "style_args.h"
#include "style_error.h"
#include "membrane_output.h"
#include "stability_checks.h"

using namespace LAMMPS_NS;
using membrane::Disk;
using membrane::LEFT;
using membrane::RIGHT;
using membrane::Side;
using membrane::SideData;

ScopedSeconds::ScopedSeconds(double &total) : total_(total), start_(MPI_Wtime()) {}

ScopedSeconds::~ScopedSeconds()
{
  total_ += MPI_Wtime() - start_;
}

void MembraneGather::allgather(double &bytes)
{
  allgather_doubles(world, send_, recv_, counts_, displs_);
  bytes += membrane::gathered_bytes(recv_.size(), counts_.size());
}

void MembraneGather::bands(const membrane::Platens &platens, double width, const bool active[2],
                           SideData (&sides)[2])
{
  // One pass over the local disks (or the candidates) for both sides: the
  // slices are the same.
  const membrane::BandSlices *slices[2] = {active[LEFT] ? &sides[LEFT].slices : nullptr,
                                           active[RIGHT] ? &sides[RIGHT].slices : nullptr};
  const std::vector<int> &cands = candidates_.candidates();
  const int nlocal = atom->nlocal;
  bool from_candidates = candidates_.usable(width, active, neighbor->ncalls, nlocal);
  auto candidate = [&](int k) { return cands[k]; };
  if (from_candidates) {
    extents(platens, width, active, sides, static_cast<int>(cands.size()), candidate);
    // the candidates give the bands of a full pass unless another disk might
    // now be in one (on any rank): then the full pass after all
    int covered = candidates_.still_covers(slices[LEFT], slices[RIGHT]) ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &covered, 1, MPI_INT, MPI_MIN, world);
    traffic_.detection_bytes += sizeof(int);
    from_candidates = covered != 0;
  }
  if (!from_candidates) {
    extents(platens, width, active, sides, nlocal, [](int k) { return k; });
    traffic_.full_passes++;
    remember_candidates(width, active, slices);
  }

  send_.clear();
  const int nsend = from_candidates ? static_cast<int>(cands.size()) : nlocal;
  for (int k = 0; k < nsend; k++) {
    const int i = from_candidates ? candidate(k) : k;
    if (!(atom->mask[i] & groupbit_)) continue;
    const Disk d{atom->tag[i], atom->x[i][0], atom->x[i][1], atom->radius[i]};
    membrane::put_band_records(send_, sides, active, slice_of_atom_[i], d, width);
  }
  allgather(traffic_.detection_bytes);
  membrane::take_bands(recv_, sides);
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k] && sides[k].band.empty())
      style_error(lmp, prefix_, std::string("no atoms in the ") + membrane::side_name(k) + " band");
}

// The slices' extents over the n disks local_index(0..n-1), merged over the ranks.
template <class Index>
void MembraneGather::extents(const membrane::Platens &platens, double width, const bool active[2],
                             SideData (&sides)[2], int n, Index local_index)
{
  membrane::reset_slices(sides, active, platens, width);
  slice_of_atom_.resize(atom->nlocal);
  for (int k = 0; k < n; k++) {
    const int i = local_index(k);
    if (atom->mask[i] & groupbit_)
      slice_of_atom_[i] =
          membrane::add_to_slices(sides, active, atom->x[i][0], atom->x[i][1], atom->radius[i]);
  }
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!active[k]) continue;
    std::vector<double> &extent = sides[k].slices.extents();
    MPI_Allreduce(MPI_IN_PLACE, extent.data(), static_cast<int>(extent.size()), MPI_DOUBLE,
                  k == RIGHT ? MPI_MAX : MPI_MIN, world);
    traffic_.detection_bytes += sizeof(double) * extent.size();
    sides[k].slices.finish();
  }
}

void MembraneGather::remember_candidates(double width, const bool active[2],
                                         const membrane::BandSlices *const slices[2])
{
  candidates_.clear();
  if (!membrane::BandCandidates::motion_bounded(neighbor->every, neighbor->delay,
                                                neighbor->dist_check, neighbor->build_once))
    return;
  std::vector<membrane::BandDisk> disks;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit_)
      disks.push_back({i, atom->x[i][0], atom->x[i][1], atom->radius[i]});
  // candidates reach one band width further in than the band
  candidates_.build(disks, slices[LEFT], slices[RIGHT], width, width, neighbor->skin,
                    domain->boxlo[1], domain->boxhi[1]);
  candidates_.stamp(neighbor->ncalls, atom->nlocal, active);
}

void MembraneGather::search(membrane::ChainFinder &finder, const SideData (&sides)[2],
                            const bool pending[2], const membrane::Platens &platens,
                            double tolerance, membrane::ChainResult (&results)[2])
{
  auto owner = [&](int k) { return k == RIGHT && comm->nprocs > 1 ? 1 : 0; };
  const Side side_of[2] = {Side::Left, Side::Right};
  {
    const ScopedSeconds timing(traffic_.search_seconds);
    for (int k = LEFT; k <= RIGHT; k++)
      if (pending[k] && comm->me == owner(k))
        finder.find(sides[k].band, side_of[k], platens, tolerance, results[k]);
  }
  if (comm->nprocs == 1) return;
  // Every rank holds the same band in the same order (allgather): indices
  // into it identify the disks.
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!pending[k]) continue;
    if (comm->me == owner(k)) membrane::pack_result(results[k], result_buf_);
    int size = static_cast<int>(result_buf_.size());
    MPI_Bcast(&size, 1, MPI_INT, owner(k), world);
    result_buf_.resize(size);
    MPI_Bcast(result_buf_.data(), size, MPI_INT, owner(k), world);
    traffic_.detection_bytes += sizeof(int) * (1.0 + size);
    if (comm->me != owner(k) &&
        !membrane::unpack_result(result_buf_.data(), result_buf_.size(), results[k]))
      style_error_one(lmp, prefix_, "a broadcast chain search is corrupt; this is a fault of "
                                    "fix membrane2d; please report it with the input script");
  }
}

// Atoms change index or rank only when LIGGGHTS rebuilds its neighbour lists:
// looked up (atom->map) again only then or when the list changed.
template <class TagOf>
const std::vector<int> &MembraneGather::owned(membrane::OwnedIndices &cache, std::size_t n,
                                              TagOf tag_of)
{
  if (cache.stale(neighbor->ncalls, atom->nlocal, n, tag_of))
    for (std::size_t k = 0; k < n; k++) {
      const int i = atom->map(tag_of(k));
      cache.index[k] = i >= 0 && i < atom->nlocal ? i : -1;
    }
  return cache.index;
}

membrane::Watched MembraneGather::watched(const std::vector<membrane::WatchEntry> &list,
                                          membrane::SideChain (&chains)[2], bool watch_relations,
                                          SideData (&sides)[2])
{
  double **x = atom->x;
  double local_displacement = 0.0;
  if (watch_relations)
    for (int k = LEFT; k <= RIGHT; k++) {
      const membrane::SideChain &s = chains[k];
      if (!s.active || s.watch.always) continue;
      const std::vector<Disk> &band = s.watch_band;
      const std::vector<int> &index =
          owned(band_owned_[k], band.size(), [&](std::size_t b) { return band[b].tag; });
      for (std::size_t b = 0; b < band.size(); b++) {
        const int i = index[b];
        if (i < 0) continue;
        const double dx = x[i][0] - band[b].x, dy = x[i][1] - band[b].y;
        local_displacement = std::max(local_displacement, dx * dx + dy * dy);
      }
    }

  // each rank sends its owned watched disks (by their place in the list, the
  // same on every rank) and its own maximum in one allgather
  const std::vector<int> &index =
      owned(watched_owned_, list.size(), [&](std::size_t k) { return list[k].tag; });
  send_.clear();
  for (std::size_t k = 0; k < list.size(); k++) {
    const int i = index[k];
    if (i < 0) continue;
    const double *v = atom->v[i], r = atom->radius[i];
    membrane::put_watched(send_, k, Disk{list[k].tag, x[i][0], x[i][1], r},
                          stability::step_fraction(v[0], v[1], v[2], update->dt, r),
                          atom->type[i]);
  }
  membrane::put_band_displacement(send_, std::sqrt(local_displacement));
  allgather(traffic_.step_bytes);

  const std::string step = std::to_string(update->ntimestep);
  if (!membrane::watched_complete(recv_.size(), list.size(), comm->nprocs))
    style_error(lmp, prefix_,
                "a chain, escaped or band disk was lost at step " + step +
                    " (it left the box, or its position became infinite or NaN under an infinite "
                    "force; 'thermo_modify lost ignore' hides this): the membrane cannot hold a "
                    "sample whose outer disks fly off; check the time step, the pressure and the "
                    "platens");
  if (!std::all_of(recv_.begin(), recv_.end(), [](double v) { return std::isfinite(v); })) {
    // every rank holds recv_: all come here, and find the atom together
    const std::string fault = group_atom_fault(lmp, groupbit_, 2);
    style_error(lmp, prefix_,
                fault.empty() ? "a chain particle position is not finite at step " + step +
                                    ": the run has gone unstable; reduce the time step or the "
                                    "loading rate"
                              : fault);
  }
  return membrane::take_watched(recv_, list, chains, sides);
}

void MembraneGather::start_traffic(bigint step, long long detections)
{
  // the group or the atoms may have changed between runs, and LIGGGHTS counts
  // the neighbour builds of each run from 0 (Verlet::setup)
  candidates_.clear();
  watched_owned_ = band_owned_[LEFT] = band_owned_[RIGHT] = membrane::OwnedIndices();
  traffic_ = membrane::Traffic();
  traffic_.first_step = step;
  traffic_.first_detections = detections;
}

void MembraneGather::report_traffic(const char *id, bigint step, long long detections)
{
  double seconds[2] = {traffic_.fix_seconds, traffic_.search_seconds}, slowest[2] = {0.0, 0.0};
  MPI_Reduce(seconds, slowest, 2, MPI_DOUBLE, MPI_MAX, 0, world);
  if (comm->me != 0) return;
  const std::string text =
      membrane::traffic_summary(id, traffic_.step_bytes, traffic_.detection_bytes,
                                step - traffic_.first_step, detections - traffic_.first_detections,
                                traffic_.full_passes, slowest[0], slowest[1]);
  if (screen) fprintf(screen, "%s%s\n", prefix_.c_str(), text.c_str());
  if (logfile) fprintf(logfile, "%s%s\n", prefix_.c_str(), text.c_str());
}

void MembraneGather::check_enclosed(const ScalarInput &ylo_in, double ylo,
                                    const ScalarInput &yhi_in, double yhi)
{
  double local[2] = {1e300, -1e300}, lo, hi;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit_)) continue;
    local[0] = std::min(local[0], atom->x[i][1]);
    local[1] = std::max(local[1], atom->x[i][1]);
  }
  MPI_Allreduce(&local[0], &lo, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&local[1], &hi, 1, MPI_DOUBLE, MPI_MAX, world);
  const std::string below = membrane::enclose_problem(false, ylo, lo);
  if (!below.empty()) style_error(lmp, "", keyword_message(prefix_, "ylo", ylo_in.text(), below));
  const std::string above = membrane::enclose_problem(true, yhi, hi);
  if (!above.empty()) style_error(lmp, "", keyword_message(prefix_, "yhi", yhi_in.text(), above));
}

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
#include "owned_atom.h"
#include "style_error.h"
#include "membrane_output.h"

using namespace LAMMPS_NS;
using membrane::Disk;
using membrane::LEFT;
using membrane::RIGHT;
using membrane::Side;
using membrane::SideData;

membrane::LocalAtoms MembraneGather::local() const
{
  return {atom->nlocal, atom->mask, groupbit_, atom->tag, atom->x, atom->v, atom->radius,
          atom->type};
}

int MembraneGather::owned_index(AtomId tag) const
{
  return ::owned_index(atom, tag);
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
  const std::vector<int> *cands = &candidates_.candidates();
  bool from_candidates = candidates_.usable(width, active, neighbor->ncalls, atom->nlocal);
  if (from_candidates) {
    extents(platens, width, active, sides, cands);
    // the candidates give the bands of a full pass unless another disk might
    // now be in one (on any rank): then the full pass after all
    int covered = candidates_.still_covers(slices[LEFT], slices[RIGHT]) ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &covered, 1, MPI_INT, MPI_MIN, world);
    traffic_.detection_bytes += sizeof(int);
    from_candidates = covered != 0;
  }
  if (!from_candidates) {
    extents(platens, width, active, sides, nullptr);
    traffic_.full_passes++;
    remember_candidates(width, active, slices);
  }

  send_.clear();
  membrane::put_band_records(send_, sides, active, local(), from_candidates ? cands : nullptr,
                             slice_of_atom_, width);
  allgather(traffic_.detection_bytes);
  membrane::take_bands(recv_, sides);
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k] && sides[k].band.empty())
      style_error(lmp, prefix_, std::string("no atoms in the ") + membrane::side_name(k) + " band");
}

// The slices' extents over the disks `indices` (nullptr: all), merged over the ranks.
void MembraneGather::extents(const membrane::Platens &platens, double width, const bool active[2],
                             SideData (&sides)[2], const std::vector<int> *indices)
{
  membrane::reset_slices(sides, active, platens, width);
  membrane::add_to_slices(sides, active, local(), indices, slice_of_atom_);
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
  // candidates reach one band width further in than the band
  candidates_.build(membrane::band_disks(local()), slices[LEFT], slices[RIGHT], width, width,
                    neighbor->skin, domain->boxlo[1], domain->boxhi[1]);
  candidates_.stamp(neighbor->ncalls, atom->nlocal, active);
}

void MembraneGather::search(membrane::ChainFinder &finder, const SideData (&sides)[2],
                            const bool pending[2], const membrane::Platens &platens,
                            double tolerance, membrane::ChainResult (&results)[2])
{
  auto owner = [&](int k) { return k == RIGHT && comm->nprocs > 1 ? 1 : 0; };
  const Side side_of[2] = {Side::Left, Side::Right};
  {
    const membrane::ScopedSeconds timing(traffic_.search_seconds);
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
    for (std::size_t k = 0; k < n; k++) cache.index[k] = owned_index(tag_of(k));
  return cache.index;
}

membrane::Watched MembraneGather::watched(const std::vector<membrane::WatchEntry> &list,
                                          membrane::SideChain (&chains)[2], bool watch_relations,
                                          SideData (&sides)[2])
{
  double displacement = 0.0;
  if (watch_relations)
    for (int k = LEFT; k <= RIGHT; k++) {
      const std::vector<Disk> &band = chains[k].watch_band;
      if (!chains[k].active || chains[k].watch.always) continue;
      const std::vector<int> &index =
          owned(band_owned_[k], band.size(), [&](std::size_t b) { return band[b].tag; });
      displacement = std::max(displacement, membrane::largest_displacement(band, index, local()));
    }

  // each rank sends its owned watched disks (by their place in the list, the
  // same on every rank) and its own maximum in one allgather
  const std::vector<int> &index =
      owned(watched_owned_, list.size(), [&](std::size_t k) { return list[k].tag; });
  send_.clear();
  membrane::put_watched(send_, list, index, local(), update->dt);
  membrane::put_band_displacement(send_, displacement);
  allgather(traffic_.step_bytes);

  if (!membrane::watched_complete(recv_.size(), list.size(), comm->nprocs))
    style_error(lmp, prefix_, membrane::lost_disk_error(update->ntimestep));
  if (!std::all_of(recv_.begin(), recv_.end(), [](double v) { return std::isfinite(v); })) {
    // every rank holds recv_: all come here, and find the atom together
    const std::string fault = group_atom_fault(lmp, groupbit_, 2);
    style_error(lmp, prefix_,
                fault.empty() ? membrane::not_finite_error(update->ntimestep) : fault);
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
      membrane::traffic_summary(traffic_.step_bytes, traffic_.detection_bytes,
                                step - traffic_.first_step, detections - traffic_.first_detections,
                                traffic_.full_passes, slowest[0], slowest[1]);
  if (screen) fprintf(screen, "%s%s\n", prefix_.c_str(), text.c_str());
  if (logfile) fprintf(logfile, "%s%s\n", prefix_.c_str(), text.c_str());
  // the same numbers as key=value words, for programs (bench/scaling.py)
  const long long steps = step - traffic_.first_step, dets = detections - traffic_.first_detections;
  char line[400];
  snprintf(line, sizeof(line),
           "membrane2d_traffic id=%s kb_per_step=%.6g kb_per_detection=%.6g steps=%lld "
           "detections=%lld full_passes=%lld fix_seconds=%.6g search_seconds=%.6g\n",
           id, steps > 0 ? traffic_.step_bytes / steps / 1e3 : traffic_.step_bytes / 1e3,
           dets > 0 ? traffic_.detection_bytes / dets / 1e3 : 0.0, steps, dets,
           static_cast<long long>(traffic_.full_passes), slowest[0], slowest[1]);
  if (screen) fputs(line, screen);
  if (logfile) fputs(line, logfile);
}

void MembraneGather::check_enclosed(const ScalarInput &ylo_in, double ylo,
                                    const ScalarInput &yhi_in, double yhi)
{
  double mine[2], lo, hi;
  membrane::y_range(local(), mine[0], mine[1]);
  MPI_Allreduce(&mine[0], &lo, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&mine[1], &hi, 1, MPI_DOUBLE, MPI_MAX, world);
  const std::string below = membrane::enclose_problem(false, ylo, lo);
  if (!below.empty()) style_error(lmp, prefix_, keyword_text("ylo", ylo_in.text(), below));
  const std::string above = membrane::enclose_problem(true, yhi, hi);
  if (!above.empty()) style_error(lmp, prefix_, keyword_text("yhi", yhi_in.text(), above));
}

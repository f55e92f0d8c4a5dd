#include "membrane_gather.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "neighbor.h"
#include "update.h"

#include "allgather.h"
#include "atom_faults.h"
#include "style_error.h"
#include "membrane_output.h"
#include "membrane_record.h"
#include "stability_checks.h"

using namespace LAMMPS_NS;
using membrane::Disk;
using membrane::LEFT;
using membrane::RIGHT;
using membrane::Side;

namespace {
enum BandField { B_SIDE, B_TAG, B_X, B_Y, B_R, B_TYPE, BAND_FIELDS };
enum WatchField { W_ENTRY, W_X, W_Y, W_R, W_STEP, W_TYPE, WATCH_FIELDS };
} // namespace

ScopedSeconds::ScopedSeconds(double &total) : total_(total), start_(MPI_Wtime()) {}

ScopedSeconds::~ScopedSeconds()
{
  total_ += MPI_Wtime() - start_;
}

void MembraneGather::bands(const membrane::Platens &platens, double width, const bool active[2],
                           MembraneSideData (&sides)[2])
{
  // One pass over the local disks (or the candidates) for both sides: the
  // slices are the same.
  const membrane::BandSlices *slices[2] = {active[LEFT] ? &sides[LEFT].slices : nullptr,
                                           active[RIGHT] ? &sides[RIGHT].slices : nullptr};
  const std::vector<int> &cands = candidates_.candidates();
  const int nlocal = atom->nlocal;
  bool from_candidates = candidates_usable(width, active);
  auto candidate = [&](int k) { return cands[k]; };
  auto every_disk = [](int k) { return k; };
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
    extents(platens, width, active, sides, nlocal, every_disk);
    traffic_.full_passes++;
    remember_candidates(width, active, slices);
  }

  double **x = atom->x;
  double *radius = atom->radius;
  send_.clear();
  const int nsend = from_candidates ? static_cast<int>(cands.size()) : nlocal;
  for (int k = 0; k < nsend; k++) {
    const int i = from_candidates ? candidate(k) : k;
    if (!(atom->mask[i] & groupbit_)) continue;
    for (int s = LEFT; s <= RIGHT; s++) {
      if (!active[s] ||
          !sides[s].slices.contains_in_slice(slice_of_atom_[i], x[i][0], radius[i], width))
        continue;
      const double rec[BAND_FIELDS] = {static_cast<double>(s),
                                       static_cast<double>(atom->tag[i]),
                                       x[i][0],
                                       x[i][1],
                                       radius[i],
                                       static_cast<double>(atom->type[i])};
      send_.insert(send_.end(), rec, rec + BAND_FIELDS);
    }
  }
  allgather_doubles(world, send_, recv_, counts_, displs_);
  traffic_.detection_bytes += gathered_bytes();

  // No sorting: the chain search depends on the set of disks, not on their
  // order (ties are broken by tag), so any rank count gives the same chain.
  for (MembraneSideData &s : sides) {
    s.band.clear();
    s.band_type.clear();
  }
  for (std::size_t k = 0; k < recv_.size(); k += BAND_FIELDS) {
    const double *rec = recv_.data() + k;
    MembraneSideData &s = sides[static_cast<int>(rec[B_SIDE])];
    s.band.push_back(Disk{static_cast<long>(rec[B_TAG]), rec[B_X], rec[B_Y], rec[B_R]});
    s.band_type.push_back(static_cast<int>(rec[B_TYPE]));
  }
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k] && sides[k].band.empty())
      style_error(lmp, prefix_, std::string("no atoms in the ") + membrane::side_name(k) + " band");
}

// The slices' extents over the n disks local_index(0..n-1), merged over the ranks.
template <class Index>
void MembraneGather::extents(const membrane::Platens &platens, double width, const bool active[2],
                             MembraneSideData (&sides)[2], int n, Index local_index)
{
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k]) sides[k].slices.reset(k == LEFT ? Side::Left : Side::Right, platens, width);
  const membrane::BandSlices &slicing = sides[active[LEFT] ? LEFT : RIGHT].slices;
  double **x = atom->x;
  double *radius = atom->radius;
  slice_of_atom_.resize(atom->nlocal);
  for (int k = 0; k < n; k++) {
    const int i = local_index(k);
    if (!(atom->mask[i] & groupbit_)) continue;
    const int slice = slicing.slice_of(x[i][1]);
    slice_of_atom_[i] = slice;
    for (int s = LEFT; s <= RIGHT; s++)
      if (active[s]) sides[s].slices.add_in_slice(slice, x[i][0], radius[i]);
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

// LIGGGHTS rebuilds its neighbour lists (and only then moves atoms between
// ranks or reorders them) before any atom has moved half a skin from where it
// was at the last build, when it checks every step (neigh_modify every 1
// delay 0 check yes): between two builds no disk moves more than a skin from
// where it was when the candidates were taken. Without that guarantee every
// detection is a full pass.
bool MembraneGather::candidates_usable(double width, const bool active[2]) const
{
  return candidates_.valid() && candidates_.width() == width && candidates_neighbour_builds_ ==
         neighbor->ncalls && candidates_nlocal_ == atom->nlocal &&
         candidates_active_[LEFT] == active[LEFT] && candidates_active_[RIGHT] == active[RIGHT];
}

void MembraneGather::remember_candidates(double width, const bool active[2],
                                         const membrane::BandSlices *const slices[2])
{
  candidates_.clear();
  if (!(neighbor->every == 1 && neighbor->delay == 0 && neighbor->dist_check &&
        !neighbor->build_once))
    return;
  std::vector<membrane::BandDisk> disks;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit_)
      disks.push_back({i, atom->x[i][0], atom->x[i][1], atom->radius[i]});
  // candidates reach one band width further in than the band
  candidates_.build(disks, slices[LEFT], slices[RIGHT], width, width, neighbor->skin,
                    domain->boxlo[1], domain->boxhi[1]);
  candidates_neighbour_builds_ = neighbor->ncalls;
  candidates_nlocal_ = atom->nlocal;
  candidates_active_[LEFT] = active[LEFT];
  candidates_active_[RIGHT] = active[RIGHT];
}

void MembraneGather::search(membrane::ChainFinder &finder, const MembraneSideData (&sides)[2],
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

template <class TagOf>
const std::vector<int> &MembraneGather::owned(OwnedIndices &cache, std::size_t n, TagOf tag_of)
{
  std::uint64_t hash = n;
  for (std::size_t k = 0; k < n; k++)
    hash = hash * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(tag_of(k));
  if (cache.neighbour_builds == neighbor->ncalls && cache.nlocal == atom->nlocal &&
      cache.tags_hash == hash && cache.index.size() == n)
    return cache.index;
  cache.index.resize(n);
  for (std::size_t k = 0; k < n; k++) {
    const int i = atom->map(static_cast<int>(tag_of(k)));
    cache.index[k] = i >= 0 && i < atom->nlocal ? i : -1;
  }
  cache.neighbour_builds = neighbor->ncalls;
  cache.nlocal = atom->nlocal;
  cache.tags_hash = hash;
  return cache.index;
}

MembraneGather::Watched MembraneGather::watched(const std::vector<membrane::WatchEntry> &list,
                                                membrane::SideChain (&chains)[2],
                                                bool watch_relations, MembraneSideData (&sides)[2])
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
  local_displacement = std::sqrt(local_displacement);

  // each rank sends its owned watched disks (by their place in the list, the
  // same on every rank) and its own maximum in one allgather
  const std::vector<int> &index =
      owned(watched_owned_, list.size(), [&](std::size_t k) { return list[k].tag; });
  send_.clear();
  for (std::size_t k = 0; k < list.size(); k++) {
    const int i = index[k];
    if (i < 0) continue;
    const double *v = atom->v[i];
    const double rec[WATCH_FIELDS] = {
        static_cast<double>(k),
        x[i][0],
        x[i][1],
        atom->radius[i],
        stability::step_fraction(v[0], v[1], v[2], update->dt, atom->radius[i]),
        static_cast<double>(atom->type[i])};
    send_.insert(send_.end(), rec, rec + WATCH_FIELDS);
  }
  const double trailer[WATCH_FIELDS] = {-1.0, local_displacement, 0.0, 0.0, 0.0, 0.0};
  send_.insert(send_.end(), trailer, trailer + WATCH_FIELDS);
  allgather_doubles(world, send_, recv_, counts_, displs_);
  traffic_.step_bytes += gathered_bytes();

  const std::string step = std::to_string(update->ntimestep);
  if (recv_.size() != WATCH_FIELDS * (list.size() + comm->nprocs))
    style_error(lmp, prefix_,
                "a chain, escaped or band disk was lost at step " + step +
                    " (it left the box, or its position became infinite or NaN under an infinite "
                    "force; 'thermo_modify lost ignore' hides this): the membrane cannot hold a "
                    "sample whose outer disks fly off; check the time step, the pressure and the "
                    "platens");
  bool finite = true;
  for (double v : recv_) finite = finite && std::isfinite(v);
  if (!finite) {
    // every rank holds recv_: all come here, and find the atom together
    const std::string fault = group_atom_fault(lmp, groupbit_, 2);
    style_error(lmp, prefix_,
                fault.empty() ? "a chain particle position is not finite at step " + step +
                                    ": the run has gone unstable; reduce the time step or the "
                                    "loading rate"
                              : fault);
  }
  for (int k = LEFT; k <= RIGHT; k++) {
    sides[k].chain_disks.resize(chains[k].active ? chains[k].chain_tags.size() : 0);
    sides[k].chain_types.resize(sides[k].chain_disks.size());
  }
  Watched out;
  for (std::size_t k = 0; k < recv_.size(); k += WATCH_FIELDS) {
    const double *rec = recv_.data() + k;
    if (rec[W_ENTRY] < 0.0) {
      out.band_displacement = std::max(out.band_displacement, rec[W_X]);
      continue;
    }
    const membrane::WatchEntry &e = list[static_cast<std::size_t>(rec[W_ENTRY])];
    const long tag = e.tag;
    const Disk d{tag, rec[W_X], rec[W_Y], rec[W_R]};
    for (int side = LEFT; side <= RIGHT; side++) {
      if (e.chain_position[side] >= 0) {
        sides[side].chain_disks[e.chain_position[side]] = d;
        sides[side].chain_types[e.chain_position[side]] = static_cast<int>(rec[W_TYPE]);
        // ties: the lower ID (the records come in the ranks' order)
        if (rec[W_STEP] > out.chain_step ||
            (rec[W_STEP] == out.chain_step && out.chain_step_tag >= 0 &&
             tag < out.chain_step_tag)) {
          out.chain_step = rec[W_STEP];
          out.chain_step_tag = tag;
        }
      }
      if (e.band_index[side] >= 0) chains[side].now[e.band_index[side]] = d;
    }
  }
  return out;
}

void MembraneGather::start_traffic(bigint step, long long detections)
{
  // the group or the atoms may have changed between runs, and LIGGGHTS counts
  // the neighbour builds of each run from 0 (Verlet::setup)
  candidates_.clear();
  watched_owned_ = band_owned_[LEFT] = band_owned_[RIGHT] = OwnedIndices();
  traffic_ = Traffic();
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

double MembraneGather::gathered_bytes() const
{
  return sizeof(double) * static_cast<double>(recv_.size()) +
         sizeof(int) * static_cast<double>(counts_.size());
}

void MembraneGather::group_y_range(double &lo, double &hi)
{
  double local[2] = {1e300, -1e300};
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit_)) continue;
    local[0] = std::min(local[0], atom->x[i][1]);
    local[1] = std::max(local[1], atom->x[i][1]);
  }
  MPI_Allreduce(&local[0], &lo, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&local[1], &hi, 1, MPI_DOUBLE, MPI_MAX, world);
}

#include "membrane3d_gather.h"

#include <mpi.h>

#include <algorithm>
#include <numeric>

#include "atom.h"
#include "update.h"

#include "allgather.h"
#include "atom_faults.h"
#include "membrane3d_messages.h"
#include "style_error.h"
#include "owned_atom.h"

using namespace LAMMPS_NS;
using membrane3d::GatheredSpheres;

namespace {

enum Field { F_TAG, F_X, F_Y, F_Z, F_R, F_TYPE, FIELDS };

void pack(Atom *atom, int i, std::vector<double> &send)
{
  const double fields[FIELDS] = {static_cast<double>(atom->tag[i]),
                                 atom->x[i][0],
                                 atom->x[i][1],
                                 atom->x[i][2],
                                 atom->radius[i],
                                 static_cast<double>(atom->type[i])};
  send.insert(send.end(), fields, fields + FIELDS);
}

// every rank's packed atoms, sorted by tag, checked
void share(const Membrane3dGather &from, const std::vector<double> &send, GatheredSpheres &out)
{
  std::vector<double> all;
  std::vector<int> counts, displs;
  const double bytes = allgather_doubles(from.lmp->world, send, all, counts, displs);
  if (from.received) *from.received += bytes;
  const std::size_t n = all.size() / FIELDS;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto by_tag = [&all](std::size_t a, std::size_t b) {
    return all[a * FIELDS] < all[b * FIELDS];
  };
  // on one rank the members come in ascending IDs already
  if (!std::is_sorted(order.begin(), order.end(), by_tag))
    std::sort(order.begin(), order.end(), by_tag);
  out.tags.clear();
  out.spheres.clear();
  out.types.clear();
  const bigint step = from.lmp->update->ntimestep;
  for (std::size_t k : order) {
    const double *f = &all[k * FIELDS];
    const AtomId tag = static_cast<AtomId>(f[F_TAG]);
    // a fault of the input (a run gone unstable, a radius set to 0) named as such
    if (atom_is_faulty(f + F_X, 3, f[F_R]))
      style_error(from.lmp, from.prefix, atom_fault_text(tag, f + F_X, 3, f[F_R], step));
    const std::string outside = membrane3d::platens_problem(tag, f[F_Z], from.platens, step);
    if (!outside.empty()) style_error(from.lmp, from.prefix, outside);
    out.tags.push_back(tag);
    out.spheres.push_back({Eigen::Vector3d(f[F_X], f[F_Y], f[F_Z]), f[F_R]});
    out.types.push_back(static_cast<int>(f[F_TYPE]));
  }
}

} // namespace

void Membrane3dGather::group(GatheredSpheres &out) const
{
  Atom *atom = lmp->atom;
  std::vector<double> send;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) pack(atom, i, send);
  share(*this, send, out);
}

std::size_t Membrane3dGather::tags(const std::vector<AtomId> &tags, GatheredSpheres &out) const
{
  Atom *atom = lmp->atom;
  std::vector<double> send;
  for (AtomId tag : tags) {
    const int i = owned_index(atom, tag);
    // the map not stale (the slot holds that atom), and still in the group
    if (i >= 0 && atom->tag[i] == tag && (atom->mask[i] & groupbit))
      pack(atom, i, send);
  }
  share(*this, send, out);
  return out.tags.size();
}

membrane3d::Membrane3dAuto::Group Membrane3dGather::for_auto() const
{
  const Membrane3dGather self = *this;
  const auto signature = [self] {
    Atom *atom = self.lmp->atom;
    membrane3d::GroupSignature s;
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & self.groupbit) s.add(atom->tag[i], atom->radius[i]);
    double sums[2] = {s.atoms, s.id_sum};
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, self.lmp->world);
    MPI_Allreduce(MPI_IN_PLACE, &s.largest, 1, MPI_DOUBLE, MPI_MAX, self.lmp->world);
    s.atoms = sums[0];
    s.id_sum = sums[1];
    return s;
  };
  return {signature,
          [self](const std::vector<AtomId> &tags, GatheredSpheres &out) { self.tags(tags, out); }};
}

void check_ranks_agree(LAMMPS *lmp, const std::string &prefix, const std::vector<AtomId> &member_tags,
                       std::size_t facets)
{
  double mine[3] = {static_cast<double>(member_tags.size()), static_cast<double>(facets), 0.0};
  for (AtomId tag : member_tags) mine[2] += tag;
  double lo[3], hi[3];
  MPI_Allreduce(mine, lo, 3, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(mine, hi, 3, MPI_DOUBLE, MPI_MAX, lmp->world);
  const std::string problem = membrane3d::ranks_disagree(lo, hi, lmp->update->ntimestep);
  if (!problem.empty()) style_error(lmp, prefix, problem);
}

#include "membrane3d_gather.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
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

// What stops the run at a packed atom: a fault of the input (a run gone unstable, a
// radius set to 0) named as such, or a centre not between the platens; "" for none.
std::string problem_of(const double *f, const membrane3d::Platens &platens, bigint step)
{
  const AtomId tag = static_cast<AtomId>(f[F_TAG]);
  if (atom_is_faulty(f + F_X, 3, f[F_R])) return atom_fault_text(tag, f + F_X, 3, f[F_R], step);
  return membrane3d::platens_problem(tag, f[F_Z], platens, step);
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
    const std::string problem = problem_of(f, from.platens, step);
    if (!problem.empty()) style_error(from.lmp, from.prefix, problem);
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

Membrane3dGather::Totals Membrane3dGather::totals() const
{
  Atom *atom = lmp->atom;
  const bigint step = lmp->update->ntimestep;
  Totals t;
  double most[4] = {0.0, -HUGE_VAL, -HUGE_VAL, -HUGE_VAL}; // r_max, -z_lo, z_hi, -lowest bad ID
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  int bad = -1;
  std::vector<double> send;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    send.clear();
    pack(atom, i, send);
    if (!problem_of(send.data(), platens, step).empty() &&
        (bad < 0 || atom->tag[i] < atom->tag[bad]))
      bad = i;
    sums[0] += 1.0;
    sums[1] += 2.0 * atom->radius[i];
    sums[2] += atom->x[i][0];
    sums[3] += atom->x[i][1];
    most[0] = std::max(most[0], atom->radius[i]);
    most[1] = std::max(most[1], -atom->x[i][2]);
    most[2] = std::max(most[2], atom->x[i][2]);
  }
  if (bad >= 0) most[3] = -static_cast<double>(atom->tag[bad]);
  MPI_Allreduce(MPI_IN_PLACE, sums, 4, MPI_DOUBLE, MPI_SUM, lmp->world);
  MPI_Allreduce(MPI_IN_PLACE, most, 4, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (most[3] > -HUGE_VAL) {
    // the lowest failing ID's fields, from its rank to every rank: the same message
    send.clear();
    if (bad >= 0 && -static_cast<double>(atom->tag[bad]) == most[3]) pack(atom, bad, send);
    std::vector<double> all;
    std::vector<int> counts, displs;
    allgather_doubles(lmp->world, send, all, counts, displs);
    style_error(lmp, prefix, problem_of(all.data(), platens, step));
  }
  t.atoms = sums[0];
  t.diameter_sum = sums[1];
  t.x_sum = sums[2];
  t.y_sum = sums[3];
  t.r_max = most[0];
  t.z_lo = -most[1];
  t.z_hi = most[2];
  return t;
}

void Membrane3dGather::own(std::vector<int> &index, std::vector<membrane3d::Sphere> &spheres,
                           std::vector<AtomId> &tags) const
{
  Atom *atom = lmp->atom;
  index.clear();
  spheres.clear();
  tags.clear();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    index.push_back(i);
    spheres.push_back({Eigen::Vector3d(atom->x[i][0], atom->x[i][1], atom->x[i][2]),
                       atom->radius[i]});
    tags.push_back(atom->tag[i]);
  }
}

void Membrane3dGather::some(const std::vector<int> &index, GatheredSpheres &out) const
{
  std::vector<double> send;
  for (int i : index) pack(lmp->atom, i, send);
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

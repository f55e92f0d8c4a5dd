#include "membrane3d_gather.h"

#include <algorithm>
#include <numeric>

#include "atom.h"
#include "comm.h"

#include "allgather.h"

using namespace LAMMPS_NS;

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

// every rank's packed atoms, sorted by tag
void share(LAMMPS *lmp, const std::vector<double> &send, GatheredSpheres &out)
{
  std::vector<double> all;
  std::vector<int> counts, displs;
  allgather_doubles(lmp->world, send, all, counts, displs);
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
  for (std::size_t k : order) {
    const double *f = &all[k * FIELDS];
    out.tags.push_back(static_cast<int>(f[F_TAG]));
    out.spheres.push_back({Eigen::Vector3d(f[F_X], f[F_Y], f[F_Z]), f[F_R]});
    out.types.push_back(static_cast<int>(f[F_TYPE]));
  }
}

} // namespace

double mean_diameter(const GatheredSpheres &g)
{
  double diameter = 0.0;
  for (const auto &s : g.spheres) diameter += 2.0 * s.r;
  return g.spheres.empty() ? 0.0 : diameter / static_cast<double>(g.spheres.size());
}

void gather_group(LAMMPS *lmp, int groupbit, GatheredSpheres &out)
{
  Atom *atom = lmp->atom;
  std::vector<double> send;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) pack(atom, i, send);
  share(lmp, send, out);
}

std::size_t gather_tags(LAMMPS *lmp, int groupbit, const std::vector<int> &tags, GatheredSpheres &out)
{
  Atom *atom = lmp->atom;
  std::vector<double> send;
  for (int tag : tags) {
    const int i = tag <= atom->map_tag_max ? atom->map(tag) : -1;
    // owned here, and the map not stale (the slot holds that atom)
    if (i >= 0 && i < atom->nlocal && atom->tag[i] == tag && (atom->mask[i] & groupbit))
      pack(atom, i, send);
  }
  share(lmp, send, out);
  return out.tags.size();
}

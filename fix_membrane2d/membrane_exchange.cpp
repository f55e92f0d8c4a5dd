#include "membrane_exchange.h"

#include <algorithm>
#include <cmath>

#include "stability_checks.h"

namespace membrane {

namespace {
enum BandField { B_SIDE, B_TAG, B_X, B_Y, B_R, BAND_FIELDS };
enum WatchField { W_ENTRY, W_X, W_Y, W_R, W_STEP, W_TYPE, WATCH_FIELDS };
} // namespace

void add_forces(const SideChain (&chains)[2], const SideData (&sides)[2],
                const SideLoad (&loads)[2], double pressure, double thickness,
                const LocalAtoms &atoms, const LocalIndex &local_index, double *const *f)
{
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!chains[k].active) continue;
    const std::vector<Disk> &chain = sides[k].chain_disks;
    for (std::size_t c = 0; c < chain.size(); c++) {
      const int i = local_index(chain[c].tag);
      if (i < 0) continue;
      f[i][0] += loads[k].forces[c].x();
      f[i][1] += loads[k].forces[c].y();
    }
    for (AtomId tag : chains[k].escaped_tags) {
      const int i = local_index(tag);
      if (i < 0) continue;
      const Disk d{tag, atoms.x[i][0], atoms.x[i][1], atoms.radius[i]};
      const Eigen::Vector2d push = escapee_force(d, chains[k].side, pressure, thickness);
      f[i][0] += push.x();
      f[i][1] += push.y();
    }
  }
}

void set_flags(const SideChain (&chains)[2], int nlocal, const LocalIndex &local_index,
               double *flag)
{
  std::fill(flag, flag + nlocal, 0.0);
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!chains[k].active) continue;
    for (AtomId tag : chains[k].chain_tags) {
      const int i = local_index(tag);
      if (i >= 0) flag[i] = k == LEFT ? LEFT_CHAIN : RIGHT_CHAIN;
    }
    for (AtomId tag : chains[k].escaped_tags) {
      const int i = local_index(tag);
      if (i >= 0) flag[i] = ESCAPEE;
    }
  }
}

void reset_slices(SideData (&sides)[2], const bool active[2], Platens platens, double width)
{
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k]) sides[k].slices.reset(k == LEFT ? Side::Left : Side::Right, platens, width);
}

int add_to_slices(SideData (&sides)[2], const bool active[2], double x, double y, double r)
{
  const int slice = sides[active[LEFT] ? LEFT : RIGHT].slices.slice_of(y);
  for (int k = LEFT; k <= RIGHT; k++)
    if (active[k]) sides[k].slices.add_in_slice(slice, x, r);
  return slice;
}

void add_to_slices(SideData (&sides)[2], const bool active[2], const LocalAtoms &atoms,
                   const std::vector<int> *indices, std::vector<int> &slice_of)
{
  slice_of.resize(static_cast<std::size_t>(atoms.n));
  const int n = indices ? static_cast<int>(indices->size()) : atoms.n;
  for (int k = 0; k < n; k++) {
    const int i = indices ? (*indices)[k] : k;
    if (atoms.in_group(i))
      slice_of[i] = add_to_slices(sides, active, atoms.x[i][0], atoms.x[i][1], atoms.radius[i]);
  }
}

void put_band_records(std::vector<double> &out, const SideData (&sides)[2], const bool active[2],
                      const LocalAtoms &atoms, const std::vector<int> *indices,
                      const std::vector<int> &slice_of, double width)
{
  const int n = indices ? static_cast<int>(indices->size()) : atoms.n;
  for (int k = 0; k < n; k++) {
    const int i = indices ? (*indices)[k] : k;
    if (atoms.in_group(i)) put_band_records(out, sides, active, slice_of[i], atoms.disk(i), width);
  }
}

std::vector<BandDisk> band_disks(const LocalAtoms &atoms)
{
  std::vector<BandDisk> disks;
  for (int i = 0; i < atoms.n; i++)
    if (atoms.in_group(i)) disks.push_back({i, atoms.x[i][0], atoms.x[i][1], atoms.radius[i]});
  return disks;
}

void y_range(const LocalAtoms &atoms, double &lo, double &hi)
{
  lo = 1e300;
  hi = -1e300;
  for (int i = 0; i < atoms.n; i++) {
    if (!atoms.in_group(i)) continue;
    lo = std::min(lo, atoms.x[i][1]);
    hi = std::max(hi, atoms.x[i][1]);
  }
}

void put_band_records(std::vector<double> &out, const SideData (&sides)[2], const bool active[2],
                      int slice, const Disk &d, double width)
{
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!active[k] || !sides[k].slices.contains_in_slice(slice, d.x, d.r, width)) continue;
    const double rec[BAND_FIELDS] = {static_cast<double>(k), static_cast<double>(d.tag), d.x, d.y,
                                     d.r};
    out.insert(out.end(), rec, rec + BAND_FIELDS);
  }
}

// No sorting: the chain search depends on the set of disks, not on their
// order (ties are broken by tag), so any rank count gives the same chain.
void take_bands(const std::vector<double> &records, SideData (&sides)[2])
{
  for (SideData &s : sides) s.band.clear();
  for (std::size_t k = 0; k + BAND_FIELDS <= records.size(); k += BAND_FIELDS) {
    const double *rec = records.data() + k;
    sides[static_cast<int>(rec[B_SIDE])].band.push_back(
        Disk{static_cast<AtomId>(rec[B_TAG]), rec[B_X], rec[B_Y], rec[B_R]});
  }
}

void put_watched(std::vector<double> &out, std::size_t entry, const Disk &now, double step_fraction,
                 int type)
{
  const double rec[WATCH_FIELDS] = {static_cast<double>(entry), now.x, now.y, now.r, step_fraction,
                                    static_cast<double>(type)};
  out.insert(out.end(), rec, rec + WATCH_FIELDS);
}

void put_watched(std::vector<double> &out, const std::vector<WatchEntry> &list,
                 const std::vector<int> &index, const LocalAtoms &atoms, double dt)
{
  for (std::size_t k = 0; k < list.size(); k++) {
    const int i = index[k];
    if (i < 0) continue;
    const double *v = atoms.v[i];
    put_watched(out, k, atoms.disk(i),
                stability::step_fraction(v[0], v[1], v[2], dt, atoms.radius[i]), atoms.type[i]);
  }
}

double largest_displacement(const std::vector<Disk> &band, const std::vector<int> &index,
                            const LocalAtoms &atoms)
{
  double most = 0.0;
  for (std::size_t b = 0; b < band.size(); b++) {
    const int i = index[b];
    if (i < 0) continue;
    const double dx = atoms.x[i][0] - band[b].x, dy = atoms.x[i][1] - band[b].y;
    most = std::max(most, dx * dx + dy * dy);
  }
  return std::sqrt(most);
}

void put_band_displacement(std::vector<double> &out, double displacement)
{
  const double trailer[WATCH_FIELDS] = {-1.0, displacement, 0.0, 0.0, 0.0, 0.0};
  out.insert(out.end(), trailer, trailer + WATCH_FIELDS);
}

bool watched_complete(std::size_t n, std::size_t listed, int ranks)
{
  return n == WATCH_FIELDS * (listed + static_cast<std::size_t>(ranks));
}

Watched take_watched(const std::vector<double> &records, const std::vector<WatchEntry> &list,
                     SideChain (&chains)[2], SideData (&sides)[2])
{
  for (int k = LEFT; k <= RIGHT; k++) {
    sides[k].chain_disks.resize(chains[k].active ? chains[k].chain_tags.size() : 0);
    sides[k].chain_types.resize(sides[k].chain_disks.size());
  }
  Watched out;
  for (std::size_t k = 0; k + WATCH_FIELDS <= records.size(); k += WATCH_FIELDS) {
    const double *rec = records.data() + k;
    if (rec[W_ENTRY] < 0.0) {
      out.band_displacement = std::max(out.band_displacement, rec[W_X]);
      continue;
    }
    const WatchEntry &e = list[static_cast<std::size_t>(rec[W_ENTRY])];
    const Disk d{e.tag, rec[W_X], rec[W_Y], rec[W_R]};
    for (int side = LEFT; side <= RIGHT; side++) {
      if (e.chain_position[side] >= 0) {
        sides[side].chain_disks[e.chain_position[side]] = d;
        sides[side].chain_types[e.chain_position[side]] = static_cast<int>(rec[W_TYPE]);
        // ties: the lower ID (the records come in the ranks' order)
        if (rec[W_STEP] > out.chain_step ||
            (rec[W_STEP] == out.chain_step && out.chain_step_tag >= 0 &&
             e.tag < out.chain_step_tag)) {
          out.chain_step = rec[W_STEP];
          out.chain_step_tag = e.tag;
        }
      }
      if (e.band_index[side] >= 0) chains[side].now[e.band_index[side]] = d;
    }
  }
  return out;
}

double gathered_bytes(std::size_t doubles, std::size_t ranks)
{
  return sizeof(double) * static_cast<double>(doubles) + sizeof(int) * static_cast<double>(ranks);
}

} // namespace membrane

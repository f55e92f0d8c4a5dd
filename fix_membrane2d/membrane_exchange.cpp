#include "membrane_exchange.h"

#include <algorithm>

namespace membrane {

namespace {
enum BandField { B_SIDE, B_TAG, B_X, B_Y, B_R, BAND_FIELDS };
enum WatchField { W_ENTRY, W_X, W_Y, W_R, W_STEP, W_TYPE, WATCH_FIELDS };
} // namespace

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

void put_watched(std::vector<double> &out, std::size_t entry, const Disk &now,
                 double step_fraction, int type)
{
  const double rec[WATCH_FIELDS] = {static_cast<double>(entry), now.x, now.y, now.r,
                                    step_fraction, static_cast<double>(type)};
  out.insert(out.end(), rec, rec + WATCH_FIELDS);
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

#include "membrane_state.h"

#include "platens.h"

#include <algorithm>
#include <cmath>

#include "stability_checks.h"

namespace membrane {

void forget_chain(SideChain &s)
{
  s.forgotten_tags.swap(s.chain_tags);
  s.forgotten_escaped.swap(s.escaped_tags);
  s.chain_tags.clear();
  s.escaped_tags.clear();
  s.escaped_radius.clear();
  s.watch.always = true;
}

bool accept_chain(SideChain &s, const std::vector<Disk> &band, const ChainResult &r,
                  const WatchSettings *watch)
{
  const bool forgotten = s.chain_tags.empty();
  std::vector<AtomId> old_tags, old_escaped;
  old_tags.swap(forgotten ? s.forgotten_tags : s.chain_tags);
  old_escaped.swap(forgotten ? s.forgotten_escaped : s.escaped_tags);
  s.forgotten_tags.clear();
  s.forgotten_escaped.clear();
  s.chain_tags.clear();
  for (int idx : r.chain) s.chain_tags.push_back(band[idx].tag);
  // by tag, not in r.escaped's (the band's, the ranks') order
  std::vector<int> escaped = r.escaped;
  std::sort(escaped.begin(), escaped.end(),
            [&band](int a, int b) { return band[a].tag < band[b].tag; });
  s.escaped_tags.clear();
  s.escaped_radius.clear();
  for (int idx : escaped) {
    s.escaped_tags.push_back(band[idx].tag);
    s.escaped_radius.push_back(band[idx].r);
  }
  if (watch) {
    // what this search depended on, on the band it searched (a wider band may follow)
    watch_detection(band, r, watch->platens, watch->tolerance, watch->budget, s.watch);
    s.watch_band = band;
    s.now = band;
  }
  // escapees compared as sets: a restart file of an earlier version holds them in band order
  std::sort(old_escaped.begin(), old_escaped.end());
  return s.chain_tags != old_tags || s.escaped_tags != old_escaped;
}

bool detection_needed(const SideChain (&chains)[2], Platens platens, Platens detected,
                      double tolerance, double band_displacement, double budget)
{
  const double platen_move =
      std::max(std::fabs(platens.lo - detected.lo), std::fabs(platens.hi - detected.hi));
  if (2.0 * band_displacement >= budget || band_displacement + platen_move >= budget) return true;
  for (const SideChain &s : chains)
    if (s.active && watched_relation_changed(s.watch, s.now, s.side, platens, tolerance))
      return true;
  return false;
}

double widened_band(double width, double d50)
{
  return std::min(width * BAND_WIDENING, MOST_SEARCH_WIDTH * d50);
}

bool platens_moved(const RunState &run, Platens now, double limit)
{
  return platens_moved_beyond(now, Platens{run.ylo_detected, run.yhi_detected}, limit);
}

double platen_move_limit(const RunState &run, double d50)
{
  return std::max(run.tolerance, WATCH_BUDGET * d50);
}

bool unwatched_step(const RunState &run, long long step)
{
  return run.dense.unwatched(step);
}

bool count_watched_step(RunState &run, long long step, bool detected)
{
  return run.dense.count_watched(step, detected);
}

void drop_watch(SideChain &s)
{
  s.watch.always = true;
  s.watch.pairs.clear();
  s.watch.platen_contacts.clear();
  s.watch.ahead.clear();
  s.watch.disks.clear();
  s.watch_band.clear();
  s.now.clear();
}

void set_lengths(const Definition &def, double d50, double tolerance, RunState &run)
{
  run.band_width = def.band_given > 0.0 ? def.band_given : DEFAULT_BAND * d50;
  if (run.search_width <= 0.0) run.search_width = run.band_width;
  run.tolerance = tolerance;
}

void chain_types(const SideData (&sides)[2], std::vector<AtomId> &tags, std::vector<int> &types)
{
  std::map<AtomId, int> on;
  for (const SideData &s : sides)
    for (std::size_t c = 0; c < s.chain_disks.size(); c++)
      on.emplace(s.chain_disks[c].tag, s.chain_types[c]);
  tags.clear();
  types.clear();
  for (const auto &disk : on) {
    tags.push_back(disk.first);
    types.push_back(disk.second);
  }
}

void build_watch_list(const SideChain (&sides)[2], bool watch_relations,
                      std::vector<WatchEntry> &out)
{
  out.clear();
  for (int k = LEFT; k <= RIGHT; k++) {
    const SideChain &s = sides[k];
    if (!s.active) continue;
    for (std::size_t c = 0; c < s.chain_tags.size(); c++) {
      WatchEntry e;
      e.tag = s.chain_tags[c];
      e.chain_position[k] = static_cast<int>(c);
      out.push_back(e);
    }
    for (AtomId tag : s.escaped_tags) {
      WatchEntry e; // no role: gathered only so that its loss is seen
      e.tag = tag;
      out.push_back(e);
    }
    if (watch_relations && !s.watch.always)
      for (int idx : s.watch.disks) {
        WatchEntry e;
        e.tag = s.watch_band[idx].tag;
        e.band_index[k] = idx;
        out.push_back(e);
      }
  }
  std::sort(out.begin(), out.end(),
            [](const WatchEntry &a, const WatchEntry &b) { return a.tag < b.tag; });
  // one entry per disk, with every role it has
  std::size_t n = 0;
  for (std::size_t k = 0; k < out.size(); k++) {
    if (n > 0 && out[n - 1].tag == out[k].tag) {
      for (int side = LEFT; side <= RIGHT; side++) {
        out[n - 1].chain_position[side] =
            std::max(out[n - 1].chain_position[side], out[k].chain_position[side]);
        out[n - 1].band_index[side] =
            std::max(out[n - 1].band_index[side], out[k].band_index[side]);
      }
    } else {
      out[n++] = out[k];
    }
  }
  out.resize(n);
}

namespace {
constexpr int RESULT_HEADER = 7; // ok, 4 sizes, pruned, failed_starts
}

void pack_result(const ChainResult &r, std::vector<int> &out)
{
  out.clear();
  out.push_back(r.ok ? 1 : 0);
  out.push_back(static_cast<int>(r.chain.size()));
  out.push_back(static_cast<int>(r.escaped.size()));
  out.push_back(static_cast<int>(r.failure.size()));
  out.push_back(static_cast<int>(r.visited.size()));
  out.push_back(r.pruned);
  out.push_back(r.failed_starts);
  out.insert(out.end(), r.chain.begin(), r.chain.end());
  out.insert(out.end(), r.escaped.begin(), r.escaped.end());
  out.insert(out.end(), r.failure.begin(), r.failure.end());
  out.insert(out.end(), r.visited.begin(), r.visited.end());
}

bool unpack_result(const int *data, std::size_t n, ChainResult &r)
{
  if (n < RESULT_HEADER) return false;
  std::size_t sizes = 0;
  for (int k = 1; k <= 4; k++) {
    if (data[k] < 0) return false;
    sizes += static_cast<std::size_t>(data[k]);
  }
  if (n != RESULT_HEADER + sizes) return false;
  r.ok = data[0] != 0;
  r.pruned = data[5];
  r.failed_starts = data[6];
  const int *b = data + RESULT_HEADER;
  r.chain.assign(b, b + data[1]);
  b += data[1];
  r.escaped.assign(b, b + data[2]);
  b += data[2];
  r.failure.assign(b, b + data[3]);
  b += data[3];
  r.visited.assign(b, b + data[4]);
  r.polyline.clear(); // the caller rebuilds it from the chain
  return true;
}

void load_side(const std::vector<Disk> &chain, Side side, Platens platens, double pressure,
               double thickness, SideLoad &out)
{
  out.order.resize(chain.size());
  for (std::size_t c = 0; c < chain.size(); c++) out.order[c] = static_cast<int>(c);
  polyline_from_chain(chain, out.order, platens, out.polyline);
  chain_forces(out.polyline, side, pressure, thickness, out.forces);
  out.total.setZero();
  for (const Eigen::Vector2d &f : out.forces) out.total += f;
}

bool InertialWindow::update(long long step, double height, double dt, long long window, double d50,
                            double density, double pressure, double limit)
{
  if (first_step < 0 || step < first_step) {
    first_step = step;
    first_height = height;
    return false;
  }
  if (step - first_step < window) return false;
  rate = std::fabs(height - first_height) /
         (first_height * static_cast<double>(step - first_step) * dt);
  value = pressure > 0.0 ? stability::inertial_number(rate, d50, density, pressure) : 0.0;
  first_step = step;
  first_height = height;
  const bool above = value > limit;
  const bool sustained = above && was_above;
  was_above = above;
  return sustained;
}

} // namespace membrane

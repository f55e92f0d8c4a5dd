#include "membrane_step.h"

#include "dense_detections.h"

#include "membrane_output.h"
#include "stability_checks.h"

namespace membrane {

bool detection_due(const RunState &run, const SharedKeywords &shared, long long step, Platens now,
                   double d50)
{
  const bool automatic = shared.automatic();
  return run.force_detection || detection_scheduled(shared, step, run.last_detection) ||
         (automatic && unwatched_step(run, step)) ||
         (!automatic && platens_moved(run, now, platen_move_limit(run, d50)));
}

std::vector<Notice> detect(SideChain (&chains)[2], const SideData (&sides)[2], RunState &run,
                           std::vector<WatchEntry> &watch_list, double d50, bool automatic,
                           const WatchSettings *watch, Platens platens, long long step,
                           const BandSearch &search)
{
  run.force_detection = false; // set again below after widening the band
  run.counters.detections++;
  bool pending[2] = {chains[LEFT].active, chains[RIGHT].active};
  double width = run.search_width;
  ChainResult results[2];
  std::vector<Notice> notices;
  for (int attempt = 0; attempt <= MAX_WIDENINGS && (pending[LEFT] || pending[RIGHT]); attempt++) {
    if (attempt > 0) {
      width = widened_band(width, d50);
      run.counters.widenings++;
    }
    search(width, pending, results);
    for (int k = LEFT; k <= RIGHT; k++) {
      if (!pending[k]) continue;
      SideChain &s = chains[k];
      if (!results[k].ok) {
        if (attempt < MAX_WIDENINGS) continue;
        run.counters.failures++;
        s.watch.always = true; // search again at the next step
        const std::string where =
            std::string(side_name(k)) + " side at step " + std::to_string(step);
        if (s.chain_tags.empty())
          notices.push_back({true, no_chain_error(where, results[k].failure)});
        else if (!s.warned_lost) {
          notices.push_back({false, chain_lost_warning(where, results[k].failure)});
          s.warned_lost = true;
        }
        continue;
      }
      pending[k] = false;
      // how often a detection changes anything: what skipping detections would risk
      if (accept_chain(s, sides[k].band, results[k], watch)) run.counters.changes++;
      if (automatic && !watch) drop_watch(s);
    }
  }
  if (width > run.search_width) {
    run.search_width = width;
    run.force_detection = true;
  }
  run.last_detection = step;
  run.ylo_detected = platens.lo;
  run.yhi_detected = platens.hi;
  build_watch_list(chains, watch != nullptr, watch_list);
  return notices;
}

std::vector<std::string> stability_warnings(RunState &run, double chain_step, AtomId tag,
                                            long long step, double height, double dt, double d50,
                                            double density, double pressure)
{
  std::vector<std::string> out;
  if (chain_step > CHAIN_STEP_LIMIT && !run.warned_chain_step) {
    run.warned_chain_step = true;
    out.push_back(chain_step_warning(tag, chain_step, step));
  }
  const double limit = stability::INERTIAL_QUASI_STATIC;
  if (run.inertial.update(step, height, dt, INERTIAL_WINDOW, d50, density, pressure, limit) &&
      !run.warned_inertial) {
    run.warned_inertial = true;
    out.push_back(inertial_warning(run.inertial, limit, step, d50, density, pressure));
  }
  return out;
}

} // namespace membrane

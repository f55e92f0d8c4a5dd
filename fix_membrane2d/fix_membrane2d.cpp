/* ----------------------------------------------------------------------
   fix membrane2d: see fix_membrane2d.h and doc/fix_membrane2d.md

   Every rank gathers the same side bands (membrane_gather.h) and holds the
   same chain search results, so the chain never depends on the number of
   ranks; forces are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane2d.h"

#include <algorithm>
#include <map>
#include <string>

#include "atom.h"
#include "memory.h"
#include "update.h"

#include "contact_scales.h"
#include "membrane2d_checks.h"
#include "membrane_output.h"
#include "membrane_record.h"
#include "restart_envelope.h"
#include "stability_checks.h"
#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;
using namespace membrane;

namespace {

const MembraneTraits TRAITS{2,
                            "ylo",
                            "yhi",
                            "ylo Y: the lower platen surface (length), a number or v_name",
                            "yhi Y: the upper platen surface (length), a number or v_name",
                            "disks",
                            DEFAULT_TOLERANCE,
                            MOST_TOLERANCE};

const char *const USE_SIDES = "sides left|right|both";
const std::string USE_BAND =
    "band W: the width of the side bands (length), default " + number_text(DEFAULT_BAND) + " x D50";
const char *const USE_THICKNESS = "thickness T: the out-of-plane thickness (length), default 1";

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane2d::FixMembrane2d(LAMMPS *lammps, int narg, char **arg)
  : MembraneFix(lammps, narg, arg, TRAITS), polyline(lammps, prefix),
    gather(lammps, prefix, groupbit), atoms(lammps)
{
  chains[LEFT].side = Side::Left;
  chains[RIGHT].side = Side::Right;
  chains[LEFT].active = chains[RIGHT].active = true;
  const std::vector<std::string> own = {"sides", "band", "thickness", "polyline"};
  parse(narg, arg, own, [&](StyleArgs &args, const std::string &key) {
    if (key == "sides") {
      const int which = args.choice({"left", "right", "both"}, USE_SIDES);
      chains[LEFT].active = which != 1;
      chains[RIGHT].active = which != 0;
    } else if (key == "band") {
      definition.band_given = args.positive(USE_BAND);
    } else if (key == "thickness") {
      definition.thickness = args.positive(USE_THICKNESS);
    } else if (key == "polyline") {
      std::vector<std::string> keywords = own;
      keywords.insert(keywords.end(), {"pressure", "ylo", "yhi", "tolerance", "every",
                                       "frictionless", "vtk"});
      polyline.read(args, keywords);
    } else {
      return false;
    }
    return true;
  });
  definition.sides_mask = (chains[LEFT].active ? 1 : 0) + (chains[RIGHT].active ? 2 : 0);
  definition.frictionless_type = shared.frictionless;
  definition.detect_every = shared.every;
  definition.tolerance_given = shared.tolerance_given;

  size_vector = OUTPUT_SIZE;
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  vector_atom = nullptr;
  std::fill(vector_values, vector_values + OUTPUT_SIZE, 0.0);
}

FixMembrane2d::~FixMembrane2d()
{
  memory->destroy(vector_atom);
}

std::vector<std::pair<std::string, std::string>> FixMembrane2d::frame_files() const
{
  return {{"vtk", vtk.pvd()}, {"polyline", polyline.file()}};
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::init()
{
  init_shared();
  set_lengths(definition, d50, tolerance, run);
  check_band(lmp, prefix, run.band_width, d50);
  // chain disks are pushed by the membrane on top of their contacts: an
  // unstable chain shows first as escapes
  check_time_step(lmp, groupbit, world, prefix, stability::TIME_STEP_POORLY_RESOLVED, warned_dt);
}

void FixMembrane2d::setup_pre_force(int vflag)
{
  evaluate_inputs();
  check_platens_enclose(lmp, prefix, gather, inputs.lo, lo, inputs.hi, hi);
  gather.start_traffic(update->ntimestep, run.counters.detections);
  // the chains of the last run (or the restart file) still hold when no disk
  // of the group was created, deleted, renumbered, retyped or moved since
  // (this step's detection, if any, was then done in the last step of that run)
  const bool kept = state_kept && group_checksum() == run.checksum;
  state_kept = false;
  if (kept) {
    gather_watched();
    wear_chain_types();
    // other platens (a restart, a jump) or a step counter set back: detect now, the
    // kept chains the fallback
    if (!platens_moved(run, platens(), platen_move_limit(run, d50)) &&
        update->ntimestep >= run.last_detection)
      return;
    run.force_detection = true;
  } else {
    forget_state();
  }
  pre_force(vflag);
}

void FixMembrane2d::forget_state()
{
  types.restore();
  for (SideChain &s : chains) forget_chain(s);
  for (MembraneSideData &s : sides) s.chain_disks.clear();
  watch_list.clear();
  run.force_detection = true;
}

// end of a run: every disk gets its own type back (the next run, a write_data,
// an unfix or a run without this fix see the true sample)
void FixMembrane2d::post_run()
{
  types.restore();
  run.checksum = group_checksum();
  state_kept = true;
  gather.report_traffic(id, update->ntimestep, run.counters.detections);
}

void FixMembrane2d::setup(int vflag)
{
  post_force(vflag);
}

// chain detection happens before the pair forces, so that a disk joining
// the chain is frictionless in this very step
void FixMembrane2d::pre_force(int)
{
  const ScopedSeconds timing(gather.fix_seconds());
  evaluate_inputs();
  const bigint step = update->ntimestep;
  const bool unwatched = automatic() && unwatched_step(run, step);
  bool detect = on_any_rank(detection_due());
  if (!detect) {
    gather_watched();
    // from what every rank gathered: the same on every rank
    detect = automatic() && detection_needed(chains, platens(),
                                             Platens{run.ylo_detected, run.yhi_detected},
                                             run.tolerance, watched.band_displacement,
                                             WATCH_BUDGET * d50);
  }
  const bool watch = automatic() && !unwatched && !count_watched_step(run, step, detect);
  if (detect) {
    run.force_detection = false; // detect_chains() sets it again after widening the band
    detect_chains(watch);
    run.last_detection = step;
    run.ylo_detected = lo;
    run.yhi_detected = hi;
    build_watch_list(chains, watch, watch_list);
    gather_watched(); // the new chain's positions, speeds and types
    wear_chain_types();
  }
  // after a run or a restart write the chain disks wear their own types
  if (!types.applied()) wear_chain_types();
}

// This rank's view of the schedule (on_any_rank makes it every rank's): a forced
// detection, the schedule of the shared keyword every, a dense every-auto window,
// with every N platens moved beyond the tolerance.
bool FixMembrane2d::detection_due()
{
  const bigint step = update->ntimestep;
  return run.force_detection || detection_scheduled(shared, step, run.last_detection) ||
         (automatic() && unwatched_step(run, step)) ||
         (!automatic() && platens_moved(run, platens(), platen_move_limit(run, d50)));
}

// A band narrower than the sample's surface roughness can cut every contact
// path to the top (seen at 8 % axial strain with 4 D50 where 10 D50 found the
// chain): before declaring the chain lost, widen the band and search again.
// The width reached is kept for the rest of the run (a rough outline stays
// rough), and both sides are searched again with it at the next step, so
// every auto and every 1 search the same bands.
void FixMembrane2d::detect_chains(bool watch_it)
{
  run.counters.detections++;
  bool pending[2] = {chains[LEFT].active, chains[RIGHT].active};
  const bool active[2] = {chains[LEFT].active, chains[RIGHT].active};
  const WatchSettings watch{platens(), run.tolerance, WATCH_BUDGET * d50};
  double width = run.search_width;
  ChainResult results[2];
  for (int attempt = 0; attempt <= MAX_WIDENINGS && (pending[LEFT] || pending[RIGHT]); attempt++) {
    if (attempt > 0) {
      width = widened_band(width, d50);
      run.counters.widenings++;
    }
    gather.bands(platens(), width, active, sides);
    gather.search(finder, sides, pending, platens(), run.tolerance, results);
    for (int k = LEFT; k <= RIGHT; k++) {
      if (!pending[k]) continue;
      if (!results[k].ok) {
        if (attempt == MAX_WIDENINGS) chain_lost(k, results[k].failure);
        continue;
      }
      pending[k] = false;
      SideChain &s = chains[k];
      // how often a detection changes anything: what skipping detections would risk
      if (accept_chain(s, sides[k].band, results[k], watch_it ? &watch : nullptr))
        run.counters.changes++;
      if (automatic() && !watch_it) drop_watch(s);
    }
  }
  if (width > run.search_width) {
    run.search_width = width;
    run.force_detection = true;
  }
}

void FixMembrane2d::chain_lost(int k, const std::string &why)
{
  SideChain &s = chains[k];
  run.counters.failures++;
  s.watch.always = true; // search again at the next step
  const std::string where =
      std::string(side_name(k)) + " side at step " + std::to_string(update->ntimestep);
  if (s.chain_tags.empty()) fail(no_chain_error(where, why));
  if (!s.warned_lost) warn(chain_lost_warning(where, why));
  s.warned_lost = true;
}

void FixMembrane2d::gather_watched()
{
  watched = gather.watched(watch_list, chains, automatic(), sides);
}

// The chain disks of both sides (gathered this step with their types) wear the
// frictionless type, the disks that left the chains their own.
void FixMembrane2d::wear_chain_types()
{
  if (types.type() <= 0) return;
  std::map<AtomId, int> on;
  for (const MembraneSideData &s : sides)
    for (std::size_t c = 0; c < s.chain_disks.size(); c++)
      on.emplace(static_cast<AtomId>(s.chain_disks[c].tag), s.chain_types[c]);
  std::vector<AtomId> tags;
  std::vector<int> now;
  for (const auto &disk : on) {
    tags.push_back(disk.first);
    now.push_back(disk.second);
  }
  types.wear(tags, now);
}

void FixMembrane2d::post_force(int)
{
  const ScopedSeconds timing(gather.fix_seconds());
  // positions of the chain disks: gathered in pre_force (they do not move in between)
  for (int k = LEFT; k <= RIGHT; k++)
    if (chains[k].active)
      load_side(sides[k].chain_disks, chains[k].side, platens(), pressure, definition.thickness,
                loads[k]);
  atoms.add_forces(chains, sides, loads, pressure, definition.thickness);
  check_stability();
  atoms.flags(chains, vector_atom, flag_capacity);
  output_vector(chains, loads, run, platens(), pressure, watched.chain_step, vector_values);
  const bigint step = update->ntimestep;
  polyline.write(step, chains, sides, loads);
  if (vtk.due(step)) vtk.write(step, chains_vtk_frame(chains, sides, loads));
}

// the chain disks' step (bench/stability_sweep.md) and the inertial number
// of the loading: warned once each, the values stay in f_ID[15] and f_ID[16]
void FixMembrane2d::check_stability()
{
  const bigint step = update->ntimestep;
  if (watched.chain_step > CHAIN_STEP_LIMIT && !run.warned_chain_step) {
    run.warned_chain_step = true;
    warn(chain_step_warning(watched.chain_step_tag, watched.chain_step, step));
  }
  // p = the membrane pressure, the smaller principal stress: I is an upper bound
  const double limit = stability::INERTIAL_QUASI_STATIC;
  if (run.inertial.update(step, hi - lo, update->dt, INERTIAL_WINDOW, d50, density, pressure,
                          limit) &&
      !run.warned_inertial) {
    run.warned_inertial = true;
    warn(inertial_warning(run.inertial, limit, step, d50, density, pressure));
  }
}

// restart: see fix_membrane2d.h and membrane/membrane_fix.h
void FixMembrane2d::write_restart(FILE *fp)
{
  types.restore_for_restart();
  membrane::RunState saved = run;
  saved.checksum = group_checksum();
  write_restart_record(lmp, fp, membrane::write_record(definition, saved, chains));
}

void FixMembrane2d::restart(char *raw)
{
  bool same = false;
  const std::string why =
      read_record(reinterpret_cast<const double *>(raw), RestartRecordReader::UNKNOWN_LENGTH,
                  definition, same, run, chains);
  if (!why.empty()) fail(restart_unreadable(id, why, !same));
  if (!same) {
    warn(restart_other_definition(id));
    return;
  }
  state_kept = true;
  build_watch_list(chains, automatic(), watch_list);
}

double FixMembrane2d::memory_usage()
{
  double bytes = flag_capacity * sizeof(double);
  for (const MembraneSideData &s : sides)
    bytes += s.band.capacity() * sizeof(Disk) + s.chain_disks.capacity() * sizeof(Disk);
  return bytes + types.memory_usage();
}

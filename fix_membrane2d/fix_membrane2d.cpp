/* ----------------------------------------------------------------------
   fix membrane2d: see fix_membrane2d.h and doc/fix_membrane2d.md

   Every rank gathers the same side bands (membrane_gather.h) and holds the
   same chain search results, so the chain never depends on the number of
   ranks; forces are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane2d.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "contact_scales.h"
#include "frictionless_type.h"
#include "membrane_checks.h"
#include "membrane_output.h"
#include "membrane_record.h"
#include "stability_checks.h"
#include "style_args.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using namespace membrane;

namespace {

const char *const PREFIX = "Fix membrane2d: "; // every message starts so (doc/messages.md)

const char *const KEYWORDS[] = {"pressure",  "ylo",       "yhi",   "sides",        "band",
                                "tolerance", "thickness", "every", "frictionless", "polyline",
                                "vtk"};
const char *const USE_PRESSURE =
    "pressure P: the confining pressure (force/area), a number >= 0 or v_name";
const char *const USE_YLO = "ylo Y: the bottom platen surface (length), a number or v_name";
const char *const USE_YHI = "yhi Y: the top platen surface (length), a number or v_name";
const char *const USE_SIDES = "sides left|right|both";
const char *const USE_EVERY =
    "every auto|N: detect when the chain can have changed (auto) or every N >= 1 steps";
const std::string USE_BAND =
    "band W: the width of the side bands (length), default " + number_text(DEFAULT_BAND) + " x D50";
const std::string USE_TOLERANCE = "tolerance G: the largest gap (length) counted as a contact, "
                                  "default " +
                                  number_text(DEFAULT_TOLERANCE) + " x D50";

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane2d::FixMembrane2d(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), inputs("ylo", "yhi", USE_PRESSURE, USE_YLO, USE_YHI),
    frames(lammps, PREFIX),
    gather(lammps, PREFIX, groupbit), atoms(lammps), d50(0.0), density(0.0), pressure(0.0),
    ylo(0.0), yhi(0.0), flag_capacity(0)
{
  check_atom_setup(lmp, PREFIX);

  chains[LEFT].side = Side::Left;
  chains[RIGHT].side = Side::Right;
  chains[LEFT].active = chains[RIGHT].active = true;
  StyleArgs args(lmp, PREFIX, narg, arg, 3);
  while (args.more()) {
    const std::string key = args.keyword();
    if (inputs.read(args, key)) continue; // pressure, ylo, yhi
    if (key == "sides") {
      const int which = args.choice({"left", "right", "both"}, USE_SIDES);
      chains[LEFT].active = which != 1;
      chains[RIGHT].active = which != 0;
    } else if (key == "band") {
      definition.band_given = args.positive(USE_BAND);
    } else if (key == "tolerance") {
      definition.tolerance_given = args.non_negative(USE_TOLERANCE);
    } else if (key == "thickness") {
      definition.thickness =
          args.positive("thickness T: the out-of-plane thickness (length), default 1");
    } else if (key == "every") {
      const char *value = args.value(USE_EVERY);
      definition.detect_every =
          strcmp(value, "auto") == 0
              ? DETECT_AUTO
              : static_cast<int>(args.to_integer(value, 1, 1000000000L, USE_EVERY));
    } else if (key == "frictionless") {
      definition.frictionless_type =
          static_cast<int>(args.integer(1, atom->ntypes,
                                        "frictionless T: the atom type chain disks take (its "
                                        "coefficientFriction with every type is 0)"));
    } else if (key == "polyline" || key == "vtk") {
      frames.read(key, args, KEYWORDS, sizeof(KEYWORDS) / sizeof(KEYWORDS[0]));
    } else {
      std::string keywords;
      for (const char *k : KEYWORDS) keywords += (keywords.empty() ? "" : ", ") + std::string(k);
      args.unknown(keywords);
    }
  }
  inputs.require(args);
  definition.sides_mask = sides_mask();
  atoms.set_frictionless_type(definition.frictionless_type);

  vector_flag = 1;
  size_vector = OUTPUT_SIZE;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  restart_global = 1;
  restart_peratom = 1; // only to give chain disks their frictionless type back after packing
  atom->add_callback(1);
  vector_atom = nullptr;
  std::fill(vector_values, vector_values + OUTPUT_SIZE, 0.0);
}

FixMembrane2d::~FixMembrane2d()
{
  // after 'unfix' the chain disks are ordinary disks again, with their friction
  if (atom && atom->type) atoms.restore(chains);
  if (atom) atom->delete_callback(id, 1);
  memory->destroy(vector_atom);
}

int FixMembrane2d::setmask()
{
  return PRE_FORCE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::init()
{
  inputs.init(lmp, PREFIX);
  check_frictionless_type(lmp, PREFIX, definition.frictionless_type, style, "chain disks");
  check_other_membranes(lmp, PREFIX, this, gather);

  // D50 sets the default band width and gap tolerance; with the density, the inertial number
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty)
    error->all(FLERR, (std::string(PREFIX) + "the fix group '" + group->names[igroup] +
                       "' has no atoms; give it the sample's disks")
                          .c_str());
  d50 = grains.d50;
  density = grains.density;
  set_lengths(definition, d50, run);
  check_lengths(lmp, PREFIX, run.band_width, run.tolerance, d50);
  // chain disks are pushed by the membrane on top of their contacts: an
  // unstable chain shows first as escapes
  check_time_step(lmp, groupbit, world, PREFIX, stability::TIME_STEP_POORLY_RESOLVED, warned_dt);
}

void FixMembrane2d::evaluate_platens()
{
  ylo = inputs.lo.evaluate_checked(lmp, PREFIX, "ylo", false);
  yhi = inputs.hi.evaluate_checked(lmp, PREFIX, "yhi", false);
  check_platens_order(lmp, PREFIX, inputs.lo, ylo, yhi);
}

void FixMembrane2d::setup_pre_force(int vflag)
{
  evaluate_platens();
  check_platens_enclose(lmp, PREFIX, gather, inputs.lo, ylo, inputs.hi, yhi);
  gather.start_traffic(update->ntimestep, run.counters.detections);
  // the chains of the last run (or the restart file) still hold when no disk
  // of the group was created, deleted, renumbered, retyped or moved since
  // (this step's detection, if any, was then done in the last step of that run)
  const bool kept = state_kept && gather.group_checksum() == run.checksum;
  state_kept = false;
  if (kept) {
    gather_watched();
    atoms.apply(chains, sides);
    if (!platens_moved(run, Platens{ylo, yhi}, platen_move_limit(run, d50))) return;
    run.force_detection = true; // other platens (a restart, a jump): the kept chains the fallback
  } else {
    forget_state();
  }
  pre_force(vflag);
}

void FixMembrane2d::forget_state()
{
  atoms.restore(chains);
  atoms.forget();
  for (SideChain &s : chains) forget_chain(s);
  for (MembraneSideData &s : sides) s.chain_disks.clear();
  watch_list.clear();
  run.force_detection = true;
}

// end of a run: every disk gets its own type back (the next run, a
// write_data, an unfix or a run without this fix see the true sample)
void FixMembrane2d::post_run()
{
  atoms.restore(chains);
  run.checksum = gather.group_checksum();
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
  evaluate_platens();
  const bigint step = update->ntimestep;
  const bool unwatched = detect_auto() && unwatched_step(run, step);
  bool detect = run.force_detection || unwatched ||
                (!detect_auto() && (step % definition.detect_every == 0 ||
                                    platens_moved(run, Platens{ylo, yhi},
                                                  platen_move_limit(run, d50))));
  if (!detect) {
    gather_watched();
    detect =
        detect_auto() &&
        detection_needed(chains, Platens{ylo, yhi}, Platens{run.ylo_detected, run.yhi_detected},
                         run.tolerance, watched.band_displacement, WATCH_BUDGET * d50);
  }
  const bool watch = detect_auto() && !unwatched && !count_watched_step(run, step, detect);
  if (detect) {
    run.force_detection = false; // detect_chains() sets it again after widening the band
    detect_chains(watch);
    run.ylo_detected = ylo;
    run.yhi_detected = yhi;
    build_watch_list(chains, watch, watch_list);
    gather_watched(); // the new chain's positions and speeds
  }
  // after a run or a restart write the chain disks wear their own types
  if (!atoms.applied()) atoms.apply(chains, sides);
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
  const Platens platens{ylo, yhi};
  const WatchSettings watch{platens, run.tolerance, WATCH_BUDGET * d50};
  double width = run.search_width;
  ChainResult results[2];
  for (int attempt = 0; attempt <= MAX_WIDENINGS && (pending[LEFT] || pending[RIGHT]); attempt++) {
    if (attempt > 0) {
      width = widened_band(width, d50);
      run.counters.widenings++;
    }
    gather.bands(platens, width, active, sides);
    gather.search(finder, sides, pending, platens, run.tolerance, results);
    for (int k = LEFT; k <= RIGHT; k++) {
      if (!pending[k]) continue;
      if (!results[k].ok) {
        if (attempt == MAX_WIDENINGS) chain_lost(k, results[k].failure);
        continue;
      }
      pending[k] = false;
      SideChain &s = chains[k];
      const std::vector<long> old_tags = s.chain_tags.empty() ? s.forgotten_tags : s.chain_tags;
      // how often a detection changes anything: what skipping detections would risk
      if (accept_chain(s, sides[k].band, results[k], watch_it ? &watch : nullptr))
        run.counters.changes++;
      if (detect_auto() && !watch_it) drop_watch(s);
      atoms.change_chain(old_tags, s.chain_tags, results[k].chain, sides[k]);
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
  if (s.chain_tags.empty()) error->all(FLERR, (PREFIX + no_chain_error(where, why)).c_str());
  if (!s.warned_lost && comm->me == 0)
    error->warning(FLERR, (PREFIX + chain_lost_warning(where, why)).c_str());
  s.warned_lost = true;
}

void FixMembrane2d::gather_watched()
{
  watched = gather.watched(watch_list, chains, detect_auto(), sides);
}

void FixMembrane2d::post_force(int)
{
  const ScopedSeconds timing(gather.fix_seconds());
  pressure = inputs.pressure.evaluate_checked(lmp, PREFIX, "pressure", true);
  // positions of the chain disks: gathered in pre_force (they do not move in between)
  for (int k = LEFT; k <= RIGHT; k++)
    if (chains[k].active)
      load_side(sides[k].chain_disks, chains[k].side, Platens{ylo, yhi}, pressure,
                definition.thickness, loads[k]);
  atoms.add_forces(chains, sides, loads, pressure, definition.thickness);
  check_stability();
  atoms.flags(chains, vector_atom, flag_capacity);
  output_vector(chains, loads, run, Platens{ylo, yhi}, pressure, watched.chain_step, vector_values);
  frames.write(update->ntimestep, chains, sides, loads);
}

// the chain disks' step (bench/stability_sweep.md) and the inertial number
// of the loading: warned once each, the values stay in f_ID[15] and f_ID[16]
void FixMembrane2d::check_stability()
{
  const bigint step = update->ntimestep;
  if (watched.chain_step > CHAIN_STEP_LIMIT && !run.warned_chain_step) {
    run.warned_chain_step = true;
    if (comm->me == 0)
      error->warning(
          FLERR,
          (PREFIX + chain_step_warning(watched.chain_step_tag, watched.chain_step, step)).c_str());
  }
  // p = the membrane pressure, the smaller principal stress: I is an upper bound
  const double limit = stability::INERTIAL_QUASI_STATIC;
  if (run.inertial.update(step, yhi - ylo, update->dt, INERTIAL_WINDOW, d50, density, pressure,
                          limit) &&
      !run.warned_inertial) {
    run.warned_inertial = true;
    if (comm->me == 0)
      error->warning(
          FLERR,
          (PREFIX + inertial_warning(run.inertial, limit, step, d50, density, pressure)).c_str());
  }
}

// restart: see fix_membrane2d.h
void FixMembrane2d::write_restart(FILE *fp)
{
  atoms.restore_for_restart(chains);
  membrane::RunState saved = run;
  saved.checksum = gather.group_checksum();
  const std::vector<double> rec = write_record(definition, saved, chains);
  if (comm->me == 0) {
    const int size = static_cast<int>(rec.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(rec.data(), sizeof(double), rec.size(), fp);
  }
}

int FixMembrane2d::pack_restart(int i, double *buf)
{
  atoms.packed(i); // called after LIGGGHTS packed atom i with its own type
  buf[0] = 1;
  return 1;
}

void FixMembrane2d::restart(char *raw)
{
  bool same = false;
  const std::string why =
      read_record(reinterpret_cast<const double *>(raw), static_cast<size_t>(-1) / sizeof(double),
                  definition, same, run, chains);
  if (!why.empty()) error->all(FLERR, (PREFIX + restart_unreadable(id, why, !same)).c_str());
  if (!same) {
    if (comm->me == 0) error->warning(FLERR, (PREFIX + restart_other_definition(id)).c_str());
    return;
  }
  state_kept = true;
  build_watch_list(chains, detect_auto(), watch_list);
}

double FixMembrane2d::memory_usage()
{
  double bytes = flag_capacity * sizeof(double);
  for (const MembraneSideData &s : sides)
    bytes += s.band.capacity() * sizeof(Disk) + s.chain_disks.capacity() * sizeof(Disk);
  bytes += atoms.memory_usage();
  return bytes;
}

/* ----------------------------------------------------------------------
   fix membrane2d: see fix_membrane2d.h and doc/fix_membrane2d.md

   Every rank gathers the same side bands (membrane_gather.h) and holds the
   same chain search results, so the chain never depends on the number of
   ranks; forces are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane2d.h"

#include <algorithm>
#include <string>

#include "atom.h"
#include "comm.h"
#include "memory.h"
#include "update.h"

#include "contact_scales.h"
#include "membrane_output.h"
#include "membrane_record.h"
#include "membrane_step.h"
#include "membrane_vtk.h"
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
const char *const USE_POLYLINE = "polyline N FILE: write the chains every N >= 1 steps to FILE";

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane2d::FixMembrane2d(LAMMPS *lammps, int narg, char **arg)
  : MembraneFix(lammps, narg, arg, TRAITS), gather(lammps, prefix, groupbit)
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
      const long long every = args.integer(1, 1000000000L, USE_POLYLINE);
      const std::string file = frame_file_name(args, USE_POLYLINE, keywords);
      check_file_opened(lmp, prefix, "polyline", file, polyline.open(file, every, comm->me == 0));
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
  return {{"vtk", vtk.pvd()}, {"polyline", polyline.path()}};
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::init()
{
  init_shared();
  set_lengths(definition, d50, tolerance, run);
  const std::string band = band_problem(run.band_width, d50);
  if (!band.empty()) fail(keyword_text("band", number_text(run.band_width), band));
  // chain disks are pushed by the membrane on top of their contacts: an
  // unstable chain shows first as escapes
  check_time_step(lmp, groupbit, world, prefix, stability::TIME_STEP_POORLY_RESOLVED, warned_dt);
}

void FixMembrane2d::setup_pre_force(int vflag)
{
  evaluate_inputs();
  gather.check_enclosed(inputs.lo, platens.lo, inputs.hi, platens.hi);
  gather.start_traffic(update->ntimestep, run.counters.detections);
  // the chains of the last run (or the restart file) still hold when no disk
  // of the group was created, deleted, renumbered, retyped or moved since
  // (this step's detection, if any, was then done in the last step of that run)
  if (group_as_remembered()) {
    gather_watched();
    wear_chain_types();
    // other platens (a restart, a jump) or a step counter set back: detect now, the
    // kept chains the fallback
    if (!platens_moved(run, platens, platen_move_limit(run, d50)) &&
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
  for (SideData &s : sides) s.chain_disks.clear();
  watch_list.clear();
  run.force_detection = true;
}

// end of a run: every disk gets its own type back (the next run, a write_data,
// an unfix or a run without this fix see the true sample)
void FixMembrane2d::post_run()
{
  types.restore();
  remember_group(group_checksum());
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
  bool detect = on_any_rank(detection_due(run, shared, step, platens, d50));
  if (!detect) {
    gather_watched();
    // from what every rank gathered: the same on every rank
    detect = automatic() && detection_needed(chains, platens,
                                             Platens{run.ylo_detected, run.yhi_detected},
                                             run.tolerance, watched.band_displacement,
                                             WATCH_BUDGET * d50);
  }
  const bool watch = automatic() && !unwatched && !count_watched_step(run, step, detect);
  if (detect) {
    detect_chains(watch);
    gather_watched(); // the new chain's positions, speeds and types
    wear_chain_types();
  }
  // after a run or a restart write the chain disks wear their own types
  if (!types.applied()) wear_chain_types();
}

// a side whose chain is lost is searched again at the next step (membrane_step.h)
void FixMembrane2d::detect_chains(bool watch_it)
{
  const bool active[2] = {chains[LEFT].active, chains[RIGHT].active};
  const WatchSettings watch{platens, run.tolerance, WATCH_BUDGET * d50};
  auto search = [&](double width, const bool (&pending)[2], ChainResult (&results)[2]) {
    gather.bands(platens, width, active, sides);
    gather.search(finder, sides, pending, platens, run.tolerance, results);
  };
  for (const Notice &n : detect(chains, sides, run, watch_list, d50, automatic(),
                                watch_it ? &watch : nullptr, platens, update->ntimestep, search))
    n.fatal ? fail(n.text) : warn(n.text);
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
  std::vector<AtomId> tags;
  std::vector<int> now;
  chain_types(sides, tags, now);
  types.wear(tags, now);
}

void FixMembrane2d::post_force(int)
{
  const ScopedSeconds timing(gather.fix_seconds());
  // positions of the chain disks: gathered in pre_force (they do not move in between)
  for (int k = LEFT; k <= RIGHT; k++)
    if (chains[k].active)
      load_side(sides[k].chain_disks, chains[k].side, platens, pressure, definition.thickness,
                loads[k]);
  auto owned = [&](AtomId tag) { return gather.owned_index(tag); };
  add_forces(chains, sides, loads, pressure, definition.thickness, gather.local(), owned, atom->f);
  for (const std::string &w :
       stability_warnings(run, watched.chain_step, watched.chain_step_tag, update->ntimestep,
                          platens.hi - platens.lo, update->dt, d50, density, pressure))
    warn(w);
  if (atom->nmax > flag_capacity) {
    memory->destroy(vector_atom);
    flag_capacity = atom->nmax;
    memory->create(vector_atom, flag_capacity, "membrane2d:flag");
  }
  set_flags(chains, atom->nlocal, owned, vector_atom);
  output_vector(chains, loads, run, platens, pressure, watched.chain_step, vector_values);
  const bigint step = update->ntimestep;
  const std::string why = polyline.due(step) ? polyline.write(step, chains, sides, loads) : "";
  if (!why.empty()) style_error_one(lmp, prefix, keyword_text("polyline", polyline.path(), why));
  if (vtk.due(step)) vtk.write(step, chains_vtk_frame(chains, sides, loads));
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
  if (!why.empty()) fail(restart_unreadable(why, !same));
  if (!same) {
    warn(restart_other_definition("sides, frictionless, every, band, tolerance or thickness"));
    return;
  }
  remember_group(run.checksum);
  build_watch_list(chains, automatic(), watch_list);
}

double FixMembrane2d::memory_usage()
{
  double bytes = flag_capacity * sizeof(double);
  for (const SideData &s : sides)
    bytes += s.band.capacity() * sizeof(Disk) + s.chain_disks.capacity() * sizeof(Disk);
  return bytes + types.memory_usage();
}

/* ----------------------------------------------------------------------
   fix stability/guard: see fix_stability_guard.h and
   doc/fix_stability_guard.md

   Every check reduces its measures over all ranks first, so every rank
   takes the same decision and an error is raised by all of them at once
   (style_error): a failing check never leaves a rank waiting.
------------------------------------------------------------------------- */

#include "fix_stability_guard.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair.h"
#include "update.h"

#include "contact_scales.h"
#include "rank_choice.h"
#include "restart_envelope.h"
#include "scalar_input.h"
#include "style_args.h"
#include "style_error.h"

#include "stability_checks.h"
#include "stability_messages.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

constexpr double RECORD_MAGIC = 7.0e9 + 4871.0; // of this style's restart record
constexpr int RECORD_VERSION = 1;
constexpr std::size_t RECORD_LENGTH = 7; // magic, version, length and the 4 fields written

// The defaults (doc/fix_stability_guard.md, Default): the limits fix membrane2d
// shares come from stability_checks.h. A stricter 'move' than the blow-up
// fraction stops runs that need not be unstable; the default stops only those.
constexpr int DEFAULT_EVERY = 100;
constexpr double DEFAULT_MOVE = stability::STEP_FRACTION_BLOWN_UP;
constexpr double DEFAULT_OVERLAP = 0.1;
constexpr double DEFAULT_TIME_STEP = stability::TIME_STEP_POORLY_RESOLVED;
constexpr double DEFAULT_ILIMIT = stability::INERTIAL_QUASI_STATIC;
// The largest limits that keep each check meaningful (doc, Syntax): a particle
// that moves or overlaps by its radius is far beyond what the checks are for;
// above dt = 2 sqrt(m/k) velocity Verlet is unstable even for one contact; I > 1
// is a collisional flow.
constexpr long MAX_EVERY = 1000000000L;
constexpr double MAX_MOVE = 1.0;
constexpr double MAX_OVERLAP = 1.0;
constexpr double MAX_TIME_STEP = 2.0;
constexpr double MAX_ILIMIT = 1.0;

// "<what>, a number > 0 and <= <max> (<why the max>; default <default>)"
std::string limit_usage(const std::string &what, double max, double fallback,
                        const std::string &why_max = "")
{
  return what + ", a number > 0 and <= " + number_text(max) + " (" +
         (why_max.empty() ? "" : why_max + "; ") + "default " + number_text(fallback) + ")";
}

const std::string EVERY_USAGE =
    "every N, check every N steps (default " + std::to_string(DEFAULT_EVERY) + ")";
const std::string MOVE_USAGE =
    limit_usage("move F, stop the run when a particle moves more than F x its radius in one step",
                MAX_MOVE, DEFAULT_MOVE);
const std::string OVERLAP_USAGE =
    limit_usage("overlap F, warn when two particles overlap by more than F x the smaller radius",
                MAX_OVERLAP, DEFAULT_OVERLAP);
const std::string TIMESTEP_USAGE = limit_usage(
    "timestep F, warn when dt > F x sqrt(m_min/k_n)", MAX_TIME_STEP, DEFAULT_TIME_STEP,
    "velocity Verlet is unstable above " + number_text(MAX_TIME_STEP) + " even for one contact");
const std::string ILIMIT_USAGE =
    limit_usage("ilimit L, warn when the inertial number exceeds L", MAX_ILIMIT, DEFAULT_ILIMIT);
const std::string INERTIAL_USAGE =
    "inertial R P, the strain rate R >= 0 (1/time; use abs() for a signed rate) and the "
    "pressure P > 0 (force/area), each a number or v_name of an equal-style variable";

} // namespace

/* ---------------------------------------------------------------------- */

FixStabilityGuard::FixStabilityGuard(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), prefix(style_prefix("Fix", style, id)), move_limit(DEFAULT_MOVE),
    overlap_limit(DEFAULT_OVERLAP), time_step_limit(DEFAULT_TIME_STEP),
    inertial_limit(DEFAULT_ILIMIT), check_inertial(false), d50(0.0), density(0.0), natoms0(0),
    warned_overlap(false), warned_inertial(false), warnings(0)
{
  if (!atom->radius_flag)
    style_error(lmp, prefix,
                std::string("requires atom style sphere or granular (per-atom radius), not ") +
                    atom->atom_style + "; use atom_style granular");

  nevery = DEFAULT_EVERY;
  // the four limits are read alike: a number > 0 and <= the largest that is meaningful
  const struct {
    const char *key;
    const std::string &usage;
    double max;
    double &value;
  } limits[] = {{"move", MOVE_USAGE, MAX_MOVE, move_limit},
                {"overlap", OVERLAP_USAGE, MAX_OVERLAP, overlap_limit},
                {"timestep", TIMESTEP_USAGE, MAX_TIME_STEP, time_step_limit},
                {"ilimit", ILIMIT_USAGE, MAX_ILIMIT, inertial_limit}};
  std::string ilimit_text; // as written, when given
  StyleArgs args(lmp, prefix, narg, arg, 3);
  while (args.more()) {
    const std::string &key = args.keyword();
    const auto limit = std::find_if(std::begin(limits), std::end(limits),
                                    [&](const auto &l) { return key == l.key; });
    if (limit != std::end(limits)) {
      limit->value = args.number(limit->usage);
      if (!(limit->value > 0.0 && limit->value <= limit->max))
        args.bad("must be a number > 0 and <= " + number_text(limit->max), limit->usage);
      if (key == "ilimit") ilimit_text = args.current_value();
    } else if (key == "every") {
      nevery = static_cast<int>(args.integer(1, MAX_EVERY, EVERY_USAGE));
    } else if (key == "inertial") {
      // a variable's sign is checked whenever it is evaluated (check_inertial_number)
      rate_in.read(args, ScalarInput::Sign::NonNegative, INERTIAL_USAGE);
      pressure_in.read(args, ScalarInput::Sign::Positive, INERTIAL_USAGE);
      check_inertial = true;
    } else {
      args.unknown("every, move, overlap, timestep, inertial, ilimit");
    }
  }
  if (!ilimit_text.empty() && !check_inertial)
    style_error(lmp, prefix,
                keyword_text("ilimit", ilimit_text,
                             "has no effect without keyword 'inertial'; add inertial R P, or "
                             "leave ilimit out"));

  vector_flag = 1;
  restart_global = 1;
  size_vector = VECTOR_SIZE;
  global_freq = nevery;
  extvector = 0;
  std::fill(values, values + VECTOR_SIZE, 0.0);
}

int FixStabilityGuard::setmask()
{
  return END_OF_STEP;
}

void FixStabilityGuard::init()
{
  if (check_inertial) {
    rate_in.init(lmp, prefix, "inertial");
    pressure_in.init(lmp, prefix, "inertial");
  }
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty)
    style_error(lmp, prefix,
                std::string("the fix group '") + group->names[igroup] +
                    "' has no atoms; use a group with the particles to watch");
  d50 = grains.d50;
  density = grains.density;
  values[TIME_STEP_RATIO] =
      check_time_step(lmp, groupbit, world, prefix, time_step_limit, warned_dt);
}

/* ----------------------------------------------------------------------
   the atoms present at the start of each run are the ones to keep. The
   inertial number waits for the first step: wall forces that a pressure
   variable reads (fix mesh/surface/stress) are still zero during setup.
------------------------------------------------------------------------- */

void FixStabilityGuard::setup(int)
{
  maxtag0 = 0; // the atoms of the run: those of the group now, tags up to the largest
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) maxtag0 = std::max(maxtag0, atom->tag[i]);
  MPI_Allreduce(MPI_IN_PLACE, &maxtag0, 1, MPI_INT, MPI_MAX, world);
  natoms0 = count_group_atoms();
  run_checks(false, true);
  // what a variable of 'inertial' reads (a per-atom virial, say) is needed at the first check
  if (check_inertial) modify->addstep_compute_all((update->ntimestep / nevery + 1) * nevery);
}

void FixStabilityGuard::end_of_step()
{
  run_checks(check_inertial, false);
}

// the checks of the setup (at_start) and of every N steps; their measures are the output
void FixStabilityGuard::run_checks(bool inertial, bool at_start)
{
  values[STEP_FRACTION] = check_atoms(at_start);
  values[LOST] = static_cast<double>(check_lost_atoms());
  values[OVERLAP] = check_overlaps();
  if (inertial) values[INERTIAL] = check_inertial_number();
  values[WARNINGS] = warnings;
}

double FixStabilityGuard::compute_vector(int n)
{
  return values[n];
}

/* ----------------------------------------------------------------------
   restart: the warnings given (each is given once, and counted in f_ID[6]),
   so that a run continued from a restart file says and counts what one
   straight through does
------------------------------------------------------------------------- */

void FixStabilityGuard::write_restart(FILE *fp)
{
  RestartRecordWriter out(RECORD_MAGIC, RECORD_VERSION);
  for (double v : {static_cast<double>(warnings), warned_overlap ? 1.0 : 0.0,
                   warned_inertial ? 1.0 : 0.0, warned_dt})
    out.put(v);
  write_restart_record(lmp, fp, out.finish());
}

void FixStabilityGuard::restart(char *raw)
{
  RestartRecordReader in =
      read_restart_record(raw, RECORD_MAGIC, RECORD_VERSION, RECORD_VERSION, RECORD_LENGTH);
  warnings = static_cast<int>(in.get());
  warned_overlap = in.get() != 0.0;
  warned_inertial = in.get() != 0.0;
  warned_dt = in.get();
  if (!in.finished())
    style_error(lmp, prefix,
                std::string("the restart file's state of fix ") + id + " cannot be read: " +
                    in.error() + "; define this fix with another ID to start its checks afresh");
}

/* ----------------------------------------------------------------------
   non-finite values and particles that move a large fraction of their radius
   per step: the signature of an explicit integration that has blown up
   (the kinetic energy grows without bound); stop before it writes garbage.
   Returns the largest |v| dt / r.
------------------------------------------------------------------------- */

double FixStabilityGuard::check_atoms(bool at_start)
{
  const stability::AtomScan scan = stability::scan_atoms(
      static_cast<size_t>(atom->nlocal), atom->x, atom->v, atom->f, atom->radius, atom->mask,
      groupbit, update->dt, atom->rmass_flag ? atom->rmass : nullptr, atom->tag);
  const double dt_ratio = values[TIME_STEP_RATIO];

  // a radius or mass that is not a positive number: the input's fault, named first
  long bad_size = scan.bad_size;
  MPI_Allreduce(MPI_IN_PLACE, &bad_size, 1, MPI_LONG, MPI_SUM, world);
  const int ib = static_cast<int>(scan.first_bad_size);
  if (bad_size > 0) {
    double size[2] = {ib >= 0 ? atom->radius[ib] : 0.0,
                      ib >= 0 && atom->rmass_flag ? atom->rmass[ib] : 0.0};
    const int first = rank_choice::name_first(world, ib >= 0 ? atom->tag[ib] : LLONG_MAX, size, 2);
    style_error(lmp, prefix,
                stability::size_error(bad_size, update->ntimestep, first, size[0], size[1],
                                      atom->rmass_flag));
  }
  long nonfinite = scan.nonfinite;
  MPI_Allreduce(MPI_IN_PLACE, &nonfinite, 1, MPI_LONG, MPI_SUM, world);
  const int in = static_cast<int>(scan.first_nonfinite);
  if (nonfinite > 0) { // a non-finite position or velocity on any rank before a force
    const bool force_only = scan.first_kind == stability::NonFinite::Force;
    double kind = static_cast<double>(scan.first_kind);
    const int first = rank_choice::name_first(
        world, in >= 0 ? (force_only ? 1LL << 32 : 0LL) + atom->tag[in] : LLONG_MAX, &kind, 1);
    style_error(lmp, prefix,
                stability::nonfinite_error(
                    nonfinite, update->ntimestep, first, dt_ratio,
                    static_cast<stability::NonFinite>(static_cast<int>(kind)), at_start));
  }
  const rank_choice::ValueTag fastest = rank_choice::max_over_ranks(
      {scan.max_step_fraction, scan.argmax_step >= 0 ? atom->tag[scan.argmax_step] : 0}, world);
  const stability::StepVerdict verdict = stability::judge_step_fraction(fastest.value, move_limit);
  if (verdict != stability::StepVerdict::Within)
    style_error(lmp, prefix,
                stability::step_error(fastest.tag, fastest.value, update->ntimestep, move_limit,
                                      verdict, dt_ratio));
  return fastest.value;
}

/* ---------------------------------------------------------------------- */

// atoms inserted during the run (fix insert/*: larger tags) are not counted
bigint FixStabilityGuard::count_group_atoms()
{
  bigint n = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && atom->tag[i] <= maxtag0) n++;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return n;
}

/* ----------------------------------------------------------------------
   with 'thermo_modify lost ignore' LIGGGHTS drops atoms that leave a
   fixed boundary silently; a biaxial or triaxial sample must keep every particle.
   Atoms inserted since the setup neither hide a loss nor count as negative ones
------------------------------------------------------------------------- */

bigint FixStabilityGuard::check_lost_atoms()
{
  const bigint lost = natoms0 - count_group_atoms();
  if (lost > 0)
    style_error(lmp, prefix,
                stability::lost_error(lost, update->ntimestep, values[TIME_STEP_RATIO]));
  return lost;
}

/* ----------------------------------------------------------------------
   particle-particle overlaps over the pair style's neighbour list (current: it is
   rebuilt on reneighbouring and ghosts are updated every step); wall
   contacts are not in it. Returns the largest overlap / smaller radius.
------------------------------------------------------------------------- */

double FixStabilityGuard::check_overlaps()
{
  stability::OverlapScan scan;
  if (const NeighList *list = force->pair ? force->pair->list : nullptr)
    scan =
        stability::scan_overlaps(list->inum, list->ilist, list->numneigh, list->firstneigh,
                                 NEIGHMASK, atom->x, atom->radius, atom->mask, groupbit, atom->tag);
  const rank_choice::ValueTag worst =
      rank_choice::max_over_ranks({scan.max_fraction, scan.i >= 0 ? atom->tag[scan.i] : 0}, world);
  if (!stability::warn_once_now(worst.value, overlap_limit, warned_overlap)) return worst.value;
  // of the ranks with the largest overlap, the pair of the smallest tags
  double pair[2] = {scan.i >= 0 ? 1.0 * atom->tag[scan.i] : 0,
                    scan.j >= 0 ? 1.0 * atom->tag[scan.j] : 0};
  const bool mine = scan.i >= 0 && scan.max_fraction == worst.value;
  rank_choice::name_first(
      world,
      mine ? stability::pair_key(static_cast<int>(pair[0]), static_cast<int>(pair[1])) : LLONG_MAX,
      pair, 2);
  warned_overlap = true;
  warn(stability::overlap_warning(static_cast<int>(pair[0]), static_cast<int>(pair[1]), worst.value,
                                  update->ntimestep, overlap_limit, OVERLAP + 1));
  return worst.value;
}

/* ----------------------------------------------------------------------
   a variable may turn NaN, infinite, negative (R) or non-positive (P)
   mid-run, and a tiny P makes I overflow: each stops the run. Returns I.
------------------------------------------------------------------------- */

double FixStabilityGuard::check_inertial_number()
{
  const double rate = rate_in.evaluate(lmp);
  const double pressure = pressure_in.evaluate(lmp);
  modify->addstep_compute(update->ntimestep + nevery); // and at the next check
  const stability::InertialCheck inertial =
      stability::check_inertial_number(rate, pressure, d50, density);
  if (inertial.status == stability::InertialStatus::BadRate)
    bad_inertial_value(rate_in, rate, ">= 0 (the strain rate R)");
  if (inertial.status == stability::InertialStatus::BadPressure)
    bad_inertial_value(pressure_in, pressure, "> 0 (the pressure P)");
  if (inertial.status == stability::InertialStatus::Overflow)
    style_error(lmp, prefix,
                keyword_text("inertial", rate_in.text() + " " + pressure_in.text(),
                             stability::inertial_overflow(update->ntimestep, rate, pressure)));
  if (stability::warn_once_now(inertial.value, inertial_limit, warned_inertial)) {
    warned_inertial = true;
    warn(stability::inertial_warning(inertial.value, inertial_limit, update->ntimestep, rate, d50,
                                     density, domain->dimension, pressure, INERTIAL + 1));
  }
  return inertial.value;
}

// a variable of 'inertial R P' evaluated to a value it must not have
void FixStabilityGuard::bad_inertial_value(const ScalarInput &in, double value, const char *must)
{
  style_error(lmp, prefix,
              keyword_text("inertial", in.text(),
                           "is " + number_text(value) + " at step " +
                               std::to_string(update->ntimestep) + "; it must be a finite number " +
                               must));
}

void FixStabilityGuard::warn(const std::string &text)
{
  warnings++;
  style_warning(lmp, prefix, text);
}

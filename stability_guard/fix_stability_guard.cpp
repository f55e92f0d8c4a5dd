/* ----------------------------------------------------------------------
   fix stability/guard: see fix_stability_guard.h and
   doc/fix_stability_guard.md

   Every check reduces its measures over all ranks first, so every rank
   takes the same decision and an error is raised by all of them at once
   (error->all): a failing check never leaves a rank waiting.
------------------------------------------------------------------------- */

#include "fix_stability_guard.h"

#include <mpi.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "neigh_list.h"
#include "pair.h"
#include "update.h"

#include "contact_scales.h"
#include "restart_record.h"
#include "scalar_input.h"
#include "style_args.h"
#include "stability_checks.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const std::string PREFIX = "Fix stability/guard: ";
constexpr double RECORD_MAGIC = 7.0e9 + 4871.0; // of this style's restart record
constexpr int RECORD_VERSION = 1;
constexpr double SAFE_TIME_STEP_RATIO = 0.15;  // x sqrt(m_min/k_n), the published set-up
constexpr double BLOW_UP_STEP_FRACTION = 0.05; // |v| dt / r of a run that has blown up
std::string msg(const std::string &text)
{
  return PREFIX + text;
}

const char *const EVERY_USAGE = "every N, check every N steps (default 100)";
const char *const MOVE_USAGE =
    "move F, stop the run when a disk moves more than F x its radius in one step, "
    "a number > 0 and <= 1 (default 0.05)";
const char *const OVERLAP_USAGE =
    "overlap F, warn when two disks overlap by more than F x the smaller radius, "
    "a number > 0 and <= 1 (default 0.1)";
const char *const TIMESTEP_USAGE =
    "timestep F, warn when dt > F x sqrt(m_min/k_n), a number > 0 and <= 2 "
    "(velocity Verlet is unstable above 2 even for one contact; default 0.3)";
const char *const ILIMIT_USAGE =
    "ilimit L, warn when the inertial number exceeds L, a number > 0 and <= 1 (default 1e-3)";
const char *const INERTIAL_USAGE =
    "inertial R P, the strain rate R >= 0 (1/time; use abs() for a signed rate) and the "
    "pressure P > 0 (force/area), each a number or v_name of an equal-style variable";

// a value and the atom ID it belongs to, for MPI_MAXLOC over the ranks
struct ValueTag {
  double value;
  int tag;
};

ValueTag max_over_ranks(ValueTag local, MPI_Comm world)
{
  ValueTag global;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  return global;
}

} // namespace

/* ---------------------------------------------------------------------- */

FixStabilityGuard::FixStabilityGuard(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), move_limit(0.05), overlap_limit(0.1), time_step_limit(0.3),
    inertial_limit(1e-3), check_inertial(false), d50(0.0), density(0.0), natoms0(0),
    warned_overlap(false), warned_inertial(false), warnings(0)
{
  if (domain->dimension != 2)
    error->all(FLERR, msg("requires dimension 2 (this run has dimension " +
                          std::to_string(domain->dimension) + "); use dimension 2")
                          .c_str());
  if (!atom->radius_flag)
    error->all(FLERR, msg(std::string("requires atom style sphere or granular (per-atom radius), "
                                      "not ") +
                          atom->atom_style + "; use atom_style granular")
                          .c_str());

  nevery = 100;
  std::string ilimit_text; // as written, when given
  StyleArgs args(lmp, PREFIX, narg, arg, 3);
  // a limit that is a number > 0 and <= hi
  auto limit = [&](const char *usage, double hi) {
    const double v = args.number(usage);
    if (!(v > 0.0 && v <= hi)) args.bad("must be a number > 0 and <= " + number_text(hi), usage);
    return v;
  };
  while (args.more()) {
    const std::string &key = args.keyword();
    if (key == "every") {
      nevery = static_cast<int>(args.integer(1, 1000000000L, EVERY_USAGE));
    } else if (key == "move") {
      move_limit = limit(MOVE_USAGE, 1.0);
    } else if (key == "overlap") {
      overlap_limit = limit(OVERLAP_USAGE, 1.0);
    } else if (key == "timestep") {
      time_step_limit = limit(TIMESTEP_USAGE, 2.0);
    } else if (key == "ilimit") {
      inertial_limit = limit(ILIMIT_USAGE, 1.0);
      ilimit_text = args.current_value();
    } else if (key == "inertial") {
      parse_inertial_value(args, rate_in, false);
      parse_inertial_value(args, pressure_in, true);
      check_inertial = true;
    } else {
      args.unknown("every, move, overlap, timestep, inertial, ilimit");
    }
  }
  if (!ilimit_text.empty() && !check_inertial)
    error->all(FLERR, keyword_message(PREFIX, "ilimit", ilimit_text,
                                      "has no effect without keyword 'inertial'; add inertial R P, "
                                      "or leave ilimit out")
                          .c_str());

  vector_flag = 1;
  restart_global = 1;
  size_vector = VECTOR_SIZE;
  global_freq = nevery;
  extvector = 0;
  std::fill(values, values + VECTOR_SIZE, 0.0);
}

/* ----------------------------------------------------------------------
   one value of 'inertial R P': a number (checked here: R >= 0, P > 0, both
   finite) or v_name (checked whenever it is evaluated)
------------------------------------------------------------------------- */

void FixStabilityGuard::parse_inertial_value(StyleArgs &args, ScalarInput &in, bool positive)
{
  const std::string text = args.value(INERTIAL_USAGE);
  if (text.compare(0, 2, "v_") == 0) {
    if (text.size() == 2) args.bad("names no variable", INERTIAL_USAGE);
  } else {
    char *end = nullptr;
    const double v = strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') args.bad("is not a number or v_name", INERTIAL_USAGE);
    if (!std::isfinite(v)) args.bad("must be finite", INERTIAL_USAGE);
    if (positive && !(v > 0.0))
      args.bad("must be a positive number (the pressure P)", INERTIAL_USAGE);
    if (!positive && !(v >= 0.0))
      args.bad("must be a number >= 0 (the strain rate R)", INERTIAL_USAGE);
  }
  in.parse(lmp, PREFIX, "inertial", text.c_str());
}

/* ---------------------------------------------------------------------- */

int FixStabilityGuard::setmask()
{
  return END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::init()
{
  if (check_inertial) {
    rate_in.init(lmp, PREFIX, "inertial");
    pressure_in.init(lmp, PREFIX, "inertial");
  }
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty)
    error->all(FLERR, msg(std::string("the fix group '") + group->names[igroup] +
                          "' has no atoms; use a group with the disks to watch")
                          .c_str());
  d50 = grains.d50;
  density = grains.density;
  values[TIME_STEP_RATIO] =
      check_time_step(lmp, groupbit, world, PREFIX, time_step_limit, warned_dt);
}

/* ----------------------------------------------------------------------
   the atoms present at the start of each run are the ones to keep. The
   inertial number waits for the first step: wall forces that a pressure
   variable reads (fix mesh/surface/stress) are still zero during setup.
------------------------------------------------------------------------- */

void FixStabilityGuard::setup(int)
{
  natoms0 = count_group_atoms();
  check_atoms();
  check_lost_atoms();
  check_overlaps();
  values[WARNINGS] = warnings;
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::end_of_step()
{
  check_atoms();
  check_lost_atoms();
  check_overlaps();
  if (check_inertial) check_inertial_number();
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
  const std::vector<double> &rec = out.finish();
  if (comm->me != 0) return;
  const int size = static_cast<int>(rec.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(rec.data(), sizeof(double), rec.size(), fp);
}

void FixStabilityGuard::restart(char *raw)
{
  RestartRecordReader in(reinterpret_cast<const double *>(raw), 7, RECORD_MAGIC, RECORD_VERSION);
  warnings = static_cast<int>(in.get());
  warned_overlap = in.get() != 0.0;
  warned_inertial = in.get() != 0.0;
  warned_dt = in.get();
  if (!in.finished())
    error->all(FLERR, msg(std::string("the restart file's state of fix ") + id +
                          " cannot be read: " + in.error() +
                          "; define this fix with another ID to start its checks afresh")
                          .c_str());
}

/* ----------------------------------------------------------------------
   non-finite values and disks that move a large fraction of their radius
   per step: the signature of an explicit integration that has blown up
   (the kinetic energy grows without bound); stop before it writes garbage
------------------------------------------------------------------------- */

void FixStabilityGuard::check_atoms()
{
  const stability::AtomScan scan =
      stability::scan_atoms(static_cast<size_t>(atom->nlocal), atom->x, atom->v, atom->f,
                            atom->radius, atom->mask, groupbit, update->dt);

  long nonfinite = scan.nonfinite;
  MPI_Allreduce(MPI_IN_PLACE, &nonfinite, 1, MPI_LONG, MPI_SUM, world);
  if (nonfinite > 0) {
    int first = scan.first_nonfinite >= 0 ? atom->tag[scan.first_nonfinite] : INT_MAX;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, world);
    error->all(FLERR,
               msg(std::to_string(nonfinite) +
                   " atom(s) have a non-finite position, velocity or "
                   "force at step " +
                   std::to_string(update->ntimestep) + " (first: atom " + std::to_string(first) +
                   "): the run has gone unstable; " + unstable_hint())
                   .c_str());
  }

  const ValueTag local{scan.max_step_fraction,
                       scan.argmax_step >= 0 ? atom->tag[scan.argmax_step] : 0};
  const ValueTag fastest = max_over_ranks(local, world);
  values[STEP_FRACTION] = fastest.value;
  if (fastest.value > move_limit) {
    // a blown-up run moves disks > 5 % of their radius per step (bench/stability_sweep.md);
    // a stricter 'move' stops slower ones, which need not be unstable
    const bool blown_up = fastest.value > BLOW_UP_STEP_FRACTION;
    char buf[768];
    snprintf(buf, sizeof(buf),
             "atom %d moved %.3g of its radius in one step at step " BIGINT_FORMAT
             " (limit %g; a quasi-static test moves disks < 0.001): %s; %s",
             fastest.tag, fastest.value, update->ntimestep, move_limit,
             blown_up ? "the run has gone unstable (kinetic energy blow-up)"
                      : "faster than 'move' allows (unstable runs move disks > 0.05)",
             unstable_hint().c_str());
    error->all(FLERR, msg(buf).c_str());
  }
}

// what to change, for the errors of an unstable run (worded only when one is
// raised): the time step only when it is above the safe 0.15 x sqrt(m_min/k_n)
std::string FixStabilityGuard::unstable_hint() const
{
  const double dt_ratio = values[TIME_STEP_RATIO];
  char hint[320];
  if (!(dt_ratio > 0.0))
    snprintf(hint, sizeof(hint),
             "reduce the servo gain or the loading rate, or the time step if "
             "it is above %g x sqrt(m_min/k_n) (not checked: no kn peratomtypepair table)",
             SAFE_TIME_STEP_RATIO);
  else if (dt_ratio > SAFE_TIME_STEP_RATIO)
    snprintf(hint, sizeof(hint),
             "reduce the time step (now %.3g x sqrt(m_min/k_n); %g is safe), "
             "the servo gain or the loading rate",
             dt_ratio, SAFE_TIME_STEP_RATIO);
  else
    snprintf(hint, sizeof(hint),
             "the time step is safe (%.3g x sqrt(m_min/k_n), at most %g): "
             "reduce the servo gain or the loading rate",
             dt_ratio, SAFE_TIME_STEP_RATIO);
  return hint;
}

/* ---------------------------------------------------------------------- */

bigint FixStabilityGuard::count_group_atoms()
{
  bigint n = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) n++;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return n;
}

/* ----------------------------------------------------------------------
   with 'thermo_modify lost ignore' LIGGGHTS drops atoms that leave a
   fixed boundary silently; a biaxial sample must keep every disk
------------------------------------------------------------------------- */

void FixStabilityGuard::check_lost_atoms()
{
  const bigint lost = natoms0 - count_group_atoms();
  values[LOST] = static_cast<double>(lost);
  if (lost > 0)
    error->all(FLERR,
               msg(std::to_string(lost) +
                   " atom(s) of the group were lost since the start of the "
                   "run (at step " +
                   std::to_string(update->ntimestep) +
                   "): disks left the box "
                   "through a wall or the membrane; check that walls and platens enclose the "
                   "sample, and " +
                   unstable_hint())
                   .c_str());
}

/* ----------------------------------------------------------------------
   disk-disk overlaps over the pair style's neighbour list (current: it is
   rebuilt on reneighbouring and ghosts are updated every step); wall
   contacts are not in it
------------------------------------------------------------------------- */

void FixStabilityGuard::check_overlaps()
{
  ValueTag local{0.0, 0};
  int partner = 0;
  const NeighList *list = force->pair ? force->pair->list : nullptr;
  if (list) {
    double **x = atom->x;
    const double *radius = atom->radius;
    const int *mask = atom->mask;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      if (!(mask[i] & groupbit)) continue;
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if (!(mask[j] & groupbit)) continue;
        const double frac =
            stability::overlap_fraction(x[i][0] - x[j][0], x[i][1] - x[j][1], radius[i], radius[j]);
        if (frac > local.value) {
          local = {frac, atom->tag[i]};
          partner = atom->tag[j];
        }
      }
    }
  }
  const ValueTag worst = max_over_ranks(local, world);
  values[OVERLAP] = worst.value;
  if (worst.value <= overlap_limit || warned_overlap) return;
  // the partner lives on the rank that found the maximum (lowest such rank)
  int me_has = local.value == worst.value && local.tag == worst.tag ? comm->me : comm->nprocs;
  MPI_Allreduce(MPI_IN_PLACE, &me_has, 1, MPI_INT, MPI_MIN, world);
  MPI_Bcast(&partner, 1, MPI_INT, me_has, world);
  warned_overlap = true;
  char buf[512];
  snprintf(buf, sizeof(buf),
           "atoms %d and %d overlap by %.3g of the smaller radius at step " BIGINT_FORMAT
           " (limit %g): contacts this soft change the fabric and the volume; raise the contact "
           "stiffness (e.g. k_n >= 1000 x the mean stress x unit thickness) or lower the pressure "
           "(warned once; f_ID[2] is the current value)",
           std::min(worst.tag, partner), std::max(worst.tag, partner), worst.value,
           update->ntimestep, overlap_limit);
  warn(buf);
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::check_inertial_number()
{
  // a variable may turn NaN, infinite, negative (R) or non-positive (P) mid-run
  const double rate = rate_in.evaluate(lmp);
  if (!(std::isfinite(rate) && rate >= 0.0))
    bad_inertial_value(rate_in, rate, ">= 0 (the strain rate R)");
  const double pressure = pressure_in.evaluate(lmp);
  if (!(std::isfinite(pressure) && pressure > 0.0))
    bad_inertial_value(pressure_in, pressure, "> 0 (the pressure P)");
  const double inertial = stability::inertial_number(rate, d50, density, pressure);
  if (!std::isfinite(inertial))
    error->all(FLERR, keyword_message(PREFIX, "inertial", rate_in.text() + " " + pressure_in.text(),
                                      "the inertial number overflows at step " +
                                          std::to_string(update->ntimestep) + " (R = " +
                                          number_text(rate) + ", P = " + number_text(pressure) +
                                          "); the pressure is too "
                                          "small for the rate")
                          .c_str());
  values[INERTIAL] = inertial;
  if (inertial <= inertial_limit || warned_inertial) return;
  warned_inertial = true;
  char buf[512];
  snprintf(
      buf, sizeof(buf),
      "inertial number I = %.3g > %g at step " BIGINT_FORMAT " (strain rate %.3g 1/s, d50 %.3g m, "
      "density %.3g kg/m^2 per unit thickness, pressure %.3g Pa): the test is not quasi-static; "
      "lower the loading rate (warned once; f_ID[4] is the current value)",
      inertial, inertial_limit, update->ntimestep, rate, d50, density, pressure);
  warn(buf);
}

// a variable of 'inertial R P' evaluated to a value it must not have
void FixStabilityGuard::bad_inertial_value(const ScalarInput &in, double value, const char *must)
{
  error->all(FLERR, keyword_message(PREFIX, "inertial", in.text(),
                                    "is " + number_text(value) + " at step " +
                                        std::to_string(update->ntimestep) +
                                        "; it must be a finite number " + must)
                        .c_str());
  std::abort(); // Error::all does not return; tells the compiler so
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::warn(const std::string &text)
{
  warnings++;
  if (comm->me == 0) error->warning(FLERR, msg(text).c_str());
}

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
#include "neigh_list.h"
#include "pair.h"
#include "update.h"

#include "contact_scales.h"
#include "stability_checks.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const std::string PREFIX = "Fix stability/guard: ";
constexpr double SAFE_TIME_STEP_RATIO = 0.15;   // x sqrt(m_min/k_n), the published set-up
constexpr double BLOW_UP_STEP_FRACTION = 0.05;  // |v| dt / r of a run that has blown up
std::string msg(const std::string &text) { return PREFIX + text; }

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

}  // namespace

/* ---------------------------------------------------------------------- */

FixStabilityGuard::FixStabilityGuard(LAMMPS *lammps, int narg, char **arg) :
  Fix(lammps, narg, arg),
  move_limit(0.05), overlap_limit(0.1), time_step_limit(0.3), inertial_limit(1e-3),
  check_inertial(false), d50(0.0), density(0.0), natoms0(0),
  warned_overlap(false), warned_inertial(false), warnings(0)
{
  if (domain->dimension != 2) error->all(FLERR, msg("requires dimension 2").c_str());
  if (!atom->radius_flag) error->all(FLERR, msg("requires atom style sphere (granular)").c_str());

  nevery = 100;
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, msg("keyword '" + key + "' needs a value").c_str());
    const std::string value = arg[iarg + 1];
    auto positive_number = [&]() {
      char *end = nullptr;
      const double v = strtod(value.c_str(), &end);
      if (value.empty() || *end != '\0' || !(v > 0.0) || !std::isfinite(v))
        error->all(FLERR, msg(key + " must be a positive number, got '" + value + "'").c_str());
      return v;
    };
    if (key == "every") {
      char *end = nullptr;
      const long n = strtol(value.c_str(), &end, 10);
      if (value.empty() || *end != '\0' || n < 1 || n > 1000000000L)
        error->all(FLERR, msg("every must be an integer >= 1, got '" + value + "'").c_str());
      nevery = static_cast<int>(n);
    } else if (key == "move") {
      move_limit = positive_number();
    } else if (key == "overlap") {
      overlap_limit = positive_number();
    } else if (key == "timestep") {
      time_step_limit = positive_number();
    } else if (key == "ilimit") {
      inertial_limit = positive_number();
    } else if (key == "inertial") {
      if (iarg + 2 >= narg)
        error->all(FLERR, msg("inertial needs a strain rate and a pressure (numbers or v_name)").c_str());
      rate_in.parse(lmp, PREFIX, "the inertial strain rate", arg[iarg + 1]);
      pressure_in.parse(lmp, PREFIX, "the inertial pressure", arg[iarg + 2]);
      check_inertial = true;
      iarg++;
    } else {
      error->all(FLERR, msg("unknown keyword '" + key +
                            "' (expected every, move, overlap, timestep, inertial or ilimit)").c_str());
    }
    iarg += 2;
  }

  vector_flag = 1;
  size_vector = VECTOR_SIZE;
  global_freq = nevery;
  extvector = 0;
  std::fill(values, values + VECTOR_SIZE, 0.0);
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
    rate_in.init(lmp, PREFIX, "the inertial strain rate");
    pressure_in.init(lmp, PREFIX, "the inertial pressure");
  }
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty) error->all(FLERR, msg("the fix group has no atoms").c_str());
  d50 = grains.d50;
  density = grains.density;
  values[TIME_STEP_RATIO] = check_time_step(lmp, groupbit, world, PREFIX, time_step_limit, warned_dt);
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
   non-finite values and disks that move a large fraction of their radius
   per step: the signature of an explicit integration that has blown up
   (the kinetic energy grows without bound); stop before it writes garbage
------------------------------------------------------------------------- */

void FixStabilityGuard::check_atoms()
{
  const stability::AtomScan scan = stability::scan_atoms(
      static_cast<size_t>(atom->nlocal), atom->x, atom->v, atom->f, atom->radius, atom->mask,
      groupbit, update->dt);

  long nonfinite = scan.nonfinite;
  MPI_Allreduce(MPI_IN_PLACE, &nonfinite, 1, MPI_LONG, MPI_SUM, world);
  if (nonfinite > 0) {
    int first = scan.first_nonfinite >= 0 ? atom->tag[scan.first_nonfinite] : INT_MAX;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, world);
    error->all(FLERR, msg(std::to_string(nonfinite) + " atom(s) have a non-finite position, velocity or "
                          "force at step " + std::to_string(update->ntimestep) + " (first: atom " +
                          std::to_string(first) + "): the run has gone unstable; " + unstable_hint()).c_str());
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
             " (limit %g; a quasi-static test moves disks < 0.001): %s; %s", fastest.tag,
             fastest.value, update->ntimestep, move_limit,
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
    snprintf(hint, sizeof(hint), "reduce the servo gain or the loading rate, or the time step if "
             "it is above %g x sqrt(m_min/k_n) (not checked: no kn peratomtypepair table)",
             SAFE_TIME_STEP_RATIO);
  else if (dt_ratio > SAFE_TIME_STEP_RATIO)
    snprintf(hint, sizeof(hint), "reduce the time step (now %.3g x sqrt(m_min/k_n); %g is safe), "
             "the servo gain or the loading rate", dt_ratio, SAFE_TIME_STEP_RATIO);
  else
    snprintf(hint, sizeof(hint), "the time step is safe (%.3g x sqrt(m_min/k_n), at most %g): "
             "reduce the servo gain or the loading rate", dt_ratio, SAFE_TIME_STEP_RATIO);
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
    error->all(FLERR, msg(std::to_string(lost) + " atom(s) of the group were lost since the start of the "
                          "run (at step " + std::to_string(update->ntimestep) + "): disks left the box "
                          "through a wall or the membrane; check that walls and platens enclose the "
                          "sample, and " + unstable_hint()).c_str());
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
        const double frac = stability::overlap_fraction(x[i][0] - x[j][0], x[i][1] - x[j][1],
                                                        radius[i], radius[j]);
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
           std::min(worst.tag, partner), std::max(worst.tag, partner), worst.value, update->ntimestep,
           overlap_limit);
  warn(buf);
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::check_inertial_number()
{
  const double rate = rate_in.evaluate(lmp);
  const double pressure = pressure_in.evaluate(lmp);
  const double inertial = stability::inertial_number(rate, d50, density, pressure);
  values[INERTIAL] = inertial;
  if (inertial <= inertial_limit || warned_inertial) return;
  warned_inertial = true;
  char buf[512];
  snprintf(buf, sizeof(buf),
           "inertial number I = %.3g > %g at step " BIGINT_FORMAT " (strain rate %.3g 1/s, d50 %.3g m, "
           "density %.3g kg/m^2 per unit thickness, pressure %.3g Pa): the test is not quasi-static; "
           "lower the loading rate (warned once; f_ID[4] is the current value)",
           inertial, inertial_limit, update->ntimestep, rate, d50, density, pressure);
  warn(buf);
}

/* ---------------------------------------------------------------------- */

void FixStabilityGuard::warn(const std::string &text)
{
  warnings++;
  if (comm->me == 0) error->warning(FLERR, msg(text).c_str());
}

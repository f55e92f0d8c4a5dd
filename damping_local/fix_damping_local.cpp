/* ----------------------------------------------------------------------
   fix damping/local: see fix_damping_local.h and doc/fix_damping_local.md
------------------------------------------------------------------------- */

#include "fix_damping_local.h"

#include <mpi.h>

#include <cstring>
#include <string>

#include "atom.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include "damping_order.h"
#include "local_damping.h"
#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// alpha < 1: a force that drives the motion is reduced to (1 - alpha) of its
// size, so at 1 nothing would ever accelerate. alpha has no default; PFC's is
// quoted to the user.
constexpr double MAX_ALPHA = 1.0;
constexpr double PFC_ALPHA = 0.7;
constexpr bool DEFAULT_TORQUE = true;

const std::string ALPHA_USAGE = "alpha A, the local damping coefficient, a number >= 0 and < " +
                                number_text(MAX_ALPHA) + " (PFC's default is " +
                                number_text(PFC_ALPHA) + ")";
const std::string TORQUE_USAGE =
    std::string("torque yes or no, damp the torque as well (default ") +
    (DEFAULT_TORQUE ? "yes" : "no") + ")";

} // namespace

/* ---------------------------------------------------------------------- */

FixDampingLocal::FixDampingLocal(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), prefix(style_prefix("Fix", style, id)), alpha(0.0),
    damp_torque(DEFAULT_TORQUE), damping_force(nullptr)
{
  peratom_flag = 1; // the damping force F_d of the step, per atom
  size_peratom_cols = 3;
  peratom_freq = 1;
  create_attribute = 1; // set_arrays: an atom created between runs has F_d = 0

  // without rotational degrees of freedom the default 'torque yes' has nothing to do
  const bool has_rotation = atom->torque_flag && atom->omega_flag;
  bool have_alpha = false, torque_given = false;
  StyleArgs args(lmp, prefix, narg, arg, 3);
  while (args.more()) {
    const std::string &key = args.keyword();
    if (key == "alpha") {
      alpha = args.number(ALPHA_USAGE);
      if (!(alpha >= 0.0 && alpha < MAX_ALPHA))
        args.bad("must be a number >= 0 and < " + number_text(MAX_ALPHA), ALPHA_USAGE);
      have_alpha = true;
    } else if (key == "torque") {
      damp_torque = args.yes_no(TORQUE_USAGE);
      if (damp_torque && !has_rotation)
        args.bad("the atom style has no per-atom torque and angular velocity to damp "
                 "(atom style sphere or granular has them)",
                 "use torque no, or leave it out");
      torque_given = true;
    } else {
      args.unknown("alpha, torque");
    }
  }
  if (!have_alpha) args.required("alpha", ALPHA_USAGE);
  if (!torque_given && !has_rotation) damp_torque = false;

  grow_arrays(atom->nmax);
  atom->add_callback(0);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

/* ---------------------------------------------------------------------- */

FixDampingLocal::~FixDampingLocal()
{
  atom->delete_callback(id, 0);
  memory->destroy(damping_force);
}

/* ---------------------------------------------------------------------- */

int FixDampingLocal::setmask()
{
  return POST_FORCE;
}

/* ----------------------------------------------------------------------
   Forces that fixes defined after this one add in post_force to atoms of
   this group are not damped, and a later fix damping/local on the same
   atoms damps them twice: warn once per such fix. Every rank takes part
   (the groups' common atoms are counted over the ranks); rank 0 words it.
------------------------------------------------------------------------- */

void FixDampingLocal::init()
{
  if (strstr(update->integrate_style, "verlet") == nullptr)
    style_error(lmp, prefix,
                std::string("works with run_style verlet only, not ") + update->integrate_style +
                    "; use run_style verlet");

  int self = -1;
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i] == this) self = i;
  for (int i = self + 1; i < modify->nfix; i++) {
    const Fix *other = modify->fix[i];
    if (!(modify->fmask[i] & POST_FORCE) || damping::adds_no_force(other->style)) continue;
    if (warned_order.count(other->id)) continue;
    long common = 0;
    for (int j = 0; j < atom->nlocal; j++)
      if ((atom->mask[j] & groupbit) && (atom->mask[j] & other->groupbit)) common++;
    MPI_Allreduce(MPI_IN_PLACE, &common, 1, MPI_LONG, MPI_SUM, world);
    if (common == 0) continue;
    warned_order.insert(other->id);
    style_warning(lmp, prefix, damping::order_warning(id, style, other->id, other->style, common));
  }
}

/* ----------------------------------------------------------------------
   the forces of the setup step are integrated in the first half step of
   the run, so they are damped too (Modify::setup calls setup() of every
   fix in definition order, like post_force)
------------------------------------------------------------------------- */

void FixDampingLocal::setup(int vflag)
{
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   v here is the half-step velocity v(t + dt/2) of velocity Verlet: the
   only velocity there is when the forces at t + dt are known
------------------------------------------------------------------------- */

void FixDampingLocal::post_force(int)
{
  double **f = atom->f;
  double **v = atom->v;
  int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  for (int i = 0; i < nlocal; i++) {
    double *fd = damping_force[i];
    fd[0] = fd[1] = fd[2] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    damping::local_damping_force(f[i], v[i], 3, alpha, fd);
    for (int k = 0; k < 3; k++) f[i][k] += fd[k];
  }

  if (!damp_torque) return;
  double **torque = atom->torque;
  double **omega = atom->omega;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) damping::apply_local_damping(torque[i], omega[i], 3, alpha);
}

/* ---------------------------------------------------------------------- */

double FixDampingLocal::memory_usage()
{
  return 3.0 * atom->nmax * sizeof(double);
}

/* ----------------------------------------------------------------------
   the per-atom array, kept by LIGGGHTS with the atoms (rows up to nmax)
------------------------------------------------------------------------- */

void FixDampingLocal::grow_arrays(int nmax)
{
  memory->grow(damping_force, nmax, 3, "damping/local:damping_force");
  array_atom = damping_force;
}

void FixDampingLocal::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < 3; k++) damping_force[j][k] = damping_force[i][k];
}

void FixDampingLocal::set_arrays(int i)
{
  damping_force[i][0] = damping_force[i][1] = damping_force[i][2] = 0.0;
}

int FixDampingLocal::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) buf[k] = damping_force[i][k];
  return 3;
}

int FixDampingLocal::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) damping_force[nlocal][k] = buf[k];
  return 3;
}

#include "membrane_fix.h"

#include <mpi.h>

#include <cstring>

#include "atom.h"
#include "comm.h"
#include "group.h"

#include "contact_scales.h"
#include "group_checksum.h"
#include "membrane_checks.h"
#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char *const USE_PRESSURE =
    "pressure P: the confining pressure (force/area), a number >= 0 or v_name";
const char *const USE_EVERY = "every auto|N: find the membrane again when it can have changed "
                              "(auto) or N >= 1 steps after the last time";
const char *const USE_FRICTIONLESS = "frictionless T: the atom type membrane particles take (its "
                                     "friction with every type 0), or 0 for none";

std::string use_tolerance(double usual)
{
  return "tolerance G: the largest gap (length) counted as a contact, default " +
         number_text(usual) + " x D50";
}

} // namespace

MembraneFix::MembraneFix(LAMMPS *lammps, int narg, char **arg, const MembraneTraits &t)
  : Fix(lammps, narg, arg), traits(t), prefix(style_prefix("Fix", arg[2], arg[0])),
    inputs(t.lo_key, t.hi_key, USE_PRESSURE, t.lo_usage, t.hi_usage), vtk(lammps, prefix),
    types(lammps)
{
  check_membrane_setup(lmp, prefix, traits.dimension);
  vector_flag = 1;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

MembraneFix::~MembraneFix()
{
  // after 'unfix' the membrane particles are ordinary ones again, with their friction
  if (atom && atom->type) types.restore();
  if (atom && types.type() > 0) atom->delete_callback(id, 1);
}

int MembraneFix::setmask()
{
  return PRE_FORCE | POST_FORCE;
}

void MembraneFix::parse(int narg, char **arg, const std::vector<std::string> &own_keywords,
                        const OwnKeyword &own)
{
  keywords_ = {"pressure", traits.lo_key, traits.hi_key, "tolerance", "every", "frictionless",
               "vtk"};
  keywords_.insert(keywords_.end(), own_keywords.begin(), own_keywords.end());
  StyleArgs args(lmp, prefix, narg, arg, 3);
  while (args.more()) {
    const std::string key = args.keyword();
    if (inputs.read(args, key)) continue; // pressure and the platens
    if (key == "tolerance") {
      shared.tolerance_given = args.non_negative(use_tolerance(traits.default_tolerance));
    } else if (key == "every") {
      const char *value = args.value(USE_EVERY);
      shared.every = strcmp(value, "auto") == 0
                         ? membrane::EVERY_AUTO
                         : static_cast<int>(args.to_integer(value, 1, 1000000000L, USE_EVERY));
    } else if (key == "frictionless") {
      shared.frictionless = static_cast<int>(args.integer(0, atom->ntypes, USE_FRICTIONLESS));
    } else if (key == "vtk") {
      vtk.read(args, keywords_);
    } else if (!own(args, key)) {
      std::string list;
      for (const std::string &k : keywords_) list += (list.empty() ? "" : ", ") + k;
      args.unknown(list);
    }
  }
  inputs.require(args);
  types.set_type(shared.frictionless);
  if (types.type() > 0) {
    restart_peratom = 1; // only to give membrane particles their frictionless type back
    atom->add_callback(1);
  }
}

void MembraneFix::init_shared()
{
  inputs.init(lmp, prefix);
  // D50 sets the default tolerance (and fix membrane2d's band)
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty)
    fail(std::string("the fix group '") + group->names[igroup] + "' has no atoms; give it the " +
         "sample's " + traits.particles);
  check_other_membranes(lmp, prefix, this);
  check_frictionless_type(lmp, prefix, types.type(), style,
                          std::string("membrane ") + traits.particles);
  d50 = grains.d50;
  density = grains.density;
  tolerance = shared.tolerance_given >= 0.0 ? shared.tolerance_given
                                            : traits.default_tolerance * d50;
  const std::string problem =
      membrane::tolerance_problem(tolerance, d50, traits.most_tolerance, traits.default_tolerance);
  if (!problem.empty())
    style_error(lmp, prefix,
                keyword_text("tolerance", number_text(tolerance), problem));
}

void MembraneFix::evaluate_inputs()
{
  double v[3] = {inputs.pressure.evaluate(lmp), inputs.lo.evaluate(lmp), inputs.hi.evaluate(lmp)};
  const ScalarInput *given[3] = {&inputs.pressure, &inputs.lo, &inputs.hi};
  const char *const names[3] = {"pressure", traits.lo_key, traits.hi_key};
  same_on_every_rank(lmp, prefix, given, names, v, warned_spread_);
  pressure = inputs.pressure.checked(lmp, prefix, "pressure", true, v[0]);
  platens.lo = inputs.lo.checked(lmp, prefix, traits.lo_key, false, v[1]);
  platens.hi = inputs.hi.checked(lmp, prefix, traits.hi_key, false, v[2]);
  check_platens_in_order(lmp, prefix, traits.lo_key, inputs.lo, platens.lo, traits.hi_key,
                         inputs.hi, platens.hi);
}

bool MembraneFix::on_any_rank(bool mine) const
{
  int any = mine ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

std::uint64_t MembraneFix::group_checksum() const
{
  return ::group_checksum(lmp, groupbit, traits.dimension);
}

void MembraneFix::remember_group(std::uint64_t checksum)
{
  remembered_group_ = checksum;
  group_remembered_ = true;
}

bool MembraneFix::group_as_remembered()
{
  const bool same = group_remembered_ && group_checksum() == remembered_group_;
  group_remembered_ = false;
  return same;
}

int MembraneFix::pack_restart(int i, double *buf)
{
  types.packed(i); // called after LIGGGHTS packed atom i with its own type
  buf[0] = 1;
  return 1;
}

std::vector<std::pair<std::string, std::string>> MembraneFix::frame_files() const
{
  return {{"vtk", vtk.pvd()}};
}

void MembraneFix::fail(const std::string &text) const
{
  style_error(lmp, prefix, text);
}

void MembraneFix::warn(const std::string &text) const
{
  style_warning(lmp, prefix, text);
}

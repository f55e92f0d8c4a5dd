/* ----------------------------------------------------------------------
   fix membrane3d: see fix_membrane3d.h and doc/fix_membrane3d.md

   Every rank gathers the same spheres in the same order (membrane3d_gather.h)
   and computes the same membrane and loads, so neither depends on the number
   of ranks or the processor grid; loads are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane3d.h"

#include <mpi.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "group.h"
#include "update.h"

#include "frictionless_type.h"
#include "group_checksum.h"
#include "membrane3d_checks.h"
#include "membrane3d_record.h"
#include "membrane3d_skin.h"
#include "membrane_setup.h"
#include "style_args.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

const char *const PREFIX = "Fix membrane3d: "; // every message starts so (doc/messages.md)

// The default tolerance as a fraction of the group's mean diameter: the smallest at
// which the flood found no surface sphere more than two diameters inside the skin of
// the compressed triaxial sample (0.6), with a margin (bench/membrane3d_tolerance.sh).
const double DEFAULT_TOLERANCE = 0.7;
// The largest tolerance, in mean diameters: at 1 d the membrane already bridges the
// surface's hollows (1 377 membrane spheres against 1 661 at 0.6 d, V up 1.6 %).
const double MOST_TOLERANCE = 2.0;

const char *const KEYWORDS = "pressure, zlo, zhi, tolerance, every, frictionless, vtk";
const char *const USE_PRESSURE =
    "pressure P: the confining pressure (force/area), a number >= 0 or v_name";
const char *const USE_ZLO = "zlo Z: the lower platen surface (length), a number or v_name";
const char *const USE_ZHI = "zhi Z: the upper platen surface (length), a number or v_name";
const char *const USE_EVERY = "every auto|N: find the membrane again when it can have changed "
                              "(auto) or every N >= 1 steps";
const char *const USE_FRICTIONLESS = "frictionless T: the atom type membrane spheres take (its "
                                     "friction with every type 0), or 0 for none";
const char *const USE_VTK = "vtk N FILE: write the membrane every N >= 1 steps to FILE_<step>.vtp, "
                            "collected in FILE.pvd";
const std::string USE_TOLERANCE =
    "tolerance T: the largest gap (length) at which two spheres are linked, default " +
    number_text(DEFAULT_TOLERANCE) + " x the mean diameter";

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane3d::FixMembrane3d(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), inputs("zlo", "zhi", USE_PRESSURE, USE_ZLO, USE_ZHI), frames(lammps),
    types(lammps)
{
  check_membrane_setup(lmp, PREFIX, 3);

  StyleArgs args(lmp, PREFIX, narg, arg, 3);
  while (args.more()) {
    const std::string key = args.keyword();
    if (inputs.read(args, key)) continue; // pressure, zlo, zhi
    if (key == "tolerance") {
      tolerance_given = args.non_negative(USE_TOLERANCE);
    } else if (key == "every") {
      const char *value = args.value(USE_EVERY);
      every = strcmp(value, "auto") == 0 ? AUTO
                                         : static_cast<int>(args.to_integer(value, 1, 1000000000L,
                                                                            USE_EVERY));
    } else if (key == "frictionless") {
      types.set_type(static_cast<int>(args.integer(0, atom->ntypes, USE_FRICTIONLESS)));
    } else if (key == "vtk") {
      frames.read(args, PREFIX, USE_VTK,
                  {"pressure", "zlo", "zhi", "tolerance", "every", "frictionless", "vtk"});
    } else {
      args.unknown(KEYWORDS);
    }
  }
  inputs.require(args);

  vector_flag = 1;
  size_vector = OUTPUT_SIZE;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  if (types.type() > 0) {
    restart_peratom = 1; // only to give membrane spheres their frictionless type back
    atom->add_callback(1);
  }
  std::fill(output, output + OUTPUT_SIZE, 0.0);
}

FixMembrane3d::~FixMembrane3d()
{
  // after 'unfix' the membrane spheres are ordinary spheres again, with their friction
  if (atom && atom->type) types.restore();
  if (atom && types.type() > 0) atom->delete_callback(id, 1);
}

int FixMembrane3d::setmask()
{
  return PRE_FORCE | POST_FORCE;
}

[[noreturn]] void FixMembrane3d::fail(const char *what, const char *advice)
{
  error->all(FLERR, (std::string(PREFIX) + what + "; " + advice).c_str());
  std::abort(); // Error::all does not return
}

/* ---------------------------------------------------------------------- */

void FixMembrane3d::init()
{
  inputs.init(lmp, PREFIX);

  double sums[2] = {0.0, 0.0}; // diameters, spheres
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      sums[0] += 2.0 * atom->radius[i];
      sums[1] += 1.0;
    }
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  if (sums[1] == 0.0)
    fail(("the fix group '" + std::string(group->names[igroup]) + "' has no atoms").c_str(),
         "give it the sample's spheres");
  check_other_membranes(lmp, PREFIX, this);
  check_frictionless_type(lmp, PREFIX, types.type(), style, "membrane spheres");
  const double d = sums[0] / sums[1];
  tolerance = tolerance_given >= 0.0 ? tolerance_given : DEFAULT_TOLERANCE * d;
  check_tolerance(lmp, PREFIX, number_text(tolerance_given), tolerance, d, MOST_TOLERANCE,
                  DEFAULT_TOLERANCE);
}

void FixMembrane3d::evaluate_inputs()
{
  double v[3] = {inputs.pressure.evaluate(lmp), inputs.lo.evaluate(lmp), inputs.hi.evaluate(lmp)};
  const ScalarInput *given[3] = {&inputs.pressure, &inputs.lo, &inputs.hi};
  same_on_every_rank(lmp, PREFIX, given, {"pressure", "zlo", "zhi"}, v, warned_spread);
  pressure = inputs.pressure.checked(lmp, PREFIX, "pressure", true, v[0]);
  platens.lo = inputs.lo.checked(lmp, PREFIX, "zlo", false, v[1]);
  platens.hi = inputs.hi.checked(lmp, PREFIX, "zhi", false, v[2]);
  check_platens_in_order(lmp, PREFIX, inputs.lo, inputs.hi, platens);
}

void FixMembrane3d::setup_pre_force(int vflag)
{
  // the group changed between two runs: its member IDs may name other spheres now
  if (has_checksum && group_checksum(lmp, groupbit, 3) != checksum) member_tags.clear();
  pre_force(vflag);
}

void FixMembrane3d::setup(int vflag)
{
  warned_rim = warned_moved = false;
  post_force(vflag);
}

// end of a run: every sphere gets its own type back (the next run, a write_data, an
// unfix or a run without this fix see the true sample)
void FixMembrane3d::post_run()
{
  types.restore();
  checksum = group_checksum(lmp, groupbit, 3);
  has_checksum = true;
}

/* ---------------------------------------------------------------------- */

void FixMembrane3d::pre_force(int)
{
  evaluate_inputs();
  // a run that starts on the step the last one ended on (or a restart written then):
  // that step was decided, and is not counted again
  const bool decided = decided_step == update->ntimestep;
  decided_step = update->ntimestep;
  // (a step counter set back by reset_timestep or an earlier restart: found anew)
  bool due = member_tags.empty() || update->ntimestep < last_detection;
  if (!due && every == AUTO && !decided)
    due = automatic.can_have_changed(lmp, groupbit, platens, tolerance, update->ntimestep,
                                     members);
  else if (!due && every != AUTO)
    due = update->ntimestep - last_detection >= every;
  // platens moved beyond the tolerance (their images' links), an atom lost or gone from
  // the group (a restart read by a fix on another group)
  if (!due && (every != AUTO || decided))
    due = membrane3d::moved_apart(platens, detected_platens, tolerance) ||
          gather_tags(lmp, groupbit, member_tags, members) != member_tags.size();
  // one decision for all ranks: a rank that detected alone would wait forever in the
  // gather (with rank 0's inputs every rank holds the same state: this guards against
  // the unforeseen)
  int due_any = due ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &due_any, 1, MPI_INT, MPI_MAX, world);
  if (due_any) {
    detect();
    return;
  }
  if (!types.applied()) wear_types(members); // a run's start, after a restart write
  if (every != AUTO) warn_if_moved(lmp, PREFIX, members, detected_at, tolerance, last_detection,
                                   warned_moved);
}

void FixMembrane3d::post_force(int)
{
  place_and_apply(); // the positions gathered in pre_force: they do not move in between
}

// The spheres on the membrane's facets wear the frictionless type, the others their own.
void FixMembrane3d::wear_types(const GatheredSpheres &g)
{
  if (types.type() <= 0) return;
  std::vector<int> on_tags, on_types;
  for (std::size_t k = 0; k < member_tags.size(); k++)
    if (topology.side[k] == membrane3d::Side::surface) {
      const auto at = std::lower_bound(g.tags.begin(), g.tags.end(), member_tags[k]);
      if (at == g.tags.end() || *at != member_tags[k]) continue;
      on_tags.push_back(member_tags[k]);
      on_types.push_back(g.types[at - g.tags.begin()]);
    }
  types.change(on_tags, on_types);
}

void FixMembrane3d::detect()
{
  GatheredSpheres all;
  gather_group(lmp, groupbit, all);
  check_between_platens(lmp, PREFIX, all, platens);
  check_enough_spheres(lmp, PREFIX, group->names[igroup], all.spheres.size());
  std::vector<int> index;
  try {
    topology = membrane3d::members_only(
        every == AUTO ? automatic.detect(all, member_tags, platens, tolerance, update->ntimestep)
                      : detect_near_members(all, member_tags, platens, tolerance),
        index);
    if (every == AUTO) automatic.set_members(index);
  } catch (const membrane3d::FlatSample &e) {
    fail(e.what(), "it needs a sample two spheres across in x and y between z platens");
  } catch (const std::exception &e) {
    fail(e.what(), "the group must be one packing whose spheres are linked (gaps within the "
                   "tolerance)");
  }
  member_tags.clear();
  members.spheres.clear();
  for (int k : index) {
    member_tags.push_back(all.tags[k]);
    members.spheres.push_back(all.spheres[k]);
  }
  members.tags = member_tags;
  detected_at = members.spheres;
  members.types.clear();
  for (int k : index) members.types.push_back(all.types[k]);
  wear_types(all);
  last_detection = update->ntimestep;
  detected_platens = platens;
  detections += 1.0;
  check_ranks_agree(lmp, PREFIX, member_tags, topology.facets.size());
}

void FixMembrane3d::place_and_apply()
{
  check_between_platens(lmp, PREFIX, members, platens);
  membrane3d::LateralSurface membrane;
  try {
    membrane = membrane3d::place_membrane(topology, members.spheres, platens,
                                          membrane3d::Vertices::outer_faces);
  } catch (const std::exception &e) {
    fail(e.what(), "the membrane found at the last detection cannot be placed");
  }
  warn_if_open(lmp, PREFIX, membrane, warned_rim);

  std::vector<Eigen::Vector3d> load =
      membrane3d::membrane_loads(membrane, members.spheres.size(), pressure);
  const Eigen::Vector3d net = check_closed(lmp, PREFIX, load, pressure);
  membrane3d::add_escape_loads(membrane, members.spheres, pressure, load);

  double **f = atom->f;
  for (std::size_t k = 0; k < member_tags.size(); k++) {
    const int i = atom->map(member_tags[k]);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int d = 0; d < 3; d++) f[i][d] += load[k][d];
  }

  int on_surface = 0, escaped = 0;
  for (membrane3d::Side s : membrane.side) {
    on_surface += s == membrane3d::Side::surface;
    escaped += s == membrane3d::Side::outside;
  }
  centres_placed = false; // the volume through the centres when it is asked for
  output[MEMBRANE_SPHERES] = on_surface;
  output[ESCAPED_SPHERES] = escaped;
  output[FACETS] = static_cast<double>(membrane.surface.facets.size());
  output[DETECTIONS] = detections;
  output[AXIAL_FORCE] = net.z();
  output[LATERAL_FORCE] = net.head<2>().norm();
  const double outer = membrane3d::lateral_volume(membrane.surface);
  output[OUTER_VOLUME] = outer;
  output[OUTER_RADIUS] = membrane3d::equivalent_radius(outer, platens.hi - platens.lo);
  frames.write(PREFIX, membrane, members.spheres, pressure);
}

// The membrane through the centres, placed on this step's spheres only for its volume.
double FixMembrane3d::compute_vector(int n)
{
  if ((n == VOLUME || n == EQUIVALENT_RADIUS) && !centres_placed && !topology.facets.empty()) {
    const double volume = membrane3d::lateral_volume(
        membrane3d::place_membrane(topology, members.spheres, platens).surface);
    output[VOLUME] = volume;
    output[EQUIVALENT_RADIUS] = membrane3d::equivalent_radius(volume, platens.hi - platens.lo);
    centres_placed = true;
  }
  return output[n];
}

/* ---------------------------------------------------------------------- */

void FixMembrane3d::write_restart(FILE *fp)
{
  types.restore_for_restart();
  membrane3d::Membrane3dState state;
  state.tolerance_given = tolerance_given;
  state.every = every;
  state.last_detection = static_cast<double>(last_detection);
  state.decided_step = static_cast<double>(decided_step);
  state.detections = detections;
  state.member_tags = member_tags;
  state.topology = topology;
  state.detected_platens = detected_platens;
  state.has_checksum = true;
  state.checksum = group_checksum(lmp, groupbit, 3);
  if (every == AUTO) automatic.save(state);
  const std::vector<double> rec = membrane3d::write_record(state);
  if (comm->me == 0) {
    const int size = static_cast<int>(rec.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(rec.data(), sizeof(double), rec.size(), fp);
  }
}

void FixMembrane3d::restart(char *raw)
{
  membrane3d::Membrane3dState state;
  const std::string why = membrane3d::read_record(reinterpret_cast<const double *>(raw),
                                                  static_cast<size_t>(-1) / sizeof(double), state);
  if (!why.empty())
    error->all(FLERR, (std::string(PREFIX) + "cannot read fix " + id +
                       "'s record in the restart file: " + why +
                       "; unfix it before write_restart, or define it anew after read_restart")
                          .c_str());
  if (state.tolerance_given != tolerance_given || state.every != every) {
    if (comm->me == 0)
      error->warning(FLERR, (std::string(PREFIX) + "fix " + id +
                             " is defined with another tolerance or every than in the restart "
                             "file: the membrane is found anew")
                                .c_str());
    return;
  }
  detections = state.detections;
  last_detection = static_cast<bigint>(state.last_detection);
  decided_step = static_cast<bigint>(state.decided_step);
  member_tags = state.member_tags;
  topology = state.topology;
  detected_platens = state.detected_platens;
  has_checksum = state.has_checksum;
  checksum = state.checksum;
  if (every == AUTO) automatic.restore(state);
}

int FixMembrane3d::pack_restart(int i, double *buf)
{
  types.packed(i); // called after LIGGGHTS packed atom i with its own type
  buf[0] = 1;
  return 1;
}

double FixMembrane3d::memory_usage()
{
  return static_cast<double>(member_tags.capacity() * sizeof(int) +
                             topology.facets.capacity() * sizeof(topology.facets[0]) +
                             (members.spheres.capacity() + detected_at.capacity()) *
                                 sizeof(membrane3d::Sphere)) +
         automatic.memory_usage();
}

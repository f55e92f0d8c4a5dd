/* ----------------------------------------------------------------------
   fix membrane3d: see fix_membrane3d.h and doc/fix_membrane3d.md

   A detection is made from a skin of the spheres that every rank gathers alike,
   certified by each rank on its own spheres (membrane3d_distributed.h); the
   members are gathered in the same order on every rank (membrane3d_gather.h),
   which compute the same membrane and loads, so neither depends on the number
   of ranks or the processor grid; loads are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane3d.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "atom.h"
#include "comm.h"
#include "group.h"
#include "update.h"

#include "membrane3d_messages.h"
#include "membrane3d_record.h"
#include "membrane3d_distributed.h"
#include "membrane3d_tuning.h"
#include "owned_atom.h"
#include "membrane3d_vtk.h"
#include "restart_envelope.h"

using namespace LAMMPS_NS;
using membrane3d::GatheredSpheres;

namespace {

const MembraneTraits TRAITS{3,
                            "zlo",
                            "zhi",
                            "zlo Z: the lower platen surface (length), a number or v_name",
                            "zhi Z: the upper platen surface (length), a number or v_name",
                            "spheres",
                            membrane3d::DEFAULT_TOLERANCE,
                            membrane3d::MOST_TOLERANCE};

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane3d::FixMembrane3d(LAMMPS *lammps, int narg, char **arg)
  : MembraneFix(lammps, narg, arg, TRAITS)
{
  parse(narg, arg, {}, [](StyleArgs &, const std::string &) { return false; });
  size_vector = OUTPUT_SIZE;
  std::fill(output, output + OUTPUT_SIZE, 0.0);
}

void FixMembrane3d::init()
{
  init_shared();
}

void FixMembrane3d::setup_pre_force(int vflag)
{
  // the group changed between two runs: its member IDs may name other spheres now
  if (!group_as_remembered()) member_tags.clear();
  traffic.start(update->ntimestep, detections);
  pre_force(vflag);
}

void FixMembrane3d::setup(int vflag)
{
  warned_rim = warned_moved = false;
  skin_at_setup = skin_counters;
  post_force(vflag);
}

// end of a run: every sphere gets its own type back (the next run, a write_data, an
// unfix or a run without this fix see the true sample)
void FixMembrane3d::post_run()
{
  // the skin's certificates failed or its last resort was taken: said on rank 0
  const std::string note = membrane3d::skin_run_note(skin_counters - skin_at_setup);
  if (!note.empty() && comm->me == 0) {
    if (screen) std::fprintf(screen, "%s%s\n", prefix.c_str(), note.c_str());
    if (logfile) std::fprintf(logfile, "%s%s\n", prefix.c_str(), note.c_str());
  }
  types.restore();
  remember_group(group_checksum());
  traffic.report(lmp, prefix, id, update->ntimestep, detections);
}

/* ---------------------------------------------------------------------- */

void FixMembrane3d::pre_force(int)
{
  const ScopedSeconds timing(traffic.fix_seconds);
  evaluate_inputs();
  if (on_any_rank(detection_due())) {
    const Membrane3dTraffic::Detection timed(traffic);
    detect();
    return;
  }
  if (!types.applied()) wear_types(members); // a run's start, after a restart write
  if (shared.automatic() || warned_moved) return;
  const std::string moved =
      membrane3d::moved_warning(members, detected_at, tolerance, last_detection, update->ntimestep);
  if (!moved.empty()) warn(moved);
  warned_moved = !moved.empty();
}

// Each gather stops the run on an atom that is unusable or not between the platens.
Membrane3dGather FixMembrane3d::gather() const
{
  return {lmp, prefix, groupbit, platens, &traffic.received};
}

// This rank's view (on_any_rank makes it every rank's); when not due, `members`
// holds the member atoms now.
bool FixMembrane3d::detection_due()
{
  const bigint step = update->ntimestep;
  // a run that starts on the step the last one ended on (or a restart written then):
  // that step was decided, and is not counted again
  const bool decided = decided_step == step;
  decided_step = step;
  if (member_tags.empty() || membrane::detection_scheduled(shared, step, last_detection))
    return true;
  if (shared.automatic() && !decided)
    return automatic.can_have_changed(gather().for_auto(), platens, tolerance, d50, step, members);
  // platens moved beyond the tolerance (their images' links), an atom lost or gone from
  // the group (a restart read by a fix on another group)
  return membrane3d::moved_apart(platens, detected_platens, tolerance) ||
         gather().tags(member_tags, members) != member_tags.size();
}

void FixMembrane3d::post_force(int)
{
  const ScopedSeconds timing(traffic.fix_seconds);
  place_and_apply(); // the positions gathered in pre_force: they do not move in between
}

// The spheres on the membrane's facets wear the frictionless type, the others their own.
void FixMembrane3d::wear_types(const GatheredSpheres &g)
{
  if (types.type() <= 0) return;
  std::vector<AtomId> on_tags;
  std::vector<int> on_types;
  for (std::size_t k = 0; k < member_tags.size(); k++)
    if (topology.side[k] == membrane3d::Side::surface) {
      const int at = membrane3d::index_of(g, member_tags[k]);
      if (at < 0) continue;
      on_tags.push_back(member_tags[k]);
      on_types.push_back(g.types[at]);
    }
  types.wear(on_tags, on_types);
}

// every auto's watch is built from all the group's spheres; any other detection is
// made from a skin (membrane3d_distributed.h). `found` gets the spheres it was made
// from, sorted by ID: the members among them.
void FixMembrane3d::detect()
{
  const bigint step = update->ntimestep;
  const bool watch = shared.automatic() && automatic.builds_watch(step);
  GatheredSpheres found;
  Membrane3dGather::Totals totals;
  if (watch) {
    gather().group(found);
    totals.atoms = static_cast<double>(found.spheres.size());
  } else {
    totals = gather().totals();
  }
  const std::string few = membrane3d::too_few_spheres(
      group->names[igroup], static_cast<std::size_t>(totals.atoms), step);
  if (!few.empty()) fail(few);
  std::vector<int> index;
  try {
    if (watch) {
      topology = membrane3d::members_only(
          automatic.detect(found, member_tags, platens, tolerance, d50, step), index);
    } else {
      if (shared.automatic()) automatic.unwatched(platens);
      const membrane3d::MembraneTopology of_skin = membrane3d::detect_distributed(
          gather(), member_tags, tolerance, totals, found, skin_counters);
      traffic.received += skin_counters.last_bytes; // its gathers count them there
      topology = membrane3d::members_only(of_skin, index);
    }
    if (shared.automatic()) automatic.set_members(index);
  } catch (const membrane3d::FlatSample &e) {
    fail(std::string(e.what()) +
         "; it needs a sample two spheres across in x and y between z platens");
  } catch (const std::exception &e) {
    fail(std::string(e.what()) + "; the group must be one packing whose spheres are linked "
                                 "(gaps within the tolerance)");
  }
  members = membrane3d::subset(found, index);
  member_tags = members.tags;
  detected_at = members.spheres;
  wear_types(found);
  last_detection = step;
  detected_platens = platens;
  detections += 1.0;
  check_ranks_agree(lmp, prefix, member_tags, topology.facets.size());
}

void FixMembrane3d::place_and_apply()
{
  membrane3d::LateralSurface membrane;
  try {
    membrane = membrane3d::place_membrane(topology, members.spheres, platens,
                                          membrane3d::Vertices::outer_faces);
  } catch (const std::exception &e) {
    fail(std::string(e.what()) + "; the membrane found at the last detection cannot be placed");
  }
  const std::string open = membrane3d::open_warning(membrane, update->ntimestep);
  if (!open.empty() && !warned_rim) warn(open);
  warned_rim = warned_rim || !open.empty();

  std::vector<Eigen::Vector3d> load =
      membrane3d::membrane_loads(membrane, members.spheres.size(), pressure);
  Eigen::Vector3d net;
  const std::string open_loads =
      membrane3d::closure_problem(load, pressure, update->ntimestep, net);
  if (!open_loads.empty()) fail(open_loads);
  membrane3d::add_escape_loads(membrane, members.spheres, pressure, load);

  double **f = atom->f;
  for (std::size_t k = 0; k < member_tags.size(); k++) {
    const int i = owned_index(atom, member_tags[k]);
    if (i < 0) continue;
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
  if (vtk.due(update->ntimestep))
    vtk.write(update->ntimestep, membrane3d::vtk_frame(membrane, members.spheres, pressure));
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
  state.tolerance_given = shared.tolerance_given;
  state.every = shared.every;
  state.last_detection = static_cast<double>(last_detection);
  state.decided_step = static_cast<double>(decided_step);
  state.detections = detections;
  state.member_tags = member_tags;
  state.topology = topology;
  state.detected_platens = detected_platens;
  state.has_checksum = true;
  state.checksum = group_checksum();
  if (shared.automatic()) automatic.save(state);
  write_restart_record(lmp, fp, membrane3d::write_record(state));
}

void FixMembrane3d::restart(char *raw)
{
  membrane3d::Membrane3dState state;
  const std::string why = membrane3d::read_record(reinterpret_cast<const double *>(raw),
                                                  RestartRecordReader::UNKNOWN_LENGTH, state);
  if (!why.empty())
    fail(membrane::restart_unreadable(why, true));
  if (state.tolerance_given != shared.tolerance_given || state.every != shared.every) {
    warn(membrane::restart_other_definition("tolerance or every"));
    return;
  }
  detections = state.detections;
  last_detection = static_cast<bigint>(state.last_detection);
  decided_step = static_cast<bigint>(state.decided_step);
  member_tags = state.member_tags;
  topology = state.topology;
  detected_platens = state.detected_platens;
  if (state.has_checksum) remember_group(state.checksum);
  if (shared.automatic()) automatic.restore(state);
}

double FixMembrane3d::memory_usage()
{
  return static_cast<double>(member_tags.capacity() * sizeof(AtomId) +
                             topology.facets.capacity() * sizeof(topology.facets[0]) +
                             (members.spheres.capacity() + detected_at.capacity()) *
                                 sizeof(membrane3d::Sphere)) +
         automatic.memory_usage() + types.memory_usage();
}

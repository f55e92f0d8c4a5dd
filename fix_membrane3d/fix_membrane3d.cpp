/* ----------------------------------------------------------------------
   fix membrane3d: see fix_membrane3d.h and doc/fix_membrane3d.md

   A detection is made from a skin of the spheres that every rank gathers alike,
   certified by each rank on its own spheres (membrane3d_distributed.h), whatever
   the number of ranks and the processor grid. Each step each rank places the
   facets on the members it owns from the members within two rings of them
   (member_halo.h, membrane_part.h): their loads are the whole membrane's to the
   last bit; the global sums (volumes, forces, counts) are its facets' shares,
   reduced.
------------------------------------------------------------------------- */

#include "fix_membrane3d.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "atom.h"
#include "comm.h"
#include "group.h"
#include "update.h"

#include "atom_faults.h"
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
  halo.received = &traffic.received;
  pack = [this](int i, double *out) {
    for (int d = 0; d < 3; d++) out[d] = atom->x[i][d];
    out[3] = atom->radius[i];
  };
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
  halo_step = -1; // the atoms migrated and were sorted since the last run's end
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
  // a run's start, after a restart write: the members' own types
  if (types.type() > 0 && !types.applied()) {
    gather().tags(member_tags, members);
    wear_types(members);
  }
  if (shared.automatic() || warned_moved) return;
  if (detected_at.size() != member_tags.size()) { // a restart: from now
    gather().tags(member_tags, members);
    detected_at = members.spheres;
    return;
  }
  // the member farthest from where it was found (the first in member order of a tie)
  const std::pair<double, int> most = halo.farthest([this](int m, int i) {
    return (Eigen::Vector3d(atom->x[i][0], atom->x[i][1], atom->x[i][2]) - detected_at[m].x).norm();
  });
  const std::string moved = membrane3d::moved_warning(
      member_tags[most.second], most.first, tolerance, last_detection, update->ntimestep);
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
  return membrane3d::moved_apart(platens, detected_platens, tolerance) || !members_present();
}

// This step's members near this rank's own (collective): whether every member is still
// an atom of the group. A member unusable or not between the platens stops the run.
bool FixMembrane3d::members_present()
{
  if (halo.members() != member_tags.size() || halo_detections != detections ||
      halo_detected != last_detection) {
    std::vector<int> cells;
    for (const auto &f : topology.facets)
      for (const membrane3d::MembraneVertex &v : f) cells.push_back(v.sphere);
    halo.set_members(member_tags, cells, 3);
    halo_detections = detections;
    halo_detected = last_detection;
    halo_step = -1;
  }
  if (halo_step != update->ntimestep) {
    halo_step = update->ntimestep;
    double **x = atom->x;
    const double *r = atom->radius;
    const auto fault = [&](int i) {
      return atom_is_faulty(x[i], 3, r[i]) || !(x[i][2] > platens.lo && x[i][2] < platens.hi);
    };
    // the gather of them all names the first faulty one on every rank
    if (halo.refresh(groupbit, fault).fault) gather().tags(member_tags, members);
  }
  return halo.present() == member_tags.size();
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
  if (!members_present())
    fail("a topology of " + std::to_string(member_tags.size()) + " spheres placed on " +
         std::to_string(halo.present()) +
         "; the membrane found at the last detection cannot be placed");
  std::vector<double> records;
  halo.exchange(pack, records);
  near.resize(halo.plan().needed.size());
  for (std::size_t k = 0; k < near.size(); k++)
    near[k] = {Eigen::Vector3d(records[4 * k], records[4 * k + 1], records[4 * k + 2]),
               records[4 * k + 3]};
  using namespace membrane3d;
  MembranePart part;
  try {
    if (layout_plan != halo.plans_made)
      layout = part_layout(topology, halo.cells(), halo.plan().owned, halo.plan().needed);
    layout_plan = halo.plans_made;
    part = place_part(layout, near, platens, pressure, Vertices::outer_faces);
  } catch (const std::exception &e) {
    fail(std::string(e.what()) + "; the membrane found at the last detection cannot be placed");
  }
  // one reduction: the parts' sums, and whether rank 0 writes a frame
  std::array<double, PART_SUMS + 1> sum;
  std::copy(part.sums.begin(), part.sums.end(), sum.begin());
  sum[PART_SUMS] = vtk.due(update->ntimestep) ? 1.0 : 0.0;
  MPI_Allreduce(MPI_IN_PLACE, sum.data(), PART_SUMS + 1, MPI_DOUBLE, MPI_SUM, world);
  LateralSurface rims;
  rims.reaches_lo = sum[REACHES_LO] > 0;
  rims.reaches_hi = sum[REACHES_HI] > 0;
  const std::string open = open_warning(rims, update->ntimestep);
  if (!open.empty() && !warned_rim) warn(open);
  warned_rim = warned_rim || !open.empty();
  const Eigen::Vector3d net(sum[NET_X], sum[NET_Y], sum[NET_Z]);
  const std::string open_loads = closure_problem(net, sum[MAGNITUDE], pressure, update->ntimestep);
  if (!open_loads.empty()) fail(open_loads);
  std::array<double, PART_SUMS> whole;
  std::copy_n(sum.begin(), PART_SUMS, whole.begin());
  add_part_escapes(part, layout, near, whole, pressure);

  double **f = atom->f;
  for (std::size_t k = 0; k < part.load.size(); k++)
    for (int d = 0; d < 3; d++) f[halo.owned_atoms()[k]][d] += part.load[k][d];

  centres_placed = false; // the volume through the centres when it is asked for
  output[MEMBRANE_SPHERES] = sum[ON_SURFACE];
  output[ESCAPED_SPHERES] = sum[ESCAPED];
  output[FACETS] = sum[CLIPPED];
  output[DETECTIONS] = detections;
  output[AXIAL_FORCE] = net.z();
  output[LATERAL_FORCE] = net.head<2>().norm();
  const double outer = sum[VOLUME_SUM] / 2.0;
  output[OUTER_VOLUME] = outer;
  output[OUTER_RADIUS] = equivalent_radius(outer, platens.hi - platens.lo);
  if (sum[PART_SUMS] > 0) write_frame();
}

// The frame of the whole membrane: its members gathered on rank 0, placed there.
void FixMembrane3d::write_frame()
{
  std::vector<double> all;
  halo.gather_on_root(pack, all);
  if (comm->me != 0) return;
  std::vector<membrane3d::Sphere> spheres(member_tags.size());
  for (std::size_t k = 0; k < spheres.size(); k++)
    spheres[k] = {Eigen::Vector3d(all[4 * k], all[4 * k + 1], all[4 * k + 2]), all[4 * k + 3]};
  const membrane3d::LateralSurface membrane = membrane3d::place_membrane(
      topology, spheres, platens, membrane3d::Vertices::outer_faces);
  vtk.write(update->ntimestep, membrane3d::vtk_frame(membrane, spheres, pressure));
}

// The membrane through the centres, placed on this step's spheres only for its volume:
// each rank's facets, reduced (called on every rank, as thermo and variables do).
double FixMembrane3d::compute_vector(int n)
{
  if ((n == VOLUME || n == EQUIVALENT_RADIUS) && !centres_placed && !topology.facets.empty()) {
    double sum = membrane3d::place_part(layout, near, platens, pressure,
                                        membrane3d::Vertices::centres)
                     .sums[membrane3d::VOLUME_SUM];
    MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
    const double volume = sum / 2.0;
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
                             (members.spheres.capacity() + detected_at.capacity() +
                              near.capacity()) *
                                 sizeof(membrane3d::Sphere)) +
         automatic.memory_usage() + types.memory_usage() + halo.memory_usage();
}

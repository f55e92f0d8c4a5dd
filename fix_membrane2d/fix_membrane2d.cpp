/* ----------------------------------------------------------------------
   fix membrane2d: see fix_membrane2d.h and doc/fix_membrane2d.md

   Every rank gathers the same side bands (tag, x, y, r, type), sorted by
   tag, and runs the same chain search, so the chain never depends on the
   number of ranks; forces are added to owned atoms only.
------------------------------------------------------------------------- */

#include "fix_membrane2d.h"

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <string>
#include <unordered_map>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_property_global.h"
#include "force.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include "allgather.h"
#include "contact_scales.h"
#include "membrane_record.h"
#include "style_args.h"
#include "stability_checks.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using membrane::Disk;
using membrane::Side;

namespace {

enum { LEFT = 0, RIGHT = 1 };

// a failed search is repeated with the band widened by this factor, at most this often
constexpr double BAND_WIDENING = 2.5;
constexpr int MAX_WIDENINGS = 2;
// stability guards (doc/fix_membrane2d.md, "Stability guards")
constexpr double TIME_STEP_LIMIT = stability::TIME_STEP_POORLY_RESOLVED;
constexpr double CHAIN_STEP_LIMIT = 0.025; // chain disk displacement per step / radius
constexpr double INERTIAL_LIMIT = stability::INERTIAL_QUASI_STATIC;
constexpr bigint INERTIAL_WINDOW = 1000;   // steps over which the platen strain rate is averaged

const char *side_name(int s)
{
  return s == LEFT ? "left" : "right";
}

enum BandField { B_SIDE, B_TAG, B_X, B_Y, B_R, B_TYPE, BAND_FIELDS };
constexpr size_t WATCH_FIELDS = 6; // tag, x, y, r, |v| dt / r, type
// every auto: relations within this many D50 of their threshold are watched
// every step; the others may flip only after a band disk moved half as far
constexpr double WATCH_BUDGET = 0.01;

std::string msg(const std::string &text)
{
  return "Fix membrane2d: " + text;
}

const char *const KEYWORDS[] = {"pressure",  "ylo",       "yhi",   "sides",        "band",
                                "tolerance", "thickness", "every", "frictionless", "polyline"};

// a gap tolerance beyond this many D50 bridges real gaps between disks
constexpr double TOLERANCE_LIMIT = 0.25;
// a band narrower than this many D50 is cut into too many slices (membrane_band.cpp)
constexpr double BAND_MIN = 0.01;

} // namespace

/* ---------------------------------------------------------------------- */

FixMembrane2d::FixMembrane2d(LAMMPS *lammps, int narg, char **arg)
  : Fix(lammps, narg, arg), thickness(1.0), band_width(-1.0), search_width(0.0), tolerance(-1.0),
    band_given(-1.0), tolerance_given(-1.0), d50(0.0), density(0.0), detect_every(0),
    membrane_type(0), polyline_every(0), polyline_file(nullptr), polyline_fp(nullptr),
    pressure(0.0), ylo(0.0), yhi(0.0), force_detection(true), redetections(0), failures(0),
    widenings(0), changes(0), chain_step{0.0, -1}, inertial(0.0), inertial_step0(-1),
    inertial_height0(0.0), warned_chain_step(false), warned_inertial(false),
    inertial_above_before(false), nmax_flag(0)
{
  if (domain->dimension != 2) error->all(FLERR, msg("requires dimension 2").c_str());
  if (!atom->radius_flag) error->all(FLERR, msg("requires atom style sphere (granular)").c_str());
  if (atom->tag_enable == 0 || atom->map_style == 0)
    error->all(FLERR, msg("requires atom IDs and an atom map (atom_modify map array)").c_str());

  if (domain->xperiodic)
    error->all(FLERR,
               msg("the box is periodic in x: the sample would wrap across the boundary and "
                   "its outermost disks have no left and right; use boundary f f p (or m m p)")
                   .c_str());

  sides[LEFT].side = Side::Left;
  sides[RIGHT].side = Side::Right;
  sides[LEFT].active = sides[RIGHT].active = true;

  const char *usage_pressure =
      "pressure P: the confining pressure (force/area), a number >= 0 or v_name";
  const char *usage_ylo = "ylo Y: the bottom platen surface (length), a number or v_name";
  const char *usage_yhi = "yhi Y: the top platen surface (length), a number or v_name";
  bool have_pressure = false, have_ylo = false, have_yhi = false;
  StyleArgs args(lmp, msg(""), narg, arg, 3);
  while (args.more()) {
    const std::string key = args.keyword();
    if (key == "pressure") {
      const char *value = args.value(usage_pressure);
      pressure_in.parse(lmp, msg(""), "pressure", value);
      if (!pressure_in.is_variable() && !(pressure_in.evaluate(lmp) >= 0.0))
        args.bad("must be >= 0", usage_pressure);
      have_pressure = true;
    } else if (key == "ylo") {
      ylo_in.parse(lmp, msg(""), "ylo", args.value(usage_ylo));
      have_ylo = true;
    } else if (key == "yhi") {
      yhi_in.parse(lmp, msg(""), "yhi", args.value(usage_yhi));
      have_yhi = true;
    } else if (key == "sides") {
      const std::string v = args.value("sides left|right|both");
      if (v != "left" && v != "right" && v != "both")
        args.bad("must be left, right or both", "sides left|right|both");
      sides[LEFT].active = v != "right";
      sides[RIGHT].active = v != "left";
    } else if (key == "band") {
      band_width = args.positive("band W: the width of the side bands (length), default 4 x D50");
      band_given = band_width;
    } else if (key == "tolerance") {
      tolerance = args.non_negative(
          "tolerance G: the largest gap (length) counted as a contact, default 0.02 x D50");
      tolerance_given = tolerance;
    } else if (key == "thickness") {
      thickness = args.positive("thickness T: the out-of-plane thickness (length), default 1");
    } else if (key == "every") {
      const char *usage =
          "every auto|N: detect when the chain can have changed (auto) or every N >= 1 steps";
      const char *value = args.value(usage);
      detect_every = strcmp(value, "auto") == 0
                         ? 0
                         : static_cast<int>(args.to_integer(value, 1, 1000000000L, usage));
    } else if (key == "frictionless") {
      membrane_type =
          static_cast<int>(args.integer(1, atom->ntypes,
                                        "frictionless T: the atom type chain disks take (its "
                                        "coefficientFriction with every type is 0)"));
    } else if (key == "polyline") {
      const char *usage = "polyline N FILE: write the chains every N >= 1 steps to FILE";
      polyline_every = args.integer(1, 1000000000L, usage);
      const std::string file = args.value(usage);
      if (file.empty()) args.bad("the file name is empty", usage);
      for (const char *k : KEYWORDS)
        if (file == k) args.bad("the file name is the keyword '" + file + "'", usage);
      polyline_file = new char[file.size() + 1];
      strcpy(polyline_file, file.c_str());
    } else {
      std::string keywords;
      for (const char *k : KEYWORDS) keywords += (keywords.empty() ? "" : ", ") + std::string(k);
      args.unknown(keywords);
    }
  }
  if (!have_pressure) args.required("pressure", usage_pressure);
  if (!have_ylo) args.required("ylo", usage_ylo);
  if (!have_yhi) args.required("yhi", usage_yhi);

  vector_flag = 1;
  size_vector = VECTOR_SIZE;
  global_freq = 1;
  extvector = 0;
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  restart_global = 1;
  restart_peratom = 1; // only to give chain disks their frictionless type back after packing
  atom->add_callback(1);
  vector_atom = nullptr;
  std::fill(vector_values, vector_values + VECTOR_SIZE, 0.0);

  if (polyline_file) {
    // rank 0 writes; every rank stops with its reason, so no rank waits for it
    char reason[256] = "";
    if (comm->me == 0) {
      polyline_fp = fopen(polyline_file, "w");
      if (!polyline_fp) snprintf(reason, sizeof(reason), "%s", strerror(errno));
    }
    MPI_Bcast(reason, sizeof(reason), MPI_CHAR, 0, world);
    if (reason[0])
      error->all(FLERR, keyword_message(msg(""), "polyline", polyline_file,
                                        std::string("cannot open the file for writing (") + reason +
                                            "); check that its folder exists and is writable")
                            .c_str());
  }
}

/* ---------------------------------------------------------------------- */

FixMembrane2d::~FixMembrane2d()
{
  // after 'unfix' the chain disks are ordinary disks again, with their friction
  if (atom && atom->type) restore_types();
  if (atom) atom->delete_callback(id, 1);
  delete[] polyline_file;
  if (polyline_fp) fclose(polyline_fp);
  memory->destroy(vector_atom);
}

/* ---------------------------------------------------------------------- */

int FixMembrane2d::setmask()
{
  return PRE_FORCE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

/* ---------------------------------------------------------------------- */

void FixMembrane2d::init()
{
  pressure_in.init(lmp, msg(""), "pressure");
  ylo_in.init(lmp, msg(""), "ylo");
  yhi_in.init(lmp, msg(""), "yhi");

  if (membrane_type > 0) {
    // the chain is frictionless because its disks take a type whose friction is zero
    const int ntypes = atom->ntypes;
    FixPropertyGlobal *mu = static_cast<FixPropertyGlobal *>(modify->find_fix_property(
        "coefficientFriction", "property/global", "peratomtypepair", ntypes, ntypes, style));
    for (int j = 1; j <= ntypes; j++) {
      const double value = mu->compute_array(membrane_type - 1, j - 1);
      if (value != 0.0)
        error->all(FLERR, msg("coefficientFriction of the frictionless type " +
                              std::to_string(membrane_type) + " with type " + std::to_string(j) +
                              " is " + std::to_string(value) + ", it must be 0")
                              .c_str());
    }
  } else if (comm->me == 0) {
    error->warning(FLERR,
                   msg("no 'frictionless' type given: chain disks keep their friction").c_str());
  }

  check_other_membranes();

  // D50 sets the default band width and gap tolerance; with the density, the inertial number
  const GrainScales grains = group_grain_scales(lmp, groupbit, world);
  if (grains.empty) error->all(FLERR, msg("the fix group has no atoms").c_str());
  d50 = grains.d50;
  density = grains.density;
  if (band_width <= 0.0) band_width = 4.0 * d50;
  if (search_width <= 0.0) search_width = band_width; // a widened band is kept (detect_chains)
  if (tolerance < 0.0) tolerance = 0.02 * d50;
  check_lengths();
  // chain disks are pushed by the membrane on top of their contacts: an
  // unstable chain shows first as escapes
  check_time_step(lmp, groupbit, world, msg(""), TIME_STEP_LIMIT, warned_dt);
}

/* ----------------------------------------------------------------------
   two membranes on one disk would apply the pressure twice and fight over
   its type: groups of several fix membrane2d must not share a disk
------------------------------------------------------------------------- */

void FixMembrane2d::check_other_membranes()
{
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == this || strcmp(other->style, style) != 0) continue;
    bigint shared = 0, total = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) shared++;
    MPI_Allreduce(&shared, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    const bool first = f < modify->find_fix(id);
    if (total > 0)
      error->all(FLERR, msg(std::string("fixes '") + (first ? other->id : id) + "' and '" +
                            (first ? id : other->id) + "' are both membrane2d on " +
                            std::to_string(total) +
                            " disks: one membrane per sample (unfix one; "
                            "two samples need groups with no disk in common)")
                            .c_str());
  }
}

/* ----------------------------------------------------------------------
   band and tolerance are lengths: a tolerance meant as a fraction of D50
   (0.02) bridges gaps of several disks and shortens the chain; a band far
   below D50 is cut into more slices than the band code allows
------------------------------------------------------------------------- */

void FixMembrane2d::check_lengths()
{
  if (band_width < BAND_MIN * d50)
    error->all(FLERR, keyword_message(msg(""), "band", number_text(band_width),
                                      "is " + number_text(band_width / d50) +
                                          " x D50 (D50 = " + number_text(d50) +
                                          "); the band is a width in distance units, at least " +
                                          number_text(BAND_MIN) + " x D50 (default 4 x D50 = " +
                                          number_text(4.0 * d50) + ")")
                          .c_str());
  if (!(tolerance > TOLERANCE_LIMIT * d50)) return;
  char buf[512];
  snprintf(buf, sizeof(buf),
           "is %.3g x D50 (D50 = %g); it is the largest gap counted as a contact, a length in "
           "distance units, at most %g x D50; typically 0.02 x D50 = %g (the default)",
           tolerance / d50, d50, TOLERANCE_LIMIT, 0.02 * d50);
  error->all(FLERR, keyword_message(msg(""), "tolerance", number_text(tolerance), buf).c_str());
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::evaluate_platens()
{
  ylo = ylo_in.evaluate_checked(lmp, msg(""), "ylo", false);
  yhi = yhi_in.evaluate_checked(lmp, msg(""), "yhi", false);
  if (!(ylo < yhi))
    error->all(FLERR,
               keyword_message(msg(""), "ylo", ylo_in.text(),
                               "is " + number_text(ylo) + ", not below yhi = " + number_text(yhi) +
                                   " at step " + std::to_string(update->ntimestep) +
                                   "; ylo is the bottom platen surface, yhi the top one")
                   .c_str());
}

void FixMembrane2d::check_platens()
{
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    lo = std::min(lo, atom->x[i][1]);
    hi = std::max(hi, atom->x[i][1]);
  }
  double glo, ghi;
  MPI_Allreduce(&lo, &glo, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&hi, &ghi, 1, MPI_DOUBLE, MPI_MAX, world);
  if (glo < ylo)
    error->all(FLERR,
               keyword_message(msg(""), "ylo", ylo_in.text(),
                               "is " + number_text(ylo) +
                                   ", above the lowest disk centre of the group (y = " +
                                   number_text(glo) + "); the platens must enclose the sample")
                   .c_str());
  if (ghi > yhi)
    error->all(FLERR,
               keyword_message(msg(""), "yhi", yhi_in.text(),
                               "is " + number_text(yhi) +
                                   ", below the highest disk centre of the group (y = " +
                                   number_text(ghi) + "); the platens must enclose the sample")
                   .c_str());
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::setup_pre_force(int vflag)
{
  evaluate_platens();
  check_platens();
  // the chains of the last run (or the restart file) still hold when no disk
  // of the group was created, deleted, renumbered, retyped or moved since
  // (this step's detection, if any, was then done in the last step of that run)
  const bool kept = state_kept && group_checksum() == state_checksum;
  state_kept = false;
  if (kept) {
    gather_watched();
    apply_types();
    return;
  }
  forget_state();
  pre_force(vflag);
}

void FixMembrane2d::forget_state()
{
  restore_types();
  for (SideState &s : sides) {
    // kept only to count whether the next detection changes the chain
    s.forgotten_tags.swap(s.chain_tags);
    s.forgotten_escaped.swap(s.escaped_tags);
    s.chain_tags.clear();
    s.escaped_tags.clear();
    s.escaped_radius.clear();
    s.chain_disks.clear();
    s.watch.always = true;
  }
  observed_type.clear();
  watch_list.clear();
  force_detection = true;
}

/* ----------------------------------------------------------------------
   the sum over the group of a hash of each disk (order-free, so any rank
   count gives the same), taken while every disk has its own type
------------------------------------------------------------------------- */

std::uint64_t FixMembrane2d::group_checksum()
{
  std::uint64_t sum = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit)
      sum += membrane::disk_checksum(atom->tag[i], atom->type[i], atom->x[i][0], atom->x[i][1],
                                     atom->radius[i]);
  std::uint64_t total = 0;
  MPI_Allreduce(&sum, &total, 1, MPI_UINT64_T, MPI_SUM, world);
  return total;
}

/* ----------------------------------------------------------------------
   end of a run: every disk gets its own type back (the next run, a
   write_data, an unfix or a run without this fix see the true sample)
------------------------------------------------------------------------- */

void FixMembrane2d::post_run()
{
  restore_types();
  state_checksum = group_checksum();
  state_kept = true;
}

void FixMembrane2d::setup(int vflag)
{
  post_force(vflag);
}

/* ----------------------------------------------------------------------
   chain detection happens before the pair forces, so that a disk joining
   the chain is frictionless in this very step
------------------------------------------------------------------------- */

void FixMembrane2d::pre_force(int)
{
  evaluate_platens();
  bool detect = force_detection || (detect_every > 0 && update->ntimestep % detect_every == 0);
  if (!detect) {
    gather_watched();
    detect = detect_every == 0 && chains_may_have_changed();
  }
  if (detect) {
    force_detection = false; // detect_chains() sets it again after widening the band
    detect_chains();
    ylo_detected = ylo;
    yhi_detected = yhi;
    build_watch_list();
    gather_watched(); // the new chain's positions and speeds
  }
  // after a run or a restart write the chain disks wear their own types
  if (!types_applied) apply_types();
}

/* ----------------------------------------------------------------------
   every auto: a detection is needed only when a relation the last search
   depended on can have flipped (membrane::DetectionWatch): a watched one
   did, or a band disk or a platen moved far enough to flip another
------------------------------------------------------------------------- */

bool FixMembrane2d::chains_may_have_changed()
{
  const double platen_move = std::max(std::fabs(ylo - ylo_detected), std::fabs(yhi - yhi_detected));
  const double budget = WATCH_BUDGET * d50;
  if (2.0 * band_displacement >= budget || band_displacement + platen_move >= budget) return true;
  for (SideState &s : sides)
    if (s.active && membrane::watched_relation_changed(s.watch, s.now, s.side,
                                                       membrane::Platens{ylo, yhi}, tolerance))
      return true;
  return false;
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::gather_bands(double width)
{
  // One pass over the local disks for both sides: the slices are the same.
  const membrane::Platens platens{ylo, yhi};
  for (SideState &s : sides)
    if (s.active) s.slices.reset(s.side, platens, width);
  const membrane::BandSlices &slicing = sides[sides[LEFT].active ? LEFT : RIGHT].slices;
  double **x = atom->x;
  double *radius = atom->radius;
  const int nlocal = atom->nlocal;
  slice_of_atom.resize(nlocal);
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int k = slicing.slice_of(x[i][1]);
    slice_of_atom[i] = k;
    for (SideState &s : sides)
      if (s.active) s.slices.add_in_slice(k, x[i][0], radius[i]);
  }
  for (SideState &s : sides) {
    if (!s.active) continue;
    std::vector<double> &extent = s.slices.extents();
    MPI_Allreduce(MPI_IN_PLACE, extent.data(), static_cast<int>(extent.size()), MPI_DOUBLE,
                  s.side == Side::Right ? MPI_MAX : MPI_MIN, world);
    s.slices.finish();
  }

  sendbuf.clear();
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k = LEFT; k <= RIGHT; k++) {
      if (!sides[k].active ||
          !sides[k].slices.contains_in_slice(slice_of_atom[i], x[i][0], radius[i], width))
        continue;
      const double rec[BAND_FIELDS] = {static_cast<double>(k),
                                       static_cast<double>(atom->tag[i]),
                                       x[i][0],
                                       x[i][1],
                                       radius[i],
                                       static_cast<double>(atom->type[i])};
      sendbuf.insert(sendbuf.end(), rec, rec + BAND_FIELDS);
    }
  }
  allgather_doubles(world, sendbuf, recvbuf, recvcounts, displs);

  // No sorting: the chain search depends on the set of disks, not on their
  // order (ties are broken by tag), so any rank count gives the same chain.
  for (SideState &s : sides) {
    s.band.clear();
    s.band_type.clear();
  }
  const size_t n = recvbuf.size() / BAND_FIELDS;
  for (size_t k = 0; k < n; k++) {
    const double *rec = recvbuf.data() + k * BAND_FIELDS;
    SideState &s = sides[static_cast<int>(rec[B_SIDE])];
    s.band.push_back(Disk{static_cast<long>(rec[B_TAG]), rec[B_X], rec[B_Y], rec[B_R]});
    s.band_type.push_back(static_cast<int>(rec[B_TYPE]));
  }
  for (int k = LEFT; k <= RIGHT; k++)
    if (sides[k].active && sides[k].band.empty())
      error->all(FLERR, msg(std::string("no atoms in the ") + side_name(k) + " band").c_str());
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::detect_chains()
{
  // A band narrower than the sample's surface roughness can cut every contact
  // path to the top (seen at 8 % axial strain with 4 D50 where 10 D50 found the
  // chain): before declaring the chain lost, widen the band and search again.
  // The width reached is kept for the rest of the run (a rough outline stays
  // rough), and both sides are searched again with it at the next step, so
  // every auto and every 1 search the same bands.
  redetections++;
  bool pending[2] = {sides[LEFT].active, sides[RIGHT].active};
  double width = search_width;
  for (int attempt = 0; attempt <= MAX_WIDENINGS && (pending[LEFT] || pending[RIGHT]); attempt++) {
    if (attempt > 0) {
      width *= BAND_WIDENING;
      widenings++;
    }
    gather_bands(width);
    for (int k = LEFT; k <= RIGHT; k++) {
      if (!pending[k]) continue;
      find_chain(k);
      if (result.ok) {
        accept_chain(k);
        pending[k] = false;
      } else if (attempt == MAX_WIDENINGS) {
        chain_lost(k);
      }
    }
  }
  if (width > search_width) {
    search_width = width;
    force_detection = true;
  }
}

void FixMembrane2d::chain_lost(int k)
{
  SideState &s = sides[k];
  failures++;
  s.watch.always = true; // search again at the next step
  if (s.chain_tags.empty())
    error->all(FLERR,
               msg(std::string(
                       "no chain of touching particles from the bottom to the top platen on the ") +
                   side_name(k) + " side at step " + std::to_string(update->ntimestep) + ": " +
                   result.failure + "; check ylo/yhi, the band width and the tolerance")
                   .c_str());
  if (!s.warned && comm->me == 0) {
    error->warning(FLERR, msg(std::string("chain lost on the ") + side_name(k) + " side at step " +
                              std::to_string(update->ntimestep) + " (" + result.failure +
                              "): keeping the previous chain; counted in f_ID[12], warned once")
                              .c_str());
  }
  s.warned = true;
}

void FixMembrane2d::accept_chain(int k)
{
  SideState &s = sides[k];
  const bool forgotten = s.chain_tags.empty();
  const std::vector<long> old_tags = forgotten ? s.forgotten_tags : s.chain_tags;
  const std::vector<long> old_escaped = forgotten ? s.forgotten_escaped : s.escaped_tags;
  s.forgotten_tags.clear();
  s.forgotten_escaped.clear();
  s.chain_tags.clear();
  for (int idx : result.chain) s.chain_tags.push_back(s.band[idx].tag);
  s.escaped_tags.clear();
  s.escaped_radius.clear();
  for (int idx : result.escaped) {
    s.escaped_tags.push_back(s.band[idx].tag);
    s.escaped_radius.push_back(s.band[idx].r);
  }
  if (detect_every == 0) {
    // what this search depended on, on the band it searched (a wider band may follow)
    membrane::watch_detection(s.band, result, membrane::Platens{ylo, yhi}, tolerance,
                              WATCH_BUDGET * d50, s.watch);
    s.watch_band = s.band;
    s.now = s.band;
  }
  // how often a detection changes anything: what skipping detections would risk
  if (s.chain_tags != old_tags || s.escaped_tags != old_escaped) changes++;
  if (membrane_type > 0) {
    // the type a disk has when it joins the chain, as seen by every rank
    for (int idx : result.chain)
      if (s.band_type[idx] != membrane_type) observed_type[s.band[idx].tag] = s.band_type[idx];
    switch_types(old_tags, s.chain_tags);
  }
}

/* ----------------------------------------------------------------------
   The chain search of a side runs on one rank and its result is broadcast:
   with two or more ranks the left and right sides are searched at the same
   time. Every rank holds the same band in the same order (allgather), so
   indices into it identify the disks.
------------------------------------------------------------------------- */

void FixMembrane2d::find_chain(int k)
{
  SideState &s = sides[k];
  const int owner = (k == RIGHT && comm->nprocs > 1) ? 1 : 0;
  if (comm->me == owner) {
    finder.find(s.band, s.side, membrane::Platens{ylo, yhi}, tolerance, result);
    result_buf.clear();
    result_buf.push_back(result.ok ? 1 : 0);
    result_buf.push_back(static_cast<int>(result.chain.size()));
    result_buf.push_back(static_cast<int>(result.escaped.size()));
    result_buf.push_back(static_cast<int>(result.failure.size()));
    result_buf.push_back(result.pruned);
    result_buf.push_back(result.failed_starts);
    result_buf.push_back(static_cast<int>(result.visited.size()));
    result_buf.insert(result_buf.end(), result.chain.begin(), result.chain.end());
    result_buf.insert(result_buf.end(), result.escaped.begin(), result.escaped.end());
    result_buf.insert(result_buf.end(), result.failure.begin(), result.failure.end());
    result_buf.insert(result_buf.end(), result.visited.begin(), result.visited.end());
  }
  if (comm->nprocs == 1) return;
  int size = static_cast<int>(result_buf.size());
  MPI_Bcast(&size, 1, MPI_INT, owner, world);
  result_buf.resize(size);
  MPI_Bcast(result_buf.data(), size, MPI_INT, owner, world);
  if (comm->me == owner) return;
  const int *b = result_buf.data();
  result.ok = b[0] != 0;
  const int nchain = b[1], nescaped = b[2], nfailure = b[3];
  result.pruned = b[4];
  result.failed_starts = b[5];
  const int nvisited = b[6];
  b += 7;
  result.chain.assign(b, b + nchain);
  b += nchain;
  result.escaped.assign(b, b + nescaped);
  b += nescaped;
  result.failure.assign(b, b + nfailure);
  b += nfailure;
  result.visited.assign(b, b + nvisited);
}

/* ----------------------------------------------------------------------
   Disks that leave the chain get their own type (and friction) back, disks
   of the chain take the frictionless type. Ghost copies are switched too: a
   ghost's type is otherwise refreshed only when the neighbour list is rebuilt.
------------------------------------------------------------------------- */

void FixMembrane2d::apply_types()
{
  types_applied = true;
  if (membrane_type <= 0) return;
  for (SideState &s : sides)
    for (size_t c = 0; c < s.chain_disks.size(); c++)
      if (s.chain_types[c] != membrane_type)
        observed_type.emplace(s.chain_disks[c].tag, s.chain_types[c]);
  for (SideState &s : sides) switch_types({}, s.chain_tags);
}

void FixMembrane2d::restore_types()
{
  if (types_applied && membrane_type > 0)
    for (SideState &s : sides) switch_types(s.chain_tags, {});
  types_applied = false;
}

void FixMembrane2d::switch_types(const std::vector<long> &old_tags,
                                 const std::vector<long> &new_tags)
{
  if (membrane_type <= 0) return;
  std::unordered_map<long, int> change;
  std::vector<long> a = old_tags, b = new_tags;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  // leaving: in a, not in b
  for (long tag : a)
    if (!std::binary_search(b.begin(), b.end(), tag)) {
      auto it = observed_type.find(tag);
      if (it != observed_type.end()) change[tag] = it->second;
    }
  for (long tag : b) change[tag] = membrane_type;
  if (change.empty()) return;

  // the owned copy and every ghost image of each changed disk
  int *type = atom->type;
  for (const auto &entry : change)
    for (int i = atom->map(static_cast<int>(entry.first)); i >= 0; i = atom->sametag[i])
      type[i] = entry.second;
}

/* ----------------------------------------------------------------------
   The disks whose positions every rank needs at every step: the chain disks
   of both sides (for the forces), the escapees (so that a lost one stops
   the run) and, with every auto, the disks of the watched relations. One
   list, so that one allgather per step serves all.
------------------------------------------------------------------------- */

void FixMembrane2d::build_watch_list()
{
  // a sorted vector rather than a map: rebuilt at every detection (every step
  // with every 1) without allocating once it has grown
  watch_list.clear();
  for (int k = LEFT; k <= RIGHT; k++) {
    SideState &s = sides[k];
    if (!s.active) continue;
    for (size_t c = 0; c < s.chain_tags.size(); c++) {
      WatchEntry e;
      e.tag = s.chain_tags[c];
      e.chain_index[k] = static_cast<int>(c);
      watch_list.push_back(e);
    }
    for (long tag : s.escaped_tags) {
      WatchEntry e; // no role: gathered only so that its loss is seen
      e.tag = tag;
      watch_list.push_back(e);
    }
    if (detect_every == 0 && !s.watch.always)
      for (int idx : s.watch.disks) {
        WatchEntry e;
        e.tag = s.watch_band[idx].tag;
        e.band_index[k] = idx;
        watch_list.push_back(e);
      }
  }
  std::sort(watch_list.begin(), watch_list.end(),
            [](const WatchEntry &a, const WatchEntry &b) { return a.tag < b.tag; });
  // merge the entries of a disk that is watched in several roles
  size_t n = 0;
  for (size_t k = 0; k < watch_list.size(); k++) {
    if (n > 0 && watch_list[n - 1].tag == watch_list[k].tag) {
      for (int side = LEFT; side <= RIGHT; side++) {
        watch_list[n - 1].chain_index[side] =
            std::max(watch_list[n - 1].chain_index[side], watch_list[k].chain_index[side]);
        watch_list[n - 1].band_index[side] =
            std::max(watch_list[n - 1].band_index[side], watch_list[k].band_index[side]);
      }
    } else {
      watch_list[n++] = watch_list[k];
    }
  }
  watch_list.resize(n);
  for (SideState &s : sides) {
    s.chain_disks.resize(s.active ? s.chain_tags.size() : 0);
    s.chain_types.resize(s.chain_disks.size());
  }
}

/* ----------------------------------------------------------------------
   positions and step fractions of the watched disks now, plus (every auto)
   the largest displacement of a band disk since the last detection: each
   rank sends its owned disks and its own maximum in one allgather
------------------------------------------------------------------------- */

void FixMembrane2d::gather_watched()
{
  double local_displacement = 0.0;
  if (detect_every == 0)
    for (const SideState &s : sides) {
      if (!s.active || s.watch.always) continue;
      for (const Disk &d : s.watch_band) {
        const int i = atom->map(static_cast<int>(d.tag));
        if (i < 0 || i >= atom->nlocal) continue;
        const double dx = atom->x[i][0] - d.x, dy = atom->x[i][1] - d.y;
        local_displacement = std::max(local_displacement, dx * dx + dy * dy);
      }
    }
  local_displacement = std::sqrt(local_displacement);

  sendbuf.clear();
  for (const WatchEntry &e : watch_list) {
    const long tag = e.tag;
    const int i = atom->map(static_cast<int>(tag));
    if (i < 0 || i >= atom->nlocal) continue;
    const double *v = atom->v[i];
    const double rec[WATCH_FIELDS] = {
        static_cast<double>(tag),
        atom->x[i][0],
        atom->x[i][1],
        atom->radius[i],
        stability::step_fraction(v[0], v[1], update->dt, atom->radius[i]),
        static_cast<double>(atom->type[i])};
    sendbuf.insert(sendbuf.end(), rec, rec + WATCH_FIELDS);
  }
  const double trailer[WATCH_FIELDS] = {-1.0, local_displacement, 0.0, 0.0, 0.0, 0.0};
  sendbuf.insert(sendbuf.end(), trailer, trailer + WATCH_FIELDS);
  allgather_doubles(world, sendbuf, recvbuf, recvcounts, displs);

  if (recvbuf.size() != WATCH_FIELDS * (watch_list.size() + comm->nprocs))
    error->all(
        FLERR,
        msg("a chain, escaped or band disk was lost at step " + std::to_string(update->ntimestep) +
            " (it left the box; 'thermo_modify lost ignore' hides this): the membrane cannot "
            "hold a sample whose outer disks fly off; check the time step, the pressure and "
            "the platens")
            .c_str());
  for (double v : recvbuf)
    if (!std::isfinite(v))
      error->all(FLERR, msg("a chain particle position is not finite at step " +
                            std::to_string(update->ntimestep) +
                            ": the run has gone unstable; reduce the time step or the loading rate")
                            .c_str());
  band_displacement = 0.0;
  chain_step = {0.0, -1};
  for (size_t k = 0; k < recvbuf.size(); k += WATCH_FIELDS) {
    const double *rec = recvbuf.data() + k;
    if (rec[0] < 0.0) {
      band_displacement = std::max(band_displacement, rec[1]);
      continue;
    }
    const long tag = static_cast<long>(rec[0]);
    const Disk d{tag, rec[1], rec[2], rec[3]};
    const auto it = std::lower_bound(watch_list.begin(), watch_list.end(), tag,
                                     [](const WatchEntry &w, long t) { return w.tag < t; });
    const WatchEntry &e = *it;
    for (int side = LEFT; side <= RIGHT; side++) {
      if (e.chain_index[side] >= 0) {
        sides[side].chain_disks[e.chain_index[side]] = d;
        sides[side].chain_types[e.chain_index[side]] = static_cast<int>(rec[5]);
        if (rec[4] > chain_step.fraction) chain_step = {rec[4], tag};
      }
      if (e.band_index[side] >= 0) sides[side].now[e.band_index[side]] = d;
    }
  }
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::post_force(int)
{
  pressure = pressure_in.evaluate_checked(lmp, msg(""), "pressure", true);
  // positions of the chain disks: gathered in pre_force (they do not move in between)
  for (SideState &s : sides) {
    if (!s.active) continue;
    chain_index.resize(s.chain_disks.size());
    for (size_t k = 0; k < chain_index.size(); k++) chain_index[k] = static_cast<int>(k);
    membrane::polyline_from_chain(s.chain_disks, chain_index, membrane::Platens{ylo, yhi},
                                  s.polyline);
    membrane::chain_forces(s.polyline, s.side, pressure, thickness, s.forces);
    s.total.setZero();
    for (const Eigen::Vector2d &f : s.forces) s.total += f;
  }
  apply_forces();
  check_chain_step();
  check_inertial_number();
  update_flags();
  update_outputs();
  if (polyline_fp && update->ntimestep % polyline_every == 0) write_polylines();
}

/* ----------------------------------------------------------------------
   A chain disk of a quasi-static test moves far less than 1e-3 of its
   radius per step (up to 0.014 in settling and pressure jumps that stay
   stable, bench/stability_sweep.md); 2.5 % means the membrane shoots it (a pressure jump, a
   time step near the critical one): warn once, the value stays in f_ID[15]
------------------------------------------------------------------------- */

void FixMembrane2d::check_chain_step()
{
  if (chain_step.fraction <= CHAIN_STEP_LIMIT || warned_chain_step) return;
  warned_chain_step = true;
  if (comm->me != 0) return;
  char buf[512];
  snprintf(buf, sizeof(buf),
           "chain disk %ld moved %.3g of its radius in one step at step " BIGINT_FORMAT
           " (limit %g; quasi-static chains move < 0.001): its speed jumped. Ramp the pressure "
           "instead of jumping it, or reduce the time step or the loading rate (warned once; "
           "f_ID[15] is the current value)",
           chain_step.tag, chain_step.fraction, update->ntimestep, CHAIN_STEP_LIMIT);
  error->warning(FLERR, msg(buf).c_str());
}

/* ----------------------------------------------------------------------
   I = eps_rate d50 sqrt(rho / p), with the axial strain rate of the platens
   averaged over INERTIAL_WINDOW steps and p = the membrane pressure (the
   smaller principal stress, so I is an upper bound): warn once when above
   1e-3 in two windows in a row
------------------------------------------------------------------------- */

void FixMembrane2d::check_inertial_number()
{
  const double height = yhi - ylo;
  const bigint step = update->ntimestep;
  if (inertial_step0 < 0 || step < inertial_step0) {
    inertial_step0 = step;
    inertial_height0 = height;
    return;
  }
  if (step - inertial_step0 < INERTIAL_WINDOW) return;
  const double rate = std::fabs(height - inertial_height0) /
                      (inertial_height0 * static_cast<double>(step - inertial_step0) * update->dt);
  inertial = pressure > 0.0 ? stability::inertial_number(rate, d50, density, pressure) : 0.0;
  inertial_step0 = step;
  inertial_height0 = height;
  // a platen servo's transient (re-consolidation) can exceed it for one window
  const bool above = inertial > INERTIAL_LIMIT;
  const bool sustained = above && inertial_above_before;
  inertial_above_before = above;
  if (!sustained || warned_inertial) return;
  warned_inertial = true;
  if (comm->me != 0) return;
  char buf[512];
  snprintf(buf, sizeof(buf),
           "inertial number I = %.3g > %g at step " BIGINT_FORMAT " (axial strain rate %.3g 1/s of "
           "the platens, d50 %.3g m, density %.3g kg/m^2 per unit thickness, pressure %.3g Pa): "
           "the test is not quasi-static; lower the loading rate below %.3g 1/s (warned once; "
           "f_ID[16] is the current value)",
           inertial, INERTIAL_LIMIT, step, rate, d50, density, pressure,
           rate * INERTIAL_LIMIT / inertial);
  error->warning(FLERR, msg(buf).c_str());
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::apply_forces()
{
  double **f = atom->f;
  const int nlocal = atom->nlocal;
  for (SideState &s : sides) {
    if (!s.active) continue;
    for (size_t k = 0; k < s.chain_disks.size(); k++) {
      const int i = atom->map(static_cast<int>(s.chain_disks[k].tag));
      if (i < 0 || i >= nlocal) continue;
      f[i][0] += s.forces[k].x();
      f[i][1] += s.forces[k].y();
    }
    for (size_t k = 0; k < s.escaped_tags.size(); k++) {
      const int i = atom->map(static_cast<int>(s.escaped_tags[k]));
      if (i < 0 || i >= nlocal) continue;
      const Disk d{s.escaped_tags[k], atom->x[i][0], atom->x[i][1], atom->radius[i]};
      const Eigen::Vector2d push = membrane::escapee_force(d, s.side, pressure, thickness);
      f[i][0] += push.x();
      f[i][1] += push.y();
    }
  }
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::update_flags()
{
  if (atom->nmax > nmax_flag) {
    memory->destroy(vector_atom);
    nmax_flag = atom->nmax;
    memory->create(vector_atom, nmax_flag, "membrane2d:flag");
  }
  const int nlocal = atom->nlocal;
  std::fill(vector_atom, vector_atom + nlocal, 0.0);
  auto mark = [&](long tag, double flag) {
    const int i = atom->map(static_cast<int>(tag));
    if (i >= 0 && i < nlocal) vector_atom[i] = flag;
  };
  for (int k = LEFT; k <= RIGHT; k++) {
    if (!sides[k].active) continue;
    for (long tag : sides[k].chain_tags) mark(tag, k == LEFT ? LEFT_CHAIN : RIGHT_CHAIN);
    for (long tag : sides[k].escaped_tags) mark(tag, ESCAPEE);
  }
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::update_outputs()
{
  double *v = vector_values;
  std::fill(v, v + VECTOR_SIZE, 0.0);
  const SideState &l = sides[LEFT], &r = sides[RIGHT];
  if (l.active && r.active) {
    v[AREA] = membrane::sample_area(l.polyline, r.polyline);
    v[MEAN_WIDTH] = v[AREA] / (yhi - ylo);
    v[MID_WIDTH] = membrane::width_at(0.5 * (ylo + yhi), l.polyline, r.polyline);
  }
  v[CHAIN_LEFT] = l.active ? static_cast<double>(l.chain_tags.size()) : 0.0;
  v[CHAIN_RIGHT] = r.active ? static_cast<double>(r.chain_tags.size()) : 0.0;
  v[ESCAPED] = static_cast<double>(l.escaped_tags.size() + r.escaped_tags.size());
  v[FX_LEFT] = l.total.x();
  v[FY_LEFT] = l.total.y();
  v[FX_RIGHT] = r.total.x();
  v[FY_RIGHT] = r.total.y();
  v[REDETECTIONS] = static_cast<double>(redetections);
  v[FAILURES] = static_cast<double>(failures);
  v[PRESSURE] = pressure;
  v[WIDENINGS] = static_cast<double>(widenings);
  v[CHAIN_STEP] = chain_step.fraction;
  v[INERTIAL] = inertial;
  v[CHANGES] = static_cast<double>(changes);
}

double FixMembrane2d::compute_vector(int n)
{
  return vector_values[n];
}

/* ---------------------------------------------------------------------- */

void FixMembrane2d::write_polylines()
{
  fprintf(polyline_fp, "ITEM: TIMESTEP\n" BIGINT_FORMAT "\n", update->ntimestep);
  for (int k = LEFT; k <= RIGHT; k++) {
    const SideState &s = sides[k];
    if (!s.active) continue;
    fprintf(polyline_fp, "ITEM: POLYLINE %s %zu\n", side_name(k), s.polyline.size());
    for (const Eigen::Vector2d &p : s.polyline) fprintf(polyline_fp, "%.10g %.10g\n", p.x(), p.y());
    fprintf(polyline_fp, "ITEM: CHAIN %s %zu (tag x y r fx fy)\n", side_name(k),
            s.chain_disks.size());
    for (size_t c = 0; c < s.chain_disks.size(); c++) {
      const Disk &d = s.chain_disks[c];
      fprintf(polyline_fp, "%ld %.10g %.10g %.10g %.10g %.10g\n", d.tag, d.x, d.y, d.r,
              s.forces[c].x(), s.forces[c].y());
    }
  }
  fflush(polyline_fp);
}

/* ----------------------------------------------------------------------
   restart: everything a run continued from the file needs to give the
   output of one straight through (the chains, escapees, what the last
   detection depended on, the band width reached, counters, the inertial
   window), with the definition it was written with. The disks in the file
   carry their own types: write_restart() gives them back before LIGGGHTS
   packs the atoms and pack_restart() switches each packed one again, so a
   restart read by another definition, another fix ID or no membrane at all
   holds the true sample.
------------------------------------------------------------------------- */

void FixMembrane2d::write_restart(FILE *fp)
{
  const int nlocal = atom->nlocal;
  restored_for_restart.assign(nlocal, 0);
  if (types_applied && membrane_type > 0)
    for (const SideState &s : sides)
      for (long tag : s.chain_tags) {
        const int i = atom->map(static_cast<int>(tag));
        if (i < 0 || i >= nlocal) continue;
        const auto it = observed_type.find(tag);
        if (it == observed_type.end() || atom->type[i] != membrane_type) continue;
        atom->type[i] = it->second;
        restored_for_restart[i] = 1;
      }
  types_applied = false; // pre_force switches the disks a region write skipped
  const std::uint64_t checksum = group_checksum();

  RestartRecordWriter out = membrane::record_writer();
  // the definition
  out.put((sides[LEFT].active ? 1 : 0) + (sides[RIGHT].active ? 2 : 0));
  out.put(membrane_type);
  out.put(detect_every);
  out.put(band_given);
  out.put(tolerance_given);
  out.put(thickness);
  // the state
  out.put(static_cast<double>(checksum >> 32));
  out.put(static_cast<double>(checksum & 0xffffffffu));
  out.put(band_width);
  out.put(search_width);
  out.put(tolerance);
  out.put(force_detection ? 1 : 0);
  out.put(ylo_detected);
  out.put(yhi_detected);
  for (const SideState &s : sides) {
    membrane::put_tags(out, s.chain_tags);
    membrane::put_tags(out, s.escaped_tags);
    for (double r : s.escaped_radius) out.put(r);
    membrane::put_watch(out, s.watch);
    membrane::put_disks(out, s.watch_band);
    out.put(s.warned ? 1 : 0);
  }
  for (bigint c : {redetections, failures, widenings, changes}) out.put(static_cast<double>(c));
  out.put(inertial);
  out.put(static_cast<double>(inertial_step0));
  out.put(inertial_height0);
  out.put(inertial_above_before ? 1 : 0);
  out.put(warned_inertial ? 1 : 0);
  out.put(warned_chain_step ? 1 : 0);
  const std::vector<double> &rec = out.finish();
  if (comm->me == 0) {
    const int size = static_cast<int>(rec.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(rec.data(), sizeof(double), rec.size(), fp);
  }
}

int FixMembrane2d::pack_restart(int i, double *buf)
{
  // called after LIGGGHTS packed atom i with its own type
  if (i < static_cast<int>(restored_for_restart.size()) && restored_for_restart[i]) {
    atom->type[i] = membrane_type;
    restored_for_restart[i] = 0;
  }
  buf[0] = 1;
  return 1;
}

void FixMembrane2d::restart(char *raw)
{
  RestartRecordReader in = membrane::record_reader(reinterpret_cast<const double *>(raw),
                                                   static_cast<size_t>(-1) / sizeof(double));
  if (!in.ok())
    error->all(FLERR,
               msg(std::string("the restart file's state of fix ") + id +
                   " cannot be read: " + in.error() +
                   "; read it with the version that wrote it, or define this fix with another ID "
                   "(the chains are then found again)")
                   .c_str());
  const int sides_mask = static_cast<int>(in.get());
  const int type = static_cast<int>(in.get());
  const int every = static_cast<int>(in.get());
  const double band = in.get(), tol = in.get(), thick = in.get();
  const int mask_now = (sides[LEFT].active ? 1 : 0) + (sides[RIGHT].active ? 2 : 0);
  if (sides_mask != mask_now || type != membrane_type || every != detect_every ||
      band != band_given || tol != tolerance_given || thick != thickness) {
    if (comm->me == 0)
      error->warning(
          FLERR, msg(std::string("fix ") + id +
                     " is defined otherwise than in the restart file "
                     "(sides, frictionless, every, band, tolerance or thickness): its chains are "
                     "found again at the first step and its counters start from 0")
                     .c_str());
    return;
  }
  const std::uint64_t hi = static_cast<std::uint64_t>(in.get()),
                      lo = static_cast<std::uint64_t>(in.get());
  state_checksum = (hi << 32) | lo;
  band_width = in.get();
  search_width = in.get();
  tolerance = in.get();
  force_detection = in.get() != 0.0;
  ylo_detected = in.get();
  yhi_detected = in.get();
  for (SideState &s : sides) {
    membrane::get_tags(in, s.chain_tags);
    membrane::get_tags(in, s.escaped_tags);
    s.escaped_radius.resize(s.escaped_tags.size());
    for (double &r : s.escaped_radius) r = in.get();
    membrane::get_watch(in, s.watch);
    membrane::get_disks(in, s.watch_band);
    s.now = s.watch_band;
    s.warned = in.get() != 0.0;
  }
  for (bigint *c : {&redetections, &failures, &widenings, &changes})
    *c = static_cast<bigint>(in.get());
  inertial = in.get();
  inertial_step0 = static_cast<bigint>(in.get());
  inertial_height0 = in.get();
  inertial_above_before = in.get() != 0.0;
  warned_inertial = in.get() != 0.0;
  warned_chain_step = in.get() != 0.0;
  if (!in.finished())
    error->all(FLERR, msg(std::string("the restart file's state of fix ") + id +
                          " cannot be read: " + in.error())
                          .c_str());
  state_kept = true;
  build_watch_list();
}

/* ---------------------------------------------------------------------- */

double FixMembrane2d::memory_usage()
{
  double bytes = nmax_flag * sizeof(double);
  bytes += (sendbuf.capacity() + recvbuf.capacity()) * sizeof(double);
  for (const SideState &s : sides)
    bytes += s.band.capacity() * sizeof(Disk) + s.chain_disks.capacity() * sizeof(Disk);
  bytes += observed_type.size() * (sizeof(long) + sizeof(int) + 32);
  return bytes;
}

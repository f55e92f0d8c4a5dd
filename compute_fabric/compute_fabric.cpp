/* ----------------------------------------------------------------------
   compute fabric: see compute_fabric.h and doc/compute_fabric.md
------------------------------------------------------------------------- */

#include "compute_fabric.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "compute_pair_gran_local.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include "allgather.h"
#include "style_args.h"
#include "stability_index.h"

using namespace LAMMPS_NS;

namespace {

constexpr double RAD2DEG = 180.0 / M_PI;

// One contact as exchanged between ranks: tags, centres, force on atom a,
// radius sum (wall: a's radius).
enum ContactField { TAG_A, TAG_B, XA, YA, XB, YB, FAX, FAY, RADSUM, CONTACT_FIELDS };

// every message starts so (doc/messages.md, common/style_args.h)
const char *const PREFIX = "Compute fabric: ";
const char *const KEYWORDS =
    "bins, estimator, stability, rattlers, histogram, stress, region, walls";
const char *const USE_BINS =
    "bins N, the number of angular bins over 360 deg, an even integer from 6 to 3600 (default 18)";
const char *const USE_ESTIMATOR = "estimator unbiased, published or tensor (default unbiased)";
const char *const USE_STABILITY =
    "stability yes or no, the mean stability index as vector entry 13 (default no)";
const char *const USE_RATTLERS =
    "rattlers yes or no, particles with 0 or 1 contact in the mean stability index (default no)";
const char *const USE_HISTOGRAM =
    "histogram yes or no, the polar histogram as a global array (default no)";
const char *const USE_WALLS =
    "walls yes or no, also count the contacts with the mesh walls of fix wall/gran (default no)";
const char *const USE_STRESS =
    "stress A or v_name, the sample area (length^2 per unit thickness) of the Love-Weber stress";
const char *const USE_UPDATE =
    "update_on_run_end yes or no, invoke the compute at the end of each run (default no)";
const char *const USE_REGION = "region ID, count only the particles whose centre is inside region "
                               "ID (a region defined before compute fabric)";

bool yes_no(StyleArgs &args, const char *usage)
{
  const std::string value = args.value(usage);
  if (value == "yes") return true;
  if (value != "no") args.bad("must be yes or no", usage);
  return false;
}

std::string msg(const std::string &text)
{
  return PREFIX + text;
}

} // namespace

/* ---------------------------------------------------------------------- */

ComputeFabric::ComputeFabric(LAMMPS *lammps, int &iarg, int narg, char **arg)
  : Compute(lammps, iarg, narg, arg), nbins(18), estimator(Estimator::Unbiased),
    stability_flag(false), rattlers_flag(false), histogram_flag(false), stress_flag(false),
    area_ivar(-1), iregion(-1), walls_flag(false), gathered_step(-1), nparticles(0), no_normal(0),
    first_no_normal(0), warned_no_normal(false), nmax_atom(0)
{
  if (domain->dimension != 2)
    error->all(
        FLERR,
        msg("requires dimension 2: it is a 2D compute; set dimension 2 before create_box").c_str());
  if (!atom->radius_flag)
    error->all(FLERR, msg("requires per-atom radii; use atom_style granular (or sphere)").c_str());
  if (atom->tag_enable == 0 || atom->map_style == 0)
    error->all(FLERR, msg("requires atom IDs and an atom map; add atom_modify map array "
                          "before create_box")
                          .c_str());

  // the base class leaves its output pointers uninitialised
  vector = nullptr;
  array = nullptr;
  vector_atom = nullptr;
  array_atom = nullptr;
  vector_local = nullptr;
  array_local = nullptr;

  parse_args(iarg, narg, arg);

  vector_flag = 1;
  size_vector = VECTOR_SIZE;
  extvector = 0;
  memory->create(vector, VECTOR_SIZE, "fabric:vector");
  std::fill(vector, vector + VECTOR_SIZE, 0.0);

  if (histogram_flag) {
    array_flag = 1;
    size_array_rows = nbins;
    size_array_cols = 4;
    extarray = 0;
    memory->create(array, nbins, 4, "fabric:array");
  }

  // per-atom: contact count, stability index
  peratom_flag = 1;
  size_peratom_cols = 2;
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::parse_args(int iarg, int narg, char **arg)
{
  StyleArgs args(lmp, PREFIX, narg, arg, iarg);
  while (args.more()) {
    const std::string key = args.keyword();
    if (key == "bins") {
      const long n = args.integer(LONG_MIN, LONG_MAX, USE_BINS);
      if (n < 6 || n > 3600 || n % 2 != 0)
        args.bad("must be an even integer from 6 to 3600", USE_BINS);
      nbins = static_cast<int>(n);
    } else if (key == "estimator") {
      const std::string value = args.value(USE_ESTIMATOR);
      if (value == "unbiased")
        estimator = Estimator::Unbiased;
      else if (value == "published")
        estimator = Estimator::Published;
      else if (value == "tensor")
        estimator = Estimator::Tensor;
      else
        args.bad("must be unbiased, published or tensor", USE_ESTIMATOR);
    } else if (key == "stability") {
      stability_flag = yes_no(args, USE_STABILITY);
    } else if (key == "rattlers") {
      rattlers_flag = yes_no(args, USE_RATTLERS);
    } else if (key == "histogram") {
      histogram_flag = yes_no(args, USE_HISTOGRAM);
    } else if (key == "walls") {
      walls_flag = yes_no(args, USE_WALLS);
    } else if (key == "stress") {
      const char *value = args.value(USE_STRESS);
      if (strncmp(value, "v_", 2) == 0) {
        if (value[2] == '\0') args.bad("names no variable", USE_STRESS);
      } else {
        char *end = nullptr;
        const double area = strtod(value, &end);
        if (*value == '\0' || *end != '\0') args.bad("is neither a number nor v_name", USE_STRESS);
        if (!(std::isfinite(area) && area > 0.0))
          args.bad("must be a positive number (the sample area)", USE_STRESS);
      }
      area_in.parse(lmp, PREFIX, "stress", value);
      stress_flag = true;
    } else if (key == "region") {
      idregion = args.value(USE_REGION);
      if (domain->find_region(const_cast<char *>(idregion.c_str())) < 0)
        args.bad("there is no region " + idregion, USE_REGION);
    } else if (key == "update_on_run_end") {
      // LIGGGHTS' Compute reads it for every compute, only right after the style
      args.value(USE_UPDATE);
      args.bad("must come first, right after fabric (LIGGGHTS reads it there for every compute)",
               USE_UPDATE);
    } else {
      args.unknown(KEYWORDS);
    }
  }
  if (rattlers_flag && !stability_flag && comm->me == 0)
    error->warning(FLERR,
                   keyword_message(PREFIX, "rattlers", "yes",
                                   "has no effect without stability yes (it only changes the "
                                   "mean stability index, vector entry 13); add stability yes")
                       .c_str());
}

/* ---------------------------------------------------------------------- */

ComputeFabric::~ComputeFabric()
{
  memory->destroy(vector);
  memory->destroy(array);
  memory->destroy(array_atom);
  delete[] pairs.id;
  delete[] walls.id;
}

/* ----------------------------------------------------------------------
   Contact forces come from LIGGGHTS' own compute pair/gran/local: the pair
   style evaluates its contact model again at the current positions with the
   stored contact history (not updated), so these are the forces the pair
   applied this step. A pair style accepts only one such compute, so every
   compute fabric reads the same one: one the user defined (before or after
   this compute), else ours, created at the first init (when every compute
   of the input script exists) in group all, because pack_contacts keeps
   only the contacts of this compute's group anyway.
------------------------------------------------------------------------- */

void ComputeFabric::find_source(ContactSource &src)
{
  src.compute = nullptr;
  for (int i = 0; i < modify->ncompute; i++) {
    Compute *c = modify->compute[i];
    if (c == this || strcmp(c->style, src.style) != 0) continue;
    if (src.id && strcmp(c->id, src.id) != 0) continue;
    const std::string named = std::string("compute ") + c->id + " (" + src.style + ", group " +
                              group->names[c->igroup] + ")";
    ComputePairGranLocal *found = static_cast<ComputePairGranLocal *>(c);
    if (found->offset_x1() < 0 || found->offset_id1() < 0 || found->offset_f() < 0)
      error->all(FLERR, msg(named + " lacks the values pos, id or force that compute " + id +
                            " (fabric) reads from it; define it as compute " + c->id + " " +
                            group->names[c->igroup] + " " + src.style + " pos id force")
                            .c_str());
    if (c->igroup != 0 && c->igroup != igroup)
      error->all(FLERR, msg("compute " + std::string(id) + " (fabric, group " +
                            group->names[igroup] + ") reads the contacts from " + named +
                            ", which leaves out the contacts "
                            "outside group " +
                            group->names[c->igroup] + "; define compute " + c->id +
                            " in group all: a pair style takes one compute " + src.style +
                            " and every compute fabric reads it")
                            .c_str());
    src.compute = found;
    if (!src.id) {
      src.id = new char[strlen(c->id) + 1];
      strcpy(src.id, c->id);
    }
    return;
  }
}

void ComputeFabric::create_source(ContactSource &src, const char *suffix)
{
  std::string cid = std::string(id) + suffix;
  delete[] src.id;
  src.id = new char[cid.size() + 1];
  strcpy(src.id, cid.c_str());

  char *args[6];
  args[0] = src.id;
  args[1] = (char *)"all";
  args[2] = const_cast<char *>(src.style);
  args[3] = (char *)"pos";
  args[4] = (char *)"id";
  args[5] = (char *)"force";
  // pair/gran/local refuses to be created after a run ("define this compute
  // before first run"), which includes any script that starts with read_restart.
  // The check protects its optional 'history' columns, whose layout is fixed when
  // the pair style first runs; we ask for pos, id and force only, which the pair
  // reports at any time, so we create it as if at step 0.
  const bigint now = update->ntimestep;
  update->ntimestep = 0;
  modify->add_compute(6, args);
  update->ntimestep = now;
  src.compute = static_cast<ComputePairGranLocal *>(modify->compute[modify->ncompute - 1]);
}

void ComputeFabric::init_source(ContactSource &src, const char *suffix)
{
  find_source(src);
  if (!src.compute && src.id) {
    // deleted (uncompute) since the last run: read another one, or ours
    delete[] src.id;
    src.id = nullptr;
    find_source(src);
  }
  if (!src.compute) create_source(src, suffix);
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::init()
{
  init_source(pairs, "_contacts");
  if (walls_flag) {
    // (fix_wall_gran.h cannot be included from the Debian headers, so a mesh
    // wall is recognised by the mesh fixes it needs)
    if (modify->n_fixes_style("wall/gran") == 0 || modify->n_fixes_style("mesh/surface") == 0)
      error->all(FLERR,
                 keyword_message(PREFIX, "walls", "yes",
                                 "needs a fix wall/gran with mesh walls (LIGGGHTS reports no "
                                 "contact forces for primitive walls); use mesh walls (fix "
                                 "mesh/surface and fix wall/gran ... mesh) or walls no")
                     .c_str());
    init_source(walls, "_walls");
  }

  if (!idregion.empty()) {
    iregion = domain->find_region(const_cast<char *>(idregion.c_str()));
    if (iregion < 0)
      error->all(FLERR,
                 keyword_message(PREFIX, "region", idregion,
                                 "region " + idregion +
                                     " was deleted; define it again "
                                     "before the run, or use a compute fabric without region")
                     .c_str());
  }
  if (stress_flag) {
    area_in.init(lmp, PREFIX, "stress"); // the variable exists and is equal-style
    if (area_in.is_variable())
      area_ivar = input->variable->find(const_cast<char *>(area_in.text().substr(2).c_str()));
  }
  gathered_step = -1;
}

/* ---------------------------------------------------------------------- */

bool ComputeFabric::atom_selected(int i) const
{
  if (!(atom->mask[i] & groupbit)) return false;
  if (iregion < 0) return true;
  double **x = atom->x;
  return domain->regions[iregion]->match(x[i][0], x[i][1], x[i][2]) != 0;
}

/* ----------------------------------------------------------------------
   one record per contact: tags (b = -1 for a wall), centres (for a wall,
   b's position is the contact point), force on a
------------------------------------------------------------------------- */

void ComputeFabric::pack_contacts(const ContactSource &src, bool wall)
{
  ComputePairGranLocal *c = src.compute;
  const int nrows = c->size_local_rows;
  double **rows = c->get_data();
  const int ox = c->offset_x1(), oid = c->offset_id1(), of = c->offset_f();
  Region *region = iregion >= 0 ? domain->regions[iregion] : nullptr;

  for (int r = 0; r < nrows; r++) {
    const double *row = rows[r];
    double rec[CONTACT_FIELDS];
    if (wall) {
      // wall/gran/local: pos = contact point, particle centre; id = mesh, triangle, tag
      const double *cp = row + ox, *xp = row + ox + 3;
      const int ip = atom->map(static_cast<int>(row[oid + 2]));
      if (ip < 0 || !(atom->mask[ip] & groupbit)) continue;
      if (region && !region->match(xp[0], xp[1], xp[2])) continue;
      const double w[CONTACT_FIELDS] = {row[oid + 2], -1.0,    xp[0],       xp[1],           cp[0],
                                        cp[1],        row[of], row[of + 1], atom->radius[ip]};
      std::copy(w, w + CONTACT_FIELDS, rec);
    } else {
      const double *xa = row + ox, *xb = row + ox + 3;
      // a pair/gran/local of group all (the user's) reports contacts outside our group
      const int ia = atom->map(static_cast<int>(row[oid]));
      const int ib = atom->map(static_cast<int>(row[oid + 1]));
      if (ia < 0 || ib < 0 || !(atom->mask[ia] & groupbit) || !(atom->mask[ib] & groupbit))
        continue;
      if (region && (!region->match(xa[0], xa[1], xa[2]) || !region->match(xb[0], xb[1], xb[2])))
        continue;
      const double p[CONTACT_FIELDS] = {
          row[oid], row[oid + 1], xa[0],
          xa[1],    xb[0],        xb[1],
          row[of],  row[of + 1],  atom->radius[ia] + atom->radius[ib]};
      std::copy(p, p + CONTACT_FIELDS, rec);
      if (rec[TAG_A] > rec[TAG_B]) {
        // make a the smaller tag; the force on the new a is minus the old one
        std::swap(rec[TAG_A], rec[TAG_B]);
        std::swap(rec[XA], rec[XB]);
        std::swap(rec[YA], rec[YB]);
        rec[FAX] = -rec[FAX];
        rec[FAY] = -rec[FAY];
      }
    }
    sendbuf.insert(sendbuf.end(), rec, rec + CONTACT_FIELDS);
  }
}

/* ----------------------------------------------------------------------
   Every rank ends with the same contact list, sorted by (tag a, tag b) with
   tag a < tag b, so every statistic is summed in the same order whatever the
   number of ranks. pair/gran/local already reports a contact across a
   processor boundary on one rank only (newton off: the smaller tag's side).
------------------------------------------------------------------------- */

void ComputeFabric::gather_contacts()
{
  if (gathered_step == update->ntimestep) return;
  gathered_step = update->ntimestep;

  // Ghost velocities date from the start of the step; the contact model's
  // damping terms need the current ones, or a contact across a processor
  // boundary would differ from the same contact inside one rank.
  bool refreshed = false;
  sendbuf.clear();
  for (ContactSource *src : {&pairs, &walls}) {
    if (!src->compute) continue;
    if (src->compute->invoked_local != update->ntimestep) {
      if (!refreshed) comm->forward_comm();
      refreshed = true;
      src->compute->compute_local();
    }
    pack_contacts(*src, src == &walls);
  }

  allgather_doubles(world, sendbuf, recvbuf, recvcounts, displs);

  const int ncontacts = static_cast<int>(recvbuf.size()) / CONTACT_FIELDS;
  // one 64-bit key per contact sorts faster than comparing doubles
  sort_keys.resize(ncontacts);
  const double *buf = recvbuf.data();
  for (int c = 0; c < ncontacts; c++) {
    const double *rec = buf + c * CONTACT_FIELDS;
    // a wall (tag -1) sorts after the particles a touches
    const uint64_t low = static_cast<uint32_t>(static_cast<int64_t>(rec[TAG_B]));
    const uint64_t key = (static_cast<uint64_t>(rec[TAG_A]) << 32) | low;
    sort_keys[c] = {key, c};
  }
  std::sort(sort_keys.begin(), sort_keys.end());

  contact_list.resize(ncontacts);
  no_normal = 0;
  for (int c = 0; c < ncontacts; c++) {
    const double *rec = buf + sort_keys[c].second * CONTACT_FIELDS;
    // positions are remapped into the box: undo a periodic wrap
    double lx = rec[XB] - rec[XA], ly = rec[YB] - rec[YA], dz = 0.0;
    domain->minimum_image(lx, ly, dz);
    // force on b from a is minus the force on a from b
    fabric::Contact &k = contact_list[c];
    k = fabric::make_contact(static_cast<long>(rec[TAG_A]), static_cast<long>(rec[TAG_B]), lx, ly,
                             -rec[FAX], -rec[FAY], rec[RADSUM]);
    if (!fabric::has_normal(k) && no_normal++ == 0) first_no_normal = c;
  }
  if (no_normal > 0) warn_no_normal();

  index_contact_ends();

  long nlocal_selected = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom_selected(i)) nlocal_selected++;
  MPI_Allreduce(&nlocal_selected, &nparticles, 1, MPI_LONG, MPI_SUM, world);
}

/* ----------------------------------------------------------------------
   contacts with coincident centres (fabric::make_contact): once per compute,
   by rank 0, from the contact list every rank holds
------------------------------------------------------------------------- */

void ComputeFabric::warn_no_normal()
{
  if (warned_no_normal) return;
  warned_no_normal = true;
  if (comm->me != 0) return;
  const fabric::Contact &k = contact_list[first_no_normal];
  const std::string pair = k.b >= 0 ? "atoms " + std::to_string(k.a) + " and " + std::to_string(k.b)
                                    : "atom " + std::to_string(k.a) + " and a mesh wall";
  const std::string text = msg(
      std::to_string(no_normal) + " contact(s) with coincident centres (" + pair + ", distance " +
      number_text(std::hypot(k.lx, k.ly)) +
      ") have no normal; left out "
      "of the fabric and force directions, the stress and the stability index, still counted in "
      "N_c, C_n and Z_m (c_" +
      std::string(id) +
      "[17] is their number); were two atoms created "
      "at one point? (warned once)");
  error->warning(FLERR, text.c_str());
}

/* ----------------------------------------------------------------------
   the contact angles about each particle, grouped by tag: a stable sort of
   the contact ends, so that time and memory follow the number of contacts,
   not the largest atom ID (IDs may be sparse up to 2^31 with map hash)
------------------------------------------------------------------------- */

void ComputeFabric::index_contact_ends()
{
  ends.clear();
  for (const fabric::Contact &k : contact_list) {
    // a contact without a normal counts for both particles but has no angle
    const double theta = fabric::has_normal(k) ? std::atan2(k.ny, k.nx) : NAN;
    ends.push_back({k.a, theta});
    if (k.b >= 0) ends.push_back({k.b, theta + M_PI});
  }
  std::stable_sort(ends.begin(), ends.end(),
                   [](const End &x, const End &y) { return x.tag < y.tag; });
  end_tag.clear();
  end_start.clear();
  end_angle.resize(ends.size());
  for (size_t e = 0; e < ends.size(); e++) {
    if (e == 0 || ends[e].tag != ends[e - 1].tag) {
      end_tag.push_back(ends[e].tag);
      end_start.push_back(static_cast<int>(e));
    }
    end_angle[e] = ends[e].angle;
  }
  end_start.push_back(static_cast<int>(ends.size()));
}

/* ----------------------------------------------------------------------
   contact count of every selected particle; particles without contacts
   count as zeros
------------------------------------------------------------------------- */

std::vector<int> ComputeFabric::contacts_per_particle() const
{
  std::vector<int> per_particle;
  per_particle.reserve(nparticles);
  for (size_t t = 0; t + 1 < end_start.size(); t++)
    if (end_start[t + 1] > end_start[t]) per_particle.push_back(end_start[t + 1] - end_start[t]);
  per_particle.resize(std::max<long>(nparticles, per_particle.size()), 0);
  return per_particle;
}

/* ---------------------------------------------------------------------- */

// A variable is checked whenever it is evaluated (the same on every rank).
// It is evaluated here directly, not with ScalarInput::evaluate: that one
// clears the invoked flags of all computes (modify->clearstep_compute), which
// inside an output (thermo, fix ave/time) that invokes this compute makes the
// output skip scheduling the computes it already invoked, e.g. a per-atom
// virial for compute stress/atom at its next step.
double ComputeFabric::sample_area()
{
  const double area =
      area_in.is_variable() ? input->variable->compute_equal(area_ivar) : area_in.evaluate(lmp);
  if (!(std::isfinite(area) && area > 0.0))
    error->all(FLERR, keyword_message(PREFIX, "stress", area_in.text(),
                                      "is " + number_text(area) + " at step " +
                                          std::to_string(update->ntimestep) +
                                          "; it must be a positive number (the sample area)")
                          .c_str());
  return area;
}

/* ----------------------------------------------------------------------
   mean stability index over the particles with >= 2 contacts (rattlers
   with 0 or 1 contact count as 1 when 'rattlers yes')
------------------------------------------------------------------------- */

double ComputeFabric::mean_stability_index()
{
  // summed in tag order, so the same on any number of ranks
  double sum = 0.0;
  long n = 0;
  for (size_t t = 0; t + 1 < end_start.size(); t++) {
    const int first = end_start[t], last = end_start[t + 1];
    if (last - first < 2) continue;
    angles.assign(end_angle.begin() + first, end_angle.begin() + last);
    sum += fabric::stability_index(angles);
    n++;
  }
  if (rattlers_flag) {
    const long rattlers = nparticles - n;
    sum += static_cast<double>(rattlers);
    n = nparticles;
  }
  return n > 0 ? sum / n : 0.0;
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::compute_vector()
{
  invoked_vector = update->ntimestep;
  gather_contacts();

  std::fill(vector, vector + VECTOR_SIZE, 0.0);
  const fabric::BinCorrection correction = estimator == Estimator::Published
                                               ? fabric::BinCorrection::Published
                                               : fabric::BinCorrection::Unbiased;
  fabric::Anisotropy fabric_a;
  fabric::ForceAnisotropy force_a;
  if (estimator == Estimator::Tensor) {
    fabric_a = fabric::normal_anisotropy_tensor(contact_list);
    force_a = fabric::force_anisotropy_tensor(contact_list, fabric_a);
  } else {
    const fabric::Histogram hist = fabric::polar_histogram(contact_list, nbins);
    fabric_a = fabric::normal_anisotropy_histogram(hist, correction);
    force_a = fabric::force_anisotropy_histogram(hist, correction);
  }
  vector[A] = fabric_a.a;
  vector[THETA_A] = fabric_a.theta * RAD2DEG;
  vector[A_N] = force_a.an;
  vector[THETA_N] = force_a.theta_n * RAD2DEG;
  vector[F0] = force_a.f0;
  vector[A_T] = force_a.at;
  vector[THETA_T] = force_a.theta_t * RAD2DEG;
  vector[EMPTY_BINS] = force_a.empty_bins;

  const fabric::Coordination coord = fabric::coordination(contacts_per_particle());
  vector[CN] = coord.Cn;
  vector[ZM] = coord.Zm;
  vector[NCONTACT] = static_cast<double>(contact_list.size());
  vector[NPARTICLE] = static_cast<double>(nparticles);
  vector[NO_NORMAL] = static_cast<double>(no_normal);

  if (stability_flag) vector[MEAN_GSI] = mean_stability_index();

  if (stress_flag) {
    const Eigen::Matrix2d sigma = fabric::love_weber_stress(contact_list, sample_area());
    vector[SXX] = sigma(0, 0);
    vector[SYY] = sigma(1, 1);
    vector[SXY] = 0.5 * (sigma(0, 1) + sigma(1, 0));
  }
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::compute_array()
{
  invoked_array = update->ntimestep;
  gather_contacts();
  const fabric::Histogram hist = fabric::polar_histogram(contact_list, nbins);
  const double width = 2.0 * M_PI / nbins;
  for (int g = 0; g < nbins; g++) {
    array[g][0] = (g + 0.5) * width * RAD2DEG;
    array[g][1] = hist.count[g];
    array[g][2] = hist.mean_fn[g];
    array[g][3] = hist.mean_ft[g];
  }
}

/* ----------------------------------------------------------------------
   per-atom contact count and stability index (1 for < 2 contacts);
   computed only when a dump or variable asks for them
------------------------------------------------------------------------- */

void ComputeFabric::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  gather_contacts();

  if (atom->nmax > nmax_atom) {
    memory->destroy(array_atom);
    nmax_atom = atom->nmax;
    memory->create(array_atom, nmax_atom, 2, "fabric:array_atom");
  }
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) array_atom[i][0] = array_atom[i][1] = 0.0;

  for (int i = 0; i < nlocal; i++) {
    if (!atom_selected(i)) continue;
    const auto it =
        std::lower_bound(end_tag.begin(), end_tag.end(), static_cast<long>(atom->tag[i]));
    const bool found = it != end_tag.end() && *it == atom->tag[i];
    const size_t t = static_cast<size_t>(it - end_tag.begin());
    const int first = found ? end_start[t] : 0;
    const int last = found ? end_start[t + 1] : 0;
    angles.assign(end_angle.begin() + first, end_angle.begin() + last);
    array_atom[i][0] = static_cast<double>(last - first);
    array_atom[i][1] = fabric::stability_index(angles);
  }
}

/* ---------------------------------------------------------------------- */

double ComputeFabric::memory_usage()
{
  double bytes = contact_list.capacity() * sizeof(fabric::Contact);
  bytes += (sendbuf.capacity() + recvbuf.capacity()) * sizeof(double);
  bytes += 2.0 * nmax_atom * sizeof(double);
  return bytes;
}

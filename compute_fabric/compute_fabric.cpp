/* ----------------------------------------------------------------------
   compute fabric: see compute_fabric.h and doc/compute_fabric.md
------------------------------------------------------------------------- */

#include "compute_fabric.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <cstdint>

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

bool is_yes_no(const char *s) { return strcmp(s, "yes") == 0 || strcmp(s, "no") == 0; }

}  // namespace

/* ---------------------------------------------------------------------- */

ComputeFabric::ComputeFabric(LAMMPS *lammps, int &iarg, int narg, char **arg) :
  Compute(lammps, iarg, narg, arg),
  nbins(18), estimator(Estimator::Unbiased), stability_flag(false),
  rattlers_flag(false), histogram_flag(false), stress_flag(false),
  area_value(0.0), area_varname(nullptr), area_ivar(-1),
  idregion(nullptr), iregion(-1),
  walls_flag(false),
  gathered_step(-1), nparticles(0), no_normal(0), first_no_normal(0),
  warned_no_normal(false), nmax_atom(0)
{
  if (domain->dimension != 2)
    error->all(FLERR, "Compute fabric requires dimension 2");
  if (atom->tag_enable == 0 || atom->map_style == 0)
    error->all(FLERR, "Compute fabric requires atom IDs and an atom map (atom_modify map array)");
  if (!atom->radius_flag)
    error->all(FLERR, "Compute fabric requires atom style sphere (granular)");

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
  while (iarg < narg) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, (std::string("Illegal compute fabric command: keyword '") + key +
                         "' needs a value").c_str());
    const char *value = arg[iarg + 1];
    if (strcmp(key, "bins") == 0) {
      char *end = nullptr;
      long n = strtol(value, &end, 10);
      if (*end != '\0' || n < 6 || n > 3600 || n % 2 != 0)
        error->all(FLERR, "Illegal compute fabric command: 'bins' must be an even integer from 6 to 3600");
      nbins = static_cast<int>(n);
    } else if (strcmp(key, "estimator") == 0) {
      if (strcmp(value, "unbiased") == 0) estimator = Estimator::Unbiased;
      else if (strcmp(value, "published") == 0) estimator = Estimator::Published;
      else if (strcmp(value, "tensor") == 0) estimator = Estimator::Tensor;
      else error->all(FLERR, "Illegal compute fabric command: 'estimator' must be unbiased, published or tensor");
    } else if (strcmp(key, "stability") == 0 || strcmp(key, "rattlers") == 0 ||
               strcmp(key, "histogram") == 0 || strcmp(key, "walls") == 0) {
      if (!is_yes_no(value))
        error->all(FLERR, (std::string("Illegal compute fabric command: '") + key +
                           "' must be yes or no").c_str());
      const bool on = strcmp(value, "yes") == 0;
      if (key[0] == 's') stability_flag = on;
      else if (key[0] == 'r') rattlers_flag = on;
      else if (key[0] == 'w') walls_flag = on;
      else histogram_flag = on;
    } else if (strcmp(key, "stress") == 0) {
      stress_flag = true;
      if (strncmp(value, "v_", 2) == 0) {
        area_varname = new char[strlen(value + 2) + 1];
        strcpy(area_varname, value + 2);
      } else {
        char *end = nullptr;
        area_value = strtod(value, &end);
        if (*end != '\0' || !(area_value > 0.0) || !std::isfinite(area_value))
          error->all(FLERR, "Illegal compute fabric command: 'stress' needs a positive area or v_name");
      }
    } else if (strcmp(key, "region") == 0) {
      if (domain->find_region(value) < 0)
        error->all(FLERR, (std::string("Compute fabric: region '") + value + "' does not exist").c_str());
      idregion = new char[strlen(value) + 1];
      strcpy(idregion, value);
    } else {
      error->all(FLERR, (std::string("Illegal compute fabric command: unknown keyword '") +
                         key + "'").c_str());
    }
    iarg += 2;
  }
}

/* ---------------------------------------------------------------------- */

ComputeFabric::~ComputeFabric()
{
  memory->destroy(vector);
  memory->destroy(array);
  memory->destroy(array_atom);
  delete[] area_varname;
  delete[] idregion;
  delete[] pairs.id;
  delete[] walls.id;
}

/* ----------------------------------------------------------------------
   Contact forces come from LIGGGHTS' own compute pair/gran/local: the pair
   style evaluates its contact model again at the current positions with the
   stored contact history (not updated), so these are the forces the pair
   applied this step. A pair style accepts only one such compute: reuse one
   the user defined (before or after this compute), else create ours at the
   first init, when every compute of the input script exists.
------------------------------------------------------------------------- */

void ComputeFabric::find_source(ContactSource &src)
{
  src.compute = nullptr;
  for (int i = 0; i < modify->ncompute; i++) {
    Compute *c = modify->compute[i];
    if (c == this || strcmp(c->style, src.style) != 0) continue;
    if (src.id && strcmp(c->id, src.id) != 0) continue;
    ComputePairGranLocal *found = static_cast<ComputePairGranLocal *>(c);
    if (found->offset_x1() < 0 || found->offset_id1() < 0 || found->offset_f() < 0)
      error->all(FLERR, (std::string("Compute fabric: compute ") + c->id + " (" + src.style +
                         ") must include the values 'pos id force' for compute fabric to read it").c_str());
    if (c->igroup != 0 && c->igroup != igroup)
      error->all(FLERR, (std::string("Compute fabric: compute ") + c->id + " (" + src.style +
                         ") must use group all or the group of compute fabric").c_str());
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
  args[1] = group->names[igroup];
  args[2] = const_cast<char *>(src.style);
  args[3] = (char *) "pos";
  args[4] = (char *) "id";
  args[5] = (char *) "force";
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
  if (!src.compute && src.id)
    error->all(FLERR, (std::string("Compute fabric: compute ") + src.id + " (" + src.style +
                       ") that it reads was deleted").c_str());
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
      error->all(FLERR, "Compute fabric: 'walls yes' needs a fix wall/gran with mesh walls "
                        "(LIGGGHTS reports no contact forces for primitive walls)");
    init_source(walls, "_walls");
  }

  if (idregion) {
    iregion = domain->find_region(idregion);
    if (iregion < 0)
      error->all(FLERR, (std::string("Compute fabric: region '") + idregion + "' does not exist").c_str());
  }
  if (area_varname) {
    area_ivar = input->variable->find(area_varname);
    if (area_ivar < 0)
      error->all(FLERR, (std::string("Compute fabric: variable '") + area_varname +
                         "' for the stress area does not exist").c_str());
    if (!input->variable->equalstyle(area_ivar))
      error->all(FLERR, (std::string("Compute fabric: variable '") + area_varname +
                         "' for the stress area must be equal-style").c_str());
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
      const double w[CONTACT_FIELDS] = {row[oid + 2], -1.0, xp[0], xp[1], cp[0], cp[1],
                                        row[of], row[of + 1], atom->radius[ip]};
      std::copy(w, w + CONTACT_FIELDS, rec);
    } else {
      const double *xa = row + ox, *xb = row + ox + 3;
      // a pair/gran/local of group all (the user's) reports contacts outside our group
      const int ia = atom->map(static_cast<int>(row[oid]));
      const int ib = atom->map(static_cast<int>(row[oid + 1]));
      if (ia < 0 || ib < 0 || !(atom->mask[ia] & groupbit) || !(atom->mask[ib] & groupbit)) continue;
      if (region && (!region->match(xa[0], xa[1], xa[2]) || !region->match(xb[0], xb[1], xb[2])))
        continue;
      const double p[CONTACT_FIELDS] = {row[oid], row[oid + 1], xa[0], xa[1], xb[0], xb[1],
                                        row[of], row[of + 1], atom->radius[ia] + atom->radius[ib]};
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
    k = fabric::make_contact(static_cast<long>(rec[TAG_A]), static_cast<long>(rec[TAG_B]),
                             lx, ly, -rec[FAX], -rec[FAY], rec[RADSUM]);
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
  const std::string text =
      "Compute fabric: " + std::to_string(no_normal) + " contact(s) with coincident centres (" +
      pair + ", distance " + number_text(std::hypot(k.lx, k.ly)) + ") have no normal; left out "
      "of the fabric and force directions, the stress and the stability index, still counted in "
      "N_c, C_n and Z_m (c_" + std::string(id) + "[17] is their number); were two atoms created "
      "at one point? (warned once)";
  error->warning(FLERR, text.c_str());
}

/* ----------------------------------------------------------------------
   the contact angles about each particle, grouped by tag (counting sort:
   tags are at most natoms with an atom map, so this is O(contacts))
------------------------------------------------------------------------- */

void ComputeFabric::index_contact_ends()
{
  long maxtag = 0;
  for (const fabric::Contact &k : contact_list) maxtag = std::max({maxtag, k.a, k.b});
  end_start.assign(maxtag + 2, 0);
  for (const fabric::Contact &k : contact_list) {
    end_start[k.a + 1]++;
    if (k.b >= 0) end_start[k.b + 1]++;
  }
  for (long t = 0; t <= maxtag; t++) end_start[t + 1] += end_start[t];
  end_angle.resize(end_start[maxtag + 1]);
  fill.assign(end_start.begin(), end_start.end() - 1);
  for (const fabric::Contact &k : contact_list) {
    // a contact without a normal counts for both particles but has no angle
    const double theta = fabric::has_normal(k) ? std::atan2(k.ny, k.nx) : NAN;
    end_angle[fill[k.a]++] = theta;
    if (k.b >= 0) end_angle[fill[k.b]++] = theta + M_PI;
  }
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

double ComputeFabric::sample_area()
{
  if (!area_varname) return area_value;
  const double area = input->variable->compute_equal(area_ivar);
  if (!(area > 0.0) || !std::isfinite(area))
    error->all(FLERR, "Compute fabric: the stress area variable is not a positive number");
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
    const size_t t = static_cast<size_t>(atom->tag[i]);
    const int first = t + 1 < end_start.size() ? end_start[t] : 0;
    const int last = t + 1 < end_start.size() ? end_start[t + 1] : 0;
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

/* ----------------------------------------------------------------------
   compute fabric's own contacts and their reduction: see fabric_local.h
------------------------------------------------------------------------- */

#include "fabric_local.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "compute_pair_gran_local.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "region.h"
#include "update.h"

#include "contact_record.h"
#include "fabric_sums.h"
#include "math_constants.h"
#include "number_text.h"
#include "style_error.h"

using namespace LAMMPS_NS;
using namespace fabric;

bool LAMMPS_NS::atom_selected(const Atom *atom, int i, int groupbit, Region *region)
{
  if (!(atom->mask[i] & groupbit)) return false;
  if (!region) return true;
  double **x = atom->x;
  return region->match(x[i][0], x[i][1], x[i][2]) != 0;
}

// MPI_Allreduce operation on (hi, lo) pairs: ExactSum::merge
static void merge_exact_sums(void *in, void *inout, int *len, MPI_Datatype *)
{
  const double *from = static_cast<const double *>(in);
  double *into = static_cast<double *>(inout);
  for (int k = 0; k < *len; k++) {
    ExactSum sum{into[2 * k], into[2 * k + 1]};
    sum.merge({from[2 * k], from[2 * k + 1]});
    into[2 * k] = sum.hi;
    into[2 * k + 1] = sum.lo;
  }
}

FabricLocal::FabricLocal(LAMMPS *lammps, Compute *fabric_compute, const std::string &prefix_)
  : Pointers(lammps), owner(fabric_compute), prefix(prefix_),
    three_d(lammps->domain->dimension == 3), sources(lammps, fabric_compute, prefix_)
{
  // a pair is one element, so MPI never splits one when it segments a reduction
  MPI_Type_contiguous(2, MPI_DOUBLE, &pair_type);
  MPI_Type_commit(&pair_type);
  MPI_Op_create(merge_exact_sums, 1, &merge_op);
}

FabricLocal::~FabricLocal()
{
  MPI_Op_free(&merge_op);
  MPI_Type_free(&pair_type);
}

void FabricLocal::init(bool with_walls)
{
  sources.init(with_walls);
}

/* ----------------------------------------------------------------------
   Each contact is counted on exactly one rank. compute pair/gran/local gets
   a row per touching pair of its half neighbour list, i local; with newton
   off a pair of an owned atom i and a ghost j is in the lists of both
   owners, and LIGGGHTS keeps the row only where tag i > tag j (compute
   pair/gran/local's add_pair): the contact belongs to the owner of the
   LARGER tag. add_rows applies that rule again (a no-op on LIGGGHTS 3.8,
   a guard against a duplicate). A pair of two owned atoms (also through a
   periodic image) has one row. A wall contact belongs to its particle's
   owner (wall/gran/local reports local particles only).
------------------------------------------------------------------------- */

int FabricLocal::collect(Region *region, bool angles_wanted)
{
  // Ghost velocities date from the start of the step; the contact model's
  // damping terms need the current ones, or a contact across a processor
  // boundary would differ from the same contact inside one rank.
  bool refreshed = false;
  with_angles = angles_wanted;
  local.clear();
  local3.clear();
  missing.clear();
  theta.clear();
  const int nall = atom->nlocal + atom->nghost;
  counts.assign(nall, 0);
  if (with_angles) {
    if (static_cast<int>(ends.size()) < nall) ends.resize(nall);
    for (int i = 0; i < nall; i++) ends[i].clear();
  }
  for (ComputePairGranLocal *src : {sources.pairs(), sources.walls()}) {
    if (!src) continue;
    if (src->invoked_local != update->ntimestep) {
      if (!refreshed) comm->forward_comm();
      refreshed = true;
      src->compute_local();
    }
    add_rows(src, src == sources.walls(), region);
  }
  sent.assign(nall, 0);
  return send_ends_round();
}

void FabricLocal::add_contact(const Contact &c, int index_a, int index_b)
{
  local.push_back(c);
  counts[index_a]++;
  if (index_b >= 0) counts[index_b]++;
  if (!has_normal(c)) missing.push_back({c.a, c.b, std::hypot(c.lx, c.ly)});
  if (!with_angles) return;
  // a contact without a normal counts for both particles but has no angle
  const double angle = has_normal(c) ? std::atan2(c.ny, c.nx) : NAN;
  theta.push_back(angle);
  ends[index_a].push_back(angle);
  if (index_b >= 0) ends[index_b].push_back(angle + math_constants::PI);
}

void FabricLocal::add_contact3(const Contact3 &c, int index_a, int index_b)
{
  local3.push_back(c);
  counts[index_a]++;
  if (index_b >= 0) counts[index_b]++;
  if (!has_normal(c)) missing.push_back({c.a, c.b, c.l.norm()});
}

// A pair/gran/local of group all (the user's) reports contacts outside the
// group, and a region leaves out more: both ends must be selected.
void FabricLocal::add_rows(ComputePairGranLocal *c, bool wall, Region *region)
{
  const int nrows = c->size_local_rows, nlocal = atom->nlocal;
  double **rows = c->get_data();
  const int ox = c->offset_x1(), oid = c->offset_id1(), of = c->offset_f();
  const int groupbit = owner->groupbit;

  for (int r = 0; r < nrows; r++) {
    const double *row = rows[r];
    ContactRecord rec;
    int index_a, index_b = -1;
    if (wall) {
      // wall/gran/local: pos = contact point, particle centre; id = mesh, triangle, tag
      const double *cp = row + ox, *xp = row + ox + 3;
      const int ip = atom->map(static_cast<int>(row[oid + 2]));
      if (ip < 0 || ip >= nlocal || !(atom->mask[ip] & groupbit)) continue;
      if (region && !region->match(xp[0], xp[1], xp[2])) continue;
      if (three_d) {
        double l[3] = {cp[0] - xp[0], cp[1] - xp[1], cp[2] - xp[2]};
        domain->minimum_image(l[0], l[1], l[2]);
        add_contact3(wall_contact3(static_cast<long>(row[oid + 2]), l, row + of, atom->radius[ip]),
                     ip, -1);
        continue;
      }
      rec = wall_record(static_cast<long>(row[oid + 2]), xp, cp, row + of, atom->radius[ip]);
      index_a = ip;
    } else {
      const double *xa = row + ox, *xb = row + ox + 3;
      const long tag_i = static_cast<long>(row[oid]), tag_j = static_cast<long>(row[oid + 1]);
      const int ia = atom->map(static_cast<int>(tag_i));
      const int ib = atom->map(static_cast<int>(tag_j));
      if (ia < 0 || ib < 0 || ia >= nlocal) continue;
      // the rule above: a ghost pair belongs to the owner of the larger tag
      if (!force->newton_pair && ib >= nlocal && tag_i < tag_j) continue;
      if (!(atom->mask[ia] & groupbit) || !(atom->mask[ib] & groupbit)) continue;
      if (region && (!region->match(xa[0], xa[1], xa[2]) || !region->match(xb[0], xb[1], xb[2])))
        continue;
      index_a = tag_i < tag_j ? ia : ib;
      index_b = tag_i < tag_j ? ib : ia;
      if (three_d) {
        double l[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
        domain->minimum_image(l[0], l[1], l[2]);
        add_contact3(pair_contact3(tag_i, tag_j, l, row + of, atom->radius[ia] + atom->radius[ib]),
                     index_a, index_b);
        continue;
      }
      rec = pair_record(tag_i, tag_j, xa, xb, row + of, atom->radius[ia] + atom->radius[ib]);
    }
    // positions are remapped into the box: undo a periodic wrap
    double lx = rec[XB] - rec[XA], ly = rec[YB] - rec[YA], dz = 0.0;
    domain->minimum_image(lx, ly, dz);
    add_contact(record_contact(rec.data(), lx, ly), index_a, index_b);
  }
}

/* ----------------------------------------------------------------------
   The counts (and angles) gathered at a ghost go to its owner by LIGGGHTS'
   reverse communication (every ghost copy reaches the owner, through the
   copies a corner ghost is made from): one double per ghost without angles,
   else END_SLOTS. One round carries up to END_SLOTS - 1 angles per ghost;
   usually one round is enough (the flag whether more are needed travels with
   the sums, reduce), else finish_ends repeats them.
------------------------------------------------------------------------- */

int FabricLocal::send_ends_round()
{
  comm->reverse_comm_compute(owner);
  if (!with_angles) return 0;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  for (int i = nlocal; i < nall; i++)
    if (sent[i] < static_cast<int>(ends[i].size())) return 1;
  return 0;
}

void FabricLocal::finish_ends()
{
  int left = 1, any = 1;
  while (true) {
    MPI_Allreduce(&left, &any, 1, MPI_INT, MPI_MAX, world);
    if (!any) return;
    left = send_ends_round();
  }
}

int FabricLocal::pack_ends(int n, int first, double *buf)
{
  if (!with_angles) {
    for (int i = first; i < first + n; i++) buf[i - first] = counts[i];
    return 1;
  }
  for (int i = first; i < first + n; i++) {
    double *slot = buf + (i - first) * END_SLOTS;
    const int k = std::min(END_SLOTS - 1, static_cast<int>(ends[i].size()) - sent[i]);
    slot[0] = k;
    for (int e = 0; e < k; e++) slot[1 + e] = ends[i][sent[i] + e];
    sent[i] += k;
  }
  return END_SLOTS;
}

void FabricLocal::unpack_ends(int n, const int *list, const double *buf)
{
  for (int m = 0; m < n; m++) {
    if (!with_angles) {
      counts[list[m]] += static_cast<int>(buf[m]);
      continue;
    }
    const double *slot = buf + m * END_SLOTS;
    const int k = static_cast<int>(slot[0]);
    counts[list[m]] += k;
    ends[list[m]].insert(ends[list[m]].end(), slot + 1, slot + 1 + k);
  }
}

void FabricLocal::reduce(std::vector<double> &packed)
{
  MPI_Allreduce(MPI_IN_PLACE, packed.data(), static_cast<int>(packed.size() / 2), pair_type,
                merge_op, world);
}

bool FabricLocal::reduce(FabricSums &sums, ParticleSums &particles, int left)
{
  std::vector<double> packed = sums.pack();
  const std::vector<double> p = particles.pack();
  packed.insert(packed.end(), p.begin(), p.end());
  packed.push_back(left); // an exact sum of 0s and 1s
  packed.push_back(0.0);
  reduce(packed);
  sums.unpack(packed.data());
  particles.unpack(packed.data() + 2 * sums.pairs());
  return packed[packed.size() - 2] > 0.0;
}

// (tag a, tag b) as one key in the order of the old sorted list: a wall
// (b = -1) after the particles a touches. LIGGGHTS' tags are ints.
/* ----------------------------------------------------------------------
   contacts with coincident centres (fabric::make_contact): printed by rank
   0, naming the pair with the smallest tags over all ranks
------------------------------------------------------------------------- */

void FabricLocal::warn_missing_normals(long count, const std::string &count_output)
{
  unsigned long long key = std::numeric_limits<unsigned long long>::max(), first = 0;
  double length = std::numeric_limits<double>::infinity(), distance = 0.0;
  for (const MissingNormal &c : missing) {
    const unsigned long long k = (static_cast<unsigned long long>(c.a) << 32) |
                                 static_cast<uint32_t>(static_cast<int64_t>(c.b));
    if (k < key) {
      key = k;
      length = c.length;
    }
  }
  MPI_Allreduce(&key, &first, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, world);
  if (key != first) length = std::numeric_limits<double>::infinity();
  MPI_Allreduce(&length, &distance, 1, MPI_DOUBLE, MPI_MIN, world);
  const long a = static_cast<long>(first >> 32);
  const uint32_t low = static_cast<uint32_t>(first & 0xffffffffULL);
  const std::string pair = low == 0xffffffffU
                               ? "atom " + std::to_string(a) + " and a mesh wall"
                               : "atoms " + std::to_string(a) + " and " + std::to_string(low);
  style_warning(lmp, prefix,
                std::to_string(count) + " contact(s) with coincident centres (" + pair +
                    ", distance " + number_text(distance) +
                    ") have no normal; left out of the fabric and force directions, the stress "
                    "and the stability index, still counted in N_c, C_n and Z_m (" +
                    count_output +
                    " is their number); were two atoms created at one point? (warned once)");
}

double FabricLocal::memory_usage() const
{
  double bytes = static_cast<double>(local.capacity()) * sizeof(Contact) +
                 static_cast<double>(local3.capacity()) * sizeof(Contact3) +
                 static_cast<double>(missing.capacity()) * sizeof(MissingNormal);
  bytes += theta.capacity() * sizeof(double);
  for (const std::vector<double> &e : ends) bytes += e.capacity() * sizeof(double);
  return bytes + (sent.capacity() + counts.capacity()) * sizeof(int);
}

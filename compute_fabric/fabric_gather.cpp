/* ----------------------------------------------------------------------
   compute fabric's contact gather: see fabric_gather.h
------------------------------------------------------------------------- */

#include "fabric_gather.h"

#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "compute_pair_gran_local.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "modify.h"
#include "region.h"
#include "update.h"

#include "allgather.h"
#include "contact_record.h"
#include "style_args.h"

using namespace LAMMPS_NS;
using namespace fabric;

namespace {

// every message starts so (doc/messages.md)
const char *const PREFIX = "Compute fabric: ";

std::string msg(const std::string &text)
{
  return PREFIX + text;
}

char *copy_of(const std::string &text)
{
  char *copy = new char[text.size() + 1];
  strcpy(copy, text.c_str());
  return copy;
}

} // namespace

bool LAMMPS_NS::atom_selected(const Atom *atom, int i, int groupbit, Region *region)
{
  if (!(atom->mask[i] & groupbit)) return false;
  if (!region) return true;
  double **x = atom->x;
  return region->match(x[i][0], x[i][1], x[i][2]) != 0;
}

FabricGather::FabricGather(LAMMPS *lammps, Compute *fabric_compute)
  : Pointers(lammps), owner(fabric_compute)
{
}

FabricGather::~FabricGather()
{
  delete[] pairs.id;
  delete[] walls.id;
}

/* ----------------------------------------------------------------------
   Contact forces come from LIGGGHTS' own compute pair/gran/local: the pair
   style evaluates its contact model again at the current positions with the
   stored contact history (not updated), so these are the forces the pair
   applied this step. A pair style accepts only one such compute, so every
   compute fabric reads the same one: one the user defined (before or after
   the compute fabric), else ours, created at the first init (when every
   compute of the input script exists) in group all, because pack_contacts
   keeps only the contacts of the compute fabric's group anyway.
------------------------------------------------------------------------- */

void FabricGather::init(bool with_walls)
{
  init_source(pairs, "_contacts");
  if (!with_walls) return;
  // (fix_wall_gran.h cannot be included from the Debian headers, so a mesh
  // wall is recognised by the mesh fixes it needs)
  if (modify->n_fixes_style("wall/gran") == 0 || modify->n_fixes_style("mesh/surface") == 0)
    error->all(FLERR, keyword_message(PREFIX, "walls", "yes",
                                      "needs a fix wall/gran with mesh walls (LIGGGHTS reports "
                                      "no contact forces for primitive walls); use mesh walls "
                                      "(fix mesh/surface and fix wall/gran ... mesh) or walls no")
                          .c_str());
  init_source(walls, "_walls");
}

void FabricGather::init_source(ContactSource &src, const char *suffix)
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

void FabricGather::find_source(ContactSource &src)
{
  src.compute = nullptr;
  const std::string fabric_group = group->names[owner->igroup];
  for (int i = 0; i < modify->ncompute; i++) {
    Compute *c = modify->compute[i];
    if (c == owner || strcmp(c->style, src.style) != 0) continue;
    if (src.id && strcmp(c->id, src.id) != 0) continue;
    const std::string source_group = group->names[c->igroup];
    const std::string named =
        std::string("compute ") + c->id + " (" + src.style + ", group " + source_group + ")";
    ComputePairGranLocal *found = static_cast<ComputePairGranLocal *>(c);
    if (found->offset_x1() < 0 || found->offset_id1() < 0 || found->offset_f() < 0)
      error->all(FLERR, msg(named + " lacks the values pos, id or force that compute " + owner->id +
                            " (fabric) reads from it; define it as compute " + c->id + " " +
                            source_group + " " + src.style + " pos id force")
                            .c_str());
    if (c->igroup != 0 && c->igroup != owner->igroup)
      error->all(FLERR, msg("compute " + std::string(owner->id) + " (fabric, group " +
                            fabric_group + ") reads the contacts from " + named +
                            ", which leaves out the contacts outside group " + source_group +
                            "; define compute " + c->id +
                            " in group all: a pair style takes one compute " + src.style +
                            " and every compute fabric reads it")
                            .c_str());
    src.compute = found;
    if (!src.id) src.id = copy_of(c->id);
    return;
  }
}

void FabricGather::create_source(ContactSource &src, const char *suffix)
{
  delete[] src.id;
  src.id = copy_of(std::string(owner->id) + suffix);

  char *args[6] = {src.id,        (char *)"all", const_cast<char *>(src.style),
                   (char *)"pos", (char *)"id",  (char *)"force"};
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

/* ----------------------------------------------------------------------
   Every rank ends with the same contact list, sorted by (tag a, tag b) with
   tag a < tag b, so every statistic is summed in the same order whatever the
   number of ranks. pair/gran/local already reports a contact across a
   processor boundary on one rank only (newton off: the smaller tag's side).
------------------------------------------------------------------------- */

std::vector<Contact> FabricGather::gather(Region *region)
{
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
    pack_contacts(*src, src == &walls, region);
  }

  allgather_doubles(world, sendbuf, recvbuf, recvcounts, displs);

  const std::vector<int> order = order_by_tags(recvbuf);
  std::vector<Contact> contacts(order.size());
  for (size_t c = 0; c < order.size(); c++) {
    const double *rec = recvbuf.data() + order[c] * CONTACT_FIELDS;
    // positions are remapped into the box: undo a periodic wrap
    double lx = rec[XB] - rec[XA], ly = rec[YB] - rec[YA], dz = 0.0;
    domain->minimum_image(lx, ly, dz);
    contacts[c] = record_contact(rec, lx, ly);
  }
  return contacts;
}

// A pair/gran/local of group all (the user's) reports contacts outside the
// group, and a region leaves out more: both ends must be selected.
void FabricGather::pack_contacts(const ContactSource &src, bool wall, Region *region)
{
  ComputePairGranLocal *c = src.compute;
  const int nrows = c->size_local_rows;
  double **rows = c->get_data();
  const int ox = c->offset_x1(), oid = c->offset_id1(), of = c->offset_f();
  const int groupbit = owner->groupbit;

  for (int r = 0; r < nrows; r++) {
    const double *row = rows[r];
    ContactRecord rec;
    if (wall) {
      // wall/gran/local: pos = contact point, particle centre; id = mesh, triangle, tag
      const double *cp = row + ox, *xp = row + ox + 3;
      const int ip = atom->map(static_cast<int>(row[oid + 2]));
      if (ip < 0 || !(atom->mask[ip] & groupbit)) continue;
      if (region && !region->match(xp[0], xp[1], xp[2])) continue;
      rec = wall_record(static_cast<long>(row[oid + 2]), xp, cp, row + of, atom->radius[ip]);
    } else {
      const double *xa = row + ox, *xb = row + ox + 3;
      const int ia = atom->map(static_cast<int>(row[oid]));
      const int ib = atom->map(static_cast<int>(row[oid + 1]));
      if (ia < 0 || ib < 0 || !(atom->mask[ia] & groupbit) || !(atom->mask[ib] & groupbit))
        continue;
      if (region && (!region->match(xa[0], xa[1], xa[2]) || !region->match(xb[0], xb[1], xb[2])))
        continue;
      rec = pair_record(static_cast<long>(row[oid]), static_cast<long>(row[oid + 1]), xa, xb,
                        row + of, atom->radius[ia] + atom->radius[ib]);
    }
    sendbuf.insert(sendbuf.end(), rec.begin(), rec.end());
  }
}

long FabricGather::count_particles(Region *region) const
{
  long nlocal_selected = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom_selected(atom, i, owner->groupbit, region)) nlocal_selected++;
  long n = 0;
  MPI_Allreduce(&nlocal_selected, &n, 1, MPI_LONG, MPI_SUM, world);
  return n;
}

double FabricGather::memory_usage() const
{
  return static_cast<double>(sendbuf.capacity() + recvbuf.capacity()) * sizeof(double);
}

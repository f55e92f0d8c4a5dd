/* ----------------------------------------------------------------------
   compute fabric's contact sources: see gran_local_sources.h
------------------------------------------------------------------------- */

#include "gran_local_sources.h"

#include <cstring>
#include <string>

#include "compute.h"
#include "compute_pair_gran_local.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "update.h"

#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;

namespace {

char *copy_of(const std::string &text)
{
  char *copy = new char[text.size() + 1];
  strcpy(copy, text.c_str());
  return copy;
}

} // namespace

GranLocalSources::GranLocalSources(LAMMPS *lammps, Compute *fabric_compute,
                                   const std::string &prefix_)
  : Pointers(lammps), owner(fabric_compute), prefix(prefix_)
{
}

GranLocalSources::~GranLocalSources()
{
  delete[] pairs_.id;
  delete[] walls_.id;
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

void GranLocalSources::init(bool with_walls)
{
  // before the pair/gran/local it creates says so without naming compute fabric
  if (!force->pair)
    style_error(lmp, prefix,
                "compute " + std::string(owner->id) +
                    " reads the contacts of the pair style, and there is none; define a "
                    "granular pair style (e.g. pair_style gran model hertz tangential "
                    "history) before the run");
  init_source(pairs_, "_contacts");
  if (!with_walls) return;
  // (fix_wall_gran.h cannot be included from the Debian headers, so a mesh
  // wall is recognised by the mesh fixes it needs)
  if (modify->n_fixes_style("wall/gran") == 0 || modify->n_fixes_style("mesh/surface") == 0)
    style_error(lmp, prefix,
                keyword_text("walls", "yes",
                             "needs a fix wall/gran with mesh walls (LIGGGHTS reports no contact "
                             "forces for primitive walls); use mesh walls (fix mesh/surface and "
                             "fix wall/gran ... mesh) or walls no"));
  init_source(walls_, "_walls");
}

void GranLocalSources::init_source(ContactSource &src, const char *suffix)
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

void GranLocalSources::find_source(ContactSource &src)
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
      style_error(lmp, prefix,
                  named + " lacks the values pos, id or force that compute " + owner->id +
                      " (fabric) reads from it; define it as compute " + c->id + " " +
                      source_group + " " + src.style + " pos id force");
    if (c->igroup != 0 && c->igroup != owner->igroup)
      style_error(lmp, prefix,
                  "compute " + std::string(owner->id) + " (fabric, group " + fabric_group +
                      ") reads the contacts from " + named +
                      ", which leaves out the contacts outside group " + source_group +
                      "; define compute " + c->id +
                      " in group all: a pair style takes one compute " + src.style +
                      " and every compute fabric reads it");
    src.compute = found;
    if (!src.id) src.id = copy_of(c->id);
    return;
  }
}

void GranLocalSources::create_source(ContactSource &src, const char *suffix)
{
  delete[] src.id;
  src.id = copy_of(std::string(owner->id) + suffix);
  const int taken = modify->find_compute(src.id);
  if (taken >= 0)
    style_error(lmp, prefix,
                "compute " + std::string(owner->id) + " (fabric) creates its compute " + src.style +
                    " as '" + src.id + "', and compute " + src.id + " (" +
                    modify->compute[taken]->style + ") exists; rename one of them");

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

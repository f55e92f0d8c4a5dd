#include "membrane_checks.h"

#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "update.h"

#include "fix_membrane2d.h"
#include "membrane_output.h"
#include "membrane_setup.h"
#include "style_args.h"
#include "vtk_series.h"

using namespace LAMMPS_NS;

void check_atom_setup(LAMMPS *lmp, const char *prefix)
{
  check_membrane_setup(lmp, prefix, 2);
}

void check_platens_order(LAMMPS *lmp, const char *prefix, const ScalarInput &ylo_in, double ylo,
                         double yhi)
{
  if (!(ylo < yhi))
    lmp->error->all(
        FLERR, keyword_message(prefix, "ylo", ylo_in.text(),
                               "is " + number_text(ylo) + ", not below yhi = " + number_text(yhi) +
                                   " at step " + std::to_string(lmp->update->ntimestep) +
                                   "; ylo is the bottom platen surface, yhi the top one")
                   .c_str());
}

// two membranes on one disk would apply the pressure twice and fight over its type
void check_other_membranes(LAMMPS *lmp, const char *prefix, Fix *self, MembraneGather &gather)
{
  Modify *modify = lmp->modify;
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == self || strcmp(other->style, self->style) != 0) continue;
    const bigint total = gather.shared_disks(other->groupbit);
    const bool first = f < modify->find_fix(self->id);
    const std::string pair = std::string(prefix) + "fixes '" + (first ? other->id : self->id) +
                             "' and '" + (first ? self->id : other->id) + "' ";
    if (total > 0)
      lmp->error->all(FLERR, (pair + "are both membrane2d on " + std::to_string(total) +
                              " disks: one membrane per sample (unfix one; "
                              "two samples need groups with no disk in common)")
                                 .c_str());
    // each would overwrite the other's frames (and the .pvd would list only one)
    for (const char *key : {"polyline", "vtk"}) {
      const std::string mine = static_cast<FixMembrane2d *>(self)->frame_files().file(key);
      if (vtk_series::same_file(mine,
                                static_cast<FixMembrane2d *>(other)->frame_files().file(key)))
        lmp->error->all(FLERR, (pair + "both write " + key + " frames to '" + mine +
                                "': give each fix its own file")
                                   .c_str());
    }
  }
}

void check_lengths(LAMMPS *lmp, const char *prefix, double band, double tolerance, double d50)
{
  const std::string band_text = membrane::band_problem(band, d50);
  if (!band_text.empty())
    lmp->error->all(FLERR, keyword_message(prefix, "band", number_text(band), band_text).c_str());
  const std::string tolerance_text = membrane::tolerance_problem(tolerance, d50);
  if (!tolerance_text.empty())
    lmp->error->all(
        FLERR,
        keyword_message(prefix, "tolerance", number_text(tolerance), tolerance_text).c_str());
}

void check_platens_enclose(LAMMPS *lmp, const char *prefix, MembraneGather &gather,
                           const ScalarInput &ylo_in, double ylo, const ScalarInput &yhi_in,
                           double yhi)
{
  double lo, hi;
  gather.group_y_range(lo, hi);
  const std::string enclose = "; the platens must enclose the sample";
  if (lo < ylo)
    lmp->error->all(FLERR, keyword_message(prefix, "ylo", ylo_in.text(),
                                           "is " + number_text(ylo) +
                                               ", above the lowest disk centre of the group (y = " +
                                               number_text(lo) + ")" + enclose)
                               .c_str());
  if (hi > yhi)
    lmp->error->all(FLERR,
                    keyword_message(prefix, "yhi", yhi_in.text(),
                                    "is " + number_text(yhi) +
                                        ", below the highest disk centre of the group (y = " +
                                        number_text(hi) + ")" + enclose)
                        .c_str());
}

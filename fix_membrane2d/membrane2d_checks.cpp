#include "membrane2d_checks.h"

#include "membrane_output.h"
#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;

void check_band(LAMMPS *lmp, const std::string &prefix, double band, double d50)
{
  const std::string problem = membrane::band_problem(band, d50);
  if (!problem.empty())
    style_error(lmp, "", keyword_message(prefix, "band", number_text(band), problem));
}

void check_platens_enclose(LAMMPS *lmp, const std::string &prefix, MembraneGather &gather,
                           const ScalarInput &ylo_in, double ylo, const ScalarInput &yhi_in,
                           double yhi)
{
  double lo, hi;
  gather.group_y_range(lo, hi);
  const std::string enclose = "; the platens must enclose the sample";
  if (lo < ylo)
    style_error(lmp, "",
                keyword_message(prefix, "ylo", ylo_in.text(),
                                "is " + number_text(ylo) +
                                    ", above the lowest disk centre of the group (y = " +
                                    number_text(lo) + ")" + enclose));
  if (hi > yhi)
    style_error(lmp, "",
                keyword_message(prefix, "yhi", yhi_in.text(),
                                "is " + number_text(yhi) +
                                    ", below the highest disk centre of the group (y = " +
                                    number_text(hi) + ")" + enclose));
}

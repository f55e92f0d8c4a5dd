// The margin of a 4 x 4 determinant whose rows move (flood_watch.cpp's power_safe, the
// kinetic flood's kinetic_margin.cpp): internal to the core; no LIGGGHTS here.
#ifndef LIGGGHTS_MEMBRANE_DETERMINANT_MARGIN_H
#define LIGGGHTS_MEMBRANE_DETERMINANT_MARGIN_H

#include <algorithm>
#include <array>
#include <cmath>

namespace membrane3d {

// Whether the determinant `det` keeps its sign while each row i (of norm row_norm[i])
// moves by up to row_change[i]: the first-order (cofactor) terms `first`, the Hadamard
// bound of the rest (the product of the grown row norms less its terms of order 0 and
// 1) and the round-off allowance round_off times the product of the row norms, all
// below |det|.
inline bool determinant_margin(double det, double first, const std::array<double, 4> &row_norm,
                               const std::array<double, 4> &row_change, double round_off)
{
  double rows = 1, grown = 1, linear = 0;
  for (int i = 0; i < 4; ++i) {
    rows *= row_norm[i];
    grown *= row_norm[i] + row_change[i];
    double others = row_change[i];
    for (int j = 0; j < 4; ++j)
      if (j != i) others *= row_norm[j];
    linear += others;
  }
  const double rest = std::max(0.0, grown - rows - linear);
  return first + rest + round_off * rows < std::abs(det);
}

} // namespace membrane3d

#endif

#include "grain_size.h"

#include <algorithm>
#include <cmath>

namespace grains {

double d50_by_mass(std::vector<double> diameters, int dimension)
{
  if (diameters.empty()) return 0.0;
  std::sort(diameters.begin(), diameters.end());
  const auto mass = [dimension](double d) { return std::pow(d, dimension); };
  double total = 0.0;
  for (double d : diameters) total += mass(d);
  double cumulative = 0.0;
  for (double d : diameters) {
    cumulative += mass(d);
    if (cumulative >= 0.5 * total) return d;
  }
  return diameters.back();
}

} // namespace grains

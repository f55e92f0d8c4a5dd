#include "grain_size.h"

#include <algorithm>

namespace stability {

double d50_by_area(std::vector<double> diameters)
{
  if (diameters.empty()) return 0.0;
  std::sort(diameters.begin(), diameters.end());
  double total = 0.0;
  for (double d : diameters) total += d * d;
  double cumulative = 0.0;
  for (double d : diameters) {
    cumulative += d * d;
    if (cumulative >= 0.5 * total) return d;
  }
  return diameters.back();
}

} // namespace stability

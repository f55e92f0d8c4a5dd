#include "local_damping.h"

#include <cmath>

namespace damping {

double sign(double v)
{
  if (v > 0.0) return 1.0;
  if (v < 0.0) return -1.0;
  return 0.0;
}

double local_damping_component(double f, double v, double alpha)
{
  // written out so that sign(v) = 0 gives +0.0, never -0.0
  if (v > 0.0) return -alpha * std::fabs(f);
  if (v < 0.0) return alpha * std::fabs(f);
  return 0.0;
}

void local_damping_force(const double *f, const double *v, std::size_t n, double alpha, double *fd)
{
  for (std::size_t k = 0; k < n; k++) fd[k] = local_damping_component(f[k], v[k], alpha);
}

void apply_local_damping(double *f, const double *v, std::size_t n, double alpha)
{
  for (std::size_t k = 0; k < n; k++) f[k] += local_damping_component(f[k], v[k], alpha);
}

} // namespace damping

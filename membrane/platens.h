// The two platens of a membrane (the surfaces of the lower and upper one along the
// platens' axis: y in 2D, z in 3D), and whether they moved since the membrane's last
// detection by more than `limit`: the contacts with the platens (2D) or the links
// with the spheres' images in them (3D) can have changed, so the membrane is found
// anew. Shared by the LIGGGHTS-free cores of fix membrane2d and fix membrane3d. A
// position not known (NaN: a restart record of an older version) is never taken as
// moved.
#ifndef LIGGGHTS_MEMBRANE_PLATENS_H
#define LIGGGHTS_MEMBRANE_PLATENS_H

#include <cmath>

namespace membrane {

struct Platens {
  double lo, hi; // the lower and upper platen surfaces
};

inline bool platens_moved_beyond(const Platens &now, const Platens &then, double limit)
{
  return std::fabs(now.lo - then.lo) > limit || std::fabs(now.hi - then.hi) > limit;
}

} // namespace membrane

#endif

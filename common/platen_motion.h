// Whether a membrane's platens moved since its last detection by more than `limit`:
// the contacts with the platens (2D) or the links with the spheres' images in them
// (3D) can have changed, so the membrane is found anew. Shared by the LIGGGHTS-free
// cores of fix membrane2d and fix membrane3d. A position not known (NaN: a restart
// record of an older version) is never taken as moved.
#ifndef LIGGGHTS_MEMBRANE_PLATEN_MOTION_H
#define LIGGGHTS_MEMBRANE_PLATEN_MOTION_H

#include <cmath>

inline bool platens_moved_beyond(double lo, double hi, double lo_then, double hi_then, double limit)
{
  return std::fabs(lo - lo_then) > limit || std::fabs(hi - hi_then) > limit;
}

#endif

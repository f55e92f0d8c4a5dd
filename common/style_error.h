#ifndef LIGGGHTS_MEMBRANE_STYLE_ERROR_H
#define LIGGGHTS_MEMBRANE_STYLE_ERROR_H

#include <cstdlib>
#include <string>

#include "comm.h"
#include "error.h"
#include "lammps.h"

// The one way our styles speak (doc/messages.md). Every message starts as
// LIGGGHTS' own Error::fix_error starts it, with the style and the ID:
//
//   Fix membrane2d (id mem): <what is wrong>; <what to do>
//   Compute fabric (id fab): ...
//
// `kind` is "Fix" or "Compute"; `style` and `id` as the command gave them.
inline std::string style_prefix(const char *kind, const char *style, const char *id)
{
  return std::string(kind) + " " + style + " (id " + id + "): ";
}

// Stops the run on every rank. Call it only with values every rank shares
// (reduced, or the same by construction): a rank that stopped alone would
// leave the others waiting in their next collective call.
[[noreturn]] inline void style_error(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                                     const std::string &text)
{
  lmp->error->all(FLERR, (prefix + text).c_str());
  std::abort(); // Error::all does not return
}

// Stops the run from one rank, for what only that rank knows (rank 0 writing a
// file): the others are stopped by MPI_Abort.
[[noreturn]] inline void style_error_one(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                                         const std::string &text)
{
  lmp->error->one(FLERR, (prefix + text).c_str());
  std::abort(); // Error::one does not return
}

// Printed once, by rank 0.
inline void style_warning(LAMMPS_NS::LAMMPS *lmp, const std::string &prefix,
                          const std::string &text)
{
  if (lmp->comm->me == 0) lmp->error->warning(FLERR, (prefix + text).c_str());
}

#endif

#include "membrane3d_frames.h"

#include <mpi.h>

#include <cstdio>

#include "comm.h"
#include "error.h"
#include "update.h"

#include "membrane3d_vtk.h"
#include "style_args.h"

using namespace LAMMPS_NS;

void Membrane3dFrames::read(StyleArgs &args, const char *prefix, const char *usage,
                            std::initializer_list<const char *> keywords)
{
  every_ = args.integer(1, 1000000000L, usage);
  const std::string file = args.value(usage);
  if (file.empty()) args.bad("the file name is empty", usage);
  for (const char *k : keywords)
    if (file == k) args.bad("the file name is the keyword '" + file + "'", usage);
  series_.name(file);
  char reason[256] = "";
  if (comm->me == 0)
    std::snprintf(reason, sizeof(reason), "%s", series_.start(update->ntimestep).c_str());
  MPI_Bcast(reason, sizeof(reason), MPI_CHAR, 0, world);
  if (reason[0])
    error->all(FLERR, keyword_message(prefix, "vtk", series_.pvd(),
                                      std::string("cannot open the file for writing (") + reason +
                                          "); check that its folder exists and is writable")
                          .c_str());
}

void Membrane3dFrames::write(const char *prefix, const membrane3d::LateralSurface &membrane,
                             const std::vector<membrane3d::Sphere> &spheres, double pressure)
{
  if (every_ == 0 || update->ntimestep % every_ != 0 || comm->me != 0) return;
  const std::string why =
      series_.add(update->ntimestep, membrane3d::vtk_frame(membrane, spheres, pressure));
  if (!why.empty())
    error->one(FLERR, keyword_message(prefix, "vtk", series_.frame_path(update->ntimestep),
                                      "cannot write the frame (" + why + ")")
                          .c_str());
}

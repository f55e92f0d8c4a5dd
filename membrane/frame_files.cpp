#include "frame_files.h"

#include <mpi.h>

#include <cstdio>

#include "comm.h"
#include "update.h"

#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;

const char *const VtkFrames::USAGE =
    "vtk N FILE: write the membrane every N >= 1 steps to FILE_<step>.vtp, collected in FILE.pvd";

std::string frame_file_name(StyleArgs &args, const std::string &usage,
                            const std::vector<std::string> &keywords)
{
  const std::string file = args.value(usage);
  if (file.empty()) args.bad("the file name is empty", usage);
  for (const std::string &k : keywords)
    if (file == k) args.bad("the file name is the keyword '" + file + "'", usage);
  return file;
}

void check_file_opened(LAMMPS *lmp, const std::string &prefix, const std::string &key,
                       const std::string &file, const std::string &reason)
{
  char text[256] = "";
  if (lmp->comm->me == 0) std::snprintf(text, sizeof(text), "%s", reason.c_str());
  MPI_Bcast(text, sizeof(text), MPI_CHAR, 0, lmp->world);
  if (text[0])
    style_error(lmp, prefix,
                keyword_text(key, file,
                                std::string("cannot open the file for writing (") + text +
                                    "); check that its folder exists and is writable"));
}

VtkFrames::VtkFrames(LAMMPS *lammps, std::string prefix)
  : Pointers(lammps), prefix_(std::move(prefix))
{
}

void VtkFrames::read(StyleArgs &args, const std::vector<std::string> &keywords)
{
  every_ = args.integer(1, 1000000000L, USAGE);
  series_.name(frame_file_name(args, USAGE, keywords));
  check_file_opened(lmp, prefix_, "vtk", series_.pvd(),
                    comm->me == 0 ? series_.start(update->ntimestep) : "");
}

bool VtkFrames::due(bigint step) const
{
  return every_ > 0 && step % every_ == 0 && comm->me == 0;
}

void VtkFrames::write(bigint step, const std::string &frame)
{
  // a step written again (a run of 0 steps, a second run from the same step) replaces its frame
  const std::string why = series_.add(step, frame);
  if (!why.empty())
    style_error_one(lmp, prefix_,
                    keyword_text("vtk", series_.frame_path(step),
                                    "cannot write the frame (" + why + ")"));
}

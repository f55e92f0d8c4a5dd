#include "membrane_frames.h"

#include <mpi.h>

#include <cerrno>
#include <cstring>

#include <unistd.h>

#include "comm.h"
#include "error.h"
#include "update.h"

#include "membrane_output.h"
#include "membrane_vtk.h"
#include "style_args.h"

namespace {

const char *const USE_POLYLINE = "polyline N FILE: write the chains every N >= 1 steps to FILE";
const char *const USE_VTK = "vtk N FILE: write the chains every N >= 1 steps to FILE_<step>.vtp, "
                            "collected in FILE.pvd";

} // namespace

MembraneFrames::~MembraneFrames()
{
  if (polyline_) std::fclose(polyline_);
}

void MembraneFrames::read(const std::string &key, StyleArgs &args, const char *const *keywords,
                          int nkeywords)
{
  const bool vtk = key == "vtk";
  const char *use = vtk ? USE_VTK : USE_POLYLINE;
  (vtk ? vtk_every_ : polyline_every_) = args.integer(1, 1000000000L, use);
  std::string file = args.value(use);
  if (file.empty()) args.bad("the file name is empty", use);
  for (int k = 0; k < nkeywords; k++)
    if (file == keywords[k]) args.bad("the file name is the keyword '" + file + "'", use);
  if (!vtk) polyline_file_ = file;
  if (vtk) {
    vtk_.name(file);
    file = vtk_.pvd();
  }
  char reason[256] = "";
  if (comm->me == 0) {
    std::string why;
    if (vtk) {
      why = vtk_.start(update->ntimestep);
    } else {
      if (polyline_) std::fclose(polyline_);
      polyline_ = std::fopen(file.c_str(), "w");
      polyline_frames_.clear();
      if (!polyline_) why = std::strerror(errno);
    }
    std::snprintf(reason, sizeof(reason), "%s", why.c_str());
  }
  MPI_Bcast(reason, sizeof(reason), MPI_CHAR, 0, world);
  if (reason[0])
    error->all(FLERR, keyword_message(prefix_, key, file,
                                      std::string("cannot open the file for writing (") + reason +
                                          "); check that its folder exists and is writable")
                          .c_str());
}

std::string MembraneFrames::file(const std::string &key) const
{
  if (key == "polyline") return polyline_file_;
  return vtk_.pvd();
}

void MembraneFrames::write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
                           const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2])
{
  if (comm->me != 0) return;
  if (polyline_ && step % polyline_every_ == 0) {
    // each step once: a step written again replaces its frame and the later ones
    const long end = std::ftell(polyline_);
    const long start = membrane::polyline_frame_start(polyline_frames_, step, end);
    if (start < end && (std::fflush(polyline_) != 0 || ftruncate(fileno(polyline_), start) != 0 ||
                        std::fseek(polyline_, start, SEEK_SET) != 0))
      error->one(FLERR, keyword_message(prefix_, "polyline", polyline_file_,
                                        std::string("cannot cut the file to rewrite step ") +
                                            std::to_string(step) + " (" + std::strerror(errno) +
                                            "); check that it is a regular file")
                            .c_str());
    std::fprintf(polyline_, "ITEM: TIMESTEP\n" BIGINT_FORMAT "\n", step);
    for (int k = membrane::LEFT; k <= membrane::RIGHT; k++)
      if (chains[k].active)
        membrane::write_polyline_side(polyline_, membrane::side_name(k), loads[k].polyline,
                                      sides[k].chain_disks, loads[k].forces);
    std::fflush(polyline_);
  }
  if (vtk_every_ > 0 && step % vtk_every_ == 0) {
    std::vector<membrane::VtkSide> shown;
    for (int k = membrane::LEFT; k <= membrane::RIGHT; k++)
      if (chains[k].active)
        shown.push_back({k == membrane::LEFT ? 1 : 2, &loads[k].polyline, &sides[k].chain_disks,
                         &loads[k].forces});
    // a step written again (a run of 0 steps, a second run from the same step) replaces its frame
    const std::string why = vtk_.add(step, membrane::vtk_frame(shown));
    if (!why.empty())
      error->one(FLERR, keyword_message(prefix_, "vtk", vtk_.frame_path(step),
                                        "cannot write the frame (" + why + ")")
                            .c_str());
  }
}

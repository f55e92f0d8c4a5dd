#include "membrane_frames.h"

#include <cerrno>
#include <cstring>

#include <unistd.h>

#include "comm.h"
#include "update.h"

#include "frame_files.h"
#include "membrane_output.h"
#include "membrane_vtk.h"
#include "style_args.h"
#include "style_error.h"

const char *const PolylineFrames::USAGE =
    "polyline N FILE: write the chains every N >= 1 steps to FILE";

PolylineFrames::~PolylineFrames()
{
  if (out_) std::fclose(out_);
}

void PolylineFrames::read(StyleArgs &args, const std::vector<std::string> &keywords)
{
  every_ = args.integer(1, 1000000000L, USAGE);
  file_ = frame_file_name(args, USAGE, keywords);
  std::string why;
  if (comm->me == 0) {
    if (out_) std::fclose(out_);
    out_ = std::fopen(file_.c_str(), "w");
    frames_.clear();
    if (!out_) why = std::strerror(errno);
  }
  check_file_opened(lmp, prefix_, "polyline", file_, why);
}

void PolylineFrames::write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
                           const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2])
{
  if (comm->me != 0 || !out_ || step % every_ != 0) return;
  // each step once: a step written again replaces its frame and the later ones
  const long end = std::ftell(out_);
  const long start = membrane::polyline_frame_start(frames_, step, end);
  if (start < end && (std::fflush(out_) != 0 || ftruncate(fileno(out_), start) != 0 ||
                      std::fseek(out_, start, SEEK_SET) != 0))
    style_error_one(lmp, "",
                    keyword_message(prefix_, "polyline", file_,
                                    std::string("cannot cut the file to rewrite step ") +
                                        std::to_string(step) + " (" + std::strerror(errno) +
                                        "); check that it is a regular file"));
  std::fprintf(out_, "ITEM: TIMESTEP\n" BIGINT_FORMAT "\n", step);
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++)
    if (chains[k].active)
      membrane::write_polyline_side(out_, membrane::side_name(k), loads[k].polyline,
                                    sides[k].chain_disks, loads[k].forces);
  std::fflush(out_);
}

std::string chains_vtk_frame(const membrane::SideChain (&chains)[2],
                             const MembraneSideData (&sides)[2],
                             const membrane::SideLoad (&loads)[2])
{
  std::vector<membrane::VtkSide> shown;
  for (int k = membrane::LEFT; k <= membrane::RIGHT; k++)
    if (chains[k].active)
      shown.push_back({k == membrane::LEFT ? 1 : 2, &loads[k].polyline, &sides[k].chain_disks,
                       &loads[k].forces});
  return membrane::vtk_frame(shown);
}

#include "membrane_frames.h"

#include "comm.h"

#include "frame_files.h"
#include "style_args.h"
#include "style_error.h"

namespace {
const char *const USAGE = "polyline N FILE: write the chains every N >= 1 steps to FILE";
}

void PolylineFrames::read(StyleArgs &args, const std::vector<std::string> &keywords)
{
  every_ = args.integer(1, 1000000000L, USAGE);
  file_ = frame_file_name(args, USAGE, keywords);
  const std::string why = comm->me == 0 ? out_.open(file_) : "";
  check_file_opened(lmp, prefix_, "polyline", file_, why);
}

void PolylineFrames::write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
                           const membrane::SideData (&sides)[2],
                           const membrane::SideLoad (&loads)[2])
{
  if (comm->me != 0 || !out_.is_open() || step % every_ != 0) return;
  const std::string why = out_.write(step, chains, sides, loads);
  if (!why.empty()) style_error_one(lmp, "", keyword_message(prefix_, "polyline", file_, why));
}

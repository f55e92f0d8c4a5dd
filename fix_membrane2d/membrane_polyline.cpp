#include "membrane_polyline.h"

#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace membrane {

PolylineFile::~PolylineFile()
{
  if (out_) std::fclose(out_);
}

std::string PolylineFile::open(const std::string &path, long long every, bool writer)
{
  path_ = path;
  every_ = every;
  if (!writer) return "";
  if (out_) std::fclose(out_);
  out_ = std::fopen(path.c_str(), "w");
  frames_.clear();
  return out_ ? "" : std::strerror(errno);
}

std::string PolylineFile::write(long long step, const SideChain (&chains)[2],
                                const SideData (&sides)[2], const SideLoad (&loads)[2])
{
  const long end = std::ftell(out_);
  const long start = polyline_frame_start(frames_, step, end);
  if (start < end && (std::fflush(out_) != 0 || ftruncate(fileno(out_), start) != 0 ||
                      std::fseek(out_, start, SEEK_SET) != 0))
    return "cannot cut the file to rewrite step " + std::to_string(step) + " (" +
           std::strerror(errno) + "); check that it is a regular file";
  std::fprintf(out_, "ITEM: TIMESTEP\n%lld\n", step);
  for (int k = LEFT; k <= RIGHT; k++)
    if (chains[k].active)
      write_polyline_side(out_, side_name(k), loads[k].polyline, sides[k].chain_disks,
                          loads[k].forces);
  std::fflush(out_);
  return "";
}

} // namespace membrane

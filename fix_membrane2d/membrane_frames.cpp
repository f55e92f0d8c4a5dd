#include "membrane_frames.h"

#include <mpi.h>

#include <cerrno>
#include <cstring>

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

std::string base_name(const std::string &path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// the whole file, "" when it cannot be read
std::string read_file(const std::string &path)
{
  std::string text;
  if (std::FILE *fp = std::fopen(path.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof(buf), fp)) > 0;) text.append(buf, n);
    std::fclose(fp);
  }
  return text;
}

// text to `path`; false (errno set) when it cannot be written
bool write_file(const std::string &path, const std::string &text)
{
  std::FILE *fp = std::fopen(path.c_str(), "w");
  if (!fp) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), fp) == text.size();
  return std::fclose(fp) == 0 && ok;
}

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
    if (file.size() > 4 && file.compare(file.size() - 4, 4, ".pvd") == 0) file.resize(file.size() - 4);
    vtk_base_ = file;
    file += ".pvd";
    // a run continued from a restart goes on with the frames before its first
    // step, so that its collection is that of a run straight through
    vtk_frames_.clear();
    if (comm->me == 0)
      for (const auto &f : membrane::pvd_frames(read_file(file)))
        if (f.first < update->ntimestep) vtk_frames_.push_back(f);
  }
  char reason[256] = "";
  if (comm->me == 0) {
    bool ok = true;
    if (vtk) {
      ok = write_file(file, membrane::pvd_collection(vtk_frames_));
    } else {
      if (polyline_) std::fclose(polyline_);
      polyline_ = std::fopen(file.c_str(), "w");
      ok = polyline_ != nullptr;
    }
    if (!ok) std::snprintf(reason, sizeof(reason), "%s", std::strerror(errno));
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
  return vtk_base_.empty() ? "" : vtk_base_ + ".pvd";
}

void MembraneFrames::write(LAMMPS_NS::bigint step, const membrane::SideChain (&chains)[2],
                           const MembraneSideData (&sides)[2], const membrane::SideLoad (&loads)[2])
{
  if (comm->me != 0) return;
  if (polyline_ && step % polyline_every_ == 0) {
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
    const std::string frame = vtk_base_ + "_" + std::to_string(step) + ".vtp";
    // a step written again (a run of 0 steps, a second run from the same step) replaces its frame
    if (vtk_frames_.empty() || vtk_frames_.back().first != step)
      vtk_frames_.push_back({step, base_name(frame)});
    if (!write_file(frame, membrane::vtk_frame(shown)) ||
        !write_file(vtk_base_ + ".pvd", membrane::pvd_collection(vtk_frames_)))
      error->one(FLERR, keyword_message(prefix_, "vtk", frame,
                                        std::string("cannot write the frame (") +
                                            std::strerror(errno) + ")")
                            .c_str());
  }
}

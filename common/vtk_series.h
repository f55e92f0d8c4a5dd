#ifndef LIGGGHTS_MEMBRANE_VTK_SERIES_H
#define LIGGGHTS_MEMBRANE_VTK_SERIES_H

// A series of VTK frames for ParaView, as the membrane styles write them (keyword
// vtk N FILE): FILE_<step>.vtp per frame and FILE.pvd, the collection of the
// frames, kept current after each frame; and the pieces of a PolyData file. No
// LIGGGHTS here: the styles call it on rank 0 and turn a failure (the reason
// returned) into an error.

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace vtk_series {

// Whether two frame files given by name are one file ("a.pvd", "./a.pvd", its absolute
// path, a path through a link): two fixes writing it would interleave or overwrite
// each other's frames. Neither need exist yet.
inline bool same_file(const std::string &a, const std::string &b)
{
  if (a.empty() || b.empty()) return false;
  namespace fs = std::filesystem;
  std::error_code ea, eb;
  // absolute first: of a relative name that does not exist it keeps the name as it is
  const fs::path pa = fs::weakly_canonical(fs::absolute(a, ea), ea);
  const fs::path pb = fs::weakly_canonical(fs::absolute(b, eb), eb);
  return ea || eb ? a == b : pa == pb;
}

// The start of a one-piece PolyData file, up to its PointData.
inline std::string polydata_start(std::size_t points, std::size_t verts, std::size_t lines,
                                  std::size_t polys)
{
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <PolyData>\n    <Piece NumberOfPoints=\"" +
         std::to_string(points) + "\" NumberOfVerts=\"" + std::to_string(verts) +
         "\" NumberOfLines=\"" + std::to_string(lines) + "\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(polys) + "\">\n      <PointData>\n";
}

// One ascii DataArray of n tuples; `value(k)` gives tuple k (its first `ncomp`
// components), every digit written so that ParaView shows the run's values.
template <class Value>
void data_array(std::string &out, const char *type, const char *name, int ncomp, std::size_t n,
                Value value)
{
  out += "        <DataArray type=\"" + std::string(type) + "\" Name=\"" + name +
         "\" NumberOfComponents=\"" + std::to_string(ncomp) + "\" format=\"ascii\">\n         ";
  char buf[32];
  for (std::size_t k = 0; k < n; k++) {
    const std::array<double, 3> v = value(k);
    for (int c = 0; c < ncomp; c++) {
      std::snprintf(buf, sizeof(buf), " %.17g", v[c]);
      out += buf;
    }
  }
  out += "\n        </DataArray>\n";
}

// Ends the PointData and writes the Points block of `n` points, `point(k)` giving
// point k.
template <class Point>
void points_block(std::string &out, std::size_t n, Point point)
{
  out += "      </PointData>\n      <Points>\n";
  data_array(out, "Float64", "Points", 3, n, point);
  out += "      </Points>\n";
}

// The end of a one-piece PolyData file, after its cell blocks.
inline void polydata_end(std::string &out)
{
  out += "    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

// A PolyData cell block (Verts, Lines, Polys): each cell's point indices.
inline void cell_block(std::string &out, const char *block, const std::vector<std::vector<long long>> &cells)
{
  out += "      <" + std::string(block) +
         ">\n        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n         ";
  for (const auto &cell : cells)
    for (long long p : cell) out += " " + std::to_string(p);
  out += "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" "
         "format=\"ascii\">\n         ";
  std::size_t end = 0;
  for (const auto &cell : cells) out += " " + std::to_string(end += cell.size());
  out += "\n        </DataArray>\n      </" + std::string(block) + ">\n";
}

using Frames = std::vector<std::pair<long long, std::string>>; // (time step, file)

inline std::string base_name(const std::string &path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// the whole file, "" when it cannot be read
inline std::string read_file(const std::string &path)
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
inline bool write_file(const std::string &path, const std::string &text)
{
  std::FILE *fp = std::fopen(path.c_str(), "w");
  if (!fp) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), fp) == text.size();
  return std::fclose(fp) == 0 && ok;
}

// The .pvd collection: (time step, file name relative to the .pvd) per frame.
inline std::string pvd_collection(const Frames &frames)
{
  std::string out = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <Collection>\n";
  for (const auto &f : frames)
    out += "    <DataSet timestep=\"" + std::to_string(f.first) + "\" part=\"0\" file=\"" +
           f.second + "\"/>\n";
  out += "  </Collection>\n</VTKFile>\n";
  return out;
}

// The frames of a collection written by pvd_collection, in order.
inline Frames pvd_frames(const std::string &pvd)
{
  Frames frames;
  const std::string step_key = "timestep=\"", file_key = "file=\"";
  for (std::size_t at = pvd.find("<DataSet "); at != std::string::npos;
       at = pvd.find("<DataSet ", at + 1)) {
    const std::size_t s = pvd.find(step_key, at), f = pvd.find(file_key, at);
    if (s == std::string::npos || f == std::string::npos) break;
    const std::size_t f_end = pvd.find('"', f + file_key.size());
    if (f_end == std::string::npos) break;
    frames.push_back({std::atoll(pvd.c_str() + s + step_key.size()),
                      pvd.substr(f + file_key.size(), f_end - f - file_key.size())});
  }
  return frames;
}

class Series {
 public:
  // FILE (with or without .pvd): every rank knows the names.
  void name(std::string file)
  {
    if (file.size() > 4 && file.compare(file.size() - 4, 4, ".pvd") == 0) file.resize(file.size() - 4);
    base_ = file;
  }

  // On the writing rank. A run continued from a restart goes on with the frames
  // before its first `step`, so that its collection is that of a run straight
  // through. Returns why FILE.pvd cannot be written, "" when it can.
  std::string start(long long step)
  {
    frames_.clear();
    for (const auto &f : pvd_frames(read_file(pvd())))
      if (f.first < step) frames_.push_back(f);
    return write_file(pvd(), pvd_collection(frames_)) ? "" : std::strerror(errno);
  }

  // The frame of `step`; the reason it could not be written, "" when it was. The
  // frames at or after `step` go: a step written again replaces its frame, and after
  // a reset_timestep the later run's frames overwrite the files of the earlier one.
  std::string add(long long step, const std::string &frame)
  {
    const std::string path = frame_path(step);
    while (!frames_.empty() && frames_.back().first >= step) frames_.pop_back();
    frames_.push_back({step, base_name(path)});
    if (!write_file(path, frame) || !write_file(pvd(), pvd_collection(frames_)))
      return std::strerror(errno);
    return "";
  }

  std::string pvd() const { return base_.empty() ? "" : base_ + ".pvd"; }
  std::string frame_path(long long step) const { return base_ + "_" + std::to_string(step) + ".vtp"; }

 private:
  std::string base_;
  Frames frames_;
};

} // namespace vtk_series

#endif

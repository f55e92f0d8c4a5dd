#ifndef LIGGGHTS_MEMBRANE_MEMBRANE_VTK_H
#define LIGGGHTS_MEMBRANE_MEMBRANE_VTK_H

// The membrane as VTK files for ParaView (fix membrane2d keyword vtk): one
// XML PolyData file per frame (the .pvd collection: common/vtk_series.h). No LIGGGHTS.

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

#include "membrane_chain.h"
#include "membrane_state.h"

namespace membrane {

// What one side shows in a frame: its polyline (contact points, platen ends)
// and its chain disks (chain order) with the force on each.
struct VtkSide {
  int side = 0; // 1 left, 2 right (as the per-atom flag)
  const Polyline *polyline = nullptr;
  const std::vector<Disk> *chain = nullptr;
  const std::vector<Eigen::Vector2d> *forces = nullptr;
};

// The frame as a .vtp file: the points are each side's polyline vertices, then
// its chain disk centres (z = 0); one Line cell per polyline, one Vertex cell
// per disk. Point data: side, tag (-1 on polyline vertices), radius (0 there),
// force (0 there; z = 0).
std::string vtk_frame(const std::vector<VtkSide> &sides);
// The frame of the active sides' chains.
std::string chains_vtk_frame(const SideChain (&chains)[2], const SideData (&sides)[2],
                             const SideLoad (&loads)[2]);

} // namespace membrane

#endif

#include "membrane3d_traffic.h"

#include <mpi.h>

#include <cstdio>

#include "comm.h"

using namespace LAMMPS_NS;

void Membrane3dTraffic::start(bigint step, double detections)
{
  *this = Membrane3dTraffic();
  first_step_ = step;
  first_detections_ = detections;
}

void Membrane3dTraffic::report(LAMMPS *lmp, const std::string &prefix, const char *id, bigint step,
                               double detections) const
{
  // the busiest rank's bytes: with an uneven grid rank 0 may hold little of the membrane
  double mine[4] = {fix_seconds, detection_seconds_, received - detection_bytes_,
                    detection_bytes_};
  double most[4] = {0.0, 0.0, 0.0, 0.0};
  MPI_Reduce(mine, most, 4, MPI_DOUBLE, MPI_MAX, 0, lmp->world);
  const double *slowest = most;
  if (lmp->comm->me != 0) return;
  // a run of 0 steps: its setup counts as one step
  const long long steps = step - first_step_;
  const long long dets = static_cast<long long>(detections - first_detections_);
  const double kb_step = most[2] / (steps > 0 ? steps : 1) / 1e3;
  const double kb_detection = dets > 0 ? most[3] / dets / 1e3 : 0.0;
  char text[600];
  std::snprintf(text, sizeof(text),
                "%sthe busiest rank received %.3g kB per step (the member spheres) and %.3g kB per "
                "detection (its skin of spheres) over %lld steps with %lld detections; the fix "
                "took %.3g s, its detections %.3g s (slowest rank)\n"
                "membrane3d_traffic id=%s kb_per_step=%.6g kb_per_detection=%.6g steps=%lld "
                "detections=%lld fix_seconds=%.6g detection_seconds=%.6g\n",
                prefix.c_str(), kb_step, kb_detection, steps, dets, slowest[0], slowest[1], id,
                kb_step, kb_detection, steps, dets, slowest[0], slowest[1]);
  if (lmp->screen) std::fputs(text, lmp->screen);
  if (lmp->logfile) std::fputs(text, lmp->logfile);
}

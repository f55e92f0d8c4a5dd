#ifndef LIGGGHTS_MEMBRANE_DENSE_DETECTIONS_H
#define LIGGGHTS_MEMBRANE_DENSE_DETECTIONS_H

// every auto of both membranes: when at least DENSE_DETECTIONS of DENSE_WINDOW
// watched steps detected, the next UNWATCHED_STEPS steps detect every step without
// building the watch, which then costs more than it saves (a long chain or a large
// surface has some relation flipping at most steps; in 2D at 134 k disks a watched
// step cost about 1 + 4.7 r ms at a detection rate r, an unwatched one 3.6 ms); then
// the watch is tried again.
// The membrane is the same either way (every auto = every 1); only the detection
// count differs. No LIGGGHTS here.
// fix membrane3d sets a shorter window and a longer unwatched run
// (membrane3d_auto.cpp): there a detection found from the skin of the last membrane
// costs half of one that builds the watch, so the watched windows of a sample whose
// membrane changes at most steps would cost more than they save.
constexpr long long DENSE_WINDOW = 100;
constexpr long long DENSE_DETECTIONS = 70;
constexpr long long UNWATCHED_STEPS = 500;

struct DenseDetections {
  // the schedule: a window of `window` watched steps with at least `dense` detections
  // is followed by `unwatched_steps` without the watch (the constants above unless a
  // style sets its own)
  long long window = DENSE_WINDOW, dense = DENSE_DETECTIONS, unwatched_steps = UNWATCHED_STEPS;
  // the watched steps of the open window and how many of them detected, and the step
  // before which every step detects without a watch (-1: none)
  long long window_steps = 0, window_detections = 0;
  long long unwatched_until = -1;

  // (a step counter set back, by reset_timestep or a restart of an earlier step, ends
  // the unwatched run: it never lasts more than `unwatched_steps` from `step`; before,
  // reset_timestep 0 after a dense window at step 10^6 left 10^6 steps unwatched)
  bool unwatched(long long step) const
  {
    return step < unwatched_until && unwatched_until - step <= unwatched_steps;
  }

  // after a watched step decided whether to detect: counts it in the window; true
  // when the window closes dense (this detection and the next UNWATCHED_STEPS - 1
  // steps then go without a watch)
  bool count_watched(long long step, bool detected)
  {
    window_steps++;
    if (detected) window_detections++;
    if (window_steps < window) return false;
    const bool closed_dense = window_detections >= dense;
    window_steps = window_detections = 0;
    if (closed_dense) unwatched_until = step + unwatched_steps;
    return closed_dense;
  }
};

#endif

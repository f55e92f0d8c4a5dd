#ifndef LIGGGHTS_MEMBRANE_SCOPED_SECONDS_H
#define LIGGGHTS_MEMBRANE_SCOPED_SECONDS_H

#include <chrono>

// Adds the wall-clock time of its scope to `total` (the membranes' traffic reports:
// the seconds a fix, its searches or its detections took on this rank).
class ScopedSeconds {
 public:
  explicit ScopedSeconds(double &total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~ScopedSeconds()
  {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  ScopedSeconds(const ScopedSeconds &) = delete;
  ScopedSeconds &operator=(const ScopedSeconds &) = delete;

 private:
  double &total_;
  std::chrono::steady_clock::time_point start_;
};

#endif

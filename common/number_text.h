#ifndef LIGGGHTS_MEMBRANE_NUMBER_TEXT_H
#define LIGGGHTS_MEMBRANE_NUMBER_TEXT_H

// Numbers and counts in messages, the same in the styles and in their LIGGGHTS-free
// cores: %g (a tolerance of 1e-12 is not "0.000000"), "1 sphere" and "3 spheres".

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>

inline std::string number_text(double v)
{
  if (std::isnan(v)) return "nan"; // not "-nan", whatever its sign bit
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

inline std::string count_text(std::size_t n, const std::string &one, const std::string &many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

#endif

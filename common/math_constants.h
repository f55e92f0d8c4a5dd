#ifndef LIGGGHTS_MEMBRANE_MATH_CONSTANTS_H
#define LIGGGHTS_MEMBRANE_MATH_CONSTANTS_H

// The numbers every style shares, defined here only (M_PI is not standard C++,
// and LIGGGHTS' MathConst would tie the LIGGGHTS-free cores to LIGGGHTS).
namespace math_constants {

constexpr double PI = 3.14159265358979323846;
constexpr double TWO_PI = 2.0 * PI;
constexpr double RAD2DEG = 180.0 / PI;

} // namespace math_constants

#endif

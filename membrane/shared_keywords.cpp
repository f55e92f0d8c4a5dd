#include "shared_keywords.h"

#include <cstdio>

namespace membrane {

std::string tolerance_problem(double tolerance, double d50, double most, double usual)
{
  if (!(tolerance > most * d50)) return "";
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "is %g x D50 (D50 = %g); it is the largest gap counted as a contact, a length "
                "in distance units, at most %g x D50; typically %g x D50 = %g (the default)",
                tolerance / d50, d50, most, usual, usual * d50);
  return buf;
}

} // namespace membrane

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

std::string restart_unreadable(const std::string &reason, bool other_format)
{
  return "this fix's state in the restart file cannot be read: " + reason +
         (other_format ? "; read it with the version that wrote it, or define this fix with "
                         "another ID (the membrane is then found anew)"
                       : "");
}

std::string restart_other_definition(const std::string &keywords)
{
  return "this fix is defined otherwise than in the restart file (" + keywords +
         "): the membrane is found anew at the first step and its counters start from 0";
}

} // namespace membrane

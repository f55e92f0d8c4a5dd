#include "damping_order.h"

namespace damping {

bool adds_no_force(const std::string &style)
{
  static const char *const no_force[] = {
      "enforce2d", "freeze", "setforce", "lineforce", "planeforce",
      // these read the force or act on heat and species only
      "store/force", "heat/gran", "heat/gran/conduction", "couple/cfd/convection",
      "couple/cfd/radiation", "couple/cfd/convectiveImpl", "couple/cfd/speciesConvection",
      "sph/mixidx"};
  for (const char *s : no_force)
    if (style == s) return true;
  return false;
}

std::string order_warning(const std::string &id, const std::string &style,
                          const std::string &other_id, const std::string &other_style, long common)
{
  const std::string other = "fix " + other_id + " (" + other_style + ")";
  const std::string atoms = std::to_string(common) + " atom(s) that fix " + id + " damps";
  if (other_style == style)
    return other + " also damps " + atoms +
           ": their force is damped twice; give the two fixes groups without common atoms";
  return other + " is defined after fix " + id + " and acts in post_force on " + atoms +
         ": forces it adds to them are not damped; define fix " + id + " after fix " + other_id;
}

} // namespace damping

#ifndef LIGGGHTS_MEMBRANE_DAMPING_ORDER_H
#define LIGGGHTS_MEMBRANE_DAMPING_ORDER_H
// Fix damping/local damps the force as it stands when its post_force runs, and
// LIGGGHTS runs post_force in the order the fixes were defined: a fix defined
// after it that adds force in post_force leaves that force undamped, and a
// second fix damping/local damps twice. Which fix styles may come after it,
// and what the warning about one that may not says (no LIGGGHTS here).

#include <string>

namespace damping {

// Whether a fix of `style` adds no force in post_force: it removes, projects or
// prescribes force components (a damping force computed before goes with the
// rest, as it should), or reads the force or acts on heat and species only.
bool adds_no_force(const std::string &style);

// The warning about fix `other_id` of `other_style`, defined after fix `id` of
// `style` and acting in post_force on `common` atoms that fix `id` damps.
std::string order_warning(const std::string &id, const std::string &style,
                          const std::string &other_id, const std::string &other_style, long common);

} // namespace damping

#endif

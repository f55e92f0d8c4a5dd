// Stock LIGGGHTS 3.8 has no run-time plugin loading: the style name -> creator
// maps live in Modify as *private* members, filled from style_*.h at build time.
// We insert our creators into those maps right after LAMMPS is constructed.
//
// Reaching a private member without editing LIGGGHTS' headers uses the
// explicit-instantiation access idiom: an explicit template instantiation may
// name private members ([temp.explicit]/12), and the friend function it defines
// hands out the pointer-to-member. This is standard C++, not a hack on layout.

#include "register_styles.h"

#include <map>
#include <string>

#include "lammps.h"
#include "modify.h"
#include "fix.h"
#include "compute.h"

#include "compute_fabric.h"
#include "fix_membrane2d.h"
#include "fix_membrane3d.h"
#include "fix_damping_local.h"
#include "fix_stability_guard.h"

using namespace LAMMPS_NS;

namespace {

using FixCreator = Fix *(*)(LAMMPS *, int, char **);
using ComputeCreator = Compute *(*)(LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator>;
using ComputeMap = std::map<std::string, ComputeCreator>;

template <typename Tag, typename Tag::type Member> struct PrivateMember {
  friend typename Tag::type member_pointer(Tag) { return Member; }
};

struct FixMapTag {
  using type = FixMap *Modify::*;
  friend type member_pointer(FixMapTag);
};
struct ComputeMapTag {
  using type = ComputeMap *Modify::*;
  friend type member_pointer(ComputeMapTag);
};

template <typename T> Fix *create_fix(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}

// LIGGGHTS computes take the argument cursor by reference.
template <typename T> Compute *create_compute(LAMMPS *lmp, int iarg, int narg, char **arg)
{
  return new T(lmp, iarg, narg, arg);
}

template struct PrivateMember<FixMapTag, &Modify::fix_map>;
template struct PrivateMember<ComputeMapTag, &Modify::compute_map>;

} // namespace

void register_project_styles(LAMMPS *lmp)
{
  FixMap &fix_map = *(lmp->modify->*member_pointer(FixMapTag{}));
  ComputeMap &compute_map = *(lmp->modify->*member_pointer(ComputeMapTag{}));

  // Same style lines a LIGGGHTS source build reads from style_fix.h /
  // style_compute.h, so a name is declared exactly once, in the style's header.
#define FIX_CLASS
#define FixStyle(key, Class) fix_map[#key] = &create_fix<Class>;
#include "fix_membrane2d.h"
#include "fix_membrane3d.h"
#include "fix_damping_local.h"
#include "fix_stability_guard.h"
#undef FixStyle
#undef FIX_CLASS

#define COMPUTE_CLASS
#define ComputeStyle(key, Class) compute_map[#key] = &create_compute<Class>;
#include "compute_fabric.h"
#undef ComputeStyle
#undef COMPUTE_CLASS
}

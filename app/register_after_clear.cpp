// The input command `clear` destroys LIGGGHTS' Modify and builds a new one
// whose style maps know only the built-in styles, so our styles would vanish
// from a script after `clear` (e.g. before read_restart). Input::clear() then
// calls LAMMPS::post_create(), a non-inline function of libliggghts that no
// other code depends on. This executable defines that same symbol: the dynamic
// linker binds libliggghts' calls to ours (symbol interposition; libliggghts is
// not linked -Bsymbolic, and the executable exports the symbol, see
// app/CMakeLists.txt), and ours runs the library's own version first, found
// with dlsym(RTLD_NEXT), then registers our styles again.
// tests/scripts/membrane_restart.in runs `clear` + `read_restart` + our fix.

#include <dlfcn.h>
#include <cstdio>
#include <cstdlib>

#include "lammps.h"

#include "register_styles.h"

void LAMMPS_NS::LAMMPS::post_create()
{
  using PostCreate = void (*)(LAMMPS_NS::LAMMPS *);
  static PostCreate library_post_create =
      reinterpret_cast<PostCreate>(dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS6LAMMPS11post_createEv"));
  if (!library_post_create) {
    fprintf(stderr, "liggghts-membrane: LAMMPS::post_create not found in libliggghts\n");
    abort();
  }
  library_post_create(this);
  register_project_styles(this);
}

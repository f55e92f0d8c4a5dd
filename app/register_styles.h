#ifndef LIGGGHTS_MEMBRANE_REGISTER_STYLES_H
#define LIGGGHTS_MEMBRANE_REGISTER_STYLES_H

namespace LAMMPS_NS {
class LAMMPS;
}

// Add this project's fix and compute styles to a LIGGGHTS instance, so that
// input scripts can use them exactly like built-in styles.
void register_project_styles(LAMMPS_NS::LAMMPS *lmp);

#endif

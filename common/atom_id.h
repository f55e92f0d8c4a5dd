#ifndef LIGGGHTS_MEMBRANE_ATOM_ID_H
#define LIGGGHTS_MEMBRANE_ATOM_ID_H

// An atom ID as LIGGGHTS 3.8 keeps it (int *atom->tag), one type for every style.
using AtomId = int;

#endif

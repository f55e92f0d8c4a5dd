/* ----------------------------------------------------------------------
   compute fabric's global vector in 3D (doc/compute_fabric.md, "In 3D"):
   the fabric and force anisotropy tensors of fabric_tensors3d.h, the
   coordination numbers and the Love-Weber stress, from the contacts each
   rank collected (FabricLocal) and the merged particle sums. Two
   reductions: the force sums are weighted by the sample's fabric.
------------------------------------------------------------------------- */

#ifndef LIGGGHTS_MEMBRANE_FABRIC_OUTPUT3D_H
#define LIGGGHTS_MEMBRANE_FABRIC_OUTPUT3D_H

#include "fabric_local.h"

namespace LAMMPS_NS {

namespace fabric3d {

// 0-based; c_ID[k + 1] in input scripts. Each tensor: xx yy zz xy xz yz.
enum VectorIndex {
  A = 0,     // fabric anisotropy, sqrt(3/2 a:a)
  A_N,       // normal force anisotropy
  A_T,       // tangential force anisotropy
  F0,        // mean normal force of the model
  CN,        // C_n
  ZM,        // Z_m
  NCONTACT,  // N_c
  NPARTICLE, // N_p
  NO_NORMAL, // contacts without a normal
  SKIPPED,   // contacts outside the fabric model (1 + a:nn <= 0), no force
  A_TENSOR,  // a_ij, 6 entries
  AN_TENSOR = A_TENSOR + 6,
  AT_TENSOR = AN_TENSOR + 6,
  STRESS = AT_TENSOR + 6, // sigma_ij with stress V, else 0
  VECTOR_SIZE = STRESS + 6
};

// Fills vector[VECTOR_SIZE]; volume > 0: the stress too. Collective. Returns the
// number of contacts without a normal over all ranks.
long fill_vector(double *vector, FabricLocal &source, const fabric::ParticleSums &particles,
                 double volume);

} // namespace fabric3d

} // namespace LAMMPS_NS

#endif

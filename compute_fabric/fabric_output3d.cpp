/* ----------------------------------------------------------------------
   compute fabric in 3D: see fabric_output3d.h
------------------------------------------------------------------------- */

#include "fabric_output3d.h"

#include <algorithm>
#include <vector>

using namespace LAMMPS_NS;

namespace {

// the ranks' sums of one kind merged in place
template <class Sums> void reduce(Sums &sums, FabricLocal &source)
{
  std::vector<double> packed = sums.pack();
  source.reduce(packed);
  sums.unpack(packed.data());
}

void put(double *into, const Eigen::Matrix3d &tensor)
{
  const fabric::Components c = fabric::components(tensor);
  std::copy(c.begin(), c.end(), into);
}

} // namespace

long fabric3d::fill_vector(double *vector, FabricLocal &source,
                           const fabric::ParticleSums &particles, double volume)
{
  fabric::ContactSums3 sums;
  for (const fabric::Contact3 &c : source.contacts3()) sums.add(c);
  reduce(sums, source);
  const fabric::Anisotropy3 fabric = fabric::fabric_anisotropy(sums);
  fabric::ForceSums3 forces;
  for (const fabric::Contact3 &c : source.contacts3()) forces.add(c, fabric.a);
  reduce(forces, source);
  const fabric::ForceAnisotropy3 force = fabric::force_anisotropy(forces);
  const fabric::Coordination coordination = fabric::coordination(particles);

  std::fill(vector, vector + VECTOR_SIZE, 0.0);
  vector[A] = fabric.invariant;
  vector[A_N] = force.normal.invariant;
  vector[A_T] = force.tangential.invariant;
  vector[F0] = force.f0;
  vector[CN] = coordination.Cn;
  vector[ZM] = coordination.Zm;
  vector[NCONTACT] = sums.sum[fabric::ContactSums3::CONTACTS].value();
  vector[NPARTICLE] = particles.particles.value();
  const long no_normal = static_cast<long>(sums.sum[fabric::ContactSums3::NO_NORMAL].value());
  vector[NO_NORMAL] = no_normal;
  vector[SKIPPED] = force.skipped;
  put(vector + A_TENSOR, fabric.a);
  put(vector + AN_TENSOR, force.normal.a);
  put(vector + AT_TENSOR, force.tangential.a);
  if (volume > 0.0) put(vector + STRESS, fabric::love_weber_stress(sums, volume));
  return no_normal;
}

/* ----------------------------------------------------------------------
   compute fabric: see compute_fabric.h and doc/compute_fabric.md
------------------------------------------------------------------------- */

#include "compute_fabric.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include "fabric_output3d.h"
#include "math_constants.h"
#include "stability_index.h"
#include "style_args.h"
#include "style_error.h"

using namespace LAMMPS_NS;

namespace {

using math_constants::RAD2DEG;

} // namespace

/* ---------------------------------------------------------------------- */

ComputeFabric::ComputeFabric(LAMMPS *lammps, int &iarg, int narg, char **arg)
  : Compute(lammps, iarg, narg, arg), prefix(style_prefix("Compute", style, id)), nbins(18), estimator(fabric::Estimator::Unbiased),
    stability_flag(false), rattlers_flag(false), histogram_flag(false), stress_flag(false),
    walls_flag(false), area_ivar(-1), iregion(-1), three_d(lammps->domain->dimension == 3),
    contact_source(lammps, this, prefix), warned_no_normal(false), nmax_atom(0)
{
  if (!atom->radius_flag)
    style_error(lmp, prefix, "requires per-atom radii; use atom_style granular (or sphere)");
  if (atom->tag_enable == 0 || atom->map_style == 0)
    style_error(lmp, prefix,
                "requires atom IDs and an atom map; add atom_modify map array before create_box");

  // the base class leaves its output pointers uninitialised
  vector = vector_atom = vector_local = nullptr;
  array = array_atom = array_local = nullptr;

  parse_args(iarg, narg, arg);

  vector_flag = 1;
  size_vector = three_d ? static_cast<int>(fabric3d::VECTOR_SIZE) : static_cast<int>(VECTOR_SIZE);
  extvector = 0;
  memory->create(vector, size_vector, "fabric:vector");
  std::fill(vector, vector + size_vector, 0.0);

  if (histogram_flag) {
    array_flag = 1;
    size_array_rows = nbins;
    size_array_cols = 4;
    extarray = 0;
    memory->create(array, nbins, 4, "fabric:array");
  }

  // per-atom: contact count, stability index (3D: the count only, a vector)
  peratom_flag = 1;
  size_peratom_cols = three_d ? 0 : 2;

  // the contact angles seen at ghosts go to their owners (FabricLocal)
  comm_reverse = FabricLocal::END_SLOTS;
}

/* ----------------------------------------------------------------------
   each keyword's usage ends its messages; doc/compute_fabric.md lists them
------------------------------------------------------------------------- */

void ComputeFabric::parse_args(int iarg, int narg, char **arg)
{
  StyleArgs args(lmp, prefix, narg, arg, iarg);
  while (args.more()) {
    const std::string key = args.keyword();
    if (three_d && (key == "bins" || key == "estimator" || key == "histogram"))
      args.refused("is 2D only (the polar histogram and its estimators); in 3D compute fabric "
                   "fits the anisotropy tensors (vector entries 1-3, 11-28); leave it out");
    if (three_d && (key == "stability" || key == "rattlers"))
      args.refused("is 2D only (the stability index of contacts around a disk); in 3D use Z_m "
                   "(vector entry 6) and the per-sphere contact counts (c_ID); leave it out");
    if (key == "bins") {
      const char *usage = "bins N, the number of angular bins over 360 deg, an even integer "
                          "from 6 to 3600 (default 18)";
      const long n = args.integer(LONG_MIN, LONG_MAX, usage);
      // even: the rose is point-symmetric, so a bin and its opposite match
      if (n < 6 || n > 3600 || n % 2 != 0)
        args.bad("must be an even integer from 6 to 3600", usage);
      nbins = static_cast<int>(n);
    } else if (key == "estimator") {
      // in the order of the names below
      const fabric::Estimator named[] = {fabric::Estimator::Unbiased, fabric::Estimator::Published,
                                         fabric::Estimator::Tensor};
      estimator = named[args.choice({"unbiased", "published", "tensor"},
                                    "estimator unbiased, published or tensor (default unbiased)")];
    } else if (key == "stability") {
      stability_flag = args.yes_no(
          "stability yes or no, the mean stability index as vector entry 13 (default no)");
    } else if (key == "rattlers") {
      rattlers_flag = args.yes_no("rattlers yes or no, particles with 0 or 1 contact in the mean "
                                  "stability index (default no)");
    } else if (key == "histogram") {
      histogram_flag =
          args.yes_no("histogram yes or no, the polar histogram as a global array (default no)");
    } else if (key == "stress") {
      area_in = ScalarInput(); // a repeated stress: v_name then A must forget the name
      area_in.read(args, ScalarInput::Sign::Positive,
                   "stress A or v_name, the sample area (2D, length^2 per unit thickness) or "
                   "volume (3D) of the Love-Weber stress");
      stress_flag = true;
    } else if (key == "region") {
      const char *usage = "region ID, count only the particles whose centre is inside region ID "
                          "(a region defined before compute fabric)";
      idregion = args.value(usage);
      if (domain->find_region(const_cast<char *>(idregion.c_str())) < 0)
        args.bad("there is no region " + idregion, usage);
    } else if (key == "walls") {
      walls_flag = args.yes_no("walls yes or no, also count the contacts with the mesh walls of "
                               "fix wall/gran (default no)");
    } else if (key == "update_on_run_end") {
      // LIGGGHTS' Compute reads it for every compute, only right after the style
      const char *usage =
          "update_on_run_end yes or no, invoke the compute at the end of each run (default no)";
      args.value(usage);
      args.bad("must come first, right after fabric (LIGGGHTS reads it there for every compute)",
               usage);
    } else {
      args.unknown(three_d ? "stress, region, walls" // the others are 2D only
                           : "bins, estimator, stability, rattlers, histogram, stress, region, walls");
    }
  }
  if (rattlers_flag && !stability_flag)
    style_warning(lmp, prefix,
                  keyword_text("rattlers", "yes",
                               "has no effect without stability yes (it only changes the mean "
                               "stability index, vector entry 13); add stability yes"));
}

/* ---------------------------------------------------------------------- */

ComputeFabric::~ComputeFabric()
{
  memory->destroy(vector);
  memory->destroy(array);
  memory->destroy(array_atom);
  memory->destroy(vector_atom);
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::init()
{
  contact_source.init(walls_flag);

  if (!idregion.empty()) {
    iregion = domain->find_region(const_cast<char *>(idregion.c_str()));
    if (iregion < 0)
      style_error(lmp, prefix,
                  keyword_text("region", idregion,
                               "region " + idregion +
                                   " was deleted; define it again before the run, or use a "
                                   "compute fabric without region"));
  }
  if (stress_flag) {
    area_in.init(lmp, prefix, "stress"); // the variable exists and is equal-style
    if (area_in.is_variable())
      area_ivar = input->variable->find(const_cast<char *>(area_in.text().substr(2).c_str()));
  }
  current.step = -1;
}

/* ---------------------------------------------------------------------- */

Region *ComputeFabric::region() const
{
  return iregion >= 0 ? domain->regions[iregion] : nullptr;
}

/* ----------------------------------------------------------------------
   once per timestep (all ranks take part): each rank adds its own contacts
   and owned particles to partial sums, merged by one MPI_Allreduce (two
   with estimator tensor, whose force sums need the fabric fit first)
------------------------------------------------------------------------- */

const ComputeFabric::StepSums &ComputeFabric::sums_now(bool with_angles)
{
  with_angles = with_angles || stability_flag;
  if (current.step == update->ntimestep && (current.with_angles || !with_angles)) return current;
  current.step = update->ntimestep;
  current.with_angles = with_angles;
  const int left = contact_source.collect(region(), with_angles);

  current.sums = fabric::FabricSums(nbins);
  const std::vector<fabric::Contact> &contacts = contact_source.contacts();
  const std::vector<double> &theta = contact_source.angles();
  for (size_t k = 0; k < contacts.size(); k++)
    theta.empty() ? current.sums.add(contacts[k]) : current.sums.add(contacts[k], theta[k]);
  current.particles = particle_sums(stability_flag);
  if (contact_source.reduce(current.sums, current.particles, left)) {
    // a ghost had more contact angles than one round carries: all of them first
    contact_source.finish_ends();
    current.particles = particle_sums(stability_flag);
    std::vector<double> packed = current.particles.pack();
    contact_source.reduce(packed);
    current.particles.unpack(packed.data());
  }

  if (estimator == fabric::Estimator::Tensor) {
    const fabric::Anisotropy fabric = fabric::normal_anisotropy_tensor(current.sums);
    current.tensor = fabric::ForceTensorSums();
    for (size_t k = 0; k < contacts.size(); k++)
      theta.empty() ? current.tensor.add(contacts[k], fabric)
                    : current.tensor.add(contacts[k], fabric, theta[k]);
    std::vector<double> packed = current.tensor.pack();
    contact_source.reduce(packed);
    current.tensor.unpack(packed.data());
  }
  const long no_normal = static_cast<long>(current.sums.no_normal.value());
  if (no_normal > 0 && !warned_no_normal) warn_no_normal(no_normal);
  return current;
}

// this rank's particle sums; with_lambda: also lambda of each selected owned
// particle from its contact angles (ghost pairs included), 1 for < 2 contacts
fabric::ParticleSums ComputeFabric::particle_sums(bool with_lambda)
{
  if (with_lambda) current.lambda.assign(atom->nlocal, 1.0);
  current.have_lambda = with_lambda;
  fabric::ParticleSums p;
  Region *selected_region = region();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!atom_selected(atom, i, groupbit, selected_region)) continue;
    if (with_lambda) current.lambda[i] = fabric::stability_index(contact_source.ends_of(i));
    p.add(contact_source.count_of(i), with_lambda ? current.lambda[i] : 0.0);
  }
  return p;
}

// contacts with coincident centres: warned once per compute (collective)
void ComputeFabric::warn_no_normal(long count)
{
  warned_no_normal = true;
  contact_source.warn_missing_normals(count, "c_" + std::string(id) + (three_d ? "[9]" : "[17]"));
}

/* ---------------------------------------------------------------------- */

// A variable is checked whenever it is evaluated (the same on every rank).
// It is evaluated here directly, not with ScalarInput::evaluate: that one
// clears the invoked flags of all computes (modify->clearstep_compute), which
// inside an output (thermo, fix ave/time) that invokes this compute makes the
// output skip scheduling the computes it already invoked, e.g. a per-atom
// virial for compute stress/atom at its next step.
double ComputeFabric::sample_area()
{
  if (evaluating_area) // the variable invokes this compute: it would recurse until it crashed
    style_error(lmp, prefix,
                keyword_text("stress", area_in.text(),
                             "reads compute " + std::string(id) +
                                 " itself; give the sample's size from other quantities"));
  evaluating_area = true;
  const double area =
      area_in.is_variable() ? input->variable->compute_equal(area_ivar) : area_in.evaluate(lmp);
  evaluating_area = false;
  if (!(std::isnormal(area) && area > 0.0))
    style_error(lmp, prefix,
                keyword_text("stress", area_in.text(),
                             "is " + number_text(area) + " at step " +
                                 std::to_string(update->ntimestep) +
                                 "; it must be a positive number (the sample " +
                                 (three_d ? "volume)" : "area)") +
                                 // 1e-320 would make every stress infinite
                                 (area > 0.0 ? ", not a subnormal one" : "")));
  return area;
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::compute_vector()
{
  invoked_vector = update->ntimestep;
  const StepSums &step = sums_now(false);
  if (three_d) {
    const long no_normal = fabric3d::fill_vector(vector, contact_source, step.particles,
                                                 stress_flag ? sample_area() : 0.0);
    if (no_normal > 0 && !warned_no_normal) warn_no_normal(no_normal);
    return;
  }

  std::fill(vector, vector + VECTOR_SIZE, 0.0);
  const fabric::Anisotropies an = fabric::anisotropies(step.sums, step.tensor, estimator);
  vector[A] = an.fabric.a;
  vector[THETA_A] = an.fabric.theta * RAD2DEG;
  vector[A_N] = an.force.an;
  vector[THETA_N] = an.force.theta_n * RAD2DEG;
  vector[F0] = an.force.f0;
  vector[A_T] = an.force.at;
  vector[THETA_T] = an.force.theta_t * RAD2DEG;
  vector[EMPTY_BINS] = an.force.empty_bins;

  const fabric::Coordination coord = fabric::coordination(step.particles);
  vector[CN] = coord.Cn;
  vector[ZM] = coord.Zm;
  vector[NCONTACT] = step.sums.contacts.value();
  vector[NPARTICLE] = step.particles.particles.value();
  vector[NO_NORMAL] = step.sums.no_normal.value();

  if (stability_flag)
    vector[MEAN_STABILITY_INDEX] = fabric::mean_stability_index(step.particles, rattlers_flag);

  if (stress_flag) {
    const Eigen::Matrix2d sigma = fabric::love_weber_stress(step.sums, sample_area());
    vector[SXX] = sigma(0, 0);
    vector[SYY] = sigma(1, 1);
    vector[SXY] = 0.5 * (sigma(0, 1) + sigma(1, 0));
  }
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::compute_array()
{
  invoked_array = update->ntimestep;
  const fabric::Histogram hist = fabric::histogram_of(sums_now(false).sums);
  for (int g = 0; g < nbins; g++) {
    array[g][0] = fabric::bin_centre(g, nbins) * RAD2DEG;
    array[g][1] = hist.count[g];
    array[g][2] = hist.mean_fn[g];
    array[g][3] = hist.mean_ft[g];
  }
}

/* ----------------------------------------------------------------------
   per-atom contact count and stability index (1 for < 2 contacts);
   computed only when a dump or variable asks for them
------------------------------------------------------------------------- */

void ComputeFabric::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  sums_now(!three_d);
  if (!three_d && !current.have_lambda) particle_sums(true);

  if (atom->nmax > nmax_atom) {
    nmax_atom = atom->nmax;
    if (three_d)
      memory->grow(vector_atom, nmax_atom, "fabric:vector_atom");
    else
      memory->grow(array_atom, nmax_atom, 2, "fabric:array_atom");
  }
  Region *selected_region = region();
  for (int i = 0; i < atom->nlocal; i++) {
    const bool selected = atom_selected(atom, i, groupbit, selected_region);
    const double count = selected ? contact_source.count_of(i) : 0.0;
    if (three_d) {
      vector_atom[i] = count;
      continue;
    }
    array_atom[i][0] = count;
    array_atom[i][1] = selected ? current.lambda[i] : 0.0;
  }
}

/* ---------------------------------------------------------------------- */

double ComputeFabric::memory_usage()
{
  return contact_source.memory_usage() + current.lambda.capacity() * sizeof(double) +
         2.0 * nmax_atom * sizeof(double);
}

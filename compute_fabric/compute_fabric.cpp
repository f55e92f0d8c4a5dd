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
#include "error.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "region.h"
#include "update.h"
#include "variable.h"

#include "stability_index.h"
#include "style_args.h"

using namespace LAMMPS_NS;

namespace {

constexpr double RAD2DEG = 180.0 / M_PI;

// every message starts so (doc/messages.md, common/style_args.h)
const char *const PREFIX = "Compute fabric: ";

std::string msg(const std::string &text)
{
  return PREFIX + text;
}

} // namespace

/* ---------------------------------------------------------------------- */

ComputeFabric::ComputeFabric(LAMMPS *lammps, int &iarg, int narg, char **arg)
  : Compute(lammps, iarg, narg, arg), nbins(18), estimator(fabric::Estimator::Unbiased),
    stability_flag(false), rattlers_flag(false), histogram_flag(false), stress_flag(false),
    walls_flag(false), area_ivar(-1), iregion(-1), contact_source(lammps, this),
    warned_no_normal(false), nmax_atom(0)
{
  if (domain->dimension != 2)
    error->all(
        FLERR,
        msg("requires dimension 2: it is a 2D compute; set dimension 2 before create_box").c_str());
  if (!atom->radius_flag)
    error->all(FLERR, msg("requires per-atom radii; use atom_style granular (or sphere)").c_str());
  if (atom->tag_enable == 0 || atom->map_style == 0)
    error->all(FLERR, msg("requires atom IDs and an atom map; add atom_modify map array "
                          "before create_box")
                          .c_str());

  // the base class leaves its output pointers uninitialised
  vector = nullptr;
  array = nullptr;
  vector_atom = nullptr;
  array_atom = nullptr;
  vector_local = nullptr;
  array_local = nullptr;

  parse_args(iarg, narg, arg);

  vector_flag = 1;
  size_vector = VECTOR_SIZE;
  extvector = 0;
  memory->create(vector, VECTOR_SIZE, "fabric:vector");
  std::fill(vector, vector + VECTOR_SIZE, 0.0);

  if (histogram_flag) {
    array_flag = 1;
    size_array_rows = nbins;
    size_array_cols = 4;
    extarray = 0;
    memory->create(array, nbins, 4, "fabric:array");
  }

  // per-atom: contact count, stability index
  peratom_flag = 1;
  size_peratom_cols = 2;

  // the contact angles seen at ghosts go to their owners (FabricLocal)
  comm_reverse = FabricLocal::END_SLOTS;
}

/* ----------------------------------------------------------------------
   each keyword's usage ends its messages; doc/compute_fabric.md lists them
------------------------------------------------------------------------- */

void ComputeFabric::parse_args(int iarg, int narg, char **arg)
{
  StyleArgs args(lmp, PREFIX, narg, arg, iarg);
  while (args.more()) {
    const std::string key = args.keyword();
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
                   "stress A or v_name, the sample area (length^2 per unit thickness) of the "
                   "Love-Weber stress");
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
      args.unknown("bins, estimator, stability, rattlers, histogram, stress, region, walls");
    }
  }
  if (rattlers_flag && !stability_flag && comm->me == 0)
    error->warning(FLERR,
                   keyword_message(PREFIX, "rattlers", "yes",
                                   "has no effect without stability yes (it only changes the "
                                   "mean stability index, vector entry 13); add stability yes")
                       .c_str());
}

/* ---------------------------------------------------------------------- */

ComputeFabric::~ComputeFabric()
{
  memory->destroy(vector);
  memory->destroy(array);
  memory->destroy(array_atom);
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::init()
{
  contact_source.init(walls_flag);

  if (!idregion.empty()) {
    iregion = domain->find_region(const_cast<char *>(idregion.c_str()));
    if (iregion < 0)
      error->all(FLERR,
                 keyword_message(PREFIX, "region", idregion,
                                 "region " + idregion +
                                     " was deleted; define it again "
                                     "before the run, or use a compute fabric without region")
                     .c_str());
  }
  if (stress_flag) {
    area_in.init(lmp, PREFIX, "stress"); // the variable exists and is equal-style
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
  if (current.sums.no_normal.value() > 0.0 && !warned_no_normal) warn_no_normal();
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

/* ----------------------------------------------------------------------
   contacts with coincident centres (fabric::make_contact): once per compute,
   printed by rank 0, naming the pair with the smallest tags over all ranks
------------------------------------------------------------------------- */

void ComputeFabric::warn_no_normal()
{
  warned_no_normal = true;
  long a = 0, b = 0;
  double distance = 0.0;
  contact_source.first_missing_normal(a, b, distance); // collective
  if (comm->me != 0) return;
  const std::string pair = b >= 0 ? "atoms " + std::to_string(a) + " and " + std::to_string(b)
                                  : "atom " + std::to_string(a) + " and a mesh wall";
  const long count = static_cast<long>(current.sums.no_normal.value());
  const std::string text = msg(
      std::to_string(count) + " contact(s) with coincident centres (" + pair + ", distance " +
      number_text(distance) +
      ") have no normal; left out "
      "of the fabric and force directions, the stress and the stability index, still counted in "
      "N_c, C_n and Z_m (c_" +
      std::string(id) +
      "[17] is their number); were two atoms created "
      "at one point? (warned once)");
  error->warning(FLERR, text.c_str());
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
  const double area =
      area_in.is_variable() ? input->variable->compute_equal(area_ivar) : area_in.evaluate(lmp);
  if (!(std::isfinite(area) && area > 0.0))
    error->all(FLERR, keyword_message(PREFIX, "stress", area_in.text(),
                                      "is " + number_text(area) + " at step " +
                                          std::to_string(update->ntimestep) +
                                          "; it must be a positive number (the sample area)")
                          .c_str());
  return area;
}

/* ---------------------------------------------------------------------- */

void ComputeFabric::compute_vector()
{
  invoked_vector = update->ntimestep;
  const StepSums &step = sums_now(false);

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
  sums_now(true);
  if (!current.have_lambda) particle_sums(true);

  if (atom->nmax > nmax_atom) {
    memory->destroy(array_atom);
    nmax_atom = atom->nmax;
    memory->create(array_atom, nmax_atom, 2, "fabric:array_atom");
  }
  Region *selected_region = region();
  for (int i = 0; i < atom->nlocal; i++) {
    array_atom[i][0] = array_atom[i][1] = 0.0;
    if (!atom_selected(atom, i, groupbit, selected_region)) continue;
    array_atom[i][0] = contact_source.count_of(i);
    array_atom[i][1] = current.lambda[i];
  }
}

/* ---------------------------------------------------------------------- */

int ComputeFabric::pack_reverse_comm(int n, int first, double *buf)
{
  return contact_source.pack_ends(n, first, buf);
}

void ComputeFabric::unpack_reverse_comm(int n, int *list, double *buf)
{
  contact_source.unpack_ends(n, list, buf);
}

/* ---------------------------------------------------------------------- */

double ComputeFabric::memory_usage()
{
  return contact_source.memory_usage() + current.lambda.capacity() * sizeof(double) +
         2.0 * nmax_atom * sizeof(double);
}

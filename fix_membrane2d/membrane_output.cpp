#include "membrane_output.h"

#include <algorithm>

#include "number_text.h"
#include "stability_checks.h"

namespace membrane {

namespace {

std::string g(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%g", v);
  return buf;
}

} // namespace

// band and tolerance are lengths: a tolerance meant as a fraction of D50
// (0.02) bridges gaps of several disks and shortens the chain; a band far
// below D50 is cut into more slices than the band code allows
std::string band_problem(double band, double d50)
{
  if (band >= BAND_MIN * d50) return "";
  return "is " + g(band / d50) + " x D50 (D50 = " + g(d50) +
         "); the band is a width in distance units, at least " + g(BAND_MIN) + " x D50 (default " +
         g(DEFAULT_BAND) + " x D50 = " + g(DEFAULT_BAND * d50) + ")";
}

std::string enclose_problem(bool top, double platen, double centre)
{
  if (top ? !(centre > platen) : !(centre < platen)) return "";
  return "is " + number_text(platen) + (top ? ", below the highest" : ", above the lowest") +
         " disk centre of the group (y = " + number_text(centre) +
         "); the platens must enclose the sample";
}

std::string chain_step_warning(AtomId tag, double fraction, long long step)
{
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "chain disk %d moved %.3g of its radius in one step at step %lld (limit %g; "
                "quasi-static chains move < %g): its speed jumped. Ramp the pressure instead of "
                "jumping it, or reduce the time step or the loading rate (warned once; f_ID[15] "
                "is the current value)",
                tag, fraction, step, CHAIN_STEP_LIMIT, stability::STEP_FRACTION_QUASI_STATIC);
  return buf;
}

std::string inertial_warning(const InertialWindow &w, double limit, long long step, double d50,
                             double density, double pressure)
{
  char buf[512];
  std::snprintf(buf, sizeof(buf),
                "inertial number I = %.3g > %g at step %lld (axial strain rate %.3g 1/s of the "
                "platens, d50 %.3g m, density %.3g kg/m^2 per unit thickness, pressure %.3g Pa): "
                "the test is not quasi-static; lower the loading rate below %.3g 1/s (warned "
                "once; f_ID[16] is the current value)",
                w.value, limit, step, w.rate, d50, density, pressure, w.rate * limit / w.value);
  return buf;
}

void output_vector(const SideChain (&chains)[2], const SideLoad (&loads)[2], const RunState &run,
                   Platens platens, double pressure, double chain_step, double *v)
{
  std::fill(v, v + OUTPUT_SIZE, 0.0);
  const SideChain &l = chains[LEFT], &r = chains[RIGHT];
  if (l.active && r.active) {
    v[AREA] = sample_area(loads[LEFT].polyline, loads[RIGHT].polyline);
    v[MEAN_WIDTH] = v[AREA] / (platens.hi - platens.lo);
    v[MID_WIDTH] =
        width_at(0.5 * (platens.lo + platens.hi), loads[LEFT].polyline, loads[RIGHT].polyline);
  }
  v[CHAIN_LEFT] = l.active ? static_cast<double>(l.chain_tags.size()) : 0.0;
  v[CHAIN_RIGHT] = r.active ? static_cast<double>(r.chain_tags.size()) : 0.0;
  v[ESCAPED] = static_cast<double>(l.escaped_tags.size() + r.escaped_tags.size());
  v[FX_LEFT] = loads[LEFT].total.x();
  v[FY_LEFT] = loads[LEFT].total.y();
  v[FX_RIGHT] = loads[RIGHT].total.x();
  v[FY_RIGHT] = loads[RIGHT].total.y();
  v[DETECTIONS] = static_cast<double>(run.counters.detections);
  v[FAILURES] = static_cast<double>(run.counters.failures);
  v[PRESSURE] = pressure;
  v[WIDENINGS] = static_cast<double>(run.counters.widenings);
  v[CHAIN_STEP] = chain_step;
  v[INERTIAL] = run.inertial.value;
  v[CHANGES] = static_cast<double>(run.counters.changes);
}

std::string no_chain_error(const std::string &where, const std::string &why)
{
  return "no chain of touching particles from the bottom to the top platen on the " + where + ": " +
         why + "; check ylo/yhi, the band width and the tolerance";
}

std::string chain_lost_warning(const std::string &where, const std::string &why)
{
  return "chain lost on the " + where + " (" + why +
         "): keeping the previous chain; counted in f_ID[12], warned once";
}

std::string lost_disk_error(long long step)
{
  return "a chain, escaped or band disk was lost at step " + std::to_string(step) +
         " (it left the box, or its position became infinite or NaN under an infinite force; "
         "'thermo_modify lost ignore' hides this): the membrane cannot hold a sample whose outer "
         "disks fly off; check the time step, the pressure and the platens";
}

std::string not_finite_error(long long step)
{
  return "a chain particle position is not finite at step " + std::to_string(step) +
         ": the run has gone unstable; reduce the time step or the loading rate";
}

std::string traffic_summary(double step_bytes, double detection_bytes,
                            long long steps, long long detections, long long full_passes,
                            double fix_seconds, double search_seconds)
{
  char buf[560];
  std::snprintf(buf, sizeof(buf),
                "each rank received %.3g kB per step (chain, escaped and watched disks) and "
                "%.3g kB per detection (bands, search results) over %lld steps with %lld "
                "detections (%lld of them a pass over all disks); the fix took %.3g s (slowest "
                "rank), %.3g s of it in chain searches (one rank per side)",
                steps > 0 ? step_bytes / steps / 1e3 : step_bytes / 1e3,
                detections > 0 ? detection_bytes / detections / 1e3 : 0.0, steps, detections,
                full_passes, fix_seconds, search_seconds);
  return buf;
}

long polyline_frame_start(std::vector<PolylineFrame> &frames, long long step, long end)
{
  const auto first = std::find_if(frames.begin(), frames.end(),
                                  [step](const PolylineFrame &f) { return f.step >= step; });
  const long start = first == frames.end() ? end : first->offset;
  frames.erase(first, frames.end());
  frames.push_back({step, start});
  return start;
}

void write_polyline_side(std::FILE *fp, const char *side, const Polyline &polyline,
                         const std::vector<Disk> &chain, const std::vector<Eigen::Vector2d> &forces)
{
  std::fprintf(fp, "ITEM: POLYLINE %s %zu\n", side, polyline.size());
  for (const Eigen::Vector2d &p : polyline) std::fprintf(fp, "%.10g %.10g\n", p.x(), p.y());
  std::fprintf(fp, "ITEM: CHAIN %s %zu (tag x y r fx fy)\n", side, chain.size());
  for (std::size_t c = 0; c < chain.size(); c++) {
    const Disk &d = chain[c];
    std::fprintf(fp, "%d %.10g %.10g %.10g %.10g %.10g\n", d.tag, d.x, d.y, d.r, forces[c].x(),
                 forces[c].y());
  }
}

} // namespace membrane

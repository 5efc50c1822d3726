// The prediction of an envelope's size from its input samples, and the refusal of a rho the
// sampling cannot support. The counts follow sample_envelope's own rules (candidates per
// sample, rims swept along the curves, one Poisson-disk thinning); see rho_support.h.
#include "rho_support.h"

#include "envcrust/neighbour_table.h"

#include <CGAL/squared_distance_3.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace envcrust::cli {
namespace {

constexpr unsigned kNeighbours = 8;         // r_k of the envelope's candidates and gap bound
constexpr double kGapsPerRho = 2.5;         // gaps an envelope of rho bridges (sample_envelope)
constexpr double kGapQuantile = 0.99;       // EnvelopeOptions::gap_quantile
constexpr double kCandidatesPerH2 = 12.0;   // sheet candidates per h^2 (sample_envelope)
constexpr double kMaxGeneratorsPerSample = 64.0;
// Area of the envelope per sample after the thinning, in h^2 (h = spacing). Measured with
// `envcrust envelope` of 2,000 and 5,000 samples of the hemisphere at rho 0.1 and 0.3: 1.74.
constexpr double kAreaPerSampleRelH2 = 1.75;

// Rounded up to two significant digits: a rho to type that still passes.
double round_up_2(double x) {
  if (!(x > 0)) return x;
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return std::ceil(x / unit * (1 - 1e-12)) * unit;
}

std::string format(double x, int digits = 3) {
  std::ostringstream s;
  s << std::setprecision(digits) << x;
  return s.str();
}

std::string count_text(double x) {
  std::ostringstream s;
  if (x >= 1e6)
    s << std::setprecision(2) << std::fixed << x / 1e6 << " million";
  else
    s << static_cast<long long>(std::llround(x));
  return s.str();
}

std::vector<double> neighbour_distances(const std::vector<Point3>& points) {
  const NeighbourTable table(points, kNeighbours);
  std::vector<double> rk(points.size(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto row = table.of(i);
    if (!row.empty()) rk[i] = std::sqrt(CGAL::squared_distance(points[i], points[row.back()]));
  }
  return rk;
}

double quantile(std::vector<double> values, double q) {
  const auto at = std::min(values.size() - 1, static_cast<std::size_t>(q * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at];
}

double budget_for(std::size_t samples) {
  return std::clamp(kEnvelopeBudgetPerSample * static_cast<double>(samples), kEnvelopeBudgetMin, kEnvelopeBudgetMax);
}

}  // namespace

double predict_envelope_samples(const envelope::SurfaceSamples& samples, const std::vector<double>& rk, double rho,
                                double spacing_rel_rho) {
  const double h = spacing_rel_rho * rho;
  const double per_sample_area = kAreaPerSampleRelH2 * h * h;
  double sheets = 0.0;
  for (const double r : rk) {
    // Disks of radius r_k overlap about k times: each sample stands for pi r_k^2 / k of M.
    const double area = std::numbers::pi * r * r / kNeighbours;
    const double wanted = kCandidatesPerH2 * area / (h * h);
    const double generators = wanted < 1.0 ? wanted : std::min(std::ceil(wanted), kMaxGeneratorsPerSample);
    sheets += 2.0 * std::min(generators, area / per_sample_area);
  }
  // A rim is a half-tube of radius rho around its curve: pi rho per unit of length.
  double length = 0.0;
  for (const auto& curve : samples.boundary) {
    const auto& v = curve.vertices;
    for (std::size_t i = 0; i < v.size(); ++i)
      length += std::sqrt(CGAL::squared_distance(v[i].position, v[(i + 1) % v.size()].position));
  }
  return sheets + std::numbers::pi * rho * length / per_sample_area;
}

RhoSupport rho_support(const envelope::SurfaceSamples& samples, double rho, double spacing_rel_rho) {
  RhoSupport s;
  s.rho = rho;
  s.input_samples = samples.points.size();
  s.spacing_rel_rho = spacing_rel_rho;
  const std::vector<double> rk = neighbour_distances(samples.points);
  s.min_rho_for_gaps = quantile(rk, kGapQuantile) / kGapsPerRho;
  s.budget = budget_for(samples.points.size());
  s.predicted_samples = predict_envelope_samples(samples, rk, rho, spacing_rel_rho);
  // The prediction falls as rho grows (as 1 / rho^2 once the candidates no longer limit it):
  // step up from the gap bound until it fits.
  double workable = round_up_2(std::max(rho, s.min_rho_for_gaps));
  for (int step = 0; step < 400 && predict_envelope_samples(samples, rk, workable, spacing_rel_rho) > s.budget; ++step)
    workable = round_up_2(workable * 1.05);
  s.workable_rho = workable;
  return s;
}

std::string rho_refusal(const std::string& input, const RhoSupport& s) {
  std::ostringstream m;
  m << input << ": rho " << format(s.rho) << " is more than the sampling supports: ";
  if (s.is_below_gaps())
    m << "its envelope bridges gaps up to 2.5 rho, and 1% of the samples have their 8th neighbour farther than "
      << format(kGapsPerRho * s.min_rho_for_gaps) << " (rho >= " << format(s.min_rho_for_gaps)
      << " bridges them), so it would have holes" << (s.is_over_budget() ? ", and " : "; ");
  if (s.is_over_budget())
    m << "its envelope would take about " << count_text(s.predicted_samples) << " samples (budget "
      << count_text(s.budget) << " for " << s.input_samples << " input samples); ";
  m << "use --rho " << format(s.workable_rho, 4) << " or more (or --rho auto), or --force to run it anyway";
  return m.str();
}

}  // namespace envcrust::cli

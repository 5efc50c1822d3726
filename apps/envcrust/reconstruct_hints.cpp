// The hints of `envcrust reconstruct` for scans.
#include "reconstruct_hints.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace envcrust::cli {
namespace {

// Detected boundary loops narrower than this many local spacings (and than half the widest)
// are named in a hint: --boundary-min-width drops them if they are sampling gaps. A gap
// narrower than 3 spacings is no unsampled stripe (its loop is an arc closed on itself).
constexpr double kNarrowLoopWidth = 8.0;
constexpr double kStripeMinWidth = 3.0;

// Detected boundary loops much narrower than the widest one may be unsampled stripes rather
// than holes of the surface (the foot's sole: two loops about 5 spacings wide, the ankle 13):
// which --boundary-min-width would drop them. Only when the detection dropped none by width,
// and no loop is thinner than a stripe can be. Loops below the reconstruction's resolution
// (`unresolved`: closed in the result whatever the flag) are left out of it.
std::optional<std::string> narrow_loops_hint(const LoadedSurface& loaded, const std::vector<std::size_t>& unresolved) {
  if (!loaded.detection) return std::nullopt;
  const auto& widths = loaded.detection->loop_widths;
  std::vector<std::size_t> loops;  // the loops the hint weighs
  for (std::size_t i = 0; i < widths.size(); ++i)
    if (std::find(unresolved.begin(), unresolved.end(), i) == unresolved.end()) loops.push_back(i);
  if (loops.size() < 2 || loaded.min_loop_width > 0) return std::nullopt;
  double widest = 0.0;
  for (const std::size_t i : loops) widest = std::max(widest, widths[i]);
  std::vector<std::size_t> narrow;
  double narrow_max = 0.0;
  for (const std::size_t i : loops)
    if (widths[i] >= kStripeMinWidth && widths[i] < kNarrowLoopWidth && widths[i] < 0.5 * widest) {
      narrow.push_back(i);
      narrow_max = std::max(narrow_max, widths[i]);
    }
  if (narrow.empty()) return std::nullopt;
  // The width that drops them would also drop any thinner loop, which is no stripe but a
  // boundary the detector could not close (the lion head's neck): then no advice.
  for (const std::size_t i : loops)
    if (widths[i] < kStripeMinWidth) return std::nullopt;
  // "a", "a and b", "a, b and c"
  auto listed = [&](auto&& item) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(1);
    for (std::size_t k = 0; k < narrow.size(); ++k)
      out << (k == 0 ? "" : k + 1 == narrow.size() ? " and " : ", ") << item(narrow[k]);
    return out.str();
  };
  const bool one = narrow.size() == 1;
  std::ostringstream h;
  h << std::fixed << std::setprecision(1) << "detected boundary loop" << (one ? " " : "s ")
    << listed([](std::size_t i) { return i; }) << (one ? " is " : " are ")
    << listed([&](std::size_t i) { return widths[i]; }) << " local spacings wide (the widest " << widest << "): if "
    << (one ? "it is an unsampled stripe rather than a hole" : "they are unsampled stripes rather than holes")
    << " of the surface, --boundary-min-width " << std::setprecision(0) << std::floor(narrow_max) + 1 << " drops "
    << (one ? "it" : "them");
  return h.str();
}

// A point file whose result falls into more pieces than its samples form (within 2 rho, where
// the envelope's balls overlap) was too sparse for the estimated normals or the envelope's
// sheet: the direct Power Crust needs no normals and copes with sparser samples of a closed
// surface (the original program's knotted tube, 1,281 points: 6 pieces here, a torus there).
std::optional<std::string> pieces_hint(const LoadedSurface& loaded, const analysis::AnalysisReport& report,
                                       const envelope::EnvelopeSamples& envelope) {
  const std::size_t pieces = report.topology.components.size();
  if (loaded.source != "points" || pieces < 2 || envelope.rho <= 0) return std::nullopt;
  const std::size_t groups = pipeline::sample_groups(loaded.samples.points, 2.0 * envelope.rho);
  if (pieces <= groups) return std::nullopt;
  std::ostringstream h;
  h << std::setprecision(4) << "the result has " << pieces << " pieces where the samples form " << groups
    << (groups == 1 ? " connected set" : " connected sets") << " (neighbours within 2 rho = " << 2.0 * envelope.rho
    << "): the sample may be too sparse for the estimated normals and the envelope (rho " << envelope.rho
    << ", estimated reach " << envelope.reach.reach
    << "); if the surface is closed, --method powercrust, which needs no normals, copes with sparser samples";
  return h.str();
}

}  // namespace

std::vector<std::string> scan_hints(const LoadedSurface& loaded, const pipeline::ReconstructOptions& options,
                                    const analysis::AnalysisReport& report,
                                    const std::vector<std::size_t>& unresolved_curves,
                                    const envelope::EnvelopeSamples& envelope) {
  const auto& sheet = options.sheet;
  if (loaded.kind.is_builtin || options.method != pipeline::Method::Envelope ||
      options.extraction != pipeline::Extraction::Sheet)
    return {};
  long cross_caps = 0, handles = 0;
  for (const auto& c : report.topology.components) {
    if (!c.genus) continue;
    (c.is_orientable ? handles : cross_caps) += *c.genus;
  }
  std::vector<std::string> hints;
  if (cross_caps > 0 && !(sheet.cut_to_orientable && std::isinf(sheet.orientable_max_twist_loop_rel_rho)) &&
      loaded.kind.is_orientable.value_or(true))
    hints.push_back("the result is non-orientable (" + std::to_string(cross_caps) + " cross-cap" +
                    (cross_caps == 1 ? "" : "s") + "): if the input scans an orientable surface, --orientable removes " +
                    (cross_caps == 1 ? "it" : "them") + " and closes the holes");
  std::ostringstream h;
  if (handles > 0 && sheet.cut_handles_rel_rho == 0)
    h << "the result has genus " << handles << ": if the scanned surface has no handles at the scale of rho, "
      << "--cut-handles " << pipeline::kScanCutHandlesRelRho << " removes them and closes the holes";
  else if (handles > 0 && cross_caps == 0)
    h << "the result has genus " << handles << " after the cuts at " << sheet.cut_handles_rel_rho
      << " rho: if the scanned surface has fewer handles, --cut-handles " << 2 * sheet.cut_handles_rel_rho
      << " also removes the ones up to twice as wide";
  if (!h.str().empty()) hints.push_back(h.str());
  if (const auto stripes = narrow_loops_hint(loaded, unresolved_curves)) hints.push_back(*stripes);
  if (const auto pieces = pieces_hint(loaded, report, envelope)) hints.push_back(*pieces);
  return hints;
}

}  // namespace envcrust::cli

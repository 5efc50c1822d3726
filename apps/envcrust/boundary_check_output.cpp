// Warnings and JSON of analysis::check_boundary for the reconstruct command.
#include "boundary_check_output.h"

#include "envcrust/mesh.h"
#include "envcrust/pipeline.h"

#include <algorithm>
#include <sstream>

namespace envcrust::cli {

std::vector<std::string> boundary_check_warnings(const analysis::BoundaryCheck& check,
                                                 const std::vector<Polyline>& curves,
                                                 const topology::MeshTopology& topology,
                                                 const std::string& tolerance_text) {
  std::vector<std::string> out;
  auto is_left_out = [&](std::size_t c) {
    return std::find(check.left_out_curves.begin(), check.left_out_curves.end(), c) != check.left_out_curves.end();
  };
  for (const std::size_t c : check.missing_curves) {
    const auto& m = check.matches[c];
    std::ostringstream w;
    w.precision(4);
    w << "input boundary curve " << c << " (length " << mesh::closed_length(curves[c]) << ") has no border loop of the result within "
      << tolerance_text << " along " << 100 * check.follow_fraction << "% of both";
    if (m.mesh_loop)
      w << " (the nearest, loop " << *m.mesh_loop << ", is " << check.follow_distances[c] << " away there, "
        << m.hausdorff << " at most)";
    else w << " (the result has no border)";
    if (is_left_out(c)) w << ": the result left out the part of the surface it bounds (none of it lies within "
                          << tolerance_text << " of the curve)";
    else w << ": the result closed it, tore it or moved it";
    out.push_back(w.str());
  }
  for (const std::size_t c : check.unresolved_curves) {
    std::ostringstream w;
    w.precision(4);
    w << "input boundary curve " << c << " (length " << mesh::closed_length(curves[c]) << ") is "
      << (is_left_out(c) ? "left out of the result with the part of the surface it bounds (no part of the result lies "
                           "within " + tolerance_text + " of it)"
                         : std::string("closed in the result"))
      << ": shorter than " << check.min_resolvable_length << ", it is below the resolution of the reconstruction "
      << "(the envelope bridges every hole shorter than 2 pi rho)";
    out.push_back(w.str());
  }
  for (const std::size_t l : check.extra_loops) {
    std::ostringstream w;
    w.precision(4);
    w << "border loop " << l << " of the result (length " << topology.boundary_loops[l].length
      << ") follows no boundary curve of the input within " << tolerance_text << " along " << 100 * check.follow_fraction
      << "% of both: a hole the input does not have";
    out.push_back(w.str());
  }
  return out;
}

nlohmann::json boundary_check_json(const analysis::BoundaryCheck& check, const std::vector<Polyline>& curves,
                                   const topology::MeshTopology& topology) {
  nlohmann::json missing = nlohmann::json::array(), unresolved = nlohmann::json::array(),
                 left_out = nlohmann::json::array(), extra = nlohmann::json::array(),
                 matches = nlohmann::json::array();
  for (const auto& m : check.matches)
    matches.push_back({{"curve", m.reference_loop},
                       {"curve_length", mesh::closed_length(curves[m.reference_loop])},
                       {"loop", m.mesh_loop ? nlohmann::json(*m.mesh_loop) : nlohmann::json(nullptr)},
                       {"hausdorff", m.mesh_loop ? nlohmann::json(m.hausdorff) : nlohmann::json(nullptr)},
                       {"follow_distance", m.mesh_loop ? nlohmann::json(check.follow_distances[m.reference_loop])
                                                       : nlohmann::json(nullptr)}});
  for (const std::size_t c : check.missing_curves) missing.push_back(c);
  for (const std::size_t c : check.unresolved_curves) unresolved.push_back(c);
  for (const std::size_t c : check.left_out_curves) left_out.push_back(c);
  for (const std::size_t l : check.extra_loops) extra.push_back(l);
  return {{"tolerance", check.tolerance},        {"follow_fraction", check.follow_fraction},
          {"curves", curves.size()},
          {"loops", topology.boundary_loops.size()}, {"matches", matches},
          {"missing_curves", missing},           {"unresolved_curves", unresolved},
          {"left_out_curves", left_out},
          {"min_resolvable_length", check.min_resolvable_length}, {"extra_loops", extra},
          {"is_consistent", check.is_consistent()}};
}

std::string uncovered_patches_warning(std::size_t patches) {
  return "the result leaves out " + std::to_string(patches) + (patches == 1 ? " patch" : " patches") +
         " of the input's samples (" + std::to_string(pipeline::kMinUncoveredPatch) +
         " or more samples farther than 2 rho from it)";
}

}  // namespace envcrust::cli

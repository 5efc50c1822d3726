// The JSON and text that `envcrust reconstruct` gives of a run's stages: rho
// and the envelope, the adaptive retry and the Power Crust fallback, the
// sheet's statistics, the remeshing, the seconds per stage.
#include "reconstruct_output.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "envcrust/topology.h"

namespace envcrust::cli {

nlohmann::json envelope_json(const envelope::EnvelopeSamples &e) {
  nlohmann::json j = {{"rho", e.rho},
                      {"rho_min", e.rho_min},
                      {"spacing", e.spacing},
                      {"samples", e.samples.size()},
                      {"candidates", e.candidates},
                      {"dropped_too_close", e.dropped_too_close},
                      {"input_largest_gap", e.input_coverage},
                      {"min_rho_for_gaps", e.min_rho_for_gaps},
                      {"noise", e.noise}};
  if (e.reach.pairs_examined > 0) {
    j["reach"] = {
        {"reach", e.reach.reach}, {"curvature_radius", e.reach.curvature_radius}, {"bottleneck", e.reach.bottleneck}};
    j["rho_from"] = e.is_rho_gap_bound     ? "gaps"
                    : e.is_rho_noise_bound ? "noise"
                    : e.is_rho_width_bound ? "width"
                                           : "reach";
    if (std::isfinite(e.half_width)) j["half_width"] = e.half_width;
    j["input_too_sparse"] = e.is_input_too_sparse;
  }
  return j;
}

std::string describe(const pipeline::RunDefects &d, const std::optional<long> &max_genus) {
  if (!d.genus) return d.is_empty ? "no faces" : "no manifold";
  std::string out = "genus " + std::to_string(*d.genus);
  auto count = [](std::size_t n, const char *one, const char *many) {
    return std::to_string(n) + (n == 1 ? one : many);
  };
  if (d.extra_loops > 0) out += ", " + count(d.extra_loops, " hole the input has not", " holes the input has not");
  if (d.missing_curves > 0)
    out += ", " + count(d.missing_curves, " input curve not followed", " input curves not followed");
  if (d.extra_pieces > 0)
    out += ", " + count(d.extra_pieces, " piece more than the samples form", " pieces more than the samples form");
  if (d.uncovered_patches > 0)
    out += ", " + count(d.uncovered_patches, " patch of samples left out", " patches of samples left out");
  return out + " (" + count(d.count(max_genus), " defect", " defects") + ")";
}

std::string describe(const pipeline::LocalRhoFirst &local, const std::optional<long> &max_genus) {
  std::ostringstream out;
  out << std::setprecision(4) << "rho: the local run (rho " << local.rho_min << " to " << local.rho_max << ", "
      << local.envelope_samples << " envelope samples, " << local.seconds << " s) ";
  if (local.is_kept) return out.str() + "needed no cut and has " + describe(*local.defects, max_genus) + ", kept";
  if (local.defects) {
    out << "has " << describe(*local.defects, max_genus);
  } else {
    out << "needed a cut (" << local.orientation_seams
        << (local.orientation_seams == 1 ? " orientation seam, " : " orientation seams, ") << local.handle_balls
        << (local.handle_balls == 1 ? " handle ball)" : " handle balls)");
  }
  out << ", not kept: the uniform run follows";
  return out.str();
}

std::string describe(const pipeline::PowerCrustFirst &first, const std::optional<long> &max_genus) {
  std::ostringstream out;
  out << std::setprecision(4) << "the input has no boundary curve: the direct Power Crust first (" << first.seconds
      << " s) ";
  if (!first.failure.empty()) return out.str() + "failed (" + first.failure + "), the envelope runs follow";
  out << "has " << describe(first.defects, max_genus);
  if (first.farthest_from_samples > first.allowed_distance)
    out << " and reaches " << first.farthest_from_samples << " from the samples, beyond their gaps ("
        << first.allowed_distance << ")";
  if (first.is_input_too_sparse) out << ", on samples too sparse for their size";
  return out.str() + (first.is_kept ? ", kept (no envelope run)" : ", not kept: the envelope runs follow");
}

std::string describe(const pipeline::AdaptiveRetry &retry) {
  return "rho: the uniform run has " + describe(retry.uniform, retry.max_genus) +
         (retry.max_genus ? " where the input mesh has genus " + std::to_string(*retry.max_genus) : std::string()) +
         "; with --rho-adaptive " + describe(retry.adaptive, retry.max_genus) + ", " +
         (retry.kept_adaptive ? "kept" : "not kept") + " (--no-adaptive-retry: keep the uniform run)";
}

std::string describe(const pipeline::PowerCrustFallback &fallback, const std::optional<long> &max_genus) {
  std::ostringstream spans;
  if (fallback.crust_farthest_from_samples > fallback.crust_allowed_distance)
    spans << std::setprecision(4) << " and reaches " << fallback.crust_farthest_from_samples
          << " from the samples, beyond their gaps (" << fallback.crust_allowed_distance << "): it caps holes";
  const std::string spans_holes = spans.str();
  return std::string(fallback.input_curves > 0 ? "the input's curves were detected (maybe false ones)"
                                               : "the input has no boundary curve") +
         " and the envelope's result has " + describe(fallback.envelope, max_genus) + " (the samples form " +
         std::to_string(fallback.sample_groups) + (fallback.sample_groups == 1 ? " set" : " sets") +
         " within 2 rho); " +
         (fallback.power_crust_failure.empty()
              ? "the direct Power Crust's has " + describe(fallback.power_crust, max_genus) + spans_holes
              : "the direct Power Crust failed (" + fallback.power_crust_failure + ")") +
         ", " + (fallback.kept_power_crust ? "kept" : "not kept") + " (--no-power-crust-fallback: keep the envelope's)";
}

nlohmann::json defects_json(const pipeline::RunDefects &d, const std::optional<long> &max_genus) {
  return {{"empty", d.is_empty},
          {"genus", d.genus ? nlohmann::json(*d.genus) : nlohmann::json(nullptr)},
          {"extra_loops", d.extra_loops},
          {"missing_curves", d.missing_curves},
          {"extra_pieces", d.extra_pieces},
          {"uncovered_patches", d.uncovered_patches},
          {"defects", d.genus ? nlohmann::json(d.count(max_genus)) : nlohmann::json(nullptr)}};
}

nlohmann::json run_stages_json(const pipeline::ReconstructResult &result, const pipeline::ReconstructOptions &options) {
  nlohmann::json j;
  j["method"] = options.method == pipeline::Method::Envelope ? "envelope" : "powercrust";
  if (options.method == pipeline::Method::Envelope) {
    j["extraction"] = options.extraction == pipeline::Extraction::Sheet ? "sheet" : "powershape";
    // null when the Power Crust first was kept: no envelope run was made.
    j["envelope"] = result.power_crust_first && result.power_crust_first->is_kept ? nlohmann::json(nullptr)
                                                                                  : envelope_json(result.envelope);
  }
  j["seconds"] = {{"envelope", result.seconds.envelope},
                  {"power_crust", result.seconds.power_crust},
                  {"extraction", result.seconds.extraction},
                  {"remesh", result.seconds.remesh},
                  {"simplify", result.seconds.simplify}};
  if (const auto &first = result.power_crust_first) {
    j["power_crust_first"] = {{"result", defects_json(first->defects, options.max_genus)},
                              {"farthest_from_samples", first->farthest_from_samples},
                              {"allowed_distance", first->allowed_distance},
                              {"failure", first->failure},
                              {"input_too_sparse", first->is_input_too_sparse},
                              {"seconds", first->seconds},
                              {"kept", first->is_kept}};
  }
  if (const auto &local = result.local_rho_first) {
    j["local_rho_first"] = {{"rho_min", local->rho_min},
                            {"rho_max", local->rho_max},
                            {"envelope_samples", local->envelope_samples},
                            {"orientation_seams", local->orientation_seams},
                            {"handle_balls", local->handle_balls},
                            {"result", local->defects ? defects_json(*local->defects, options.max_genus)
                                                      : nlohmann::json(nullptr)},
                            {"seconds", local->seconds},
                            {"kept", local->is_kept}};
  }
  if (const auto &retry = result.adaptive_retry) {
    j["adaptive_retry"] = {
        {"max_genus", retry->max_genus ? nlohmann::json(*retry->max_genus) : nlohmann::json(nullptr)},
        {"uniform", defects_json(retry->uniform, retry->max_genus)},
        {"adaptive", defects_json(retry->adaptive, retry->max_genus)},
        {"kept", retry->kept_adaptive ? "adaptive" : "uniform"}};
  }
  if (const auto &f = result.power_crust_fallback) {
    j["power_crust_fallback"] = {{"sample_groups", f->sample_groups},
                                 {"envelope", defects_json(f->envelope, options.max_genus)},
                                 {"power_crust", defects_json(f->power_crust, options.max_genus)},
                                 {"crust_farthest_from_samples", f->crust_farthest_from_samples},
                                 {"crust_allowed_distance", f->crust_allowed_distance},
                                 {"power_crust_failure", f->power_crust_failure},
                                 {"kept", f->kept_power_crust ? "power_crust" : "envelope"}};
  }
  if (result.sheet_stats) {
    const auto &s = *result.sheet_stats;
    j["sheet"] = {
        {"delaunay_edges", s.delaunay_edges},
        {"crossing_edges", s.crossing_edges},
        {"polygons", s.polygons},
        {"components_dropped", s.components_dropped},
        {"far_faces_removed", s.far_faces_removed},
        {"non_manifold_faces_removed", s.non_manifold_faces_removed},
        {"vertices_split", s.vertices_split},
        {"holes_filled", s.holes_filled},
        {"vertices_projected", s.vertices_projected},
        {"projections_refused", s.projections_refused},
        {"vertices_welded", s.vertices_welded},
        {"final_defects_repaired", s.final_defects_repaired},
        {"faces_dropped_at_defects", s.faces_dropped_at_defects},
        {"orientation_seams", s.orientation_seams},
        {"faces_removed_at_seams", s.faces_removed_at_seams},
        {"orientation_twists_kept", s.orientation_twists_kept},
        {"handle_balls", s.handle_balls},
        {"faces_removed_at_handles", s.faces_removed_at_handles},
        {"cut_holes_filled", s.cut_holes_filled},
        {"cut_notches_closed", s.cut_notches_closed},
        {"self_intersections_found", s.self_intersections_found},
        {"self_intersections_smoothed", s.self_intersections_smoothed},
        {"faces_removed_at_self_intersections", s.faces_removed_at_self_intersections},
        {"self_intersections_cut", s.self_intersections_cut},
        {"self_intersection_cut_rounds", s.self_intersection_cut_rounds},
        {"self_intersection_cut_widenings", s.self_intersection_cut_widenings},
        {"self_intersections_left", s.self_intersections_left},
        {"self_intersection_cut_rel_rho", options.sheet.self_intersection_cut_rel_rho},
        {"cut_to_orientable", options.sheet.cut_to_orientable},
        {"orientable_max_twist_loop_rel_rho", std::isinf(options.sheet.orientable_max_twist_loop_rel_rho)
                                                  ? nlohmann::json(nullptr)
                                                  : nlohmann::json(options.sheet.orientable_max_twist_loop_rel_rho)},
        {"cut_handles_rel_rho", options.sheet.cut_handles_rel_rho},
        {"seconds",
         {{"voronoi", s.seconds.voronoi},
          {"cleaning", s.seconds.cleaning},
          {"projection", s.seconds.projection},
          {"manifold_check", s.seconds.manifold_check},
          {"orientable_cut", s.seconds.orientable_cut},
          {"handle_cut", s.seconds.handle_cut},
          {"self_intersection_cut", s.seconds.self_intersection_cut}}}};
  }
  if (result.remesh_stats) {
    const auto &s = *result.remesh_stats;
    j["remesh"] = {{"is_remeshed", s.is_remeshed},
                   {"faces_before", s.faces_before},
                   {"faces_after", s.faces_after},
                   {"target_edge_length", s.target_edge_length},
                   {"min_angle_deg_before", s.min_angle_deg_before},
                   {"min_angle_deg_after", s.min_angle_deg_after},
                   {"seconds", s.seconds}};
  }
  if (const auto &m = result.sample_meshing) {
    j["sample_meshing"] = {{"is_kept", m->is_kept},
                           {"sheet_topology", m->sheet_topology},
                           {"samples_topology", m->samples_topology},
                           {"spacing", m->stats.spacing},
                           {"candidates_refused", m->stats.candidates_refused},
                           {"holes_filled", m->stats.holes_filled},
                           {"holes_left", m->stats.holes_left},
                           {"samples_moved", m->stats.samples_moved},
                           {"samples_left_out", m->stats.samples_left_out},
                           {"median_offset_rel_spacing", m->stats.median_offset_rel_spacing},
                           {"seconds", m->stats.seconds}};
  }
  if (const auto &s = result.simplify_stats) {
    j["simplify"] = {{"is_simplified", s->is_simplified},
                     {"vertices_before", s->vertices_before},
                     {"vertices_after", s->vertices_after},
                     {"vertices_held", s->vertices_held},
                     {"seconds", s->seconds}};
  }
  if (result.envelope_crust) {
    const auto crust = topology::analyze_topology(*result.envelope_crust);
    j["envelope_crust"] = {{"faces", crust.faces},
                           {"euler_characteristic", crust.euler_characteristic},
                           {"is_closed", crust.is_closed()},
                           {"is_manifold", crust.is_manifold()}};
  }
  return j;
}

void print_run_stages(std::ostream &out, const pipeline::ReconstructResult &result,
                      const pipeline::ReconstructOptions &options) {
  const bool is_crust_first = result.power_crust_first && result.power_crust_first->is_kept;
  if (const auto &first = result.power_crust_first) out << "  " << describe(*first, options.max_genus) << "\n";
  if (options.method == pipeline::Method::Envelope && !is_crust_first)
    out << "  envelope: rho " << (result.envelope.local_rho.empty() ? "" : "adaptive, at most ") << result.envelope.rho
        << (result.envelope.reach.pairs_examined == 0 ? ""
            : result.envelope.is_rho_gap_bound        ? " (from the input's gaps)"
            : result.envelope.is_rho_noise_bound      ? " (from the noise)"
            : result.envelope.is_rho_width_bound      ? " (from the surface's half-width)"
                                                      : " (from the reach)")
        << (result.envelope.local_rho.empty() ? "" : ", at least " + std::to_string(result.envelope.rho_min))
        << ", spacing " << result.envelope.spacing << ", " << result.envelope.samples.size() << " samples\n";
  if (const auto &local = result.local_rho_first) out << "  " << describe(*local, options.max_genus) << "\n";
  if (const auto &retry = result.adaptive_retry) out << "  " << describe(*retry) << "\n";
  if (const auto &f = result.power_crust_fallback) out << "  " << describe(*f, options.max_genus) << "\n";
  // The stages that ran (the sheet runs its own Delaunay triangulation, no
  // power crust).
  out << "  time:";
  const char *separator = " ";
  auto stage = [&](const char *name, double seconds) {
    out << separator << name << " " << seconds << " s";
    separator = ", ";
  };
  if (options.method == pipeline::Method::Envelope && !is_crust_first) stage("envelope", result.seconds.envelope);
  if (result.power_crust_stats || result.power_crust_fallback || result.power_crust_first)
    stage(options.method == pipeline::Method::PowerCrust ? "power crust"
          : result.power_crust_fallback || result.power_crust_first ? "direct power crust"
                                                                    : "power crust of the envelope",
          result.seconds.power_crust);
  if (result.sheet_stats) stage("extraction", result.seconds.extraction);
  out << "\n";
  if (const auto &m = result.sample_meshing) {
    // The surface that guided the samples' mesh: the sheet, or the Power Crust's surface
    // where the fallback replaced it.
    const char *guide = result.method == pipeline::Method::PowerCrust ? "the Power Crust's surface" : "the sheet";
    if (m->is_kept) {
      out << "  output: the input samples meshed along " << guide << " (" << m->samples_topology << "; "
          << m->stats.holes_filled << " holes closed, " << m->stats.samples_moved << " samples moved towards "
          << guide << ", " << m->stats.samples_left_out << " left out as off it), " << m->stats.seconds << " s\n";
    } else {
      out << "  output: " << guide;
      if (const auto &s = result.simplify_stats; s && s->is_simplified)
        out << ", simplified from " << s->vertices_before << " to " << s->vertices_after << " vertices in "
            << s->seconds << " s";
      out << " (the samples meshed along it have " << m->samples_topology << ", " << guide << " "
          << m->sheet_topology << ")\n";
    }
  }
  if (const auto &s = result.remesh_stats; s && s->is_remeshed)
    out << "  remesh: " << s->faces_before << " -> " << s->faces_after << " faces (target edge "
        << s->target_edge_length << "), min angle " << s->min_angle_deg_before << " -> " << s->min_angle_deg_after
        << " deg, " << s->seconds << " s\n";
}

}  // namespace envcrust::cli

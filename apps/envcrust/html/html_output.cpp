#include "html_output.h"

#include "topology_words.h"

#include "cli_common.h"

#include "envcrust/distance.h"
#include "envcrust/io.h"
#include "envcrust/topology.h"

namespace envcrust::cli::html {

void add_html_option(CLI::App& command, std::string& path, const std::string& what) {
  command.add_option("--html", path,
                     "Also write an HTML report: one self-contained page (no network needed to open it) with an "
                     "interactive 3D view of " + what + " (boundary loops in colour, a distance colour map to switch "
                     "on), the topology in plain words and the run's figures");
}

void check_html_output(const std::string& path) {
  if (path.empty()) return;
  if (!has_viewer())
    throw UsageError("--html: this envcrust was built without three.js (scripts/setup.sh installs it "
                                "with npm into third_party/node_modules; then build again)");
  io::check_output_path(path, io::OutputKind::Text);
}

void add_analysis(ReportPage& page, const analysis::AnalysisReport& report) {
  const auto& t = report.topology;
  page.summary = topology_in_words(report);
  page.boundary_loops.clear();
  for (const auto& loop : t.boundary_loops) page.boundary_loops.push_back(loop.polyline(t.points));
  if (!t.is_manifold())
    page.messages.push_back("Not a 2-manifold: " + std::to_string(t.non_manifold_edges) + " non-manifold edges, " +
                            std::to_string(t.non_manifold_vertices) + " non-manifold vertices.");
  if (report.self_intersections && report.self_intersections->face_pairs > 0)
    page.messages.push_back("The surface passes through itself: " +
                            std::to_string(report.self_intersections->face_pairs) + " pairs of faces.");
  for (const auto& w : report.warnings) page.messages.push_back("Warning: " + w);
}

ReportPage reconstruct_page(const std::string& title, const TriangleMesh& result,
                            const analysis::AnalysisReport* report, const std::vector<Point3>& input_points,
                            const std::vector<std::string>& failed_checks, const std::vector<std::string>& hints,
                            const nlohmann::json& figures) {
  ReportPage page;
  page.title = title;
  page.mesh = &result;
  page.figures = figures;
  if (!failed_checks.empty()) {
    std::string what;
    for (const auto& f : failed_checks) what += (what.empty() ? "" : "; ") + f;
    page.messages.push_back("The result fails its checks: " + what + ".");
  }
  if (report) {
    add_analysis(page, *report);
  } else {
    analysis::AnalysisReport topology_only;
    topology_only.topology = topology::analyze_topology(result);
    add_analysis(page, topology_only);
    page.messages.push_back("The analysis was skipped (--no-analysis): the summary gives the topology alone.");
  }
  for (const auto& h : hints) page.messages.push_back("Hint: " + h);
  page.vertex_distances = distance::distances_to_points(result.vertices, input_points);
  page.distance_label = "distance to the nearest input point";
  page.no_distance_reason = "the input has no points";
  return page;
}

ReportPage analyze_page(const std::string& title, const TriangleMesh& mesh, const analysis::AnalysisReport& report,
                        const analysis::Reference& reference, const std::string& reference_name,
                        const nlohmann::json& figures) {
  ReportPage page;
  page.title = title;
  page.mesh = &mesh;
  page.figures = figures;
  add_analysis(page, report);
  if (reference.mesh) {
    page.vertex_distances = distance::distances_to_mesh(mesh.vertices, *reference.mesh);
  } else if (!reference.points.empty()) {
    page.vertex_distances = distance::distances_to_points(mesh.vertices, reference.points);
  }
  page.distance_label = "distance to the reference " + reference_name;
  page.no_distance_reason = "no --reference was given to measure distances to";
  return page;
}

ReportPage failure_page(const std::string& title, const TriangleMesh* mesh, const std::string& problem) {
  ReportPage page;
  page.title = title;
  page.mesh = mesh;
  page.messages.push_back(problem);
  page.summary.push_back("The mesh could not be analyzed: " + problem + ". " +
                         (mesh && !mesh->vertices.empty()
                              ? "The view shows what could be read of it" +
                                    std::string(mesh->triangles.empty() ? " (its vertices, as points)." : ".")
                              : "Nothing of it could be shown."));
  page.figures = {{"error", problem}};
  if (mesh) page.figures.update({{"vertices", mesh->vertices.size()}, {"faces", mesh->triangles.size()}});
  page.no_distance_reason = "no distances were measured";
  return page;
}

void write_html_report(const std::string& path, const ReportPage& page) {
  io::write_atomic(path, false, [&](std::ostream& out) { write_report_page(out, page); });
}

}  // namespace envcrust::cli::html

// The HTML report: one self-contained page with an interactive 3D view of a mesh (three.js,
// embedded), its boundary loops in colour, a per-vertex distance colour map, the topology in
// plain words and the run's figures. envcrust reconstruct and analyze write it with --html.
#pragma once

#include "envcrust/types.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace envcrust::cli::html {

/// What a report page shows.
struct ReportPage {
  std::string title;                  ///< the heading, e.g. "envcrust reconstruct: scan.xyz -> scan.ply"
  std::vector<std::string> messages;  ///< problems, shown first and highlighted (a mesh with no faces)
  std::vector<std::string> summary;   ///< paragraphs in plain words (topology_in_words)
  nlohmann::json figures = nlohmann::json::object();  ///< the run's JSON report, shown as a table
  /// The mesh to show (its vertices as points when it has no triangle); null or without
  /// vertices: no 3D view, the page says so. Must outlive the call.
  const TriangleMesh* mesh = nullptr;
  std::vector<Polyline> boundary_loops;  ///< closed curves drawn in colour, one hue each
  std::vector<double> vertex_distances;  ///< one per mesh vertex for the colour map; empty: none
  std::string distance_label;            ///< what vertex_distances measure ("distance to the nearest input point")
  std::string no_distance_reason;        ///< why there is no colour map (shown on its disabled switch)
};

/// The line under the heading that says what the view shows and how to move it.
inline constexpr const char* kViewCaption =
    "The result in 3D: drag to turn it, scroll to zoom, right-drag to move it. Front faces grey-blue, "
    "back faces terracotta, boundary loops in colour.";

/// Writes the page as one HTML document to `out`: the style, scripts (three.js included) and
/// mesh data inline, so it opens without a network. The mesh is embedded as base64 typed
/// arrays (positions float32, relative to the centre of its bounding box; faces uint32;
/// distances float32; about 18 bytes per vertex and face).
/// @pre has_viewer(): without three.js the page would have no view.
void write_report_page(std::ostream& out, const ReportPage& page);

/// Whether this build can write the page (three.js was found at build time).
bool has_viewer();

}  // namespace envcrust::cli::html

#include "html_report.h"

#include "base64.h"
#include "figure_table.h"
#include "viewer_assets.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>

namespace envcrust::cli::html {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the page's typed arrays are read in the browser's byte order, little-endian everywhere");

// The pretty-printed JSON report is shown whole up to this size (a broken mesh's report can
// list thousands of loops; the table shows the first of each list anyway).
constexpr std::size_t kMaxJsonTextChars = 200000;

std::string escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// JSON inside a <script> element: '<' only occurs in strings, where \u003c reads the same and
// cannot close the element.
std::string script_json(const nlohmann::json& value) {
  const std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

template <class T>
void write_block(std::ostream& out, const char* id, const std::vector<T>& values) {
  out << "<script type=\"text/plain\" id=\"" << id << "\">";
  write_base64(out, values.data(), values.size() * sizeof(T));
  out << "</script>\n";
}

struct Frame {
  Point3 centre = Point3(0, 0, 0);
  double radius = 1.0;  // half the bounding box's diagonal
};

Frame frame_of(const std::vector<Point3>& points) {
  if (points.empty()) return {};
  double lo[3] = {points[0].x(), points[0].y(), points[0].z()};
  double hi[3] = {lo[0], lo[1], lo[2]};
  for (const auto& p : points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  Frame f;
  f.centre = Point3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
  f.radius = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2])) / 2;
  if (!(f.radius > 0)) f.radius = 1.0;  // one point, or all at one place
  return f;
}

// Positions as float32 relative to the centre: coordinates far from the origin (UTM) keep
// their precision in the view.
void append_relative(std::vector<float>& out, const Point3& p, const Frame& f) {
  out.push_back(static_cast<float>(p.x() - f.centre.x()));
  out.push_back(static_cast<float>(p.y() - f.centre.y()));
  out.push_back(static_cast<float>(p.z() - f.centre.z()));
}

// The top of the colour scale: the 99th percentile, unless the largest value is hardly more,
// so that a few outliers do not wash out the map.
double scale_top(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const double max = *std::max_element(values.begin(), values.end());
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return max <= 1.25 * *at ? max : *at;
}

// `extra_messages`: what the writer itself found, after the page's own messages.
void write_panel(std::ostream& out, const ReportPage& page, const std::vector<std::string>& extra_messages) {
  out << "<aside id=\"panel\">\n<h1 id=\"title\">" << escape(page.title) << "</h1>\n";
  out << "<p class=\"caption\" id=\"caption\">" << escape(kViewCaption) << "</p>\n";
  for (const auto& m : page.messages) out << "<p class=\"message\">" << escape(m) << "</p>\n";
  for (const auto& m : extra_messages) out << "<p class=\"message\">" << escape(m) << "</p>\n";
  out << "<h2>Topology in plain words</h2>\n<div id=\"summary\">\n";
  for (const auto& p : page.summary) out << "<p>" << escape(p) << "</p>\n";
  out << "</div>\n<h2>Figures of the run</h2>\n<table class=\"figures\" id=\"figures\">\n";
  for (const auto& [path, value] : figure_rows(page.figures))
    out << "<tr><td>" << escape(path) << "</td><td>" << escape(value) << "</td></tr>\n";
  out << "</table>\n";
  const std::string json = page.figures.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
  out << "<details><summary>The JSON report</summary><pre class=\"json\">";
  if (json.size() <= kMaxJsonTextChars) {
    out << escape(json);
  } else {
    out << escape(json.substr(0, kMaxJsonTextChars)) << "\n... (" << json.size() - kMaxJsonTextChars
        << " more characters: write the whole report with --report FILE)";
  }
  out << "</pre></details>\n";
  out << "<p class=\"caption\">Written by envcrust. The view uses three.js (MIT licence; its notice is in the "
         "embedded script).</p>\n</aside>\n";
}

void write_view(std::ostream& out, const std::string& empty_message) {
  out << "<main id=\"view\" aria-label=\"3D view\">\n<div id=\"toolbar\">"
         "<label><input type=\"checkbox\" id=\"show-loops\" checked> boundary loops</label>"
         "<label><input type=\"checkbox\" id=\"show-distance\"> distance colours</label>"
         "<button type=\"button\" id=\"reset-view\">reset view</button></div>\n"
         "<div id=\"legend\" hidden></div>\n<div id=\"loop-key\" hidden></div>\n"
         "<p id=\"view-message\">"
      << escape(empty_message.empty() ? "Loading the 3D view (it needs JavaScript and WebGL)." : empty_message)
      << "</p>\n</main>\n";
}

}  // namespace

bool has_viewer() { return has_three_js(); }

void write_report_page(std::ostream& out, const ReportPage& page) {
  static const std::vector<Point3> kNoVertices;
  const std::vector<Point3>& vertices = page.mesh ? page.mesh->vertices : kNoVertices;
  const Frame frame = frame_of(vertices);
  std::vector<float> positions;
  positions.reserve(3 * vertices.size());
  for (const auto& p : vertices) append_relative(positions, p, frame);
  std::vector<std::uint32_t> faces;
  std::size_t dropped_faces = 0;  // with a vertex index out of range: the browser would draw none
  if (page.mesh) {
    faces.reserve(3 * page.mesh->triangles.size());
    for (const auto& t : page.mesh->triangles) {
      if (t[0] >= vertices.size() || t[1] >= vertices.size() || t[2] >= vertices.size()) {
        ++dropped_faces;
        continue;
      }
      faces.insert(faces.end(), t.begin(), t.end());
    }
  }
  std::vector<float> loop_points;
  nlohmann::json loop_counts = nlohmann::json::array();
  for (const auto& loop : page.boundary_loops) {
    for (const auto& p : loop) append_relative(loop_points, p, frame);
    loop_counts.push_back(loop.size());
  }
  const bool has_distances = !page.vertex_distances.empty() && page.vertex_distances.size() == vertices.size();
  std::vector<float> distances;
  if (has_distances)
    distances.assign(page.vertex_distances.begin(), page.vertex_distances.end());

  std::string empty_message;
  if (vertices.empty()) empty_message = "Nothing to show in 3D: the mesh has no vertices.";
  nlohmann::json info = {{"vertices", vertices.size()},
                         {"faces", faces.size() / 3},
                         {"loops", loop_counts},
                         {"centre", {frame.centre.x(), frame.centre.y(), frame.centre.z()}},
                         {"radius", frame.radius},
                         {"empty_message", empty_message},
                         {"no_distance_reason", page.no_distance_reason.empty() ? "no distances were measured"
                                                                                : page.no_distance_reason}};
  if (has_distances) {
    info["distance"] = {{"label", page.distance_label},
                        {"max", *std::max_element(page.vertex_distances.begin(), page.vertex_distances.end())},
                        {"scale_top", scale_top(page.vertex_distances)}};
  } else {
    info["distance"] = nullptr;
  }

  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"envcrust\">\n<title>"
      << escape(page.title) << "</title>\n<style>\n" << viewer_css() << "</style>\n</head>\n"
      << "<body data-view=\"loading\">\n<div id=\"page\">\n";
  write_view(out, empty_message);
  std::vector<std::string> found;
  if (dropped_faces > 0)
    found.push_back(std::to_string(dropped_faces) + " faces name a vertex the mesh does not have and are not drawn.");
  write_panel(out, page, found);
  out << "</div>\n<script type=\"application/json\" id=\"mesh-info\">" << script_json(info) << "</script>\n";
  write_block(out, "data-positions", positions);
  write_block(out, "data-faces", faces);
  write_block(out, "data-loop-points", loop_points);
  if (has_distances) write_block(out, "data-distances", distances);
  out << "<script type=\"text/plain\" id=\"three-module\">" << three_module_js() << "</script>\n"
      << "<script type=\"text/plain\" id=\"orbit-controls\">" << orbit_controls_js() << "</script>\n"
      << "<script type=\"module\">\n" << viewer_js() << "</script>\n</body>\n</html>\n";
}

}  // namespace envcrust::cli::html

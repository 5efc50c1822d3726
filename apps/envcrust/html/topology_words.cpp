#include "topology_words.h"

#include <cstdlib>
#include <sstream>

namespace envcrust::cli::html {
namespace {

std::string count(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string number(double x) {
  std::ostringstream text;
  text.precision(4);
  text << x;
  return text.str();
}

std::string pieces_paragraph(const topology::MeshTopology& t) {
  std::string text = "The mesh has " + count(t.vertices, "vertex", "vertices") + ", " +
                     count(t.edges, "edge", "edges") + " and " + count(t.faces, "triangle", "triangles") + ", in ";
  if (t.components.size() == 1) return text + "one piece (all its triangles are joined through their edges).";
  return text + std::to_string(t.components.size()) +
         " separate pieces. A scan of one object should give one; more means parts were not joined "
         "(or small islands of the input were kept apart).";
}

std::string manifold_paragraph(const topology::MeshTopology& t) {
  if (t.is_manifold())
    return "It is a 2-manifold: every edge has one or two triangles and every vertex one fan of them, so it is "
           "a proper surface that other software can process.";
  return "It is not a 2-manifold: " + count(t.non_manifold_edges, "edge has", "edges have") +
         " three or more triangles and " + count(t.non_manifold_vertices, "vertex", "vertices") +
         " several fans of them. The numbers below describe it as a set of triangles; it has no genus, and "
         "other software may refuse it.";
}

std::string shape_paragraph(const topology::MeshTopology& t) {
  std::string text;
  if (t.components.size() == 1) {
    const auto& c = t.components.front();
    text = "Its shape is that of " + surface_name(c.is_orientable, c.genus, c.boundary_loops) + ". ";
  } else {
    text = "The pieces are: ";
    for (std::size_t i = 0; i < t.components.size() && i < 8; ++i) {
      const auto& c = t.components[i];
      text += (i ? "; " : "") + std::string("piece ") + std::to_string(i) + ", " +
              surface_name(c.is_orientable, c.genus, c.boundary_loops) + " (χ " +
              std::to_string(c.euler_characteristic) + ")";
    }
    if (t.components.size() > 8) text += "; and " + std::to_string(t.components.size() - 8) + " more";
    text += ". ";
  }
  text += "Its Euler characteristic is χ = V − E + F = " + std::to_string(t.euler_characteristic) +
          ": one number that sums up the shape. A disc has χ 1, a tube or a Möbius band 0, a sphere 2; "
          "each further hole or handle lowers it.";
  if (t.components.size() == 1 && t.components.front().genus) {
    const auto& c = t.components.front();
    const long g = *c.genus;
    const std::string loops = count(static_cast<std::size_t>(c.boundary_loops), "loop", "loops");
    text += c.is_orientable ? " Here χ = 2 − 2 × " + count(static_cast<std::size_t>(g), "handle", "handles") + " − " + loops + "."
                            : " Here χ = 2 − " + count(static_cast<std::size_t>(g), "cross-cap", "cross-caps") + " − " + loops + ".";
  }
  return text;
}

std::string loops_paragraph(const analysis::AnalysisReport& r) {
  const auto& loops = r.topology.boundary_loops;
  if (loops.empty())
    return "It has no boundary loop: the surface is closed, with no open edge. A scan that is open somewhere "
           "(at a foot's ankle, a face's rim) should have one loop there.";
  std::string text = "It has " + count(loops.size(), "boundary loop", "boundary loops") +
                     ": the open edges of the surface, each a closed curve, drawn in colour in the view. ";
  for (std::size_t i = 0; i < loops.size() && i < 8; ++i) {
    text += (i ? "; loop " : "Loop ") + std::to_string(i) + ": " +
            count(loops[i].vertices.size(), "vertex", "vertices") + ", length " + number(loops[i].length);
    if (i < r.loops.size() && r.loops[i].knot) text += ", " + knots::to_string(r.loops[i].knot->type);
  }
  if (loops.size() > 8) text += "; and " + std::to_string(loops.size() - 8) + " more";
  text += ".";
  bool any_knotted = false;
  for (const auto& l : r.loops)
    any_knotted = any_knotted || (l.knot && l.knot->type != knots::KnotType::Unknot);
  if (!r.loops.empty() && r.loops.front().knot)
    text += any_knotted ? " A knotted loop cannot be untangled without cutting it; a scan's rim is almost "
                          "always an unknot, so a knot there means the rim went wrong."
                        : " Every loop analyzed is an unknot: it can be laid flat as a circle.";
  for (const auto& link : r.linking) {
    if (link.linking_number == 0) continue;
    text += " Loops " + std::to_string(link.loop_a) + " and " + std::to_string(link.loop_b) + " wind around each other " +
            std::to_string(std::abs(link.linking_number)) + " times (linking number " +
            std::to_string(link.linking_number) + ").";
  }
  return text;
}

std::string orientability_paragraph(const topology::MeshTopology& t) {
  if (t.is_orientable) {
    std::string text = "It is orientable: it has two sides, drawn grey-blue (front) and terracotta (back) in the view.";
    if (t.misoriented_edges > 0)
      text += " Its faces are not all wound alike (" + count(t.misoriented_edges, "edge", "edges") +
              " that both their faces run the same way), so both colours may show on one side.";
    return text;
  }
  return "It is not orientable: it has one side only, like a Möbius band, and walking across it turns front "
         "into back; the view shows the two colours meeting along a seam. Every scan of a real object's skin is "
         "orientable, so for a scan this means a twist (a cross-cap) crept in, usually where the samples are sparse.";
}

std::string distance_paragraph(const distance::DistanceReport& d) {
  return "Distances: the result strays at most " + number(d.mesh_to_reference.max) + " (" +
         number(100 * d.relative(d.mesh_to_reference.max)) + "% of the reference's diagonal), on average " +
         number(d.mesh_to_reference.mean) + ", from the reference; the reference lies at most " +
         number(d.reference_to_mesh.max) + " (" + number(100 * d.relative(d.reference_to_mesh.max)) +
         "%) from the result (large values there mean a part of it is missing from the result).";
}

}  // namespace

std::string surface_name(bool is_orientable, std::optional<long> genus, int boundary_loops) {
  if (!genus) return "a set of triangles that is not a surface (not a 2-manifold)";
  const long g = *genus;
  const int b = boundary_loops;
  const std::string loops = std::to_string(b) + (b == 1 ? " boundary loop" : " boundary loops");
  if (is_orientable) {
    if (g == 0 && b == 0) return "a sphere (a closed surface without handles)";
    if (g == 0 && b == 1) return "a disc";
    if (g == 0 && b == 2) return "an annulus (a tube open at both ends)";
    if (g == 0) return "a disc with " + std::to_string(b - 1) + " holes";
    if (g == 1 && b == 0) return "a torus (a closed surface with one handle)";
    if (b == 0) return "a closed surface with " + std::to_string(g) + " handles";
    return "a surface with " + std::to_string(g) + (g == 1 ? " handle and " : " handles and ") + loops;
  }
  if (g == 1 && b == 1) return "a Möbius band";
  if (g == 1 && b == 0) return "a projective plane (a closed one-sided surface)";
  if (g == 2 && b == 0) return "a Klein bottle";
  return "a one-sided surface with " + std::to_string(g) + (g == 1 ? " cross-cap and " : " cross-caps and ") + loops;
}

std::vector<std::string> topology_in_words(const analysis::AnalysisReport& report) {
  const auto& t = report.topology;
  std::vector<std::string> paragraphs = {pieces_paragraph(t), manifold_paragraph(t), shape_paragraph(t),
                                         loops_paragraph(report), orientability_paragraph(t)};
  if (report.self_intersections) {
    const auto& s = *report.self_intersections;
    paragraphs.push_back(s.face_pairs == 0
                             ? std::string("It does not pass through itself") +
                                   (t.is_manifold() ? ": an embedded surface." : ".")
                             : count(s.face_pairs, "pair", "pairs") + " of faces pass through each other (" +
                                   count(s.faces, "face", "faces") + "): the surface cuts through itself there.");
  }
  if (report.distance) paragraphs.push_back(distance_paragraph(*report.distance));
  return paragraphs;
}

}  // namespace envcrust::cli::html

// The sheet as a guide for the front: the nearest sheet vertex finds the faces round it, and
// the nearest of those gives the distance and the normal line. The sheet's faces may be wound
// either way (a non-orientable sheet cannot be wound consistently), so only normal lines count.
#include "interpolate_detail.h"

#include <CGAL/squared_distance_3.h>

#include <cmath>
#include <limits>

namespace envcrust::interpolate::detail {

namespace {

// The vertices that some face uses: a vertex left without faces says nothing of where the
// sheet is.
std::vector<Point3> used_vertices(const TriangleMesh& sheet, std::vector<Index>& original) {
  std::vector<char> used(sheet.vertices.size(), 0);
  for (const auto& t : sheet.triangles)
    for (const Index v : t) used[v] = 1;
  std::vector<Point3> out;
  for (std::size_t v = 0; v < sheet.vertices.size(); ++v) {
    if (!used[v]) continue;
    out.push_back(sheet.vertices[v]);
    original.push_back(static_cast<Index>(v));
  }
  return out;
}

// The point of triangle abc nearest p, by the Voronoi regions of its corners and edges (in
// doubles: a projection tested with the exact has_on would fall off the plane by rounding).
Point3 closest_on_triangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c) {
  const Vector3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab * ap, d2 = ac * ap;
  if (d1 <= 0 && d2 <= 0) return a;
  const Vector3 bp = p - b;
  const double d3 = ab * bp, d4 = ac * bp;
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vector3 cp = p - c;
  const double d5 = ab * cp, d6 = ac * cp;
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denominator = va + vb + vc;
  return a + ab * (vb / denominator) + ac * (vc / denominator);
}

}  // namespace

SheetGuide::SheetGuide(const TriangleMesh& sheet)
    : sheet_(sheet), used_(used_vertices(sheet, original_)), vertex_index_(used_) {
  face_start_.assign(sheet.vertices.size() + 1, 0);
  for (const auto& t : sheet.triangles)
    for (const Index v : t) ++face_start_[v + 1];
  for (std::size_t v = 0; v < sheet.vertices.size(); ++v) face_start_[v + 1] += face_start_[v];
  face_list_.resize(face_start_.back());
  std::vector<std::size_t> next(face_start_.begin(), face_start_.end() - 1);
  for (std::size_t f = 0; f < sheet.triangles.size(); ++f)
    for (const Index v : sheet.triangles[f]) face_list_[next[v]++] = f;
}

SheetGuide::Nearest SheetGuide::nearest_on_faces(const Point3& p) const {
  Nearest out{p, std::numeric_limits<double>::infinity(), Vector3(0, 0, 0)};
  if (vertex_index_.empty()) return out;
  const std::size_t nearest = original_[vertex_index_.nearest(p).first];
  for (std::size_t i = face_start_[nearest]; i < face_start_[nearest + 1]; ++i) {
    const auto& t = sheet_.triangles[face_list_[i]];
    const Kernel::Triangle_3 face(sheet_.vertices[t[0]], sheet_.vertices[t[1]], sheet_.vertices[t[2]]);
    if (face.is_degenerate()) continue;
    const double d = CGAL::squared_distance(p, face);
    if (d < out.squared_distance) {
      out.squared_distance = d;
      out.normal = face.supporting_plane().orthogonal_vector();
      out.point = closest_on_triangle(p, face.vertex(0), face.vertex(1), face.vertex(2));
    }
  }
  return out;
}

Point3 SheetGuide::nearest_point(const Point3& p) const { return nearest_on_faces(p).point; }

bool SheetGuide::allows(const Point3& a, const Point3& b, const Point3& c, double max_distance,
                        double min_cosine) const {
  const Point3 centre = CGAL::centroid(a, b, c);
  const Nearest near = nearest_on_faces(centre);
  if (!std::isfinite(near.squared_distance) || std::sqrt(near.squared_distance) > max_distance)
    return false;  // only degenerate faces there
  const Vector3 own = CGAL::cross_product(b - a, c - a);
  const double lengths = std::sqrt(own.squared_length() * near.normal.squared_length());
  if (!(lengths > 0)) return true;
  return std::abs(own * near.normal) >= min_cosine * lengths;
}

}  // namespace envcrust::interpolate::detail

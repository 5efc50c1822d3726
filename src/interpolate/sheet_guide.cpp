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

bool SheetGuide::allows(const Point3& a, const Point3& b, const Point3& c, double max_distance,
                        double min_cosine) const {
  if (vertex_index_.empty()) return false;
  const Point3 centre = CGAL::centroid(a, b, c);
  const std::size_t nearest = original_[vertex_index_.nearest(centre).first];
  double best = std::numeric_limits<double>::infinity();
  Vector3 normal(0, 0, 0);
  for (std::size_t i = face_start_[nearest]; i < face_start_[nearest + 1]; ++i) {
    const auto& t = sheet_.triangles[face_list_[i]];
    const Kernel::Triangle_3 face(sheet_.vertices[t[0]], sheet_.vertices[t[1]], sheet_.vertices[t[2]]);
    if (face.is_degenerate()) continue;
    const double d = CGAL::squared_distance(centre, face);
    if (d < best) {
      best = d;
      normal = face.supporting_plane().orthogonal_vector();
    }
  }
  if (!std::isfinite(best) || std::sqrt(best) > max_distance) return false;  // only degenerate faces there
  const Vector3 own = CGAL::cross_product(b - a, c - a);
  const double lengths = std::sqrt(own.squared_length() * normal.squared_length());
  if (!(lengths > 0)) return true;
  return std::abs(own * normal) >= min_cosine * lengths;
}

}  // namespace envcrust::interpolate::detail

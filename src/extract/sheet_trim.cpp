// Trimming a mesh along the zero set of a vertex function (the sheet's overshoot past ∂M).
#include "sheet_mesh.h"

#include <map>

namespace envcrust::extract {

namespace {

// A cut closer than this fraction of an edge to one of its ends goes through that end
// instead: a new vertex there would be a duplicate of it (f * |b - a| below the rounding of
// the coordinates) or bound a sliver.
constexpr double kSnapFraction = 0.05;

// Vertices that a cut passes within kSnapFraction of get level 0: on the cut, kept.
std::vector<double> snap_levels(const TriangleMesh& m, std::vector<double> level) {
  for (const auto& tri : m.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Index a = tri[k], b = tri[(k + 1) % 3];
      const double la = level[a], lb = level[b];
      if ((la <= 0) == (lb <= 0)) continue;
      const double f = la / (la - lb);
      if (f < kSnapFraction) level[a] = 0.0;
      else if (f > 1.0 - kSnapFraction) level[b] = 0.0;
    }
  }
  return level;
}

}  // namespace

std::vector<Index> trim_mesh(TaggedMesh& t, const std::vector<double>& raw_level) {
  auto& m = t.mesh;
  const std::vector<double> level = snap_levels(m, raw_level);
  std::map<std::pair<Index, Index>, Index> cut_vertex;
  std::vector<Index> created;
  auto cut = [&](Index a, Index b) {
    const auto key = std::minmax(a, b);
    const auto it = cut_vertex.find({key.first, key.second});
    if (it != cut_vertex.end()) return it->second;
    const double la = level[a], lb = level[b];
    if (la == 0.0) return a;  // the cut passes through a snapped end
    if (lb == 0.0) return b;
    const double f = la / (la - lb);  // la and lb have opposite signs
    const auto id = static_cast<Index>(m.vertices.size());
    m.vertices.push_back(m.vertices[a] + f * (m.vertices[b] - m.vertices[a]));
    cut_vertex[{key.first, key.second}] = id;
    created.push_back(id);
    return id;
  };
  std::vector<std::array<Index, 3>> triangles;
  std::vector<double> dots;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    const auto tri = m.triangles[f];
    int inside = 0;
    for (Index v : tri) inside += level[v] <= 0 ? 1 : 0;
    auto add = [&](Index a, Index b, Index c) {
      if (a == b || b == c || a == c) return;  // a corner cut through a snapped vertex
      triangles.push_back({a, b, c});
      dots.push_back(t.face_dot[f]);
    };
    if (inside == 3) {
      add(tri[0], tri[1], tri[2]);
      continue;
    }
    if (inside == 0) continue;
    // Rotate so that the odd vertex (alone on its side) comes first; orientation is kept.
    int odd = 0;
    for (int k = 0; k < 3; ++k) {
      const bool in_k = level[tri[k]] <= 0;
      const bool in_next = level[tri[(k + 1) % 3]] <= 0;
      const bool in_prev = level[tri[(k + 2) % 3]] <= 0;
      if (in_k != in_next && in_k != in_prev) odd = k;
    }
    const Index a = tri[odd], b = tri[(odd + 1) % 3], c = tri[(odd + 2) % 3];
    const Index ab = cut(a, b), ac = cut(a, c);
    if (level[a] <= 0) {
      add(a, ab, ac);  // only the corner at a is kept
    } else {
      add(ab, b, c);   // the quad b, c, ac, ab is kept
      add(ab, c, ac);
    }
  }
  m.triangles = std::move(triangles);
  t.face_dot = std::move(dots);
  return created;
}

}  // namespace envcrust::extract

// Self-intersections of a triangle mesh: face pairs that meet other than along the vertices
// and the edge they share. Candidates are the pairs with overlapping bounding boxes (CGAL's
// box intersection); each is decided in parallel, by a separating plane in interval
// arithmetic where one shows them apart, else with exact predicates.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/centroid.h>
#include <CGAL/intersections.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace envcrust::mesh {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t,
                                                      CGAL::Box_intersection_d::ID_EXPLICIT>;
using Face = std::array<Index, 3>;

// Vectors in interval arithmetic: signs certified from the double coordinates, without the
// exact arithmetic a zero (coplanar faces: a flat region of the mesh) sends a predicate to.
using Interval = CGAL::Interval_nt<false>;
struct IntervalVector {
  Interval x, y, z;
};

IntervalVector difference(const Point3& a, const Point3& b) {
  return {Interval(a.x()) - b.x(), Interval(a.y()) - b.y(), Interval(a.z()) - b.z()};
}
Interval dot(const IntervalVector& a, const IntervalVector& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
IntervalVector cross(const IntervalVector& a, const IntervalVector& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
// -1, +1, or 0 when the interval does not decide.
int certain_sign(const Interval& v) { return v.inf() > 0 ? 1 : v.sup() < 0 ? -1 : 0; }

// Whether all of `points` lie strictly on one side of the plane through `origin` with
// normal `normal`, certainly.
bool strictly_one_side(const IntervalVector& normal, const Point3& origin, const std::vector<Point3>& p,
                       const Index* points, int count) {
  int side = 0;
  for (int k = 0; k < count; ++k) {
    const int s = certain_sign(dot(normal, difference(p[points[k]], origin)));
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
  }
  return count > 0;
}

// Whether f and g certainly meet at most in what they share, shown by a separating plane in
// interval arithmetic: the plane of one face with the other's free corners strictly on one
// side (the other face then meets that plane only in the shared corners), or, for faces in
// (nearly) one plane, the plane through an edge of f perpendicular to f with g's free
// corners strictly outside and g's shared corners on that edge (both faces then lie in
// opposite closed half-spaces whose common plane holds only the shared part of g). Two
// non-overlapping triangles in a plane are always split by a line along an edge of one of
// them, so flat regions are decided here. Undecided pairs go to the exact tests.
bool certainly_apart(const std::vector<Point3>& p, const Face& f, const Face& g, const Index* free_f, int nf,
                     const Index* free_g, int ng) {
  CGAL::Protect_FPU_rounding<true> rounding;
  auto normal_of = [&](const Face& t) { return cross(difference(p[t[1]], p[t[0]]), difference(p[t[2]], p[t[0]])); };
  const IntervalVector normal_f = normal_of(f), normal_g = normal_of(g);
  if (strictly_one_side(normal_f, p[f[0]], p, free_g, ng) || strictly_one_side(normal_g, p[g[0]], p, free_f, nf))
    return true;
  auto edge_separates = [&](const Face& t, const IntervalVector& normal, const Face& other, const Index* free_other,
                            int n_free) {
    for (int k = 0; k < 3; ++k) {
      const Index e0 = t[k], e1 = t[(k + 1) % 3];
      bool shared_on_edge = true;
      for (const Index v : other)
        if (std::find(free_other, free_other + n_free, v) == free_other + n_free && v != e0 && v != e1)
          shared_on_edge = false;
      if (!shared_on_edge) continue;
      // Points into t: (n x e) . (c - e0) = n . (e x (c - e0)) = |n|^2 for the third corner c.
      const IntervalVector inward = cross(normal, difference(p[e1], p[e0]));
      bool outside = n_free > 0;
      for (int j = 0; j < n_free && outside; ++j)
        outside = certain_sign(dot(inward, difference(p[free_other[j]], p[e0]))) < 0;
      if (outside) return true;
    }
    return false;
  };
  return edge_separates(f, normal_f, g, free_g, ng) || edge_separates(g, normal_g, f, free_f, nf);
}

// Whether faces f and g (distinct vertex sets, neither degenerate) meet beyond what they share.
bool faces_meet(const std::vector<Point3>& p, const Face& f, const Face& g) {
  // The corners of each face that the other does not have.
  Index free_f[3], free_g[3];
  int nf = 0, ng = 0;
  for (const Index v : f)
    if (std::find(g.begin(), g.end(), v) == g.end()) free_f[nf++] = v;
  for (const Index v : g)
    if (std::find(f.begin(), f.end(), v) == f.end()) free_g[ng++] = v;
  if (certainly_apart(p, f, g, free_f, nf, free_g, ng)) return false;
  const Kernel::Triangle_3 tf(p[f[0]], p[f[1]], p[f[2]]), tg(p[g[0]], p[g[1]], p[g[2]]);
  if (nf == 3) return CGAL::do_intersect(tf, tg);
  if (nf == 1) {
    // Along a shared edge (s, t), two triangles only overlap when they are coplanar and their
    // free corners lie on the same side of the edge.
    Index shared[2];
    int ns = 0;
    for (const Index v : f)
      if (v != free_f[0]) shared[ns++] = v;
    const Point3 &s = p[shared[0]], &t = p[shared[1]], &a = p[free_f[0]], &b = p[free_g[0]];
    return CGAL::orientation(s, t, a, b) == CGAL::COPLANAR && CGAL::coplanar_orientation(s, t, a, b) == CGAL::POSITIVE;
  }
  // One shared vertex: the planes' common line leaves each triangle through its opposite
  // edge, so they meet beyond the vertex exactly when an opposite edge meets the other face.
  return CGAL::do_intersect(Kernel::Segment_3(p[free_f[0]], p[free_f[1]]), tg) ||
         CGAL::do_intersect(Kernel::Segment_3(p[free_g[0]], p[free_g[1]]), tf);
}

// The boxes that may overlap one of the flagged boxes: those sharing a cell of a grid with a
// flagged one (two overlapping closed boxes share the cell of a common point). A linear pass
// that spares the tree search the bulk of a large mesh when few faces are flagged. The cells
// are as small as a typical flagged box, larger if the big ones would need too many; boxes
// spanning many cells are kept without looking.
std::vector<const Box*> near_flagged(const std::vector<const Box*>& all, const std::vector<const Box*>& flagged) {
  constexpr long kMaxCellsPerAxis = 4;
  if (flagged.empty()) return all;
  std::vector<double> sizes;
  sizes.reserve(flagged.size());
  for (const Box* b : flagged) {
    double size = 0;
    for (int d = 0; d < 3; ++d) size = std::max(size, b->max_coord(d) - b->min_coord(d));
    sizes.push_back(size);
  }
  std::sort(sizes.begin(), sizes.end());
  double extent = 0;
  for (const Box* b : all)
    for (int d = 0; d < 3; ++d) extent = std::max({extent, std::abs(b->min_coord(d)), std::abs(b->max_coord(d))});
  if (!std::isfinite(extent)) return all;
  auto cells_of = [](const Box* b, int d, double cell) {
    return std::pair(static_cast<long>(std::floor(b->min_coord(d) / cell)),
                     static_cast<long>(std::floor(b->max_coord(d) / cell)));
  };
  // The median flagged size, else the 90th percentile, else the largest: the first for which
  // the flagged boxes cover at most 27 cells each on average.
  double cell = 0;
  for (const double q : {0.5, 0.9, 1.0}) {
    cell = sizes[std::min(sizes.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sizes.size())))];
    // Cells too small to count in a long (faces of zero size, far from the origin): no filter.
    if (!(cell > 1e-12 * extent)) continue;
    double total = 0;
    for (const Box* b : flagged) {
      double n = 1;
      for (int d = 0; d < 3; ++d) {
        const auto [lo, hi] = cells_of(b, d, cell);
        n *= static_cast<double>(hi - lo + 1);
      }
      total += n;
    }
    if (total <= 27.0 * static_cast<double>(flagged.size())) break;
  }
  if (!(cell > 1e-12 * extent)) return all;
  auto range = [&](const Box* b, int d) { return cells_of(b, d, cell); };
  auto key = [](long x, long y, long z) {
    return (static_cast<std::uint64_t>(x) * 73856093u) ^ (static_cast<std::uint64_t>(y) * 19349663u) ^
           (static_cast<std::uint64_t>(z) * 83492791u);
  };
  std::unordered_set<std::uint64_t> cells;
  for (const Box* b : flagged) {
    const auto [x0, x1] = range(b, 0);
    const auto [y0, y1] = range(b, 1);
    const auto [z0, z1] = range(b, 2);
    for (long x = x0; x <= x1; ++x)
      for (long y = y0; y <= y1; ++y)
        for (long z = z0; z <= z1; ++z) cells.insert(key(x, y, z));
  }
  std::vector<const Box*> near;
  for (const Box* b : all) {
    const auto [x0, x1] = range(b, 0);
    const auto [y0, y1] = range(b, 1);
    const auto [z0, z1] = range(b, 2);
    bool hit = x1 - x0 >= kMaxCellsPerAxis || y1 - y0 >= kMaxCellsPerAxis || z1 - z0 >= kMaxCellsPerAxis;
    for (long x = x0; x <= x1 && !hit; ++x)
      for (long y = y0; y <= y1 && !hit; ++y)
        for (long z = z0; z <= z1 && !hit; ++z) hit = cells.count(key(x, y, z)) != 0;
    if (hit) near.push_back(b);
  }
  return near;
}

}  // namespace

SelfIntersections self_intersections(const TriangleMesh& input, std::size_t max_examples,
                                     const std::vector<char>* only_faces) {
  // Coincident vertices count as shared, as the analyzer welds them.
  const TriangleMesh mesh = weld_identical_vertices(input);
  const std::vector<char> skipped_face = repeated_or_degenerate_faces(mesh);
  std::vector<Box> boxes;
  boxes.reserve(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Face& t = mesh.triangles[f];
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    if (skipped_face[f] != 0 || CGAL::collinear(a, b, c)) continue;
    boxes.emplace_back(a.bbox() + b.bbox() + c.bbox(), static_cast<std::uint32_t>(f));
  }
  SelfIntersections out;
  auto is_flagged = [&](std::uint32_t f) { return only_faces == nullptr || (*only_faces)[f] != 0; };
  // The boxes are searched in one thread and the candidate pairs decided in parallel, a chunk
  // at a time. CGAL's parallel box search runs 16 searches of quarter ranges against each
  // other, and those went on for more than ten minutes on a result whose two halves lie
  // exactly in the planes z = 0 and x = 0 (1.38M faces, 8.8M box pairs), where the search in
  // one thread takes 9 s.
  using FacePair = std::pair<std::uint32_t, std::uint32_t>;
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  std::vector<FacePair> candidates, meeting;
  candidates.reserve(std::min(kChunk, 8 * boxes.size() + 1));
  auto decide = [&] {
    std::vector<char> meets(candidates.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 4096), [&](const auto& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const auto [f, g] = candidates[i];
        meets[i] = faces_meet(mesh.vertices, mesh.triangles[f], mesh.triangles[g]) ? 1 : 0;
      }
    });
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (meets[i] != 0) meeting.push_back(candidates[i]);
    candidates.clear();
  };
  auto callback = [&](const Box* x, const Box* y) {
    const std::uint32_t f = x->info(), g = y->info();
    // Against all faces, a pair of two flagged faces comes twice, and a face meets itself.
    if (only_faces != nullptr && (f == g || (is_flagged(g) && g < f))) return;
    candidates.emplace_back(std::min(f, g), std::max(f, g));
    if (candidates.size() == kChunk) decide();
  };
  // The tree sorts pointers rather than the boxes themselves; leaves of up to 2000 boxes are
  // scanned directly (as CGAL's own self-intersection search does).
  constexpr std::ptrdiff_t kCutoff = 2000;
  std::vector<const Box*> all(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) all[k] = &boxes[k];
  if (only_faces == nullptr) {
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(all.begin(), all.end(), callback, kCutoff);
  } else {
    if (only_faces->size() != mesh.triangles.size())
      throw InvalidInput("self_intersections: " + std::to_string(only_faces->size()) + " face flags for " +
                         std::to_string(mesh.triangles.size()) + " faces");
    std::vector<const Box*> flagged;
    for (const Box* b : all)
      if (is_flagged(b->info())) flagged.push_back(b);
    std::vector<const Box*> near = near_flagged(all, flagged);
    CGAL::box_intersection_d<CGAL::Sequential_tag>(flagged.begin(), flagged.end(), near.begin(), near.end(),
                                                   callback, kCutoff);
  }
  decide();
  // In face order, so that the examples do not depend on the search's order.
  std::sort(meeting.begin(), meeting.end());
  std::vector<char> involved(mesh.triangles.size(), 0);
  for (const auto& [f, g] : meeting) {
    involved[f] = involved[g] = 1;
    if (out.examples.size() < max_examples) {
      const auto& t = mesh.triangles[f];
      out.examples.push_back(CGAL::centroid(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
    }
  }
  out.face_pairs = meeting.size();
  for (std::size_t f = 0; f < involved.size(); ++f)
    if (involved[f] != 0) out.face_list.push_back(static_cast<Index>(f));
  out.faces = out.face_list.size();
  std::sort(out.examples.begin(), out.examples.end());
  return out;
}

}  // namespace envcrust::mesh

// Self-intersections of a triangle mesh: face pairs that meet other than along the vertices
// and the edge they share. Candidates are the pairs with overlapping bounding boxes (CGAL's
// box intersection, in parallel); each is decided with exact predicates.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/centroid.h>
#include <CGAL/Random.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <unordered_set>

namespace envcrust::mesh {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t,
                                                      CGAL::Box_intersection_d::ID_EXPLICIT>;
using Face = std::array<Index, 3>;

// Whether faces f and g (distinct vertex sets, neither degenerate) meet beyond what they share.
bool faces_meet(const std::vector<Point3>& p, const Face& f, const Face& g) {
  // The corners of each face that the other does not have.
  Index free_f[3], free_g[3];
  int nf = 0, ng = 0;
  for (const Index v : f)
    if (std::find(g.begin(), g.end(), v) == g.end()) free_f[nf++] = v;
  for (const Index v : g)
    if (std::find(f.begin(), f.end(), v) == f.end()) free_g[ng++] = v;
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
  std::atomic<std::size_t> pairs{0};
  std::vector<char> involved(mesh.triangles.size(), 0);
  std::mutex examples_mutex;
  SelfIntersections out;
  auto is_flagged = [&](std::uint32_t f) { return only_faces == nullptr || (*only_faces)[f] != 0; };
  auto callback = [&](const Box* x, const Box* y) {
    const std::uint32_t f = x->info(), g = y->info();
    // Against all faces, a pair of two flagged faces comes twice, and a face meets itself.
    if (only_faces != nullptr && (f == g || (is_flagged(g) && g < f))) return;
    if (!faces_meet(mesh.vertices, mesh.triangles[f], mesh.triangles[g])) return;
    ++pairs;
    std::lock_guard lock(examples_mutex);
    involved[f] = involved[g] = 1;
    if (out.examples.size() < max_examples) {
      const auto& t = mesh.triangles[f];
      out.examples.push_back(CGAL::centroid(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
    }
  };
  // As CGAL's own self-intersection search does: the tree sorts pointers rather than the
  // boxes themselves, in an order shuffled so that the parallel tasks get even shares, and
  // leaves of up to 2000 boxes are scanned directly.
  constexpr std::ptrdiff_t kCutoff = 2000;
  CGAL::Random random(0);
  std::vector<const Box*> all(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) all[k] = &boxes[k];
  CGAL::cpp98::random_shuffle(all.begin(), all.end(), random);
  if (only_faces == nullptr) {
    CGAL::box_self_intersection_d<CGAL::Parallel_tag>(all.begin(), all.end(), callback, kCutoff);
  } else {
    if (only_faces->size() != mesh.triangles.size())
      throw InvalidInput("self_intersections: " + std::to_string(only_faces->size()) + " face flags for " +
                         std::to_string(mesh.triangles.size()) + " faces");
    std::vector<const Box*> flagged;
    for (const Box* b : all)
      if (is_flagged(b->info())) flagged.push_back(b);
    std::vector<const Box*> near = near_flagged(all, flagged);
    CGAL::box_intersection_d<CGAL::Parallel_tag>(flagged.begin(), flagged.end(), near.begin(), near.end(), callback,
                                                 kCutoff);
  }
  out.face_pairs = pairs.load();
  for (std::size_t f = 0; f < involved.size(); ++f)
    if (involved[f] != 0) out.face_list.push_back(static_cast<Index>(f));
  out.faces = out.face_list.size();
  // The parallel search finds the pairs in any order: the examples are sorted to be stable.
  std::sort(out.examples.begin(), out.examples.end());
  return out;
}

}  // namespace envcrust::mesh

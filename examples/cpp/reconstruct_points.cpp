// Reconstruct a surface with boundary from a point file through the envcrust library:
//   reconstruct_points POINTS OUT_MESH
// POINTS: .xyz/.txt/.csv/.pts/.ply with x y z and optionally nx ny nz per point.
// OUT_MESH: .ply, .off or .obj.
// It prepares the samples as `envcrust reconstruct POINTS` does in its main steps (normal lines
// fitted when the file has none, boundary curves detected), reconstructs, and prints the
// result's topology.
#include <envcrust/boundary.h>
#include <envcrust/errors.h>
#include <envcrust/io.h>
#include <envcrust/neighbour_table.h>
#include <envcrust/normals.h>
#include <envcrust/pipeline.h>
#include <envcrust/topology.h>

#include <algorithm>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: reconstruct_points POINTS OUT_MESH\n";
    return 2;
  }
  try {
    envcrust::PointSet points = envcrust::io::read_points(argv[1]);

    // One search of each point's nearest neighbours serves the normal fits and the boundary.
    const envcrust::normals::NormalOptions normal_options;
    const envcrust::boundary::BoundaryOptions boundary_options;
    const unsigned k = static_cast<unsigned>(std::max({normal_options.neighbors, boundary_options.neighbors, 6}));
    const envcrust::NeighbourTable table(points.points, k);

    envcrust::pipeline::InputKind kind;
    kind.is_builtin = false;  // a point file: reconstruct's settings for scans
    if (!points.has_normals()) {
      points.normals = envcrust::normals::estimate_normal_lines(points.points, table, normal_options);
      kind.are_normals_estimated = true;
    }

    envcrust::envelope::SurfaceSamples samples;
    samples.points = points.points;
    samples.normals = points.normals;
    auto detection = envcrust::boundary::detect_boundary(samples.points, samples.normals, table, boundary_options);
    samples.boundary = std::move(detection.curves);
    kind.is_boundary_detected = true;

    const envcrust::pipeline::ReconstructOptions options = envcrust::pipeline::options_for_input(kind);
    const envcrust::pipeline::ReconstructResult result = envcrust::pipeline::reconstruct(samples, options);
    if (result.mesh.triangles.empty()) {
      std::cerr << argv[1] << ": the reconstruction is empty\n";
      return 1;
    }
    envcrust::io::write_mesh(argv[2], result.mesh);

    const auto topology = envcrust::topology::analyze_topology(result.mesh);
    std::cout << argv[1] << ": " << samples.points.size() << " points, " << samples.boundary.size()
              << " boundary curves detected -> " << argv[2] << ": " << topology.faces << " faces, chi "
              << topology.euler_characteristic << ", " << topology.boundary_loops.size() << " boundary loops, "
              << (topology.is_manifold() ? "manifold" : "not manifold") << "\n";
    for (const auto& w : result.warnings) std::cout << "  warning: " << w << "\n";
    return 0;
  } catch (const envcrust::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}

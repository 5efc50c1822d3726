// Reconstruct a surface with boundary from a point file through the envcrust library:
//   reconstruct_points POINTS OUT_MESH
// POINTS: .xyz/.txt/.csv/.pts/.ply with x y z, optionally nx ny nz, colours and other columns.
// OUT_MESH: .ply, .obj, .off or .stl.
// It does what `envcrust reconstruct POINTS -o OUT_MESH` does with its defaults: the input stage
// (input::prepare_points: duplicates merged, stray samples removed, normal lines fitted when the
// file has none, boundary curves detected), reconstruct's settings for that input, the
// reconstruction, and the output written with vertex normals and the points' colours.
#include <envcrust/attributes.h>
#include <envcrust/errors.h>
#include <envcrust/input.h>
#include <envcrust/io.h>
#include <envcrust/normals.h>
#include <envcrust/pipeline.h>
#include <envcrust/topology.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: reconstruct_points POINTS OUT_MESH\n";
    return 2;
  }
  try {
    envcrust::input::PointInput points;
    points.points = envcrust::io::read_attributed_points(argv[1]);
    points.are_normals_text_columns = envcrust::io::is_text_point_file(argv[1]);  // x y z r g b: colours
    envcrust::input::InputOptions input_options;
    input_options.name = argv[1];  // messages name the file
    const envcrust::input::PreparedInput prepared = envcrust::input::prepare_points(std::move(points), input_options);
    for (const auto& note : prepared.notes) std::cout << "  input: " << note << "\n";

    // The settings `envcrust reconstruct` chooses for a scan (pipeline::options_for_input).
    const envcrust::pipeline::ReconstructOptions options = envcrust::pipeline::options_for_input(prepared.kind);
    const envcrust::pipeline::ReconstructResult result = envcrust::pipeline::reconstruct(prepared.samples, options);
    if (result.mesh.triangles.empty()) {
      std::cerr << argv[1] << ": the reconstruction is empty\n";
      return 1;
    }
    envcrust::io::MeshVertexData vertex_data;
    vertex_data.normals = envcrust::normals::mesh_vertex_normal_lines(result.mesh);
    vertex_data.attributes =
        envcrust::attributes::carry_nearest(prepared.attribute_points, prepared.attributes, result.mesh.vertices);
    // Written in the file's coordinates: a georeferenced input was worked on near a local origin.
    envcrust::TriangleMesh written = result.mesh;
    envcrust::input::restore_origin(written.vertices, prepared.origin);
    envcrust::io::write_mesh(argv[2], written, vertex_data);

    const auto topology = envcrust::topology::analyze_topology(result.mesh);
    std::cout << argv[1] << ": " << prepared.samples.points.size() << " points, " << prepared.samples.boundary.size()
              << " boundary curves detected -> " << argv[2] << ": " << topology.faces << " faces, chi "
              << topology.euler_characteristic << ", " << topology.boundary_loops.size() << " boundary loops, "
              << (topology.is_manifold() ? "manifold" : "not manifold") << "\n";
    for (const auto& w : prepared.warnings) std::cout << "  warning: " << w << "\n";
    for (const auto& w : result.warnings) std::cout << "  warning: " << w << "\n";
    return 0;
  } catch (const envcrust::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}

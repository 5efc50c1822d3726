// Normals and carried attributes of the vertices `envcrust reconstruct` writes.
#include "output_vertex_data.h"

#include "envcrust/attributes.h"
#include "envcrust/normals.h"

namespace envcrust::cli {

io::MeshVertexData output_vertex_data(const TriangleMesh& mesh, const LoadedSurface& loaded) {
  io::MeshVertexData data;
  data.normals = normals::mesh_vertex_normal_lines(mesh);
  data.attributes = attributes::carry_nearest(loaded.attribute_points, loaded.attributes, mesh.vertices);
  return data;
}

nlohmann::json vertex_data_json(const io::MeshVertexData& data) {
  nlohmann::json j = {{"normals", !data.normals.empty()},
                      {"colours", data.attributes.has_colours()},
                      {"scalars", data.attributes.names}};
  if (!data.attributes.empty()) j["from"] = "nearest input point";
  return j;
}

}  // namespace envcrust::cli

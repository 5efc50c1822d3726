// What `envcrust reconstruct` writes per output vertex besides its position: a normal from
// the faces, and the colours and scalars of the input carried over (output_vertex_data.cpp).
#pragma once

#include "surface_input.h"

#include "envcrust/io.h"

#include <nlohmann/json.hpp>

namespace envcrust::cli {

/// Per vertex the normal line of its faces (normals::mesh_vertex_normal_lines: area-weighted,
/// signed like the faces' winding around it; on a non-orientable result no sign is consistent,
/// and it flips across the orientation seam), and the attributes of the nearest of the input's
/// attributed points (LoadedSurface::attribute_points), if it has any.
io::MeshVertexData output_vertex_data(const TriangleMesh& mesh, const LoadedSurface& loaded);

/// {"normals": true, "colours": bool, "scalars": [names], "from": "nearest input point"} for the report.
nlohmann::json vertex_data_json(const io::MeshVertexData& data);

}  // namespace envcrust::cli

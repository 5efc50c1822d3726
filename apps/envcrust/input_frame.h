// Moving between the input's coordinates and the prepared samples' frame (a local origin near
// a georeferenced input, input::PreparedInput::origin): outputs are written in the input's
// coordinates, and a reference read from a file is compared in the samples' frame.
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/types.h"

#include <vector>

namespace envcrust::cli {

/// The mesh with every vertex plus `origin`.
TriangleMesh in_input_frame(TriangleMesh mesh, const Vector3& origin);

/// The points plus `origin` (normals unchanged).
PointSet in_input_frame(PointSet points, const Vector3& origin);

/// The curves' vertices plus `origin` (frames unchanged).
std::vector<BoundaryCurve> in_input_frame(std::vector<BoundaryCurve> curves, const Vector3& origin);

/// A reference in the input's coordinates moved into the samples' frame: its mesh, points and
/// boundary loops minus `origin`.
analysis::Reference in_samples_frame(analysis::Reference reference, const Vector3& origin);

}  // namespace envcrust::cli

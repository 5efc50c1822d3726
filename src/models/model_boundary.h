// The boundary curves of a model of several patches, from the patches' exact curves.
#pragma once

#include "envcrust/types.h"

#include <vector>

namespace envcrust::models {

/// The border loops of the joined tessellation `truth`, each made of the vertices of the
/// patches' exact boundary curves (`patch_curves[p]`: patch p's) that lie within `tolerance`
/// of it, in the loop's order, with their exact frames (tangents turned to run along the loop).
/// Where the loop passes from one patch to the next the two curves' vertices become one, a
/// corner when their conormals differ by more than 30 degrees (an open box's rim).
std::vector<BoundaryCurve> model_boundary_curves(const TriangleMesh& truth,
                                                 const std::vector<std::vector<BoundaryCurve>>& patch_curves,
                                                 double tolerance);

}  // namespace envcrust::models

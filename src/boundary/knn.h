// The boundary stages' kd-tree: envcrust::NearestIndex (index-valued k-nearest and radius
// queries), under the name its callers use.
#pragma once

#include "envcrust/nearest_index.h"

namespace envcrust::boundary::detail {

/// Nearest-neighbour queries over a fixed point list (the list must outlive the index).
/// Built eagerly, so queries are safe from several threads at once.
using PointIndex = NearestIndex;

}  // namespace envcrust::boundary::detail

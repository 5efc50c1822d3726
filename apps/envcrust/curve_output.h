// Writing boundary curves: closed polylines one file per loop, or all their vertices with
// outward conormals as one point file (which `reconstruct --boundary` reads back).
#pragma once

#include "envcrust/types.h"

#include <string>
#include <vector>

namespace envcrust::cli {

/// `path` itself for one item, else NAME.0.EXT, NAME.1.EXT, ... (EXT defaults to `polyline`).
std::vector<std::string> numbered_paths(const std::string& path, std::size_t count);

/// Check before a run that `path` can take curves (write_curves). @throws IoError
void check_curve_output(const std::string& path);

/// `.polyline`: each curve as a closed polyline (numbered_paths); `.xyz` / `.ply`: every
/// vertex of every curve in one point file, its normal the outward conormal. Returns the
/// files written.
std::vector<std::string> write_curves(const std::string& path, const std::vector<BoundaryCurve>& curves);

}  // namespace envcrust::cli

// Resolving input arguments of the CLI: files or built-in surfaces ("builtin:NAME").
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/types.h"

#include <string>

namespace envcrust::cli {

/// True for "builtin:NAME" arguments.
bool is_builtin_spec(const std::string& spec);

/// A triangle mesh from a mesh file, or the exact tessellation of "builtin:NAME".
TriangleMesh load_mesh(const std::string& spec);

/// A reference for the analyzer: a mesh file (.off/.obj/.stl, or .ply with faces), a point
/// file (.xyz/.pts/.txt/.csv, or .ply without faces), or "builtin:NAME" (its exact tessellation and
/// its true boundary curves).
analysis::Reference load_reference(const std::string& spec);

}  // namespace envcrust::cli

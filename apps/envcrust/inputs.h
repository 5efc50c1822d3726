// Resolving input arguments of the CLI: files or built-in surfaces ("builtin:NAME").
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/models.h"
#include "envcrust/surfaces.h"
#include "envcrust/types.h"

#include <optional>
#include <string>

namespace envcrust::cli {

/// True for "builtin:NAME" arguments.
bool is_builtin_spec(const std::string& spec);

/// True for "builtin:NAME" and NURBS patch files (.igs/.iges/.json): surfaces whose exact
/// geometry (normals, boundary curves) is known.
bool is_parametric_spec(const std::string& spec);

/// The exact surface of "builtin:NAME", or the patches of a NURBS file joined into one model
/// (models::PatchModel); nullopt for other specs.
/// @throws IoError or InvalidInput naming the file (a patch make_nurbs_surface refuses: "part.igs:
///   patch 3 of 5: ...", patches that form no surface).
std::optional<models::PatchModel> parametric_model(const std::string& spec, const models::JoinOptions& join = {});

/// A triangle mesh from a mesh file, or the exact tessellation of a parametric spec.
TriangleMesh load_mesh(const std::string& spec);

/// A reference for the analyzer: a mesh file (.off/.obj/.stl, or .ply with faces), a point
/// file (.xyz/.pts/.txt/.csv, or .ply without faces), or a parametric spec (its exact
/// tessellation and its true boundary curves).
/// `join`: how a NURBS file's patches are joined (as the input they are compared with was).
analysis::Reference load_reference(const std::string& spec, const models::JoinOptions& join = {});

}  // namespace envcrust::cli

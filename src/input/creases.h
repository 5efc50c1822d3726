// Sharp creases of an input: when they are long enough to tear the medial sheet, the fitted
// normal lines that round them off, and the note that says what was done.
#pragma once

#include "envcrust/input.h"
#include "envcrust/mesh.h"
#include "envcrust/types.h"

#include <string>
#include <vector>

namespace envcrust::input {

/// A surface bent by more than this across an edge tears the sheet: the sheet pairs samples
/// on either side of M whose offset directions make at least extract::SheetOptions::min_angle_deg
/// (100), and across a crease bent by b the two sides' samples make 180 - b. Measured on a
/// square sheet folded along a line (two unit squares, 3,200 faces): one disc up to a bend of
/// 75 degrees, two pieces torn apart at the fold at 90 (rho automatic, 0.05 and 0.1 alike).
inline constexpr double kTearingBendDeg = 80.0;

/// ... along edges longer in total than this fraction of the diagonal (a crease, not a few
/// bad triangles of a scan: the foot mesh has 2.6%, the face mesh 6.3%, both reconstructed
/// right; the lion head 70%, an open box 462%).
inline constexpr double kCreaseMinLengthRelDiag = 0.1;

/// Sharp edges long enough in all to tear the sheet (a crease, not a few bad triangles).
bool is_long_crease(const mesh::SharpEdges& sharp, const std::vector<Point3>& points);

/// Normal lines fitted to the samples (PCA over 24 neighbours), each turned to agree with the
/// sample's given normal: they turn across a crease where the given ones jump.
std::vector<Vector3> fitted_like(const std::vector<Point3>& points, const std::vector<Vector3>& given);

/// "the mesh bends by more than 80 degrees across 96 edges (8 long in all, up to 90 degrees
/// near (x, y, z)): creases, " and what `mode` does with them. `what`: "the mesh bends";
/// `across`: "edges" or "neighbour pairs".
std::string crease_note(const std::string& what, const mesh::SharpEdges& sharp, const std::string& across,
                        CreaseMode mode);

}  // namespace envcrust::input

// Georeferenced inputs (UTM metres, ~500,000 / 5,000,000) worked on relative to a local origin
// near them, so that the stages keep the digits of their shape.
#pragma once

#include "envcrust/types.h"

#include <string>
#include <vector>

namespace envcrust::input {

/// Inputs whose bounding box lies farther from (0, 0, 0) than this many diagonals are moved.
/// There a coordinate spends over 2 of a double's 16 digits on the position, and the squared
/// distances of the power diagram (weights |p|^2 - r^2) twice as many; nearer inputs stay as
/// they are, so that no result of an input near the origin changes.
inline constexpr double kFarRelDiagonal = 100.0;

/// The origin to work relative to: zero for points within kFarRelDiagonal diagonals of
/// (0, 0, 0) (or with no finite extent); else the centre of their bounding box, each coordinate
/// rounded to a multiple of the power of ten at or above the diagonal (a hemisphere of diagonal
/// 2.8 around (500000.3, 5000000.2, 0.5) gets (500000, 5000000, 0): readable, and the
/// subtraction is exact for points within a factor 2 of it).
Vector3 local_origin(const std::vector<Point3>& points);

/// Each point minus `origin`.
void subtract_origin(std::vector<Point3>& points, const Vector3& origin);

/// The note saying which origin was chosen and why ("coordinates taken relative to (500000,
/// 5000000, 0): the input lies 1.8e+06 diagonals (2.83) from (0, 0, 0)").
std::string origin_note(const std::vector<Point3>& points, const Vector3& origin);

}  // namespace envcrust::input

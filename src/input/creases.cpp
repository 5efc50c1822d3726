// Sharp creases of an input: how long, the fitted normal lines that round them off, the note.
#include "creases.h"

#include "envcrust/normals.h"

#include <iomanip>
#include <sstream>

namespace envcrust::input {
namespace {

constexpr const char* kRoundedOff = "which fitted normal lines round off (--creases join: joined across by the sheet)";
constexpr const char* kJoined = "left out of the reach estimate and joined across by the sheet";

}  // namespace

bool is_long_crease(const mesh::SharpEdges& sharp, const std::vector<Point3>& points) {
  return sharp.count > 0 && sharp.total_length > kCreaseMinLengthRelDiag * mesh::bbox_diagonal(points);
}

std::vector<Vector3> fitted_like(const std::vector<Point3>& points, const std::vector<Vector3>& given) {
  std::vector<Vector3> fitted = normals::estimate_normal_lines(points);
  for (std::size_t i = 0; i < fitted.size(); ++i)
    if (fitted[i] * given[i] < 0) fitted[i] = -fitted[i];
  return fitted;
}

std::string crease_note(const std::string& what, const mesh::SharpEdges& sharp, const std::string& across,
                        CreaseMode mode) {
  std::ostringstream w;
  w << std::setprecision(3) << what << " by more than " << kTearingBendDeg << " degrees across " << sharp.count << " "
    << across << " (" << sharp.total_length << " long in all, up to " << sharp.max_bend_deg << " degrees near ("
    << sharp.sharpest->x() << ", " << sharp.sharpest->y() << ", " << sharp.sharpest->z() << ")): creases, "
    << (mode == CreaseMode::Join ? kJoined : kRoundedOff);
  return w.str();
}

}  // namespace envcrust::input

#include "curve_output.h"

#include "envcrust/io.h"

namespace envcrust::cli {

std::vector<std::string> numbered_paths(const std::string& path, std::size_t count) {
  if (count == 1) return {path};
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = has_ext ? path.substr(0, dot) : path;
  const std::string ext = has_ext ? path.substr(dot) : ".polyline";
  std::vector<std::string> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(stem + "." + std::to_string(i) + ext);
  return out;
}

void check_curve_output(const std::string& path) {
  io::check_output_path(path, io::extension_of(path) == "polyline" ? io::OutputKind::Polyline
                                                                    : io::OutputKind::Points);
}

std::vector<std::string> write_curves(const std::string& path, const std::vector<BoundaryCurve>& curves) {
  if (io::extension_of(path) == "polyline") {
    const auto paths = numbered_paths(path, curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i) io::write_polyline(paths[i], curves[i].polyline());
    return paths;
  }
  PointSet points;
  for (const auto& curve : curves)
    for (const auto& b : curve.vertices) {
      points.points.push_back(b.position);
      points.normals.push_back(b.conormal);
    }
  io::write_points(path, points);
  return {path};
}

}  // namespace envcrust::cli

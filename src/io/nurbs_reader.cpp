// Reading NURBS patches: the dispatch by extension, and NURBS-Python's JSON exchange format
// (IGES in iges_reader.cpp).
#include "envcrust/io.h"

#include "io_detail.h"

#include <nlohmann/json.hpp>

namespace envcrust::io {

namespace {

using detail::fail;

// out_of_range 403: "key 'degree_u' not found"; type_error 302: "type must be number, but is string"
[[noreturn]] void not_a_surface(const std::filesystem::path& path, const std::string& which,
                                const nlohmann::json::exception& e) {
  const std::string what = e.what();
  const auto bracket = what.find("] ");
  fail(path, which + "not a NURBS-Python surface: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
}

// One entry of shape.data; `which` prefixes messages ("surface 2: ") when there are several.
surfaces::NurbsPatch read_geomdl_surface(const std::filesystem::path& path, const nlohmann::json& d,
                                         const std::string& which) {
  if (d.contains("trims") && !d.at("trims").at("data").empty())
    fail(path, which + "a trimmed surface: NURBS-Python trim curves are not read (an IGES trimmed surface, entity 144, is)");
  surfaces::NurbsPatch p;
  // A whole number in [low, high] (a float such as 1e20 would not convert to an int).
  const auto whole = [&](const char* key, std::int64_t low, std::int64_t high, const char* what) {
    const auto& value = d.at(key);
    if (!value.is_number_integer() || value.get<std::int64_t>() < low || value.get<std::int64_t>() > high)
      fail(path, which + std::string(key) + " is " + value.dump() + ", not " + what + " of " + std::to_string(low) + " to " +
                     std::to_string(high));
    return value.get<std::int64_t>();
  };
  p.degree_u = static_cast<int>(whole("degree_u", 1, 64, "a degree"));
  p.degree_v = static_cast<int>(whole("degree_v", 1, 64, "a degree"));
  const auto count = [&](const char* key) { return static_cast<std::size_t>(whole(key, 1, 1000000, "a count")); };
  p.count_u = count("size_u");
  p.count_v = count("size_v");
  p.knots_u = d.at("knotvector_u").get<std::vector<double>>();
  p.knots_v = d.at("knotvector_v").get<std::vector<double>>();
  const auto points = d.at("control_points").at("points").get<std::vector<std::vector<double>>>();
  if (points.size() != p.count_u * p.count_v)
    fail(path, which + std::to_string(points.size()) + " control points, size_u x size_v = " + std::to_string(p.count_u) +
                   " x " + std::to_string(p.count_v) + " expected");
  std::vector<double> weights(points.size(), 1.0);
  if (d.at("control_points").contains("weights"))
    weights = d.at("control_points").at("weights").get<std::vector<double>>();
  if (weights.size() != points.size())
    fail(path, which + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) + " control points");
  // NURBS-Python lists v fastest (index j + size_v * i); NurbsPatch wants u fastest.
  p.control_points.resize(points.size());
  p.weights.resize(points.size());
  for (std::size_t i = 0; i < p.count_u; ++i) {
    for (std::size_t jv = 0; jv < p.count_v; ++jv) {
      const auto& q = points[jv + p.count_v * i];
      if (q.size() != 3)
        fail(path, which + "control point " + std::to_string(jv + p.count_v * i) + " has " + std::to_string(q.size()) +
                       " coordinates, 3 expected");
      p.control_points[i + p.count_u * jv] = Point3(q[0], q[1], q[2]);
      p.weights[i + p.count_u * jv] = weights[jv + p.count_v * i];
    }
  }
  return p;
}

std::vector<surfaces::NurbsPatch> read_geomdl_json(const std::filesystem::path& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(detail::read_file(path));
  } catch (const nlohmann::json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ...", or
    // "[json.exception.out_of_range.406] number overflow parsing '1e999'"
    const std::string what = e.what();
    const auto colon = what.find("parse error");
    const auto bracket = what.find("] ");
    fail(path, "invalid JSON: " + (colon != std::string::npos   ? what.substr(colon)
                                   : bracket != std::string::npos ? what.substr(bracket + 2)
                                                                  : what));
  }
  try {
    const auto& shape = j.at("shape");
    const std::string type = shape.at("type").get<std::string>();
    if (type != "surface") fail(path, "holds a NURBS " + type + ", not a surface (shape.type must be \"surface\")");
    const auto& data = shape.at("data");
    if (!data.is_array() || data.empty()) fail(path, "shape.data holds no surface");
    std::vector<surfaces::NurbsPatch> patches;
    for (std::size_t k = 0; k < data.size(); ++k) {
      const std::string which = data.size() > 1 ? "surface " + std::to_string(k + 1) + ": " : "";
      try {  // several: each message names the one at fault
        patches.push_back(read_geomdl_surface(path, data[k], which));
      } catch (const nlohmann::json::exception& e) {
        not_a_surface(path, which, e);
      }
    }
    return patches;
  } catch (const nlohmann::json::exception& e) {
    not_a_surface(path, "", e);
  }
}

}  // namespace

bool is_nurbs_file(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  return extension == "igs" || extension == "iges" || extension == "json";
}

std::vector<surfaces::NurbsPatch> read_nurbs_patches(const std::filesystem::path& path) {
  const std::string extension = extension_of(path);
  if (extension == "igs" || extension == "iges") return detail::read_iges_patches(path);
  if (extension == "json") return read_geomdl_json(path);
  detail::unknown_extension(path, ".igs, .iges, .json");
}

}  // namespace envcrust::io

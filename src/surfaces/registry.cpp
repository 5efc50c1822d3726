// The names of the built-in surfaces and the factory that makes one by name.
#include "builtin.h"

#include "envcrust/errors.h"

#include <array>
#include <utility>

namespace envcrust::surfaces {

namespace {

using Factory = std::unique_ptr<Surface> (*)();

constexpr std::array<std::pair<std::string_view, Factory>, 13> registry{{
    {"cylinder", make_cylinder},
    {"cylinder-nurbs", make_cylinder_nurbs},
    {"paraboloid", make_paraboloid},
    {"horn", make_horn},
    {"cusp", make_cusp},
    {"trefoil-ribbon", make_trefoil_ribbon},
    {"unknot-ribbon", make_unknot_ribbon},
    {"moebius", make_moebius},
    {"hemisphere", make_hemisphere},
    {"square", make_square},
    {"saddle", make_saddle},
    {"sphere", make_sphere},
    {"torus", make_torus},
}};

}  // namespace

std::vector<std::string> builtin_names() {
  std::vector<std::string> names;
  names.reserve(registry.size());
  for (const auto& [name, factory] : registry) names.emplace_back(name);
  return names;
}

std::unique_ptr<Surface> make_builtin(std::string_view name) {
  for (const auto& [known, factory] : registry) {
    if (known == name) return factory();
  }
  std::string message = "unknown surface '" + std::string(name) + "' (known: ";
  for (std::size_t i = 0; i < registry.size(); ++i) {
    if (i > 0) message += ", ";
    message += registry[i].first;
  }
  throw InvalidInput(message + ")");
}

}  // namespace envcrust::surfaces

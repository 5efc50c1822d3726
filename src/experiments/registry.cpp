// The list of experiments and running one by name.
#include <chrono>

#include "envcrust/errors.h"
#include "experiment_list.h"

namespace envcrust::experiments {

const std::vector<Experiment>& experiment_list() {
  static const std::vector<Experiment> list = {
      {"trefoil", "Figures 1, 2",
       "Trefoil ribbon at decreasing sample counts: envelope method against the direct Power Crust.",
       detail::run_trefoil},
      {"cylinder", "Figures 3, 4",
       "Open NURBS cylinder, stage by stage: tessellation, envelope balls, offset points, envelope "
       "samples, direct against envelope result.",
       detail::run_cylinder},
      {"scan", "Figures 5, 6",
       "A real scan open at one boundary: points, polar balls, pole normals, envelope samples, direct "
       "against envelope result.",
       detail::run_scan},
      {"paraboloid", "Figure 7", "Paraboloid cap x = y^2 + z^2, x <= 4: direct against envelope.",
       detail::run_paraboloid},
      {"cusp", "Figure 8",
       "The non-C2 cap y = |x|^(3/2) at several envelope radii: where the artifacts appear (error "
       "against distance to the apex), with the paper's horn for comparison.",
       detail::run_cusp},
      {"normals", "Figure 9",
       "Normal errors: exact normals rotated by increasing random angles everywhere or on the "
       "boundary only; quality against the error.",
       detail::run_normals},
      {"unknot-curve", "Figure 10",
       "PL approximations of a non-planar unknot with fewer and fewer vertices: the knot type of "
       "each.",
       detail::run_unknot_curve},
      {"unknot-radius", "Figure 11",
       "Unknot ribbon, envelope radius swept at a fixed envelope sample spacing: topology and "
       "distance against the radius, compared with the bound rho < reach.",
       detail::run_unknot_radius},
      {"density", "",
       "For each built-in open surface, the sparsest sampling at which each method still gets the "
       "topology right.",
       detail::run_density},
  };
  return list;
}

ExperimentResult run_experiment(std::string_view name, const ExperimentOptions& options) {
  std::string known;
  for (const auto& e : experiment_list()) {
    if (e.name == name) {
      const auto start = std::chrono::steady_clock::now();
      ExperimentResult result = e.run(options);
      result.name = e.name;
      result.description = e.paper_figures.empty() ? e.description : e.description + " (paper " + e.paper_figures + ")";
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
    known += (known.empty() ? "" : ", ") + e.name;
  }
  throw InvalidOptions("unknown experiment '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace envcrust::experiments

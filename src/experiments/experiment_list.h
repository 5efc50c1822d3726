// The experiment functions, one per file (registered in registry.cpp).
#pragma once

#include "envcrust/experiments.h"

namespace envcrust::experiments::detail {

ExperimentResult run_trefoil(const ExperimentOptions& options);
ExperimentResult run_cylinder(const ExperimentOptions& options);
ExperimentResult run_scan(const ExperimentOptions& options);
ExperimentResult run_paraboloid(const ExperimentOptions& options);
ExperimentResult run_cusp(const ExperimentOptions& options);
ExperimentResult run_normals(const ExperimentOptions& options);
ExperimentResult run_unknot_curve(const ExperimentOptions& options);
ExperimentResult run_unknot_radius(const ExperimentOptions& options);
ExperimentResult run_density(const ExperimentOptions& options);

}  // namespace envcrust::experiments::detail

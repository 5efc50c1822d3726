// Registration of every subcommand with the CLI11 app (one cmd_<name>.cpp each).
#pragma once

#include <CLI/CLI.hpp>

namespace envcrust::cli {

void register_sample(CLI::App& app);
void register_analyze(CLI::App& app);
void register_boundary(CLI::App& app);
void register_reconstruct(CLI::App& app);
void register_envelope(CLI::App& app);
void register_powercrust(CLI::App& app);
void register_render(CLI::App& app);
void register_experiment(CLI::App& app);

}  // namespace envcrust::cli

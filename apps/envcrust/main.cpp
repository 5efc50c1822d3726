// Entry point of the envcrust command-line tool: registers subcommands, maps errors to exit codes.
#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"envcrust: reconstruction of surfaces with boundary"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}

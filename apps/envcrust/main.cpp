// Entry point of the envcrust command-line tool: registers subcommands and maps errors to
// exit codes (1 bad input or options, 2 usage, 3 internal error, 4 a result written that fails
// its own checks).
#include "cli_common.h"
#include "commands.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>

namespace {

// An interrupted or killed run removes the output it was writing (a hidden temp file), then
// dies of the signal as it would have.
extern "C" void remove_temp_files_and_die(int signal) {
  envcrust::io::remove_pending_temp_files();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

int main(int argc, char** argv) {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, remove_temp_files_and_die);
  CLI::App app{
      "envcrust: reconstruction of surfaces with boundary through their rho-envelope.\n"
      "Run 'envcrust SUBCOMMAND --help' for the options of a subcommand.\n"
      "Exit codes: 0 success, 1 bad input or a refused run, 2 usage error, 3 internal error,\n"
      "4 (reconstruct) the result was written but fails its own checks (see --help of reconstruct)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "envcrust 0.1.0");
  envcrust::cli::register_sample(app);
  envcrust::cli::register_analyze(app);
  envcrust::cli::register_reconstruct(app);
  envcrust::cli::register_boundary(app);
  envcrust::cli::register_envelope(app);
  envcrust::cli::register_powercrust(app);
  envcrust::cli::register_render(app);
  envcrust::cli::register_experiment(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "envcrust: usage error: " << e.what() << "\n";
    return 2;
  } catch (const envcrust::cli::ChecksFailed& e) {
    std::cerr << "envcrust: " << e.what() << "\n";
    return envcrust::cli::kExitChecksFailed;
  } catch (const envcrust::cli::UsageError& e) {
    std::cerr << "envcrust: usage error: " << e.what() << "\n";
    return 2;
  } catch (const envcrust::Error& e) {
    std::cerr << "envcrust: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "envcrust: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}

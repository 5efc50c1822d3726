// Run the envcrust binary with arguments and capture exit code, stdout and stderr.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace envcrust::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `ENVCRUST_BINARY args` through the shell (args are passed verbatim).
inline CommandResult run_envcrust(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto out = dir / ("envcrust_cli_out_" + std::to_string(::getpid()));
  const auto err = dir / ("envcrust_cli_err_" + std::to_string(::getpid()));
  const std::string command = std::string(ENVCRUST_BINARY) + " " + args + " >" + out.string() +
                              " 2>" + err.string() + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace envcrust::testing

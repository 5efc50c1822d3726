// Common flags, the terminal progress bar and output helpers of the CLI.
#include "cli_common.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace envcrust::cli {

void add_common_flags(CLI::App& command, CommonFlags& flags) {
  command.add_flag("--json", flags.json, "Print the report as JSON on stdout");
  command.add_flag("-q,--quiet", flags.quiet, "No progress bar and no text summary");
}

Progress terminal_progress(bool quiet) {
  Progress progress;
  if (quiet || isatty(STDERR_FILENO) == 0) return progress;
  auto last = std::make_shared<int>(-1);
  progress.callback = [last](std::string_view stage, double fraction) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent == *last) return;
    *last = percent;
    const int width = 30;
    const int filled = percent * width / 100;
    std::fprintf(stderr, "\r%-24.*s [%.*s%*s] %3d%%", static_cast<int>(stage.size()), stage.data(),
                 filled, "##############################", width - filled, "", percent);
    if (percent >= 100) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  };
  return progress;
}

void print_json(const nlohmann::json& document) { std::cout << document.dump(2) << '\n'; }

std::string percent(double fraction) {
  std::ostringstream out;
  out.precision(3);
  out << fraction * 100.0 << '%';
  return out.str();
}

}  // namespace envcrust::cli

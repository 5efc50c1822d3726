// Common flags, the terminal progress bar and output helpers of the CLI.
#include "cli_common.h"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace envcrust::cli {

void add_common_flags(CLI::App& command, CommonFlags& flags) {
  command.add_flag("--json", flags.json, "Print the report as JSON on stdout");
  command.add_flag("-q,--quiet", flags.quiet, "No progress bar and no text summary");
}

Progress terminal_progress(bool quiet) {
  Progress progress;
  if (quiet || isatty(STDERR_FILENO) == 0) return progress;
  struct Shown {
    std::string stage;
    int percent = -1;
  };
  auto last = std::make_shared<Shown>();
  progress.callback = [last](std::string_view stage, double fraction) {
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent == last->percent && stage == last->stage) return;
    *last = {std::string(stage), percent};
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

CLI::Validator whole_number_at_least(long long min) {
  return CLI::Validator(
      [min](std::string& text) -> std::string {
        long long value = 0;
        const char* end = text.data() + text.size();
        const auto [at, error] = std::from_chars(text.data(), end, value);
        if (error == std::errc() && at == end && value >= min) return "";
        return "must be a whole number >= " + std::to_string(min) + " (got '" + text + "')";
      },
      "INT>=" + std::to_string(min));
}

CLI::Validator number_above(double min, bool inclusive) {
  std::ostringstream bound;
  bound << (inclusive ? ">= " : "> ") << min;
  return CLI::Validator(
      [min, inclusive, bound = bound.str()](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool parsed = !text.empty() && end == text.c_str() + text.size() && std::isfinite(value);
        if (parsed && (inclusive ? value >= min : value > min)) return "";
        return "must be a number " + bound + " (got '" + text + "')";
      },
      "NUMBER" + bound.str());
}

}  // namespace envcrust::cli
